#!/usr/bin/env bash
# The navigator's parameters as its estimator host writes them (plumb/component/parameters/HOST/
# strapdown): plumb-estimator --plugin strapdown on transport S, plumb-survey --plugin strapdown
# --error-model auto on transport V reading them. The survey takes the host's figures; a `plumb
# param set` on the host is written again (plumb topic echo: revision 2, the new value), and the
# running survey says what changed and that it goes on in a new survey leg through the new figures
# (the navigator aligns again), the well's latitude the one it started with. Then plumb-sim's
# stop-and-go run (S): after two stations the navigator's gyro bias is set to 2 deg/h; the survey
# says its new leg starts below the last station it has, and the stations below are priced and
# named by the new figures (the navigator aligned again at a stop), those above as before.
# usage: survey_navigator_retuned.sh BIN_DIR S V DOMAIN
set -uo pipefail
bin=$1 host_t=$2 survey_t=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
source "$here/../wait.sh"
start_work_with_programs
host=retune-host-$PLUMB_DOMAIN_ID
topic=plumb/component/parameters/retune_host_$PLUMB_DOMAIN_ID/strapdown

"$bin/plumb-estimator" --transport "$host_t" --name "$host" --input plumb/sensor/raw --reliable --plugin strapdown \
  --param strapdown.latitude_deg=35 --param strapdown.gravity=9.80665 -q > "$work/host.out" 2>&1 &
pids+=($!)
"$bin/plumb-survey" --transport "$survey_t" --tool-id drilling-survey --plugin strapdown --gravity 9.80665 \
  --total-field 50 --dip 60 --depth-clock-offset 0 --file "$work/survey.csv" --estimator-host "$host" --count 5 \
  --timeout 150 > "$work/survey.out" 2> "$work/survey.err" &
survey=$!
pids+=($survey)

if wait_for "$work/survey.err" "error model GYRO:navigator \(tactical" 30 &&
   grep -q "error model: the strapdown navigator's parameters from estimator host '$host' ([0-9]* parameters, $topic)" "$work/survey.err"; then
  pass "plumb-survey reads the host's navigator parameters from $topic"
else
  fail "no navigator parameters read: $(cat "$work/survey.err" "$work/host.out")"
fi
out=$("$bin/plumb" param set "$host" strapdown latitude_deg 40 --transport "$survey_t" 2>&1) ||
  fail "plumb param set: $out"
echo=$("$bin/plumb" topic echo "$topic" --count 1 --timeout 20 --transport "$survey_t" 2>&1)
if grep -q "^revision: 2$" <<< "$echo" && grep -A1 'name: "latitude_deg"' <<< "$echo" | grep -q 'value: "40"'; then
  pass "the host writes its parameters again after param set (revision 2, latitude_deg 40)"
else
  fail "after param set, $topic: $(head -12 <<< "$echo")"
fi
if wait_for "$work/survey.err" "navigator's parameters on estimator host '$host' changed \(latitude_deg 35 -> 40\): the navigator aligns again, a new gyro run, so the survey goes on in a new leg from its first station through its new figures \(GYRO:navigator \(tactical.*\); the 0 station\(s\) above keep theirs; the well's latitude stays 35 deg for the whole survey" 20; then
  pass "the running survey says the navigator was re-tuned, and that it goes on in a new leg through its figures"
else
  fail "no change said: $(cat "$work/survey.err")"
fi

wait_for "$work/survey.err" "attitude writer matched" 60 || fail "plumb-survey never matched the estimator: $(cat "$work/survey.err")"
"$bin/plumb-sim" --scenario drilling-survey --transport "$host_t" --rate x20 --reliable --wait-subscribers 20 \
  > "$work/sim.out" 2>&1 &
pids+=($!)
# The survey file's station rows so far (0 before the file exists).
rows() {
  local n
  n=$(grep -c "^[0-9]" "$work/survey.csv" 2> /dev/null)
  echo "${n:-0}"
}
# After two stations: the change must reach the survey before its fifth, a station or two later.
for ((i = 0; i < 600 && $(rows) < 2; ++i)); do sleep 0.1; done
out=$("$bin/plumb" param set "$host" strapdown gyro_bias_dph 2 --transport "$survey_t" 2>&1) || fail "plumb param set: $out"
if wait_for "$work/survey.err" "changed \(gyro_bias_dph \(default\) -> 2\): the navigator aligns again, a new gyro run, so the survey goes on in a new leg below MD [0-9.]+ m through its new figures \(GYRO:navigator \(tactical 2 deg/h; magnetic az 0.689 deg\), systematic errors a draw of their own\); the [0-9]+ station\(s\) above keep theirs" 30; then
  pass "re-tuned after two stations or more: $(grep -o "a new leg below MD [0-9.]* m" "$work/survey.err")"
else
  fail "the second change not said as a new leg: $(cat "$work/survey.err")"
fi
wait "$survey" || fail "plumb-survey did not reach five stations: $(tail -5 "$work/survey.err")"
below=$(grep -o "a new leg below MD [0-9.]* m" "$work/survey.err" | grep -o "[0-9][0-9.]*")
python3 - "$work/survey.csv" "${below:-nan}" <<'PY' && pass "the stations above MD ${below:-?} m priced and named by the first figures, those below by the new ones" || fail "the legs in the survey file: $(cut -d, -f1,5 "$work/survey.csv")"
import csv, sys
rows = [r for r in csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith('#'))]
below = float(sys.argv[2])
first, second = "GYRO:navigator (tactical; magnetic az 0.689 deg)", "GYRO:navigator (tactical 2 deg/h; magnetic az 0.689 deg)"
want = [first if float(r["md_m"]) <= below else second for r in rows]
assert len(rows) == 5 and want.count(first) >= 2 and want.count(second) >= 1, (below, [r["md_m"] for r in rows])
assert [r["error_model"] for r in rows] == want, [(r["md_m"], r["error_model"]) for r in rows]
PY
exit $fails
