#!/usr/bin/env bash
# Two simulated tools (different tool ids, different attitudes) publish on one
# raw topic; the estimator host keeps one state per tool id and publishes each tool's estimates
# with its own id, each right, none mixed, and no sample of one counted as lost by the other.
# Tool A on transport S, tool B on transport H (the host's), estimates read on S.
# usage: two_tools.sh BIN_DIR S H DOMAIN
set -uo pipefail
bin=$1 sim_t=$2 host_t=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
start_work_with_programs
show_logs() { for f in "$work"/*.out; do echo "--- $f"; cat "$f"; done; }
cd "$work"

# Two estimates per tool; the echo counts them, so the host needs no --count (which a tool that
# came late could not meet).
"$bin/plumb" topic echo plumb/attitude/compensated --csv --count 4 --timeout 90 --transport "$sim_t" \
  > estimates.csv 2> echo.out &
echo_pid=$!
pids+=($echo_pid)
"$bin/plumb-estimator" --transport "$host_t" --input plumb/sensor/raw --reliable --plugin compensated --window 5 \
  > host.out 2>&1 &
host=$!
pids+=($host)
sim() {  # sim TOOL TRANSPORT INC AZI
  "$bin/plumb-sim" --transport "$2" --tool-id "$1" --inclination "$3" --azimuth "$4" --rpm 60 --duration 10.5 \
    --snr-accel 40 --snr-mag 40 --g 10 --field 48.4 --dip 45.5 --rate x2 --reliable --wait-subscribers 20 --no-truth \
    > "sim_$1.out" 2>&1
}
sim T-A "$sim_t" 1.5 200 &
a=$!
sim T-B "$host_t" 5 80 &
b=$!
pids+=($a $b)
wait $a || fail "plumb-sim T-A: $(tail -2 sim_T-A.out)"
wait $b || fail "plumb-sim T-B: $(tail -2 sim_T-B.out)"
wait $echo_pid && pass "four estimates published" || fail "estimates: $(cat echo.out)"
kill -INT $host 2>/dev/null
wait $host
for t in T-A T-B; do
  awk -F, -v t="$t" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; print; next } $c["tool_id"] == t' \
    estimates.csv > "$t.csv"
done
python3 "$here/check_estimates.py" T-A.csv --inclination 1.5 --azimuth 200 --inc-tol 0.02 --azi-tol 0.3 --min-rows 2 &&
  pass "tool T-A estimated on its own (inc 1.5, azi 200)" || fail "tool T-A"
python3 "$here/check_estimates.py" T-B.csv --inclination 5 --azimuth 80 --inc-tol 0.02 --azi-tol 0.3 --min-rows 2 &&
  pass "tool T-B estimated on its own (inc 5, azi 80)" || fail "tool T-B"
grep -q "(0 lost in transit," host.out && pass "no sample counted lost across the tools" ||
  fail "lost samples: $(grep 'lost in transit' host.out)"
grep -q "estimating each tool separately" host.out && pass "the host says it estimates each tool separately" ||
  fail "no line about the second tool"
[ $fails -eq 0 ] || show_logs
finish
