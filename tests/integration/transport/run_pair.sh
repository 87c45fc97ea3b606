#!/usr/bin/env bash
# Runs a plumb-test-peer writer and reader as separate processes and passes if both pass.
#   run_pair.sh PEER WRITER_TRANSPORT READER_TRANSPORT DOMAIN TYPE
# TYPE all: both start together. TYPE late-calibration: the reader starts only after the writer
# has published, so it can only get the message through transient-local durability.
set -u
if [ $# -ne 5 ]; then
  echo "usage: run_pair.sh PEER WRITER_TRANSPORT READER_TRANSPORT DOMAIN TYPE" >&2
  exit 2
fi
peer=$1 writer_transport=$2 reader_transport=$3 domain=$4 type=$5
timeout=20
work=$(mktemp -d)
writer_pid="" reader_pid=""
cleanup() {
  for pid in $writer_pid $reader_pid; do kill "$pid" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT

run_peer() {  # role transport
  exec "$peer" --transport "$2" --domain "$domain" --role "$1" --type "$type" --timeout "$timeout" >"$work/$1.out" 2>&1
}

if [ "$type" = late-calibration ]; then
  run_peer writer "$writer_transport" &
  writer_pid=$!
  for _ in $(seq 1 $((timeout * 10))); do
    grep -q "wrote" "$work/writer.out" 2>/dev/null && break
    kill -0 "$writer_pid" 2>/dev/null || break
    sleep 0.1
  done
  if ! grep -q "wrote" "$work/writer.out" 2>/dev/null; then
    echo "writer did not publish:"; cat "$work/writer.out"; exit 1
  fi
  run_peer reader "$reader_transport" &
  reader_pid=$!
else
  run_peer reader "$reader_transport" &
  reader_pid=$!
  run_peer writer "$writer_transport" &
  writer_pid=$!
fi

wait "$reader_pid"; reader_status=$?
# The reader has checked everything (or failed): the writer need not linger any longer. (It would
# leave by itself once it sees the reader gone, but a Fast DDS writer notices a Cyclone reader's
# departure only when its lease runs out, about 10 s.)
kill -TERM "$writer_pid" 2>/dev/null
wait "$writer_pid"; writer_status=$?
writer_pid="" reader_pid=""
echo "--- writer ($writer_transport, exit $writer_status)"; cat "$work/writer.out"
echo "--- reader ($reader_transport, exit $reader_status)"; cat "$work/reader.out"
[ "$reader_status" -eq 0 ] && [ "$writer_status" -eq 0 ]
