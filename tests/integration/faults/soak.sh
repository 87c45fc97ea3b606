#!/usr/bin/env bash
# A soak at 1 kHz: the board (plumb-sim --serial) -> plumb-bridge (reliable, calibrated with the
# coefficients plumb-calibrate publishes) -> plumb-estimator (integral and compensated, 1 s windows)
# -> plumb-survey, for DURATION seconds. The resident memory (VmRSS) of every component is read
# every 10 s; from the end of the warm-up to the end it must stay flat: growth at most 2 MB + 2 %.
# The warm-up (WARMUP_S, default a quarter of the run) lets DDS histories, pools and the allocator
# fill up: the bridge's reliable keep-last 4096 histories (raw and calibrated, batches of 32
# samples, 31 a second) take 132 s to fill, and Cyclone DDS grows its writer history with them
# (about 17 MB), so the 10-minute runs warm up 180 s. A leak of
# 100 bytes per sensor batch would add 3.6 MB over 6 minutes, 0.6 MB over the 60 s run, so the
# 60 s run catches gross leaks only; the 10-minute runs (label "long") are the real check. The
# stream must also stay complete (reliable calibrated samples, attitude windows): nothing lost.
# usage: soak.sh BIN_DIR TRANSPORT|mixed DOMAIN DURATION_S [WARMUP_S]
set -uo pipefail
bin=$1 mode=$2 duration=$4
export PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
cd "$work"
show_logs() { for f in "$work"/*.log; do echo "--- $f"; tail -n 12 "$f"; done; }
if [ "$mode" = mixed ]; then
  t_bridge=fastdds t_host=cyclonedds t_survey=fastdds t_cal=cyclonedds t_watch=fastdds
else
  t_bridge=$mode t_host=$mode t_survey=$mode t_cal=$mode t_watch=$mode
fi
warmup=${5:-$((duration / 4))}

printf 'format plumb-calibration 1\naccel.bias 0.05 -0.04 0.03\n' > board.txt
"$bin/plumb-calibrate" --procedure 6pos --sim-truth board.txt --write-simulation acc_ > cal.log 2>&1 ||
  { fail "simulated calibration data"; show_logs; finish; }
"$bin/plumb-test-faults-watch" --transport $t_watch --attitude plumb/attitude/integral --sensor plumb/sensor/calibrated \
  --reliable --calibration > watch.log 2> watch_err.log &
watch=$!
declare -A pid
"$bin/plumb-calibrate" --transport $t_cal --procedure 6pos --input acc_sensor.csv --stations acc_stations.csv \
  --tool-id board --calibration-id soak --publish --linger $((duration + 60)) > calibrate.log 2>&1 &
pid[plumb-calibrate]=$!
"$bin/plumb-estimator" --transport $t_host --input plumb/sensor/calibrated --reliable --plugin integral \
  --plugin compensated --window 1 -q > estimator.log 2>&1 &
pid[plumb-estimator]=$!
"$bin/plumb-survey" --transport $t_survey --tool-id board --estimator integral --file survey.txt --gravity 9.80665 \
  --total-field 48.4 --dip 45.5 --depth-clock-offset 0 -q > survey.log 2>&1 &
pid[plumb-survey]=$!
"$bin/plumb-bridge" --transport $t_bridge --device ./board --baud 921600 --reliable --backoff-min 0.05 \
  --backoff-max 0.2 > bridge.log 2>&1 &
pid[plumb-bridge]=$!
pids+=($watch "${pid[@]}")
wait_for watch.log "^calibration " 30 || { fail "no coefficients published"; show_logs; finish; }
"$bin/plumb-sim" --serial ./board --accel-bias 0.05,-0.04,0.03 --rate-hz 1000 --duration $((duration + 30)) \
  --inclination 5 --azimuth 45 --rpm 30 --tool-id board > sim.log 2>&1 &
pid[plumb-sim]=$!
pids+=(${pid[plumb-sim]})
wait_for watch.log "^attitude " 40 || { fail "no attitude"; show_logs; finish; }

rss() { awk '/^VmRSS/ { print $2 }' "/proc/$1/status" 2>/dev/null || echo 0; }
declare -A first last
t0=$SECONDS
printf '%6s' "t/s"; for c in "${!pid[@]}"; do printf ' %16s' "$c"; done; echo "   (VmRSS, kB)"
while :; do
  t=$((SECONDS - t0))
  printf '%6d' $t
  for c in "${!pid[@]}"; do
    r=$(rss "${pid[$c]}")
    printf ' %16s' "$r"
    [ $t -ge $warmup ] && [ -z "${first[$c]:-}" ] && first[$c]=$r
    last[$c]=$r
  done
  echo
  [ $t -ge $duration ] && break
  for c in "${!pid[@]}"; do kill -0 "${pid[$c]}" 2>/dev/null || { fail "$c ended during the soak"; show_logs; finish; }; done
  sleep $((duration - t < 10 ? (duration - t > 0 ? duration - t : 1) : 10))
done
for c in "${!pid[@]}"; do
  growth=$((last[$c] - first[$c]))
  allowed=$((2048 + first[$c] / 50))
  [ "${first[$c]}" -gt 0 ] && [ $growth -le $allowed ] &&
    pass "$c: VmRSS ${first[$c]} kB after the warm-up, ${last[$c]} kB at the end (${growth} kB, at most ${allowed})" ||
    fail "$c: VmRSS ${first[$c]} kB after the warm-up, ${last[$c]} kB at the end (${growth} kB, more than ${allowed})"
done

kill -INT "${pid[plumb-sim]}"; wait "${pid[plumb-sim]}"
sleep 2
for c in plumb-survey plumb-estimator plumb-bridge plumb-calibrate; do kill -INT "${pid[$c]}"; wait "${pid[$c]}"; done
kill -INT $watch; wait $watch
summary=$(grep "^summary" watch.log)
echo "watcher: $summary"
grep -q "^summary samples=[1-9][0-9]* gaps=0 lost=0 backwards=0" watch.log &&
  pass "every calibrated sample arrived, in order" || fail "calibrated stream not complete: $summary"
python3 - watch.log <<'EOF' && pass "attitude windows complete" || fail "attitude windows missing"
import sys
starts = [int(l.split()[2]) for l in open(sys.argv[1]) if l.startswith("attitude ")]
steps = [b - a for a, b in zip(starts, starts[1:])]
bad = [s for s in steps if s <= 0 or round(s / 1e9) != 1]
print(f"{len(starts)} attitude windows of 1 s, {len(bad)} not following the previous one")
sys.exit(1 if bad or len(starts) < 5 else 0)
EOF
finish
