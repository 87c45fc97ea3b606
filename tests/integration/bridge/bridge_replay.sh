#!/usr/bin/env bash
# Replay of a sensor CSV with bad rows: each bad row is reported naming line and column,
# counted, and the replay goes on; with --strict the bridge stops with exit 1 at the first one.
# A --calibration file makes the calibrated topic carry every good row.
# usage: bridge_replay.sh BIN_DIR TRANSPORT DOMAIN
set -euo pipefail
bin=$1 transport=$2
export PLUMB_DOMAIN_ID=$3
source "$(dirname "$0")/lib.sh"

csv=$work/sensor.csv
{
  echo "# replay test"
  echo "seq,t,fx,fy,fz,bx,by,bz"
  for i in $(seq 0 99); do
    t=$(printf '0.%03d' $i)
    case $i in
      17) echo "$i,$t,0.1,abc,-9.8,20,1,40" ;;   # bad number in fy (line 20)
      42) echo "$i,$t,0.1,0.2,-9.8,20,1" ;;      # missing column bz (line 45)
      *)  echo "$i,$t,0.1,0.2,-9.8,20,1,40" ;;
    esac
  done
} > "$csv"
cat > "$work/test.cal" <<'CAL'
format plumb-calibration 1
tool_id board
calibration_id replay-test-1
accel.bias 0.1 0 0
CAL

"$bin/plumb-test-bridge-checker" --transport "$transport" --reliable --count 98 --skip 17,42 \
  --calibration-id replay-test-1 --settle 0.5 --timeout 60 --status-out "$work/status.txt" \
  > "$work/checker.out" 2>&1 &
checker=$!
pids+=($checker)
"$bin/plumb-bridge" --transport "$transport" --replay "$csv" --rate x10 --reliable --calibration "$work/test.cal" \
  --no-calibration-topic --wait-subscribers 20 > "$work/bridge.out" 2> "$work/bridge.err.out" || { show_logs; exit 1; }
wait "$checker" || { show_logs; exit 1; }
s=$work/status.txt
expect_counter "$s" csv_errors 2
expect_counter "$s" lines_ok 98
expect_counter "$s" samples_published 98
expect_counter "$s" seq_gaps 2
expect_counter "$s" calibrations_applied 1
grep -q "sensor.csv:20: column 'fy': bad number 'abc'" "$work/bridge.err.out" || { echo "FAIL - line 20 fy error"; fails=$((fails + 1)); }
grep -q "sensor.csv:45: column 'bz'" "$work/bridge.err.out" || { echo "FAIL - line 45 bz error"; fails=$((fails + 1)); }

# --strict: exit 1, one line naming line and column.
rc=0
"$bin/plumb-bridge" --transport "$transport" --replay "$csv" --rate max --strict --wait-subscribers 0 > "$work/strict.out" 2> "$work/strict.err.out" || rc=$?
[ $rc -eq 1 ] || { echo "FAIL - --strict exit code $rc"; fails=$((fails + 1)); }
grep -q "sensor.csv:20: column 'fy'" "$work/strict.err.out" || { echo "FAIL - --strict message"; fails=$((fails + 1)); }

# A header without a required column: one clear line, exit 1.
printf 't,fx,fy,bx,by,bz\n0,1,2,3,4,5\n' > "$work/nofz.csv"
rc=0
"$bin/plumb-bridge" --transport "$transport" --replay "$work/nofz.csv" > /dev/null 2> "$work/nofz.err.out" || rc=$?
[ $rc -eq 1 ] && grep -q "fz" "$work/nofz.err.out" || { echo "FAIL - missing column fz: rc $rc"; fails=$((fails + 1)); }
[ "$(wc -l < "$work/nofz.err.out")" -eq 1 ] || { echo "FAIL - more than one error line"; fails=$((fails + 1)); }
[ $fails -eq 0 ] || { show_logs; exit 1; }
echo "all checks passed"
