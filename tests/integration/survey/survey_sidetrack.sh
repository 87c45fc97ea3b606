#!/usr/bin/env bash
# A sidetrack in the live anti-collision scan: plumb-sim's stop-and-go run (transport S; 45 deg
# toward 120 deg, a station every 1.5 m to 9 m) -> plumb-estimator --plugin static (S) ->
# plumb-survey (transport V) with --sidetrack: a well that kicks off the one drilled at MD 3.75 m
# (between its stations at 3 and 4.5 m) and turns away to the right, near horizontal. Readers of
# plumb/clearance, plumb/status and plumb/survey/<tool> (transport E). The sidetrack must be scanned
# below its kick-off only, each row on plumb/clearance as `plumb clearance --sidetrack` computes it
# offline from the same stations (the survey's own, as a station list: SF within 0.1 %, distances
# within 1 mm), its levels rising from alarm as the wells part, and plumb/status saying the alarm
# against the sidetrack at the first station below the kick-off.
# usage: survey_sidetrack.sh BIN_DIR S V E DOMAIN
set -euo pipefail
bin=$1 sim_t=$2 survey_t=$3 echo_t=$4
export PLUMB_DOMAIN_ID=$5
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
source "$here/../wait.sh"
start_work_with_programs
tool=drilling-survey

# The sidetrack: a station list placed by its first row, the point of the planned path at 3.75 m.
python3 "$here/write_sidetrack.py" "$work/sidetrack-1.csv"
clearance_args=(--sidetrack "$work/sidetrack-1.csv" --reference-radius 0.1 --offset-radius 0.1)
model_args=(--error-model MWD --gravity 9.80665 --total-field 50 --dip 60)
survey_args=(--transport "$survey_t" --tool-id "$tool" --file "$work/survey.csv" --plugin static --reference true
             --declination 0 --depth-clock-offset 0 "${model_args[@]}" "${clearance_args[@]}")

# Without an ISCWSA error model the well drilled cannot be surveyed again: refused before the network.
expect_usage "--sidetrack with --error-model plumb" "^plumb-survey: --sidetrack needs an ISCWSA error model" \
  "$bin/plumb-survey" --tool-id "$tool" --file "$work/refused.csv" --reference true --declination 0 --gravity 9.80665 \
  --total-field 50 --dip 60 --error-model plumb "${clearance_args[@]}"

# Four stations lie below the kick-off (4.5, 6, 7.5 and 9 m): four rows.
"$bin/plumb" topic echo plumb/clearance --csv --count 4 --timeout 150 --transport "$echo_t" \
  > "$work/clearance.csv" 2> "$work/clearance.err" &
echo_pid=$!; pids+=($echo_pid)
"$bin/plumb" topic echo plumb/status --csv --timeout 150 --transport "$echo_t" > "$work/status.csv" 2> /dev/null &
pids+=($!)
# The stations as published (every digit: the survey file rounds them to 1 mm and 0.001 deg).
"$bin/plumb" topic echo plumb/survey/drilling_survey --csv --count 7 --timeout 150 --transport "$echo_t" \
  > "$work/stations.csv" 2> "$work/stations.err" &
stations_pid=$!; pids+=($stations_pid)
"$bin/plumb-estimator" --transport "$sim_t" --input plumb/sensor/raw --reliable --plugin static --window 5 -q \
  > "$work/estimator.out" 2>&1 &
pids+=($!)
"$bin/plumb-survey" "${survey_args[@]}" --count 7 --linger 30 > "$work/survey.out" 2> "$work/survey.err" &
survey=$!; pids+=($survey)
wait_for "$work/survey.err" "offset well sidetrack-1: 11 station" 20 || { echo "plumb-survey did not read the sidetrack:"; cat "$work/survey.err"; exit 1; }
grep -q "a sidetrack of the well drilled from MD 3.75 m" "$work/survey.err" && pass "plumb-survey says the kick-off" ||
  fail "plumb-survey's line on the sidetrack: $(grep sidetrack-1 "$work/survey.err")"
wait_for "$work/survey.err" "attitude writer matched" 30 || { echo "plumb-survey never matched the estimator:"; cat "$work/survey.err" "$work/estimator.out"; exit 1; }
wait_for "$work/status.csv" "plumb-survey" 30 || fail "no plumb-survey on plumb/status before the run"
"$bin/plumb-sim" --scenario drilling-survey --accel-bias 0,0,0 --transport "$sim_t" --rate x20 --reliable \
  --wait-subscribers 20 > "$work/sim.out" 2>&1 &
