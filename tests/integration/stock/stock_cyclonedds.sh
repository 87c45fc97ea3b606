#!/usr/bin/env bash
# A stock Cyclone DDS program (cyclone_stock.c: plain C, idlc types, no plumb code) and plumb on one
# computer, with the shipped configuration file (transports/config/cyclonedds-loopback.xml), against
# plumb on each of its transports:
#   plumb topic pub plumb/attitude/test -> cyclone-stock listen;
#   cyclone-stock publish plumb/sensor/raw -> plumb-estimator (static plugin) -> plumb topic echo.
# usage: stock_cyclonedds.sh SOURCE_DIR BIN_DIR DOMAIN
set -uo pipefail
src=$1 bin=$2
export PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
stock=$bin/plumb-test-cyclone-stock
stock_env=(env CYCLONEDDS_URI="file://$src/transports/config/cyclonedds-loopback.xml")

for t in cyclonedds fastdds; do
  "${stock_env[@]}" "$stock" listen plumb/attitude/test 3 > "$work/listen.$t" 2>&1 &
  pids+=($!); listener=$!
  wait_for "$work/listen.$t" "^listening" 20 || fail "cyclone-stock listen did not start: $(cat "$work/listen.$t")"
  "$bin/plumb" topic pub plumb/attitude/test inclination_deg=1.5 azimuth_deg=12 --count 3 --rate 5 --wait 20 \
    --transport $t > "$work/pub.$t" 2>&1 || fail "plumb topic pub ($t): $(cat "$work/pub.$t")"
  wait $listener && [ "$(grep -c "inclination_deg=1.5 azimuth_deg=12" "$work/listen.$t")" -eq 3 ] &&
    pass "stock Cyclone DDS program got plumb's 3 attitudes from $t" || fail "cyclone-stock listen ($t): $(cat "$work/listen.$t")"

  "$bin/plumb" topic echo plumb/attitude/static --csv --count 1 --timeout 60 --transport $t > "$work/att.$t" 2> "$work/echo.$t" &
  pids+=($!); echo_pid=$!
  "$bin/plumb-estimator" --plugin static --window 2 --input plumb/sensor/raw --reliable --count 2 --timeout 60 -q \
    --transport $t > "$work/host.$t" 2>&1 &
  pids+=($!); host=$!
  "${stock_env[@]}" "$stock" publish plumb/sensor/raw 40 > "$work/spub.$t" 2>&1 || fail "cyclone-stock publish ($t): $(cat "$work/spub.$t")"
  wait $host && pass "plumb-estimator ($t) accepted the stock program's batches" || fail "host ($t): $(cat "$work/host.$t")"
  wait $echo_pid && python3 "$here/../e2e/check_estimates.py" "$work/att.$t" --inclination 2 --azimuth 30 \
    --inc-tol 0.01 --azi-tol 0.1 && pass "its estimate is the stock program's attitude ($t)" ||
    fail "echo ($t): $(cat "$work/echo.$t" "$work/att.$t")"
done
finish
