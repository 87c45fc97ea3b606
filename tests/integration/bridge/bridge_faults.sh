#!/usr/bin/env bash
# A scripted board (plumb-test-serial-feeder) sends 200 frames with one of every fault and
# disappears once; the bridge must deliver exactly the usable samples on the raw topic (no
# calibration given: raw keeps flowing) and count every fault exactly on plumb/status.
# Then the ASCII line mode, detected from the data, from plumb-sim --serial-mode ascii.
# usage: bridge_faults.sh BIN_DIR TRANSPORT DOMAIN
set -euo pipefail
bin=$1 transport=$2
export PLUMB_DOMAIN_ID=$3
source "$(dirname "$0")/lib.sh"
link=$work/board

# Lost for good: 20 (CRC), 30 (truncated), 40 (replaced by a version-2 frame), 60 (never sent).
"$bin/plumb-test-bridge-checker" --transport "$transport" --topic plumb/sensor/raw --reliable \
  --count 196 --skip 20,30,40,60 --settle 0.5 --timeout 60 --status-out "$work/status.txt" \
  > "$work/checker.out" 2>&1 &
checker=$!
pids+=($checker)
"$bin/plumb-bridge" --transport "$transport" --device "$link" --baud 921600 --mode binary --reliable \
  --no-calibration-topic --backoff-min 0.05 --backoff-max 0.4 --status-period 0.2 --wait-subscribers 20 \
  > "$work/bridge.out" 2>&1 &
bridge=$!
pids+=($bridge)
sleep 1
"$bin/plumb-test-serial-feeder" --link "$link" --count 200 --rate 500 --start-delay 0.5 \
  --fault 10:garbage --fault 20:crc --fault 30:truncated --fault 40:version --fault 50:duplicate \
  --fault 60:drop --fault 70:nan --fault 80:range --fault 90:backwards --vanish-at 100 --gone 0.5 \
  > "$work/feeder.out" 2>&1 || { show_logs; exit 1; }
sleep 1
kill -INT "$bridge"
status=0
wait "$bridge" || { echo "plumb-bridge failed"; status=1; }
wait "$checker" || { echo "checker failed"; status=1; }
[ $status -eq 0 ] || { show_logs; exit 1; }
cat "$work/status.txt"
s=$work/status.txt
expect_counter "$s" state stopping
expect_counter "$s" frames_ok 197        # 200 - crc - truncated - version - drop + duplicate
expect_counter "$s" crc_errors 1
expect_counter "$s" truncated 1
expect_counter "$s" bad_version 1
expect_counter "$s" resyncs 3            # garbage, CRC error, truncated frame
expect_counter "$s" bytes_skipped 110    # 5 + 70 + 35
expect_counter "$s" seq_gaps 4
expect_counter "$s" samples_missing 4
expect_counter "$s" duplicates 1
expect_counter "$s" not_finite 1
expect_counter "$s" out_of_range 1
expect_counter "$s" saturated 1          # the out-of-range field is also past the full scale
expect_counter "$s" time_backwards 1
expect_counter "$s" opens 2
expect_counter "$s" reopens 1
expect_counter "$s" samples_published 196
expect_counter "$s" calibrated_batches 0
grep -q "device lost" "$work/bridge.out" || { echo "FAIL - no 'device lost' log line"; fails=$((fails + 1)); }
[ $fails -eq 0 ] || { show_logs; exit 1; }

# ASCII line mode, detected from the data: plumb-sim --serial-mode ascii -> bridge --mode auto.
if [ -x "$bin/plumb-sim" ]; then
  rm -f "$work"/*.out
  "$bin/plumb-test-bridge-checker" --transport "$transport" --topic plumb/sensor/raw --reliable --count 200 \
    --settle 0.5 --timeout 60 --status-out "$work/status2.txt" > "$work/checker2.out" 2>&1 &
  checker=$!
  pids+=($checker)
  "$bin/plumb-bridge" --transport "$transport" --device "$link" --no-calibration-topic --reliable \
    --backoff-min 0.05 --backoff-max 0.2 --wait-subscribers 20 > "$work/bridge2.out" 2>&1 &
  bridge=$!
  pids+=($bridge)
  sleep 1
  "$bin/plumb-sim" --serial "$link" --serial-mode ascii --duration 2 --rpm 60 --inclination 2 --no-truth --rate x2 \
    > "$work/sim2.out" 2>&1 || { show_logs; exit 1; }
  sleep 1
  kill -INT "$bridge"
  wait "$bridge" || { show_logs; exit 1; }
  wait "$checker" || { show_logs; exit 1; }
  expect_counter "$work/status2.txt" lines_ok 200
  expect_counter "$work/status2.txt" frames_ok 0
  expect_counter "$work/status2.txt" csv_errors 0
  expect_counter "$work/status2.txt" bytes_skipped 0
  [ $fails -eq 0 ] || { show_logs; exit 1; }
fi
echo "all checks passed"
