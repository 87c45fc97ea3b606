#!/usr/bin/env bash
# The rig's clock is not the tool's: plumb-sim's stop-and-go drilling run (transport S) publishes its
# depth on a rig clock OFFSET seconds ahead and DRIFT ppm fast; plumb-estimator --plugin static (S)
# and plumb-survey (transport V) with the depth clock left to estimate. The survey must match the
# stops it sees on the sensors with the depth's, find all seven stations at their true depth
# (within 0.1 m, the simulator's truth at each station's time) and state the offset it estimated,
# within 0.1 s of the one injected, in its log and in the survey file.
# usage: survey_rig_clock.sh BIN_DIR S V DOMAIN OFFSET_S DRIFT_PPM
set -euo pipefail
bin=$1 sim_t=$2 survey_t=$3
export PLUMB_DOMAIN_ID=$4
offset=$5 drift=$6
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
source "$here/../wait.sh"
start_work_with_programs
tool=drilling-survey

# A clock given by hand that is no clock: one line, exit 2, before joining the network.
expect_usage "offset not finite" "depth-clock-offset: a finite number of seconds, not nan" \
  "$bin/plumb-survey" --tool-id t --file "$work/bad.csv" --depth-clock-offset nan
expect_usage "drift not finite" "depth-clock-drift-ppm" "$bin/plumb-survey" --tool-id t --file "$work/bad.csv" --depth-clock-drift-ppm nan

"$bin/plumb-estimator" --transport "$sim_t" --input plumb/sensor/raw --reliable --plugin static --window 5 -q \
  > "$work/estimator.out" 2>&1 &
pids+=($!)
# Everything the components report, for the survey's depth clock counters (stopped at the end).
"$bin/plumb" topic echo plumb/status --transport "$survey_t" --timeout 120 > "$work/status.txt" 2>&1 &
echo_status=$!
pids+=($echo_status)
"$bin/plumb-survey" --transport "$survey_t" --tool-id "$tool" --file "$work/survey.csv" --plugin static \
  --gravity 9.80665 --total-field 50 --dip 60 --sensor-topic plumb/sensor/raw --count 7 --timeout 90 --linger 0 \
  > "$work/survey.out" 2> "$work/survey.err" &
survey=$!
pids+=($survey)
wait_for "$work/survey.err" "attitude writer matched" 30 || { echo "plumb-survey never matched the estimator:"; cat "$work/survey.err"; exit 1; }
run=(--scenario drilling-survey --accel-bias 0,0,0)
"$bin/plumb-sim" "${run[@]}" --transport "$sim_t" --rate x20 --reliable --wait-subscribers 20 \
  --rig-clock-offset "$offset" --rig-clock-drift-ppm "$drift" > "$work/sim.out" 2>&1 &
pids+=($!)
rc=0
wait "$survey" || rc=$?
"$bin/plumb-sim" "${run[@]}" --csv "$work/truth" > /dev/null
# The status echo has what the checks below read; stop it rather than wait out its 120 s (it may
# have ended already, hence || true). It decides no check.
kill "$echo_status" 2>/dev/null || true
if [ $rc -eq 0 ]; then pass "plumb-survey reached 7 stations"
else fail "plumb-survey exit $rc: $(cat "$work/survey.err")"; fi
grep "depth clock" "$work/survey.err" | tail -1

python3 - "$work/survey.csv" "$work/truth/truth.csv" "$offset" "$drift" <<'PY' || fail "survey content"
import bisect, csv, re, sys
lines = open(sys.argv[1]).read().splitlines()
rows = [r for r in csv.DictReader(l for l in lines if not l.startswith('#'))]
truth = list(csv.DictReader(open(sys.argv[2])))
offset, drift = float(sys.argv[3]), float(sys.argv[4]) * 1e-6
ok = True
def check(cond, what):
    global ok
    print(("ok   - " if cond else "FAIL - ") + what)
    ok = ok and cond
check([int(r["station"]) for r in rows] == list(range(7)), f"stations 0..6 once each ({len(rows)} rows)")
ts = [float(t["t"]) for t in truth]
worst = 0
for r in rows:
    t = truth[min(bisect.bisect_left(ts, float(r["t"])), len(truth) - 1)]
    worst = max(worst, abs(float(r["md_m"]) - float(t["depth_m"])))
check(worst < 0.1, f"every station at the simulator's depth at its time (worst {worst * 100:.1f} cm)")
mds = [float(r["md_m"]) for r in rows]
check(all(abs(md - 1.5 * k) < 0.1 for k, md in enumerate(mds)), f"one station per stop at 0, 1.5, ... 9 m: {mds}")
# The alignment the rows were made with: the last '# depth clock' line before the last row.
said = [l for l in lines if l.startswith("# depth clock")]
check(len(said) > 0, "the survey file says how the depth's clock was aligned")
if said:
    m = re.search(r"depth clock ([0-9.]+) s (ahead of|behind) the sensors' \(sd ([0-9.]+) s\) at sensor time ([-0-9.]+) s", said[-1])
    check(m is not None, f"it states offset, sigma and epoch: {said[-1]}")
    if m:
        est = float(m.group(1)) * (1 if m.group(2) == "ahead of" else -1)
        true = offset + drift * float(m.group(4))
        check(abs(est - true) < 0.1, f"offset {est:.3f} s (sd {m.group(3)} s) against {true:.3f} s injected: error {abs(est - true) * 1000:.0f} ms")
sys.exit(0 if ok else 1)
PY

# plumb/status: the survey's last report says estimated (1), the offset in microseconds and its sigma.
python3 - "$work/status.txt" "$offset" <<'PY' || fail "depth clock on plumb/status"
import re, sys
text = open(sys.argv[1]).read()
def last(name):
    found = re.findall(name + r"\D{0,12}?(\d+)", text)
    return int(found[-1]) if found else None
state, ahead, sd = last("depth_clock_state"), last("depth_clock_ahead_us"), last("depth_clock_sd_us")
print(f"plumb/status: depth_clock_state {state}, depth_clock_ahead_us {ahead}, depth_clock_sd_us {sd}")
ok = state == 1 and ahead is not None and abs(ahead / 1e6 - float(sys.argv[2])) < 0.1 and sd is not None and sd > 0
print(("ok   - " if ok else "FAIL - ") + "plumb/status states the estimated depth clock and its sigma")
sys.exit(0 if ok else 1)
PY
finish
