#!/usr/bin/env bash
# Anti-collision live: plumb-sim's stop-and-go run (transport S; 45 deg toward 120 deg, a station
# every 1.5 m to 9 m) -> plumb-estimator --plugin static (S) -> plumb-survey (transport V) with an
# offset well: a vertical well 1.6 m to the side of the path, 5.5 m ahead along it, so that the
# separation factor falls from about 3 through the warning (1.5) and the alarm (1.0) levels. A
# reader of plumb/clearance and plumb/status (transport E) must get, for every station, the
# separation factor and level that `plumb clearance` computes offline from the survey file, and
# plumb/status must say the warning and the alarm within one station of the depth where they start.
# usage: survey_clearance.sh BIN_DIR S V E DOMAIN
set -euo pipefail
bin=$1 sim_t=$2 survey_t=$3 echo_t=$4
export PLUMB_DOMAIN_ID=$5
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
source "$here/../wait.sh"
start_work_with_programs
tool=drilling-survey

# The offset well: a station list placed by its first row, 5 m above the reference's first station.
python3 - "$work/offset-1.csv" <<'PY'
import math, sys
along, side = 5.5, 1.6                     # m: ahead along the path's azimuth, and to its right
a, r = math.radians(120), math.radians(210)
north = along * math.cos(a) + side * math.cos(r)
east = along * math.sin(a) + side * math.sin(r)
with open(sys.argv[1], "w") as f:
    f.write("md_m,inclination_deg,azimuth_deg,north_m,east_m,tvd_m\n")
    f.write(f"0,0,0,{north:.4f},{east:.4f},-5\n")
    for md in range(5, 45, 5):
        f.write(f"{md},0,0,,,\n")
PY
clearance_args=(--offset "$work/offset-1.csv" --reference-radius 0.1 --offset-radius 0.1)
survey_args=(--transport "$survey_t" --tool-id "$tool" --file "$work/survey.csv" --plugin static --reference true
             --declination 0 --gravity 9.80665 --total-field 50 --dip 60 --depth-clock-offset 0 "${clearance_args[@]}")

"$bin/plumb" topic echo plumb/clearance --csv --count 7 --timeout 150 --transport "$echo_t" \
  > "$work/clearance.csv" 2> "$work/clearance.err" &
echo_pid=$!; pids+=($echo_pid)
"$bin/plumb" topic echo plumb/status --csv --timeout 150 --transport "$echo_t" > "$work/status.csv" 2> /dev/null &
pids+=($!)
"$bin/plumb-estimator" --transport "$sim_t" --input plumb/sensor/raw --reliable --plugin static --window 5 -q \
  > "$work/estimator.out" 2>&1 &
pids+=($!)
# --linger: it stays (and its transient-local topics with it) for the display that joins at the end.
"$bin/plumb-survey" "${survey_args[@]}" --count 7 --linger 90 > "$work/survey.out" 2> "$work/survey.err" &
survey=$!; pids+=($survey)
wait_for "$work/survey.err" "offset well offset-1: 9 station" 20 || { echo "plumb-survey did not read the offset well:"; cat "$work/survey.err"; exit 1; }
wait_for "$work/survey.err" "attitude writer matched" 30 || { echo "plumb-survey never matched the estimator:"; cat "$work/survey.err" "$work/estimator.out"; exit 1; }
# The status reader hears plumb-survey before the run starts: its first warning is not lost to discovery.
wait_for "$work/status.csv" "plumb-survey" 30 || fail "no plumb-survey on plumb/status before the run"
"$bin/plumb-sim" --scenario drilling-survey --accel-bias 0,0,0 --transport "$sim_t" --rate x20 --reliable \
  --wait-subscribers 20 > "$work/sim.out" 2>&1 &
sim=$!; pids+=($sim)
wait "$echo_pid" || { fail "plumb topic echo plumb/clearance: $(cat "$work/clearance.err")"; cat "$work/survey.err"; finish; }
wait "$sim" || fail "plumb-sim failed: $(tail -3 "$work/sim.out")"
wait_for "$work/survey.csv" "^6," 10 || { fail "no seventh station in the file"; finish; }

# The same survey file offline.
"$bin/plumb" clearance --reference "$work/survey.csv" "${clearance_args[@]}" --csv "$work/offline.csv" \
  > "$work/offline.out" 2> "$work/offline.err" || { fail "plumb clearance offline: $(cat "$work/offline.err")"; finish; }

