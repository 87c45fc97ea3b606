#!/usr/bin/env bash
# A day on the rig in one run, as shipped: `plumb launch rig-day.yaml` in an empty folder, in real
# time (7.5 minutes). plumb-sim plays the tool (sensors on the tool's clock, 5 min 20 s behind this
# computer's and 50 ppm slow) and the rig (its depth as a WITS feed); plumb-wits is the depth source
# (stamps on this computer's clock); the display's page port is taken by another program.
# Checked: every station at the simulator's depth at its time (within 0.1 m), the clocks' offset the
# survey estimated (its file and plumb/status) within 0.1 s of the one the simulator ran with, the
# display still serving Foxglove on its other port (degraded on plumb/status, saying why), and the
# whole chain ending by itself with exit status 0.
# VARIANT: cyclonedds, fastdds (PLUMB_TRANSPORT for every program) or mixed (the estimator host and
# the survey on Fast DDS, the rest on Cyclone DDS).
# usage: rig_day.sh LAUNCH_FILE BIN_DIR VARIANT DOMAIN
set -uo pipefail
launch_file=$1 bin=$2 variant=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
export PATH=$bin:$PATH
cd "$work" || exit 1
offset=320 drift_ppm=50
if [ "$variant" = mixed ]; then
  export PLUMB_TRANSPORT=cyclonedds
  sed -E 's/^(    cmd: plumb-(estimator|survey) .*)$/\1\n    env: {PLUMB_TRANSPORT: fastdds}/' "$launch_file" > mixed.yaml
  [ "$(grep -c "env: {PLUMB_TRANSPORT: fastdds}" mixed.yaml)" -eq 2 ] || { fail "mixed.yaml not made"; finish; }
  launch_file=$work/mixed.yaml
else
  export PLUMB_TRANSPORT=$variant
fi
# The page's port held by another program for the whole run.
python3 -c 'import socket, time; s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen(); print(s.getsockname()[1], flush=True); time.sleep(900)' > held.txt &
pids+=($!)
wait_for held.txt "[0-9]" 5 || { fail "no port held"; finish; }
page_port=$(cat held.txt) foxglove_port=$(free_port) wits_port=$(free_port)
plumb topic echo plumb/status --timeout 600 > status.txt 2>&1 &
pids+=($!)
start=$(date +%s)
timeout 700 plumb launch "$launch_file" port:="$page_port" foxglove_port:="$foxglove_port" wits_port:="$wits_port" \
  rig_clock_offset:=$offset rig_clock_drift_ppm:=$drift_ppm > out.txt 2> err.txt &
launch=$!
pids+=($launch)
# While the run goes on: the display, its page port taken, still serves Foxglove on the other.
if wait_for out.txt "^\[display\] plumb-display: the page is not served .*Foxglove on ws://127.0.0.1:$foxglove_port/" 60; then
  output_matches "plumb-display: Foxglove WebSocket server" python3 -c \
    "import urllib.request; print(urllib.request.urlopen('http://127.0.0.1:$foxglove_port/').read().decode())" &&
    pass "the page's port $page_port taken: the display serves Foxglove on $foxglove_port" ||
    fail "nothing answers on the display's Foxglove port $foxglove_port"
else
  fail "the display did not say it serves Foxglove alone: $(grep '^\[display\]' out.txt err.txt | head -5)"
fi
rc=0
wait "$launch" || rc=$?
echo "plumb launch: exit $rc after $(( $(date +%s) - start )) s"
[ $rc -eq 0 ] && pass "plumb launch ended by itself with exit status 0" || { tail -30 out.txt err.txt; fail "plumb launch: exit $rc"; }
grep -q "^\[display\] .*cannot serve on 127.0.0.1:$page_port: .*; serving the rest" out.txt err.txt &&
  pass "the display said why its page is not served" || fail "the display did not say its page's port is taken"
