#!/usr/bin/env bash
# plumb/status is a state: a monitor that joins late gets the last report of every running
# component at once, and a monitor already matched gets a component's last words ("stopping")
# when it is stopped with SIGINT.
#   plumb-sim (1 s of data, then "finished", then lingers without reporting again) and
#   plumb-estimator (--name late-host-DOMAIN: plumb status shows that name beside the computer's)
#   run on WRITER's vendor; the monitors on READER's.
# With a volatile plumb/status the late `plumb status` would never see plumb-sim: it reports
# nothing more after "finished".
# usage: late_status.sh BIN_DIR WRITER_TRANSPORT READER_TRANSPORT DOMAIN
set -uo pipefail
bin=$1 w=$2 r=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
cd "$work"
logs() { for f in "$work"/*.log "$work"/*.txt; do [ -f "$f" ] && { echo "--- $f"; tail -n 8 "$f"; }; done; }

"$bin/plumb-test-faults-watch" --transport "$r" > watch.log 2> watch_err.log &
watch=$!
name=late-host-$PLUMB_DOMAIN_ID  # its name for plumb component, not the computer's: plumb status shows it
"$bin/plumb-estimator" --transport "$w" --name "$name" --input plumb/sensor/raw --plugin integral --window 0.5 -q > host.log 2>&1 &
host=$!
pids+=($watch $host)
wait_for watch.log "^status [0-9.]+ plumb-estimator running" 30 || { fail "the early monitor got no status of the host"; logs; finish; }
"$bin/plumb-sim" --transport "$w" --duration 1 --rate-hz 100 --no-truth --linger 60 --wait-subscribers 20 > sim.log 2>&1 &
sim=$!
pids+=($sim)
wait_for watch.log "^status [0-9.]+ plumb-sim finished" 40 || { fail "plumb-sim never said finished"; logs; finish; }
wait_for host.log "starts at sequence" 10 || fail "the host got no samples: $(tail -3 host.log)"

# A monitor that joins now: plumb-sim said "finished" before it started and says nothing more.
# (6 s to listen: Fast DDS's discovery alone took up to 4 s on a loaded machine, docs/operations.md.)
"$bin/plumb" status --transport "$r" --wait 6 > late_status.txt 2>&1
if grep -qE "plumb-sim +finished" late_status.txt; then
  pass "a late 'plumb status' ($r) gets plumb-sim's last report ($w), written before it started"
else
  fail "late plumb status lacks plumb-sim finished: $(cat late_status.txt)"
fi
grep -qE "plumb-estimator +running" late_status.txt && pass "and the running host's" ||
  fail "late plumb status lacks plumb-estimator: $(cat late_status.txt)"
grep -qE "^$(hostname) +plumb-estimator +running +$name +[0-9]" late_status.txt &&
  grep -qE "^HOST +COMPONENT +STATE +NAME +REPORTS" late_status.txt && grep -qE "plumb-sim +finished +- +[0-9]" late_status.txt &&
  pass "its row names it '$name' (--name) beside the computer's name; plumb-sim, without a name, shows -" ||
  fail "late plumb status does not show the host's --name '$name': $(cat late_status.txt)"
# Six reports: the running host's, one a second, may come before the kept one of plumb-sim (its
# writer matched later: two of the host's came first in CI, across vendors on a loaded machine).
"$bin/plumb" topic echo plumb/status --transport "$r" --count 6 --timeout 15 > late_echo.txt 2>&1 &&
  grep -q "state: \"finished\"" late_echo.txt && pass "a late 'plumb topic echo plumb/status' gets it too" ||
  fail "late echo: $(cat late_echo.txt)"

# The host stopped with SIGINT: the monitor matched all along gets its last words.
kill -INT $host
wait $host
if grep -qE "^status [0-9.]+ plumb-estimator stopping" watch.log; then
  pass "the matched monitor got plumb-estimator's 'stopping'"
else
  fail "no 'stopping' from plumb-estimator: $(grep plumb-estimator watch.log | tail -2)"
fi
# Transient-local lives with its writer: a host that has gone is no longer reported to late monitors.
"$bin/plumb" status --transport "$r" --wait 6 > after_stop.txt 2>&1
if grep -q "plumb-estimator" after_stop.txt; then fail "a stopped host still reported: $(cat after_stop.txt)"
else grep -qE "plumb-sim +finished" after_stop.txt && pass "a stopped host's report goes with it; plumb-sim's stays" ||
  fail "after the stop: $(cat after_stop.txt)"; fi
kill -INT $sim $watch 2>/dev/null
finish