sim=$!; pids+=($sim)
wait "$echo_pid" || { fail "plumb topic echo plumb/clearance: $(cat "$work/clearance.err")"; cat "$work/survey.err"; finish; }
wait "$stations_pid" || { fail "plumb topic echo plumb/survey/drilling_survey: $(cat "$work/stations.err")"; finish; }
wait "$sim" || fail "plumb-sim failed: $(tail -3 "$work/sim.out")"

# The same stations offline: the well drilled as a station list (placed by its first station), the
# sidetrack against it through the same error model and field.
python3 - "$work/stations.csv" "$work/reference.csv" <<'PY'
import csv, sys
rows = sorted(csv.DictReader(open(sys.argv[1])), key=lambda r: float(r["md_m"]))
with open(sys.argv[2], "w") as f:
    f.write("md_m,inclination_deg,azimuth_deg,north_m,east_m,tvd_m\n")
    for k, r in enumerate(rows):
        place = f"{r['north_m']},{r['east_m']},{r['tvd_m']}" if k == 0 else ",,"
        f.write(f"{r['md_m']},{r['inclination_deg']},{r['azimuth_deg']},{place}\n")
PY
"$bin/plumb" clearance --reference "$work/reference.csv" "${clearance_args[@]}" "${model_args[@]}" \
  --csv "$work/offline.csv" > "$work/offline.out" 2> "$work/offline.err" ||
  { fail "plumb clearance --sidetrack offline: $(cat "$work/offline.err")"; finish; }

python3 - "$work/clearance.csv" "$work/offline.csv" "$work/status.csv" <<'PY' || fail "sidetrack clearance content"
import csv, sys
live = sorted(csv.DictReader(open(sys.argv[1])), key=lambda r: int(r["station_index"]))
offline = list(csv.DictReader(open(sys.argv[2])))
status = [r for r in csv.DictReader(open(sys.argv[3])) if (r.get("component") or "").startswith("plumb-survey")
          and r.get("counters.value")]
ok = True
def check(cond, what):
    global ok
    print(("ok   - " if cond else "FAIL - ") + what)
    ok = ok and cond
levels = {0: "clear", 1: "warning", 2: "alarm"}
check([int(r["station_index"]) for r in live] == [3, 4, 5, 6],
      f"one row per station below the kick-off, none above (stations {[r['station_index'] for r in live]})")
check(len(offline) == 4 and all(o["offset"] == "sidetrack-1" for o in offline), f"offline: 4 rows ({len(offline)})")
for l, o in zip(live, offline):
    sf, sf0 = float(l["separation_factor"]), float(o["separation_factor"])
    d, d0 = float(l["centre_to_centre_m"]), float(o["centre_to_centre_m"])
    es, es0 = float(l["ellipse_separation_m"]), float(o["ellipse_separation_m"])
    check(abs(float(l["reference_md_m"]) - float(o["reference_md_m"])) < 1e-6 and abs(sf - sf0) <= 1e-3 * abs(sf0)
          and abs(d - d0) < 1e-3 and abs(es - es0) < 1e-3 and abs(float(l["offset_md_m"]) - float(o["offset_md_m"])) < 1e-3
          and levels[int(l["level"])] == o["level"] and l["offset_well"] == "sidetrack-1",
          f"MD {float(o['reference_md_m']):.2f} m: live SF {sf:.4f} {levels[int(l['level'])]}, D {d:.4f} m; "
          f"offline SF {sf0:.4f} {o['level']}, D {d0:.4f} m (SF {abs(sf - sf0) / abs(sf0) * 100:.4f} %, D {abs(d - d0) * 1000:.4f} mm apart)")
seen = [o["level"] for o in offline]
check(seen[0] == "alarm" and seen[-1] != "alarm", f"the wells part: from alarm at the kick-off to {seen[-1]}: {seen}")
# plumb/status: the level and the line by the number of stations the survey held when it said so.
said = {}
for r in status:
    if r.get("counters.name") in ("stations", "clearance_level"):
        said.setdefault((r["stamp_ns"], r["component"]), {"error": r["last_error"]})[r["counters.name"]] = int(r["counters.value"])
first_alarm = next((v for v in sorted(said.values(), key=lambda v: v.get("stations", 0))
                    if v.get("clearance_level") == 2 and "stations" in v), None)
check(first_alarm is not None and first_alarm["stations"] == 4 and "clearance alarm at MD 4." in first_alarm["error"]
      and "against sidetrack-1" in first_alarm["error"],
      f"plumb/status says the alarm against the sidetrack at the first station below the kick-off: {first_alarm}")
sys.exit(0 if ok else 1)
PY
finish
