#!/usr/bin/env bash
# Plugins loaded, re-tuned and unloaded in a running estimator host (plumb component, plumb param):
# plumb-sim -> plumb-estimator --plugin static --plugin compensated on transport H; the plumb
# commands and the echoes on transport C. integral is loaded as a third plugin while the tool turns,
# its window set from 2 s to 1 s, then unloaded; static's and compensated's windows go on back to
# back through all of it (none missing, none cut short); integral's change applies from its next
# window; a refused value gets the words plumb-estimator --param gives.
# usage: component_runtime.sh BIN_DIR H C DOMAIN
set -uo pipefail
bin=$1 host_t=$2 cli_t=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
start_work_with_programs
show_logs() { for f in "$work"/*.out; do echo "--- $f"; tail -20 "$f"; done; }
cd "$work"
name=comp-host-$4
plumb_c() { "$bin/plumb" "$@" --transport "$cli_t"; }
rows() { local n; n=$(grep -c . "$1" 2>/dev/null) || n=0; echo $((n > 0 ? n - 1 : 0)); }  # data rows of a CSV
# wait_rows FILE N: until FILE has N data rows (bounded: 60 s, then the checks below say what is missing).
wait_rows() { for _ in $(seq 600); do [ "$(rows "$1")" -ge "$2" ] && return 0; sleep 0.1; done; return 1; }

# Line-buffered: the checks read the files while the echoes run (a file's stdout is block-buffered).
for p in static compensated integral; do
  stdbuf -oL "$bin/plumb" topic echo plumb/attitude/$p --csv --transport "$cli_t" --timeout 120 > $p.csv 2> echo_$p.out &
  pids+=($!)
done
"$bin/plumb-estimator" --transport "$host_t" --name "$name" --input plumb/sensor/raw --reliable --plugin static \
  --plugin compensated --window 2 --quiet > host.out 2>&1 &
host=$!
pids+=($host)
# 100 Hz, three times real time: a 2 s window every 0.67 s; stopped once the checks are done.
"$bin/plumb-sim" --transport "$host_t" --inclination 2 --azimuth 120 --rpm 120 --duration 600 --rate x3 --reliable \
  --wait-subscribers 20 --no-truth > sim.out 2>&1 &
sim=$!
pids+=($sim)

wait_rows static.csv 2 || fail "static published no estimate"
out=$(plumb_c component list "$name" 2>&1)
grep -q "^$name  *static  *plumb/attitude/static" <<< "$out" && grep -q "^$name  *compensated  *plumb/attitude/compensated" <<< "$out" &&
  pass "component list $name: static, compensated" || fail "component list: $(plumb_c component list "$name" 2>&1)"
out=$(plumb_c component load "$name" integral 2>&1) && pass "component load: $out" || fail "component load: $out"
wait_rows integral.csv 3 || fail "integral published fewer than 3 estimates after its load"
out=$(plumb_c param set "$name" integral window 1 2>&1) && pass "param set window 1: $out" || fail "param set: $out"
n_set=$(rows integral.csv)
out=$(plumb_c param get "$name" integral window 2>&1)
[ "$out" = 1 ] && pass "param get integral window: 1" || fail "param get integral window: '$out'"
output_matches "^max_model_error_deg = 2.5$" plumb_c param dump "$name" integral &&
  pass "param dump shows max_model_error_deg = 2.5" || fail "param dump: $(plumb_c param dump "$name" integral 2>&1)"

# Refusals: the words plumb-estimator --param gives for the same assignment, and nothing changes.
for bad in "bogus 1" "window -1"; do
  set -- $bad
  cli_err=$(plumb_c param set "$name" integral "$1" "$2" 2>&1 >/dev/null) && fail "param set $bad: exit 0"
  start_err=$("$bin/plumb-estimator" --plugin integral --param "integral.$1=$2" 2>&1 >/dev/null)
  if [ -n "${cli_err#plumb: }" ] && [ "${cli_err#plumb: }" = "${start_err#plumb-estimator: }" ]; then
    pass "param set $bad refused as the command line does: ${cli_err#plumb: }"
  else
    fail "param set $bad: '$cli_err', the command line: '$start_err'"
  fi
done
out=$(plumb_c param get "$name" integral window 2>&1)
[ "$out" = 1 ] && pass "refused values left window at 1" || fail "after the refusals: window '$out'"

wait_rows integral.csv $((n_set + 4)) || fail "integral: fewer than 4 estimates after param set"
out=$(plumb_c component unload "$name" integral 2>&1) && pass "component unload: $out" || fail "component unload: $out"
n_static=$(rows static.csv)
wait_rows static.csv $((n_static + 2)) || fail "static stopped after the unload"
n_integral=$(rows integral.csv)
wait_rows static.csv $((n_static + 4)) || fail "static stopped after the unload"
[ "$(rows integral.csv)" -eq "$n_integral" ] && pass "integral's topic stopped at the unload ($n_integral estimates)" ||
  fail "integral still publishing after the unload: $n_integral -> $(rows integral.csv)"
out=$(plumb_c component list "$name" 2>&1)
grep -q static <<< "$out" && grep -q compensated <<< "$out" && ! grep -q integral <<< "$out" &&
  pass "component list after the unload: static, compensated" ||
  fail "component list after the unload: $out"
expect_failure "a host that does not exist" "no estimator host named 'nobody' answered .*hosts seen: .*$name" \
  plumb_c component list nobody --wait 2

kill -INT $sim 2>/dev/null; wait $sim
kill -INT $host 2>/dev/null; wait $host
for p in "${pids[@]}"; do kill -INT "$p" 2>/dev/null; done; wait 2>/dev/null

out=$(python3 "$here/component_windows.py" static.csv --sample-period 0.01 --length 2 --min-rows 10) &&
  pass "static across load, set, unload: $out" || fail "static: $out"
out=$(python3 "$here/component_windows.py" compensated.csv --sample-period 0.01 --length 2 --min-rows 10) &&
  pass "compensated across load, set, unload: $out" || fail "compensated: $out"
out=$(python3 "$here/component_windows.py" integral.csv --sample-period 0.01 --length 2 --then-length 1 --min-rows 6) &&
  pass "integral: $out" || fail "integral: $out"
grep -q "(0 lost in transit," host.out && pass "host: no sample lost" || fail "host: $(grep 'lost in transit' host.out)"
[ "$(grep -c "refused: " host.out)" -eq 2 ] && pass "host logged the two refusals" || fail "host log: $(grep 'refused' host.out)"
[ $fails -eq 0 ] || show_logs
finish
