#!/usr/bin/env bash
# Two computers on one machine: a "tool" network namespace runs plumb-sim, a "surface" namespace
# runs plumb-estimator and `plumb topic echo`, joined by a veth pair (10.231.0.1 <-> 10.231.0.2,
# addresses that exist only inside the namespaces this test creates). Each side selects its
# interface with --interface and they use different DDS vendors.
# usage: two_hosts.sh BIN_DIR TOOL_TRANSPORT SURFACE_TRANSPORT
set -uo pipefail
bin=$1 tool_t=$2 surface_t=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/netns.sh"
work=$(mktemp -d)
cleanup() { kill $(jobs -p) 2>/dev/null; netns_cleanup; rm -rf "$work"; }
trap cleanup EXIT
netns_pair 10.231.0 || { rc=$?; [ $rc -eq 77 ] && exit 77; fail "netns setup"; finish; }

ip netns exec "$surface" timeout 90 "$bin/plumb" topic echo plumb/attitude/compensated --csv --count 1 --timeout 80 \
  --transport "$surface_t" --interface $surface_if > "$work/att.csv" 2> "$work/echo.err" &
echo_pid=$!
ip netns exec "$surface" timeout 90 "$bin/plumb-estimator" --plugin compensated --input plumb/sensor/raw --reliable \
  --window 5 --count 1 --timeout 80 -q --transport "$surface_t" --interface 10.231.0.2 > "$work/host.log" 2>&1 &
host_pid=$!
sleep 2
ip netns exec "$tool" timeout 90 "$bin/plumb-sim" --transport "$tool_t" --interface $tool_if --inclination 1 --azimuth 45 \
  --rpm 60 --duration 5.5 --snr-accel 40 --snr-mag 40 --rate x4 --reliable --wait-subscribers 30 > "$work/sim.log" 2>&1 ||
  fail "plumb-sim in the tool namespace: $(cat "$work/sim.log")"
wait $host_pid && pass "estimator host in the surface namespace got the stream" || fail "host: $(cat "$work/host.log")"
wait $echo_pid && python3 "$here/../e2e/check_estimates.py" "$work/att.csv" --inclination 1 --azimuth 45 \
  --inc-tol 0.02 --azi-tol 0.3 && pass "attitude crossed namespaces and matches the truth" ||
  fail "echo: $(cat "$work/echo.err" "$work/att.csv")"
finish
