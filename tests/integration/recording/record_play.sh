#!/usr/bin/env bash
# plumb record / info / play / export / estimate over real DDS: the simulator on one vendor, the
# recorder on another; the recording played back on the second and received on the first.
# usage: record_play.sh BIN_DIR SIM_T REC_T DOMAIN
set -uo pipefail
bin=$1 sim_t=$2 rec_t=$3
export PLUMB_DOMAIN_ID=$4
here=$(dirname "$0")
. "$here/../lib.sh"
. "$here/../wait.sh"
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT

# 2000 samples in batches of 10, reliable: exactly 200 sensor batches and 200 truth messages.
timeout 60 "$bin/plumb" record plumb/sensor/raw plumb/sim/truth --reliable -o "$work/run.mcap" --transport "$rec_t" \
  > "$work/rec.log" 2>&1 &
rec=$!
wait_for "$work/rec.log" "recording" 30 || fail "recorder did not start: $(cat "$work/rec.log")"
timeout 60 "$bin/plumb-sim" --inclination 30 --azimuth 45 --rpm 0 --count 2000 --batch 10 --rate x20 --reliable \
  --wait-subscribers 20 --linger 2 --transport "$sim_t" > "$work/sim.log" 2>&1 || fail "sim: $(cat "$work/sim.log")"
kill -INT $rec
wait $rec && pass "recorder stopped cleanly on SIGINT" || fail "recorder: $(cat "$work/rec.log")"

"$bin/plumb" info "$work/run.mcap" > "$work/info.txt" 2>&1 || fail "info: $(cat "$work/info.txt")"
grep -q 'Topic: plumb/sensor/raw | Type: plumb::msg::SensorBatch | Count: 200 |' "$work/info.txt" &&
  grep -q 'Topic: plumb/sim/truth | Type: plumb::msg::Truth | Count: 200 |' "$work/info.txt" &&
  grep -q 'Summary:           yes' "$work/info.txt" && grep -q "transport: $rec_t" "$work/info.txt" &&
  pass "info: 200 batches and 200 truths, as sent, with summary and metadata" || fail "info: $(cat "$work/info.txt")"

# Export: the sensor CSV of docs/conventions.md, every sample; estimate reads the recording as it is.
"$bin/plumb" export "$work/run.mcap" -o "$work/sensor.csv" 2> "$work/export.err" &&
  [ "$(grep -vc '^#' "$work/sensor.csv")" -eq 2001 ] && grep -q '^seq,t,fx,fy,fz,bx,by,bz' "$work/sensor.csv" &&
  pass "export: sensor CSV with 2000 samples" || fail "export: $(head -3 "$work/sensor.csv") $(cat "$work/export.err")"
"$bin/plumb" estimate -e static --input "$work/run.mcap" --window 0 > "$work/est_mcap.csv" 2> "$work/est.err" &&
  "$bin/plumb" estimate -e static --input "$work/sensor.csv" --window 0 > "$work/est_csv.csv" 2>> "$work/est.err" &&
  python3 - "$work/est_mcap.csv" "$work/est_csv.csv" <<'PY' &&
import csv, sys
# The CSV holds 10 significant digits: the same estimate, to that precision.
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
assert len(a) == 1 and len(b) == 1 and a[0]["valid"] == "1", (a, b)
for k in ("inclination_deg", "azimuth_deg", "toolface_deg", "total_g", "total_b"):
    assert abs(float(a[0][k]) - float(b[0][k])) < 1e-6, (k, a[0][k], b[0][k])
PY
  pass "estimate --input run.mcap gives what the exported CSV gives" ||
  fail "estimate: $(cat "$work/est_mcap.csv" "$work/est_csv.csv" "$work/est.err")"

# Compare takes recordings too: the same table from the recording as from its exported CSV.
"$bin/plumb" compare --input "$work/run.mcap" -e static -e compensated --window 0.5 --csv "$work/cmp_mcap.csv" \
  > "$work/cmp.out" 2>&1 &&
  "$bin/plumb" compare --input "$work/sensor.csv" -e static -e compensated --window 0.5 --csv "$work/cmp_csv.csv" \
  >> "$work/cmp.out" 2>&1 && python3 - "$work/cmp_mcap.csv" "$work/cmp_csv.csv" <<'PY' &&
import csv, sys
# 2000 samples at 100 Hz in 0.5 s windows: 40 rows each; the exported CSV rounds to 10 digits.
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
assert [r["plugin"] for r in a] == ["static", "compensated"] and len(b) == 2, (a, b)
for ra, rb in zip(a, b):
    assert ra["rows"] == ra["valid"] == rb["valid"] == "40" and ra["matched"] == "40", (ra, rb)
    for k in ("inclination_mean_deg", "azimuth_mean_deg", "rms_inclination_diff_deg", "rms_azimuth_diff_deg"):
        assert abs(float(ra[k]) - float(rb[k])) < 1e-5, (k, ra[k], rb[k])
    assert abs(float(ra["inclination_mean_deg"]) - 30) < 1e-3 and abs(float(ra["azimuth_mean_deg"]) - 45) < 1e-3, ra
PY
  pass "compare --input run.mcap: the exported CSV's table, 40 valid rows per plugin at the truth" ||
  fail "compare: $(cat "$work/cmp.out" "$work/cmp_mcap.csv" "$work/cmp_csv.csv")"

# Play on the recorder's vendor at x10, received on the simulator's: every batch, same values.
timeout 60 "$bin/plumb" topic echo plumb/sensor/raw --csv --reliable --count 200 --timeout 40 --transport "$sim_t" \
  > "$work/played.csv" 2> "$work/echo.err" &
echo_pid=$!
timeout 60 "$bin/plumb" play "$work/run.mcap" --topics plumb/sensor/raw --rate x10 --reliable --wait 20 \
  --transport "$rec_t" > "$work/play.log" 2>&1 || fail "play: $(cat "$work/play.log")"
wait $echo_pid && cmp -s <(grep -v '^#' "$work/played.csv") <(grep -v '^#' "$work/sensor.csv") &&
  pass "play: the 200 batches received again, sample for sample ($(tail -1 "$work/play.log"))" ||
  fail "play: $(cat "$work/play.log" "$work/echo.err"; diff <(grep -v '^#' "$work/played.csv") <(grep -v '^#' "$work/sensor.csv") | head -5)"
finish
