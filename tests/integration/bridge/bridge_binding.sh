#!/usr/bin/env bash
# Coefficients bind to a tool and to the units of the package they were made for.
# Without DDS: a coefficients file for another tool, for no tool, or for a volts package is
# refused in one line naming what is wrong. Over DDS (bridge on TRANSPORT, the others on OTHER):
# coefficients published for another tool are refused in one line, and coefficients without a
# units line made for a volts package (sensitivity ~4 m/s^2 per V) applied to an m/s^2 stream stop
# the calibrated stream (|G| = 38.8 m/s^2) with status "failed", while raw data keeps flowing.
# usage: bridge_binding.sh BIN_DIR TRANSPORT OTHER_TRANSPORT DOMAIN
set -uo pipefail
bin=$1 transport=$2 other=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
source "$here/../wait.sh"
start_work_with_programs
show_logs() { for f in "$work"/*.out; do echo "--- $f"; tail -20 "$f"; done; }
cd "$work"

# 8 s of a still tool at 100 Hz, in m/s^2 and uT as the protocol and CSV convention say.
{
  echo "seq,t,fx,fy,fz,bx,by,bz"
  for i in $(seq 0 799); do echo "$i,$((i / 100)).$(printf '%02d' $((i % 100))),0.1,0.2,-9.8,20,1,40"; done
} > sensor.csv
printf 'format plumb-calibration 1\ntool_id sim-turntable\ncalibration_id turntable-cal\n' > other_tool.cal
printf 'format plumb-calibration 1\ncalibration_id no-tool-cal\n' > no_tool.cal
printf 'format plumb-calibration 1\ntool_id board\ncalibration_id volts-cal\naccel_units V\nmag_units counts\n' > volts.cal
# A version-1 file as plumb-calibrate wrote it before the units lines: a volts package's scale.
printf 'format plumb-calibration 1\ntool_id board\ncalibration_id volts-v1\naccel.sensitivity 3.96 0 0 0 3.96 0 0 0 3.96\n' \
  > volts_v1.cal

bridge=("$bin/plumb-bridge" --transport "$transport" --replay sensor.csv --rate max --no-calibration-topic)
expect_error "file for another tool" "turntable-cal' is for tool 'sim-turntable', this bridge is tool 'board': refused" \
  "${bridge[@]}" --calibration other_tool.cal
expect_error "file naming no tool" "no-tool-cal' names no tool, this bridge is tool 'board': refused.*--calibration-any-tool" \
  "${bridge[@]}" --calibration no_tool.cal
expect_error "file for a volts package" "volts-cal' was made for a package whose accelerometers send V, this bridge's stream is in m/s2" \
  "${bridge[@]}" --calibration volts.cal
expect_error "file for another tool, bridge told its tool" "is for tool 'sim-turntable', this bridge is tool 'T9'" \
  "${bridge[@]}" --tool-id T9 --calibration other_tool.cal

# Over DDS. The raw reader (OTHER vendor) lets the bridge start; the status reader sees "failed".
"$bin/plumb" topic echo plumb/status --transport "$other" --timeout 40 > status.out 2>&1 &
pids+=($!)
"$bin/plumb" topic echo plumb/sensor/raw --csv --transport "$other" --reliable --count 100 --timeout 60 > raw.out 2>&1 &
raw=$!
pids+=($raw)
"$bin/plumb-bridge" --transport "$transport" --replay sensor.csv --rate realtime --reliable --wait-subscribers 20 \
  --status-period 0.5 --calibration volts_v1.cal > bridge.out 2>&1 &
bridge_pid=$!
pids+=($bridge_pid)
wait_bridge_matched bridge.out || { show_logs; echo "FAIL - no reader matched the bridge"; exit 1; }
identity="1,0,0,0,1,0,0,0,1"
"$bin/plumb" topic pub plumb/calibration --transport "$other" --wait 10 calibration_id=turntable-topic \
  tool_id=sim-turntable thermometer=0,1,0,0 temp_min_c=-40 temp_max_c=200 accelerometer.sensitivity=$identity \
  magnetometer.sensitivity=$identity > pub.out 2>&1 || fail "plumb topic pub: $(cat pub.out)"
wait "$raw" && pass "raw data kept flowing (100 batches on $other)" || fail "raw stream: $(tail -2 raw.out)"
rc=0
wait "$bridge_pid" || rc=$?
[ $rc -eq 1 ] && pass "bridge exit 1 after its calibrated stream was stopped" || fail "bridge exit $rc, expected 1"
n=$(grep -cE "calibrated \|G\| = 3[89]\.[0-9]* m/s\^2, expected 9\.81 \+- 20 %: coefficients do not fit this stream's units; calibrated stream stopped" bridge.out)
[ "$n" = 1 ] && pass "one line says the calibrated stream stopped: $(grep -m1 'calibrated |G|' bridge.out)" ||
  fail "expected one |G| line, got $n"
n=$(grep -c "calibration 'turntable-topic' is for tool 'sim-turntable', this bridge is tool 'board': refused" bridge.out)
[ "$n" = 1 ] && pass "coefficients of another tool on plumb/calibration refused in one line" || fail "topic refusal lines: $n"
grep -q "calibration 'volts-v1' (tool 'board', accel units not stated, mag units not stated) from volts_v1.cal applied" bridge.out &&
  pass "the log says which coefficients are applied" || fail "no 'applied' line naming id, tool and file"
grep -qE 'state: "?failed' status.out && pass "status state failed" || fail "no failed state on plumb/status"
grep -q 'coefficients do not fit this stream' status.out && pass "status names the reason" || fail "no reason on plumb/status"
grep -qE "raw_batches=[1-9]" bridge.out && pass "raw batches published" || fail "no raw batches counted"
grep -q "calibrated_batches=" bridge.out && fail "calibrated batches were published" || pass "no calibrated batch published"
grep -qE "calibrated_withheld=[1-9]" bridge.out && pass "withheld samples counted" || fail "calibrated_withheld not counted"
[ $fails -eq 0 ] || show_logs
finish
