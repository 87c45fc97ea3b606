#!/usr/bin/env bash
# The navigator's parameters as its estimator host writes them (plumb/component/parameters/HOST/
# strapdown), no sensor data needed: plumb-estimator --plugin strapdown on transport S, plumb-survey
# --plugin strapdown --error-model auto on transport V reading them. The survey takes the host's
# figures; a `plumb param set` on the host is written again (plumb topic echo: revision 2, the new
# value), and the running survey says what changed and that it goes on in a new survey leg through
# the new figures (the navigator aligns again), the well's latitude the one it started with.
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

"$bin/plumb-estimator" --transport "$host_t" --name "$host" --input plumb/sensor/raw --plugin strapdown \
  --param strapdown.latitude_deg=35 -q > "$work/host.out" 2>&1 &
pids+=($!)
"$bin/plumb-survey" --transport "$survey_t" --tool-id retuned --plugin strapdown --gravity 9.80665 --total-field 50 \
  --dip 60 --depth-clock-offset 0 --file "$work/survey.csv" --estimator-host "$host" --timeout 120 \
  > "$work/survey.out" 2> "$work/survey.err" &
pids+=($!)

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
exit $fails
