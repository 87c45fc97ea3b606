#!/usr/bin/env bash
# kill -9 and restart of each component in turn while a simulated board streams at 1 kHz:
#   plumb-sim --serial (the board, never killed) -> plumb-bridge (reliable raw + calibrated, with the
#   coefficients of plumb-calibrate from plumb/calibration) -> plumb-estimator (integral, 0.5 s
#   windows) -> plumb/attitude/integral -> plumb-survey; the watcher follows the calibrated sequence
#   numbers, the attitude windows, plumb/calibration and plumb/status.
# Each component is killed with SIGKILL, started again 2 s later, and must resume within 10 s; the
# others keep running; what the outage lost is counted (estimator host: silent_lost_samples,
# lost_samples, and lost_while_down after its own restart; board: samples dropped while nobody
# read the line; survey: attitude windows missing) and nothing else is lost: the calibrated stream
# and the attitude windows are complete outside the outages. At the end every component stops on
# SIGINT within 10 s (nothing hangs).
# usage: restart_faults.sh BIN_DIR TRANSPORT DOMAIN
set -uo pipefail
bin=$1
export PLUMB_TRANSPORT=$2 PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
cd "$work"
show_logs() { for f in "$work"/*.log; do echo "--- $f"; tail -n 12 "$f"; done; }
now() { date +%s.%N; }
declare -A pid
: > events.txt

start() {  # start COMPONENT: (re)starts it in the background, its log appended to COMPONENT.log
  case $1 in
    plumb-calibrate)
      "$bin/plumb-calibrate" --procedure 6pos --input acc_sensor.csv --stations acc_stations.csv --tool-id board \
        --calibration-id restart-test --publish --linger 600 >> "$1.log" 2>&1 & ;;
    plumb-bridge)
      "$bin/plumb-bridge" --device ./board --baud 921600 --reliable --backoff-min 0.05 --backoff-max 0.2 \
        >> "$1.log" 2>&1 & ;;
    plumb-estimator)
      "$bin/plumb-estimator" --input plumb/sensor/calibrated --reliable --plugin integral --window 0.5 -q \
        >> "$1.log" 2>&1 & ;;
    plumb-survey)
      "$bin/plumb-survey" --tool-id board --estimator integral --file survey.txt --gravity 9.80665 --total-field 48.4 \
        --dip 45.5 --depth-clock-offset 0 -q >> "$1.log" 2>&1 & ;;
  esac
  pid[$1]=$!
  pids+=($!)
  echo "start $1 $(now)" >> events.txt
}

printf 'format plumb-calibration 1\naccel.bias 0.05 -0.04 0.03\n' > board.txt
"$bin/plumb-calibrate" --procedure 6pos --sim-truth board.txt --write-simulation acc_ > cal.log 2>&1 ||
  { fail "simulated calibration data"; show_logs; finish; }
"$bin/plumb-test-faults-watch" --attitude plumb/attitude/integral --sensor plumb/sensor/calibrated --reliable \
  --calibration > watch.log 2> watch_err.log &
watch=$!
pids+=($watch)
for c in plumb-calibrate plumb-estimator plumb-survey; do start $c; done
sleep 1
start plumb-bridge
wait_for watch.log "^calibration " 30 || { fail "no coefficients published"; show_logs; finish; }
"$bin/plumb-sim" --serial ./board --accel-bias 0.05,-0.04,0.03 --rate-hz 1000 --duration 600 --inclination 5 \
  --azimuth 45 --rpm 30 --tool-id board > sim.log 2>&1 &
sim=$!
pids+=($sim)
wait_for watch.log "^attitude " 40 || { fail "no attitude"; show_logs; finish; }
sleep 3

# The host first: its counters (samples lost across the bridge's restart) must survive to the end.
for c in plumb-estimator plumb-bridge plumb-calibrate plumb-survey; do
  kill -9 "${pid[$c]}"
  echo "kill $c $(now)" >> events.txt
  sleep 2
  start $c
  case $c in
    plumb-estimator) wait_for "$c.log" "starts at sequence" 15 ;;
    plumb-bridge) sleep 4 ;;
    *) sleep 3 ;;
  esac
  for other in plumb-estimator plumb-bridge plumb-calibrate plumb-survey; do
    kill -0 "${pid[$other]}" 2>/dev/null || fail "$other ended while $c was restarted: $(tail -3 "$other.log")"
  done
  kill -0 $sim 2>/dev/null || fail "the board (plumb-sim) ended"
  sleep 2
done
sleep 2

# Nothing hangs: each stops on SIGINT. The board first, so that the stream ends in one piece.
kill -INT $sim
wait $sim
sleep 1.5
for c in plumb-survey plumb-estimator plumb-bridge plumb-calibrate; do
  kill -INT "${pid[$c]}"
  for ((i = 0; i < 100; ++i)); do kill -0 "${pid[$c]}" 2>/dev/null || break; sleep 0.1; done
  kill -0 "${pid[$c]}" 2>/dev/null && fail "$c did not stop within 10 s of SIGINT" || pass "$c stopped on SIGINT"
done
sleep 1
kill -INT $watch
wait $watch

# What the board wrote while no bridge had the line open is gone (a pseudo-terminal keeps nothing
# for a reader that is not there; a real serial line neither), and the board may not even know it.
dropped=$(grep -o "[0-9]* samples dropped so far" sim.log | tail -1 | cut -d' ' -f1)
echo "board: ${dropped:-0} samples counted dropped by the board while nobody read the line"
grep -h "starts at sequence\|resumed after a silence\|restarted its sequence\|samples lost while silent\|lost while this host was down" plumb-estimator.log
grep -h "attitude gap" plumb-survey.log | head -3
python3 "$here/check_faults.py" restart watch.log --events events.txt --window-ns 500000000 --rate-hz 1000 || { fails=$((fails + 1)); show_logs; }
finish
