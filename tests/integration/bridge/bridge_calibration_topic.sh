#!/usr/bin/env bash
# Calibration from the topic: the bridge starts with none (raw only), refuses unusable
# coefficients (a singular sensitivity), then applies good ones published on plumb/calibration,
# after which the calibrated topic carries every sample, contiguous, with the calibration id.
# usage: bridge_calibration_topic.sh BIN_DIR TRANSPORT DOMAIN
set -euo pipefail
bin=$1 transport=$2
export PLUMB_DOMAIN_ID=$3
source "$(dirname "$0")/lib.sh"
csv=$work/sensor.csv
{
  echo "seq,t,fx,fy,fz,bx,by,bz"
  for i in $(seq 0 1499); do echo "$i,$((i / 100)).$(printf '%02d' $((i % 100))),0.1,0.2,-9.8,20,1,40"; done
} > "$csv"
"$bin/plumb-test-bridge-checker" --transport "$transport" --reliable --any-start --count 200 \
  --calibration-id from-topic --timeout 60 --status-out "$work/status.txt" > "$work/checker.out" 2>&1 &
checker=$!
pids+=($checker)
"$bin/plumb-bridge" --transport "$transport" --replay "$csv" --rate realtime --reliable --wait-subscribers 20 \
  > "$work/bridge.out" 2>&1 &
bridge=$!
pids+=($bridge)
sleep 2
identity="1,0,0,0,1,0,0,0,1"
"$bin/plumb" topic pub plumb/calibration --transport "$transport" --wait 10 calibration_id=singular tool_id=board \
  thermometer=0,1,0,0 accelerometer.sensitivity=0,0,0,0,0,0,0,0,0 > "$work/pub1.out" 2>&1 || { show_logs; exit 1; }
"$bin/plumb" topic pub plumb/calibration --transport "$transport" --wait 10 calibration_id=from-topic tool_id=board \
  thermometer=0,1,0,0 temp_min_c=-40 temp_max_c=200 accelerometer.sensitivity=$identity \
  magnetometer.sensitivity=$identity accelerometer.bias=0.1,0,0 > "$work/pub2.out" 2>&1 || { show_logs; exit 1; }
status=0
wait "$checker" || { echo "checker failed"; status=1; }
kill -INT "$bridge" 2>/dev/null || true
wait "$bridge" || true
[ $status -eq 0 ] || { show_logs; exit 1; }
expect_counter "$work/status.txt" calibrations_rejected 1
expect_counter "$work/status.txt" calibrations_applied 1
grep -q "calibration 'singular'.*rejected: accelerometer sensitivity is singular" "$work/bridge.out" ||
  { echo "FAIL - singular coefficients not refused"; fails=$((fails + 1)); }
grep -q "calibration 'from-topic'.*applied" "$work/bridge.out" || { echo "FAIL - not applied"; fails=$((fails + 1)); }
grep -q "no calibration yet" "$work/bridge.out" || { echo "FAIL - no 'raw only' log line"; fails=$((fails + 1)); }
[ $fails -eq 0 ] || { show_logs; exit 1; }
echo "all checks passed"
