#!/usr/bin/env bash
# Nothing lost: plumb-sim writes 60 s of 1 kHz frames (real time) into a pseudo-terminal, the
# bridge publishes them reliably; every sequence number 0..59999 must arrive exactly once, in
# order, on the calibrated topic, and the bridge must count no problem at all.
# usage: bridge_nothing_lost.sh BIN_DIR TRANSPORT DOMAIN
set -euo pipefail
bin=$1 transport=$2
export PLUMB_DOMAIN_ID=$3
source "$(dirname "$0")/lib.sh"
link=$work/board
[ -x "$bin/plumb-sim" ] || { echo "plumb-sim not built"; exit 1; }
cat > "$work/cal.cal" <<'CAL'
format plumb-calibration 1
tool_id sim
calibration_id nothing-lost
accel.bias 0.01 -0.02 0.03
CAL
n=60000
"$bin/plumb-test-bridge-checker" --transport "$transport" --reliable --count $n --calibration-id nothing-lost \
  --settle 1 --timeout 150 --status-out "$work/status.txt" > "$work/checker.out" 2>&1 &
checker=$!
pids+=($checker)
"$bin/plumb-bridge" --transport "$transport" --device "$link" --tool-id sim --baud 921600 --reliable --calibration "$work/cal.cal" \
  --no-calibration-topic --backoff-min 0.05 --backoff-max 0.2 --wait-subscribers 20 > "$work/bridge.out" 2>&1 &
bridge=$!
pids+=($bridge)
wait_bridge_matched "$work/bridge.out" || { show_logs; echo "FAIL - no reader matched the bridge"; exit 1; }
"$bin/plumb-sim" --serial "$link" --rate-hz 1000 --duration 60 --batch 1 --rpm 60 --inclination 2 --azimuth 200 \
  --no-truth --tool-id sim > "$work/sim.out" 2>&1 || { show_logs; exit 1; }
sleep 1
kill -INT "$bridge"
status=0
wait "$bridge" || { echo "plumb-bridge failed"; status=1; }
wait "$checker" || { echo "checker failed"; status=1; }
[ $status -eq 0 ] || { show_logs; exit 1; }
cat "$work/checker.out" "$work/status.txt"
s=$work/status.txt
expect_counter "$s" frames_ok $n
expect_counter "$s" samples_published $n
for c in crc_errors truncated bad_version resyncs bytes_skipped seq_gaps duplicates time_backwards not_finite; do
  expect_counter "$s" $c 0
done
[ $fails -eq 0 ] || { show_logs; exit 1; }
echo "all checks passed"
