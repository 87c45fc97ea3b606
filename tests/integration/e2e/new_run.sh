#!/usr/bin/env bash
# A running estimator host and a source started twice (two plumb-sim runs, each clock from 0, like
# a replay run again): the second run is a new run, estimated afresh, not refused as time going
# back. usage: new_run.sh BIN_DIR TRANSPORT DOMAIN
set -uo pipefail
bin=$1 t=$2
export PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
start_work_with_programs

"$bin/plumb" topic echo plumb/attitude/compensated --csv --count 8 --timeout 60 --transport "$t" \
  > "$work/att.csv" 2> "$work/echo.err" &
echo_pid=$!
"$bin/plumb-estimator" --transport "$t" --input plumb/sensor/raw --reliable --plugin compensated --window 1 \
  > "$work/host.out" 2>&1 &
host=$!
pids+=($echo_pid $host)
for run in "3 100" "7 200"; do
  read -r inc azi <<<"$run"
  "$bin/plumb-sim" --transport "$t" --inclination "$inc" --azimuth "$azi" --rpm 60 --duration 4 --rate x2 --reliable \
    --wait-subscribers 20 --no-truth > "$work/sim_$inc.out" 2>&1 || fail "plumb-sim run $inc: $(tail -2 "$work/sim_$inc.out")"
done
wait $echo_pid && pass "eight estimates published" || fail "estimates: $(cat "$work/echo.err")"
kill -INT $host 2>/dev/null
wait $host
python3 - "$work/att.csv" <<'PY' && pass "both runs estimated, each at its own truth" || fail "estimates: $(cat "$work/att.csv")"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
got = [(round(float(r["inclination_deg"]), 2), round(float(r["azimuth_deg"]), 1)) for r in rows]
sys.exit(0 if got == [(3.0, 100.0)] * 4 + [(7.0, 200.0)] * 4 else 1)
PY
output_matches "time went back from 3.99 s to 0 s: a new run" cat "$work/host.out" &&
  pass "the host says it started a new run" || fail "host log: $(cat "$work/host.out")"
output_matches "restarted its sequence (now 0, was 399): a new source" cat "$work/host.out" &&
  output_matches "0 lost in transit" cat "$work/host.out" &&
  pass "the sequence starting over is a new source, not a loss" || fail "host log: $(cat "$work/host.out")"
finish
