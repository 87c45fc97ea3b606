#!/usr/bin/env bash
# What a new user met that looked like success or said nothing: a recording of plumb-sim alone read
# as empty, plugins without one valid row exiting 0, a misspelt plugin or transport name exiting 1,
# a recorder or a survey waiting in silence, a repair naming a file that is not there. The DDS
# parts run across vendors (the simulator on Fast DDS, the listeners on Cyclone DDS).
# usage: said_not_silent.sh BIN_DIR DOMAIN
set -uo pipefail
bin=$1
export PLUMB_DOMAIN_ID=$2
unset PLUMB_TRANSPORT PLUMB_INTERFACE PLUMB_SECURITY
here=$(dirname "$0")
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs

# --- A misspelt plugin or transport name is a usage error naming the close matches.
expect_usage "plumb-estimator --plugin" "unknown estimator 'compensate': did you mean compensated\?" \
  timeout 20 "$bin/plumb-estimator" --plugin compensate
expect_usage "plumb estimate -e" "did you mean compensated\?" "$bin/plumb" estimate -e compensate --input /dev/null
expect_usage "plumb compare -e" "did you mean integral\?" "$bin/plumb" compare -e integrl --input /dev/null
expect_usage "plumb topic --transport" "unknown transport 'fastds': did you mean fastdds\?" \
  timeout 20 "$bin/plumb" topic list --transport fastds --wait 0
expect_usage "plumb transports --transport" "did you mean cyclonedds\?" "$bin/plumb" transports --transport cyclone
expect_usage "plumb-sim --transport" "did you mean fastdds\?" timeout 20 "$bin/plumb-sim" --transport fastdd --duration 1
expect_usage "\$PLUMB_TRANSPORT" "did you mean cyclonedds\?" env PLUMB_TRANSPORT=cyclonedd timeout 20 "$bin/plumb-survey" --tool-id t --file "$work/s.txt" --skip-check gravity --skip-check field --skip-check dip
expect_usage "example subscriber --transport" "did you mean fastdds\?" timeout 20 "$bin/plumb-example-subscriber" --transport fast-dds

# --- A plugin without one valid row: exit 1, with its last reason and counts (no DDS).
"$bin/plumb-sim" --csv "$work/turning" --rpm 60 --duration 4 > /dev/null 2>&1 || fail "plumb-sim --csv"
rc=0
"$bin/plumb" estimate -e static --input "$work/turning/sensor.csv" --window 1 > "$work/static.csv" 2> "$work/static.err" || rc=$?
[ $rc -eq 1 ] && grep -qE "^plumb estimate: static made no valid estimate \(0 of [1-9][0-9]*; last reason: platform rotating" "$work/static.err" &&
  pass "estimate: no valid row is a failure: $(tail -1 "$work/static.err")" || fail "estimate, no valid row: exit $rc, $(cat "$work/static.err")"
rc=0
"$bin/plumb" compare --input "$work/turning/sensor.csv" -e compensated -e static --window 1 > "$work/cmp.out" 2> "$work/cmp.err" || rc=$?
[ $rc -eq 1 ] && grep -q "^compensated" "$work/cmp.out" && grep -q "static made no valid estimate" "$work/cmp.err" &&
  pass "compare: the table, then the plugin that made no valid row: exit 1" || fail "compare, no valid row: exit $rc, $(cat "$work/cmp.out" "$work/cmp.err")"
# What those invalid rows did not measure is an empty cell, not a number that looks measured.
python3 - "$work/static.csv" <<'PY' && pass "invalid rows: empty cells for what was not measured" || fail "invalid rows carry numbers: $(head -3 "$work/static.csv")"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert rows and all(r["valid"] == "0" for r in rows), rows
for k in ("inclination_deg", "azimuth_deg", "toolface_deg", "inclination_sd_deg", "dip_deg", "total_b"):
    assert all(r[k] == "" for r in rows), (k, [r[k] for r in rows])
assert all(float(r["rpm"]) > 50 for r in rows)  # the speed is measured all the same
PY
"$bin/plumb" estimate -e compensated --input "$work/turning/sensor.csv" --window 1 > /dev/null 2>&1 &&
  pass "estimate with valid rows exits 0" || fail "compensated on the turning platform failed"

