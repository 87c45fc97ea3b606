#!/usr/bin/env bash
# Two "computers": network namespaces joined by a veth pair, with only multicast-capable veth
# interfaces between them (no shared loopback). plumb-test-peer writes every topic type in one,
# and reads and checks them in the other, each given its interface (by name on one side, by
# address on the other). Needs root and iproute2; exits 77 (skipped) without them.
#   run_two_hosts.sh PEER WRITER_TRANSPORT READER_TRANSPORT DOMAIN
set -u
if [ $# -ne 4 ]; then
  echo "usage: run_two_hosts.sh PEER WRITER_TRANSPORT READER_TRANSPORT DOMAIN" >&2
  exit 2
fi
peer=$1 writer_transport=$2 reader_transport=$3 domain=$4
if ! ip netns add "plumb-probe-$$" 2>/dev/null; then
  echo "cannot create network namespaces here (needs root and iproute2): skipped"
  exit 77
fi
ip netns del "plumb-probe-$$"
a="plumb-peer-a-$$" b="plumb-peer-b-$$"
work=$(mktemp -d)
writer_pid="" reader_pid=""
cleanup() {
  for pid in $writer_pid $reader_pid; do kill "$pid" 2>/dev/null; done
  ip netns del "$a" 2>/dev/null
  ip netns del "$b" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
ip netns add "$a" && ip netns add "$b" || exit 1
ip link add "vpa$$" netns "$a" type veth peer name "vpb$$" netns "$b" || exit 1
ip -n "$a" addr add 10.232.0.1/24 dev "vpa$$"
ip -n "$b" addr add 10.232.0.2/24 dev "vpb$$"
for ns in "$a" "$b"; do ip -n "$ns" link set lo up; done
ip -n "$a" link set "vpa$$" up multicast on
ip -n "$b" link set "vpb$$" up multicast on
ip -n "$a" route add 224.0.0.0/4 dev "vpa$$"
ip -n "$b" route add 224.0.0.0/4 dev "vpb$$"

ip netns exec "$b" "$peer" --transport "$reader_transport" --domain "$domain" --role reader --type all \
  --timeout 30 --interface 10.232.0.2 >"$work/reader.out" 2>&1 &
reader_pid=$!
ip netns exec "$a" "$peer" --transport "$writer_transport" --domain "$domain" --role writer --type all \
  --timeout 30 --interface "vpa$$" >"$work/writer.out" 2>&1 &
writer_pid=$!
wait "$reader_pid"; reader_status=$?
kill -TERM "$writer_pid" 2>/dev/null
wait "$writer_pid"; writer_status=$?
writer_pid="" reader_pid=""
echo "--- writer ($writer_transport in $a, exit $writer_status)"; cat "$work/writer.out"
echo "--- reader ($reader_transport in $b, exit $reader_status)"; cat "$work/reader.out"
[ "$reader_status" -eq 0 ] && [ "$writer_status" -eq 0 ]
