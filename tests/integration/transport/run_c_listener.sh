#!/usr/bin/env bash
# The plain C listener (Cyclone DDS + IDL only) receives one attitude that plumb-test-peer
# publishes on the given vendor, and prints it exactly as expected.
#   run_c_listener.sh PEER LISTENER WRITER_TRANSPORT DOMAIN
set -u
if [ $# -ne 4 ]; then
  echo "usage: run_c_listener.sh PEER LISTENER WRITER_TRANSPORT DOMAIN" >&2
  exit 2
fi
peer=$1 listener=$2 writer_transport=$3 domain=$4
topic=plumb/attitude/test
work=$(mktemp -d)
writer_pid="" listener_pid=""
cleanup() {
  for pid in $writer_pid $listener_pid; do kill "$pid" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT

expected=$("$peer" --print-expected-attitude) || exit 1
"$listener" --domain "$domain" --count 1 --timeout 20 "$topic" >"$work/listener.out" 2>&1 &
listener_pid=$!
"$peer" --transport "$writer_transport" --domain "$domain" --role writer --type attitude \
  --attitude-topic "$topic" --timeout 20 >"$work/writer.out" 2>&1 &
writer_pid=$!
wait "$listener_pid"; listener_status=$?
kill -TERM "$writer_pid" 2>/dev/null  # the listener is done: no need to linger
wait "$writer_pid"; writer_status=$?
writer_pid="" listener_pid=""
echo "--- writer ($writer_transport, exit $writer_status)"; cat "$work/writer.out"
echo "--- listener (exit $listener_status)"; cat "$work/listener.out"
[ "$listener_status" -eq 0 ] && [ "$writer_status" -eq 0 ] || exit 1
if ! grep -qxF -- "$expected" "$work/listener.out"; then
  echo "--- expected line"; echo "$expected"
  exit 1
fi
echo "listener printed the expected attitude"
