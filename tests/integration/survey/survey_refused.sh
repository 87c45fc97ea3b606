#!/usr/bin/env bash
# Surveys, bad input live: plumb-survey fed by hand (`plumb topic pub`) with a stop at 10 m, then a
# stop at 5 m (the depth went backwards) and a stop whose field is far from the reference. The
# backwards station is refused with one stderr line and counted (status degraded), the field one is
# kept and flagged; neither is dropped in silence, and the survey file holds exactly the two kept.
# usage: survey_refused.sh BIN_DIR TRANSPORT DOMAIN
set -euo pipefail
bin=$1
export PLUMB_TRANSPORT=$2 PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
source "$here/../wait.sh"
start_work_with_programs

"$bin/plumb-survey" --tool-id t1 --plugin static --file "$work/survey.csv" --gravity 9.80665 --total-field 50 --dip 60 \
  --depth-clock-offset 0 > "$work/out" 2> "$work/err" &
pids+=($!)
wait_for "$work/err" "file .*survey.csv" 20 || { cat "$work/err"; exit 1; }
s=1000000000
depth() { "$bin/plumb" topic pub plumb/depth tool_id=t1 stamp_ns=$(($1 * s)) depth_m=$2 flags=1 --wait 10 > /dev/null; }
window() {  # END_S TOTAL_B
  "$bin/plumb" topic pub plumb/attitude/static tool_id=t1 estimator=static window_start_ns=$((($1 - 5) * s)) \
    window_end_ns=$(($1 * s)) inclination_deg=30 azimuth_deg=100 inclination_sd_deg=0.01 azimuth_sd_deg=0.1 \
    total_g=9.80665 total_b=$2 dip_deg=60 flags=3 --wait 10 > /dev/null
}
# Stop 1 at 10 m (0..10 s), stop 2 at 5 m (20..30 s): backwards. Stop 3 at 20 m (40..50 s), |B| off by 2 uT.
depth 0 10; depth 10 10; window 10 50
wait_for "$work/survey.csv" "^0," 20 || { echo "no first station:"; cat "$work/err"; exit 1; }
depth 20 5; depth 30 5; window 30 50
wait_for "$work/err" "station refused" 20 || { echo "no refusal said:"; cat "$work/err"; exit 1; }
depth 40 20; depth 50 20; window 50 52
wait_for "$work/survey.csv" "^1," 20 || { echo "no third station:"; cat "$work/err"; exit 1; }

if output_matches "station refused: station 1 (MD 5 m): measured depth goes backwards" cat "$work/err"; then
  pass "backwards station refused in one line: $(grep refused "$work/err")"
else
  fail "refusal line: $(cat "$work/err")"
fi
rows=$(grep -c '^[0-9]' "$work/survey.csv")
if [ "$rows" -eq 2 ] && grep -q '^1,.*,fail,|B| off by 2' "$work/survey.csv"; then
  pass "the field station kept and flagged: $(grep '^1,' "$work/survey.csv" | sed 's/.*,fail,/fail: /')"
else
  fail "survey file ($rows rows): $(cat "$work/survey.csv")"
fi
"$bin/plumb" topic echo plumb/status --count 3 --timeout 10 > "$work/status" 2>&1 || true
if grep -A1 '"refused_stations"' "$work/status" | grep -q "value: 1" && grep -q 'state: "degraded"' "$work/status"; then
  pass "status says degraded, refused_stations 1"
else
  fail "status: $(head -c 600 "$work/status")"
fi
finish