python3 - "$work/clearance.csv" "$work/offline.csv" "$work/status.csv" "$work/survey.csv" <<'PY' || fail "clearance content"
import csv, sys
live = list(csv.DictReader(open(sys.argv[1])))
offline = list(csv.DictReader(open(sys.argv[2])))
status = [r for r in csv.DictReader(open(sys.argv[3])) if (r.get("component") or "").startswith("plumb-survey")
          and r.get("counters.value")]
survey = [r for r in csv.DictReader(l for l in open(sys.argv[4]) if not l.startswith("#"))]
ok = True
def check(cond, what):
    global ok
    print(("ok   - " if cond else "FAIL - ") + what)
    ok = ok and cond
levels = {0: "clear", 1: "warning", 2: "alarm"}
check(sorted(int(r["station_index"]) for r in live) == list(range(7)), f"one clearance per station ({len(live)} messages)")
check(len(offline) == 7, f"offline: 7 reference stations ({len(offline)})")
live.sort(key=lambda r: int(r["station_index"]))
for l, o in zip(live, offline):
    sf, sf0 = float(l["separation_factor"]), float(o["separation_factor"])
    check(abs(float(l["reference_md_m"]) - float(o["reference_md_m"])) < 1e-6 and abs(sf - sf0) < 1e-3 * sf0
          and abs(float(l["centre_to_centre_m"]) - float(o["centre_to_centre_m"])) < 1e-3
          and levels[int(l["level"])] == o["level"] and l["offset_well"] == o["offset"] == "offset-1",
          f"MD {float(o['reference_md_m']):.2f} m: live SF {sf:.4f} {levels[int(l['level'])]}, offline {sf0:.4f} {o['level']}")
seen = [o["level"] for o in offline]
check(seen[0] == "clear" and "warning" in seen and seen[-1] == "alarm" and seen.index("warning") < seen.index("alarm"),
      f"the run falls from clear through warning to alarm: {seen}")
# plumb/status: the level (counter clearance_level) and the line (last_error), by the number of
# stations the survey held when it said so.
said = {}
for r in status:
    if r.get("counters.name") in ("stations", "clearance_level"):
        said.setdefault((r["stamp_ns"], r["component"]), {"error": r["last_error"], "state": r["state"]})[r["counters.name"]] = int(r["counters.value"])
first = {}
for v in sorted(said.values(), key=lambda v: v.get("stations", 0)):
    if "stations" in v and "clearance_level" in v:
        first.setdefault(v["clearance_level"], (v["stations"], v["error"], v["state"]))
for level, name in ((1, "warning"), (2, "alarm")):
    starts = seen.index(name) + 1   # the survey holds this many stations when the level starts
    got = first.get(level)
    check(got is not None and got[0] <= starts + 1 and f"clearance {name}" in got[1] and "offset-1" in got[1],
          f"plumb/status says the {name} by station {starts + 1} (said at {got[0] if got else None} station(s): {got[1] if got else ''!r})")
check(first.get(2, (0, "", ""))[2] == "degraded", "the alarm puts plumb-survey in state degraded")
sys.exit(0 if ok else 1)
PY

# The display, joining after the survey: the nearest offset of the newest station (transient-local).
if [ -x "$bin/plumb-display" ]; then
  "$bin/plumb-display" --transport "$echo_t" --port 0 --no-foxglove > "$work/display.log" 2>&1 &
  pids+=($!)
  wait_for "$work/display.log" "serving http://127.0.0.1:[0-9]+/" 20 || { fail "plumb-display did not start"; finish; }
  port=$(sed -nE 's|.*serving http://127\.0\.0\.1:([0-9]+)/.*|\1|p' "$work/display.log" | head -1)
  PYTHONPATH=$here/../display python3 - "$port" "$work/offline.csv" <<'PY' || fail "the display's clearance"
import csv, json, sys, time
from wsclient import WebSocket
last = list(csv.DictReader(open(sys.argv[2])))[-1]
ws = WebSocket(f"ws://127.0.0.1:{sys.argv[1]}/ws")
deadline, got = time.time() + 30, None
while time.time() < deadline and got is None:
    frame = json.loads(ws.recv())
    for c in frame.get("clearance", []):
        if c["i"] == 6:
            got = c
ok = got is not None and got["off"] == "offset-1" and abs(got["sf"] - float(last["separation_factor"])) < 0.006 and got["lvl"] == 2
print(("ok   - " if ok else "FAIL - ") + f"the display shows the newest station's nearest offset: {got} (offline SF {float(last['separation_factor']):.3f})")
sys.exit(0 if ok else 1)
PY
fi
finish