grep -q "^\[wits\] .*connection from 127.0.0.1" out.txt err.txt && pass "plumb-wits took the rig's feed" ||
  fail "plumb-wits never got the rig's connection: $(grep '^\[wits\]' out.txt err.txt | tail -3)"
grep "^\[survey\] .*depth clock" out.txt err.txt | tail -1
grep "^\[sim\] .*WITS frames sent" out.txt

# The truth on the run's time; the tool's clock origin as plumb-sim stated it.
plumb-sim --scenario drilling-survey --accel-bias 0,0,0 --csv truth > /dev/null
origin=$(sed -nE "s/^\[sim\] plumb-sim: the tool's clock reads ([0-9.]+) s at run time 0 .*/\1/p" out.txt | head -1)
[ -n "$origin" ] || { fail "plumb-sim did not state its tool clock"; finish; }
python3 - survey-rig-day.csv truth/truth.csv "$origin" "$offset" "$drift_ppm" <<'PY' || fail "the survey's stations and clock"
import bisect, csv, re, sys
lines = open(sys.argv[1]).read().splitlines()
rows = [r for r in csv.DictReader(l for l in lines if not l.startswith('#'))]
truth = list(csv.DictReader(open(sys.argv[2])))
origin, offset, drift = float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5]) * 1e-6
ok = True
def check(cond, what):
    global ok
    print(("ok   - " if cond else "FAIL - ") + what)
    ok = ok and cond
run_time = lambda tool_t: (tool_t - origin) / (1 - drift)
check([int(r["station"]) for r in rows] == list(range(7)), f"stations 0..6 once each ({len(rows)} rows)")
ts = [float(t["t"]) for t in truth]
worst = 0
for r in rows:
    t = truth[min(bisect.bisect_left(ts, run_time(float(r["t"]))), len(truth) - 1)]
    worst = max(worst, abs(float(r["md_m"]) - float(t["depth_m"])))
check(rows and worst < 0.1, f"every station at the simulator's depth at its time (worst {worst * 100:.1f} cm)")
said = [l for l in lines if l.startswith("# depth clock")]
m = re.search(r"depth clock ([0-9.]+) s (ahead of|behind) the sensors' \(sd ([0-9.]+) s\) at sensor time ([-0-9.]+) s",
              said[-1]) if said else None
check(m is not None, f"the survey file states the depth clock: {said[-1] if said else 'nothing'}")
if m:
    est = float(m.group(1)) * (1 if m.group(2) == "ahead of" else -1)
    true = offset + drift * run_time(float(m.group(4)))
    check(abs(est - true) < 0.1, f"offset {est:.3f} s (sd {m.group(3)} s) against {true:.3f} s: error {abs(est - true) * 1000:.0f} ms")
sys.exit(0 if ok else 1)
PY

# plumb/status: the survey's last word on the clock, and the display degraded with its reason.
python3 - status.txt "$offset" "$page_port" <<'PY' || fail "plumb/status"
import re, sys
text = open(sys.argv[1]).read()
def last(name):
    found = re.findall(name + r"\D{0,12}?(\d+)", text)
    return int(found[-1]) if found else None
state, ahead, sd = last("depth_clock_state"), last("depth_clock_ahead_us"), last("depth_clock_sd_us")
ok1 = state == 1 and ahead is not None and abs(ahead / 1e6 - float(sys.argv[2])) < 0.1 and sd is not None and sd > 0
print(("ok   - " if ok1 else "FAIL - ") + f"plumb/status: the survey's depth clock estimated (state {state}), {ahead} us ahead, sd {sd} us")
messages = text.split('component: "')[1:]
ok2 = any(m.startswith('plumb-display"') and 'state: "degraded"' in m and
          re.search(r'last_error: "cannot serve on 127\.0\.0\.1:' + sys.argv[3], m) for m in messages)
print(("ok   - " if ok2 else "FAIL - ") + "plumb/status: the display degraded, saying its page's port is taken")
sys.exit(0 if ok1 and ok2 else 1)
PY
finish
