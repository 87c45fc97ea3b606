#!/bin/bash
# Offline calibration from simulated turntable recordings, and its bad input.
# Usage: calibration_offline.sh BIN_DIR
set -u
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cal=$bin/plumb-calibrate

# Inclination error after calibration, read from the report: must be below 0.02 deg.
check_report() {
  local what=$1 report=$2
  local after
  after=$(sed -n 's/.*before \([0-9.]*\) deg, after \([0-9.]*\) deg.*/\2/p' "$report" | head -1)
  if [ -z "$after" ]; then fail "$what: no inclination line in the report"; return; fi
  if awk -v a="$after" 'BEGIN { exit !(a < 0.02) }'; then pass "$what: inclination error after $after deg"; else fail "$what: inclination error after $after deg"; fi
}

for p in 6pos lsq mag; do
  "$cal" --procedure $p --write-simulation ${p}_ >/dev/null || fail "$p: --write-simulation"
done
if "$cal" --procedure 6pos --input 6pos_sensor.csv --stations 6pos_stations.csv --nominal 6pos_nominal.txt \
    --output c6.txt --report r6.txt --tool-id T1 >/dev/null; then
  pass "6pos: exit 0"
  grep -q '^format plumb-calibration 1' c6.txt && pass "6pos: coefficients file" || fail "6pos: coefficients file"
  check_report 6pos r6.txt
else
  fail "6pos: calibration failed"
fi
"$cal" --procedure lsq --input lsq_sensor.csv --stations lsq_stations.csv --output cl.txt --report rl.txt >/dev/null \
  && pass "lsq: exit 0" || fail "lsq: calibration failed"
grep -q 'accel.sensitivity.zz' rl.txt && pass "lsq: report has standard deviations" || fail "lsq: report"
"$cal" --procedure mag --input mag_sensor.csv --stations mag_stations.csv --base mag_truth.txt --output cm.txt >/dev/null \
  && pass "mag: exit 0" || fail "mag: calibration failed"

# Bad input: nothing written on failure.
expect_failure "24pos on a 6-position recording" "position \+x@90 is missing" \
  "$cal" --procedure 24pos --input 6pos_sensor.csv --stations 6pos_stations.csv --output bad.txt --report rbad.txt
[ ! -e bad.txt ] && pass "failed procedure wrote no coefficients" || fail "failed procedure wrote coefficients"
grep -q 'FAILED' rbad.txt && pass "failed procedure's report says so" || fail "report of the failure"
sed 's/^p+y,\(.*\),+y,/p+y,\1,+z,/' 6pos_stations.csv > wrong.csv
expect_failure "tool in the wrong orientation" "station 'p-z'|station 'p\+y'|position \+z is repeated" \
  "$cal" --procedure 6pos --input 6pos_sensor.csv --stations wrong.csv --output bad.txt
grep -v '^p-y,' 6pos_stations.csv > missing.csv
expect_failure "missing position" "position -y is missing" "$cal" --procedure 6pos --input 6pos_sensor.csv --stations missing.csv
head -4 lsq_stations.csv > few.csv
expect_failure "too few stations" "at least 12 .* got 2" "$cal" --procedure lsq --input lsq_sensor.csv --stations few.csv
sed 's/,+x,/,+q,/' 6pos_stations.csv > badorient.csv
expect_failure "bad orientation names file and line" "badorient.csv:3: column 'orientation'" \
  "$cal" --procedure 6pos --input 6pos_sensor.csv --stations badorient.csv
printf 'name,start_s,orientation\n' > nocol.csv
expect_failure "station list without end_s" "lacks column 'end_s'" "$cal" --procedure 6pos --input 6pos_sensor.csv --stations nocol.csv
expect_failure "unknown procedure" "procedure" "$cal" --procedure 7pos --input x --stations y
expect_failure "missing sensor file" "nope.csv" "$cal" --procedure 6pos --input nope.csv --stations 6pos_stations.csv \
  --report rnope.txt
grep -q 'FAILED.*nope.csv' rnope.txt && pass "report written when the input cannot be read" || fail "no report for unreadable input"
expect_failure "max error too strict" "exceeds the tolerance" \
  "$cal" --procedure 6pos --input 6pos_sensor.csv --stations 6pos_stations.csv --output bad.txt --max-error-deg 1e-7
[ ! -e bad.txt ] && pass "no coefficients from any failure" || fail "coefficients written by a failure"
"$cal" --help >/dev/null && pass "--help" || fail "--help"
finish
