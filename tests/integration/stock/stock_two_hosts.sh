#!/usr/bin/env bash
# The stock Cyclone DDS program (cyclone_stock.c) and plumb on two "computers": network namespaces
# joined by a veth pair (../multihost/netns.sh). The program uses the shipped interface configuration
# (transports/config/cyclonedds-interface.xml) with the interface name edited, as a team would;
# plumb uses --interface. For each plumb transport:
#   tool side: cyclone-stock publish plumb/sensor/raw -> surface side: plumb-estimator -> plumb topic echo;
#   tool side: plumb topic pub plumb/attitude/test  -> surface side: cyclone-stock listen.
# usage: stock_two_hosts.sh SOURCE_DIR BIN_DIR DOMAIN
set -uo pipefail
src=$1 bin=$2
export PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
. "$here/../multihost/netns.sh"
work=$(mktemp -d)
cleanup() { kill $(jobs -p) 2>/dev/null; netns_cleanup; rm -rf "$work"; }
trap cleanup EXIT
netns_pair 10.232.0 || exit $?
stock=$bin/plumb-test-cyclone-stock
for side in tool surface; do
  ifname=$tool_if; [ $side = surface ] && ifname=$surface_if
  sed "s|name=\"eth1\"|name=\"$ifname\"|" "$src/transports/config/cyclonedds-interface.xml" > "$work/$side.xml"
done
in_tool() { ip netns exec "$tool" env CYCLONEDDS_URI="file://$work/tool.xml" "$@"; }
in_surface() { ip netns exec "$surface" env CYCLONEDDS_URI="file://$work/surface.xml" "$@"; }

for t in cyclonedds fastdds; do
  in_surface "$bin/plumb" topic echo plumb/attitude/static --csv --count 1 --timeout 60 --transport $t \
    --interface "$surface_if" > "$work/att.$t" 2> "$work/echo.$t" &
  echo_pid=$!
  in_surface "$bin/plumb-estimator" --plugin static --window 2 --input plumb/sensor/raw --reliable --count 2 --timeout 60 -q \
    --transport $t --interface 10.232.0.2 > "$work/host.$t" 2>&1 &
  host=$!
  in_tool "$stock" publish plumb/sensor/raw 40 > "$work/spub.$t" 2>&1 || fail "cyclone-stock publish (tool side): $(cat "$work/spub.$t")"
  wait $host && pass "plumb-estimator ($t, surface) accepted the stock program's batches from the tool side" ||
    fail "host ($t): $(cat "$work/host.$t")"
  wait $echo_pid && python3 "$here/../e2e/check_estimates.py" "$work/att.$t" --inclination 2 --azimuth 30 \
    --inc-tol 0.01 --azi-tol 0.1 && pass "its estimate crossed back ($t)" || fail "echo ($t): $(cat "$work/echo.$t" "$work/att.$t")"

  in_surface "$stock" listen plumb/attitude/test 3 > "$work/listen.$t" 2>&1 &
  listener=$!
  wait_for "$work/listen.$t" "^listening" 20 || fail "cyclone-stock listen did not start: $(cat "$work/listen.$t")"
  in_tool "$bin/plumb" topic pub plumb/attitude/test inclination_deg=1.5 azimuth_deg=12 --count 3 --rate 5 --wait 20 \
    --transport $t --interface "$tool_if" > "$work/pub.$t" 2>&1 || fail "plumb topic pub ($t): $(cat "$work/pub.$t")"
  wait $listener && [ "$(grep -c "inclination_deg=1.5 azimuth_deg=12" "$work/listen.$t")" -eq 3 ] &&
    pass "stock program (surface) got plumb's 3 attitudes from the tool side ($t)" ||
    fail "cyclone-stock listen ($t): $(cat "$work/listen.$t")"
done

# The link check of the README: plumb status on the surface lists the tool side's component.
in_tool "$bin/plumb-estimator" --plugin static --input plumb/sensor/raw --timeout 8 -q --interface "$tool_if" \
  > /dev/null 2>&1 &
same_domain=$!
if output_matches "plumb-estimator *running" in_surface "$bin/plumb" status --wait 3 --interface "$surface_if"; then
  pass "plumb status on the surface lists the tool side's component and its state"
else
  fail "plumb status across: $(in_surface "$bin/plumb" status --wait 3 --interface "$surface_if" 2>&1)"
fi

# Stop it (the function's subshell is $same_domain; the estimator runs inside the namespace).
ip netns pids "$tool" | xargs -r kill 2>/dev/null
wait $same_domain 2>/dev/null

# Two computers on different domain ids: plumb status on the surface hears nobody and says what to check.
in_tool "$bin/plumb-estimator" --plugin static --input plumb/sensor/raw --timeout 20 -q --interface "$tool_if" \
  --domain $((PLUMB_DOMAIN_ID - 1)) > /dev/null 2>&1 &
expect_error "plumb status, other side on another domain" "no plumb component seen.*domain $PLUMB_DOMAIN_ID.*same --domain" \
  in_surface "$bin/plumb" status --wait 3 --interface "$surface_if"
finish