# --- A recorder with nothing to record says so, and fails.
rc=0
timeout 30 "$bin/plumb" record -o "$work/empty.mcap" --duration 4 --transport cyclonedds > /dev/null 2> "$work/empty.err" || rc=$?
grep -q "^plumb record: nothing received for 3 s on any plumb topic; no topic has a writer on domain $PLUMB_DOMAIN_ID" "$work/empty.err" &&
  pass "the recorder says what it waits for" || fail "recorder silent: $(cat "$work/empty.err")"
[ $rc -eq 1 ] && grep -q "nothing recorded" "$work/empty.err" && pass "nothing recorded: exit 1, $(tail -1 "$work/empty.err")" ||
  fail "empty recording: exit $rc, $(cat "$work/empty.err")"
expect_failure "estimate on a recording without messages" "no sensor message on plumb/sensor/calibrated or plumb/sensor/raw; the recording holds .*\(0 messages\)" \
  "$bin/plumb" estimate -e compensated --input "$work/empty.mcap"

# --- A recording made while only plumb-sim runs: raw is read, and said.
timeout 60 "$bin/plumb-sim" --inclination 2 --azimuth 45 --rpm 60 --loop --wait-subscribers 0 --transport fastdds > "$work/sim.log" 2>&1 &
pids+=($!)
# The recorder starts once the simulator's writer exists: on a loaded machine a Fast DDS participant
# took longer to start than a 4 s recording lasted (seen once on CI).
wait_for "$work/sim.log" "plumb-sim: simulating" 30 || fail "plumb-sim did not start: $(cat "$work/sim.log")"
timeout 30 "$bin/plumb" record -o "$work/run.mcap" --duration 4 --transport cyclonedds > /dev/null 2> "$work/rec.err" ||
  fail "record beside plumb-sim: $(cat "$work/rec.err")"
"$bin/plumb" export "$work/run.mcap" -o "$work/run.csv" 2> "$work/export.err" && [ "$(grep -vc '^#' "$work/run.csv")" -gt 100 ] &&
  grep -q "reading plumb/sensor/raw ([1-9][0-9]* messages; plumb/sensor/calibrated holds none)" "$work/export.err" &&
  pass "export reads raw when calibrated is empty: $(head -1 "$work/export.err")" || fail "export: $(cat "$work/export.err")"
"$bin/plumb" estimate -e compensated --input "$work/run.mcap" --window 1 > "$work/est.csv" 2> "$work/est.err" &&
  [ "$(grep -c . "$work/est.csv")" -gt 2 ] && grep -q "reading plumb/sensor/raw" "$work/est.err" &&
  pass "estimate reads raw: $(grep -c . "$work/est.csv") lines" || fail "estimate on the recording: $(cat "$work/est.err")"
"$bin/plumb" compare --input "$work/run.mcap" -e compensated --window 1 > "$work/cmp_run.out" 2> "$work/cmp_run.err" &&
  grep -qE "^compensated +[1-9]" "$work/cmp_run.out" && pass "compare reads raw" || fail "compare on the recording: $(cat "$work/cmp_run.out" "$work/cmp_run.err")"
expect_failure "export of the empty topic" "no message on 'plumb/sensor/calibrated'; the recording holds .*plumb/sensor/raw \([1-9][0-9]* messages\)" \
  "$bin/plumb" export "$work/run.mcap" --topic plumb/sensor/calibrated

# --- A repair in place names the file it repaired.
"$bin/plumb" record --repair "$work/run.mcap" > /dev/null 2> "$work/repair.err" &&
  grep -q "repaired $work/run.mcap in place" "$work/repair.err" && ! grep -q "\.repaired" "$work/repair.err" && [ ! -e "$work/run.mcap.repaired" ] &&
  pass "repair: $(cat "$work/repair.err")" || fail "repair: $(cat "$work/repair.err")"

# --- A survey of a tool nobody publishes names the tools it hears.
timeout 30 "$bin/plumb" topic pub plumb/attitude/compensated tool_id=rig7 inclination_deg=1 --count 40 --rate 5 --wait 0 \
  > /dev/null 2>&1 &
pids+=($!)
timeout 30 "$bin/plumb-survey" --tool-id rig1 --estimator compensated --file "$work/survey.txt" --skip-check gravity --skip-check field --skip-check dip --timeout 5 > /dev/null 2> "$work/survey.err"
grep -q "no attitude for tool 'rig1' on plumb/attitude/compensated for 3 s (1 writer(s) matched); heard tool id(s) 'rig7'" "$work/survey.err" &&
  pass "the survey names the tools it hears: $(grep -m1 "no attitude" "$work/survey.err")" || fail "survey: $(cat "$work/survey.err")"
finish
