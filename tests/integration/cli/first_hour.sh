#!/usr/bin/env bash
# A new user's first hour: the usual mistakes get one line that says what is wrong and
# what to do, usage errors exit 2, nothing waits in silence, interrupted commands report what they
# did, output is for people. usage: first_hour.sh BIN_DIR DOMAIN
set -uo pipefail
bin=$1
export PLUMB_DOMAIN_ID=$2
unset PLUMB_TRANSPORT PLUMB_INTERFACE
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../wait.sh"
work=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  wait 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT

# --- One grammar: usage errors are one line and exit status 2, on every executable.
expect_usage "plumb: unknown option" "plumb: .*--nosuch.*see plumb --help" "$bin/plumb" topic list --nosuch
expect_usage "plumb topic echo: no topic" "topic is required|topic" "$bin/plumb" topic echo
expect_usage "plumb-sim: unknown option" "^plumb-sim: .*--nosuch" "$bin/plumb-sim" --nosuch
expect_usage "plumb-sim: a value out of range" "^plumb-sim: .*batch" "$bin/plumb-sim" --batch 99
expect_usage "plumb-estimator: no plugin" "^plumb-estimator: .*--plugin.*required" "$bin/plumb-estimator"
expect_usage "plumb-bridge: unknown option" "^plumb-bridge: .*--nosuch" "$bin/plumb-bridge" --nosuch
expect_usage "plumb-calibrate: bad procedure" "^plumb-calibrate: .*procedure" "$bin/plumb-calibrate" --procedure 7pos
expect_usage "example subscriber: unknown option" "^plumb-example-subscriber: .*--nosuch" "$bin/plumb-example-subscriber" --nosuch
expect_usage "plumb-plot: unknown plot" "^plumb-plot: .*bogus" "$bin/plumb-plot" bogus
expect_usage "C listener: unknown option" "^plumb-c-attitude-listener: .*--nosuch" "$bin/plumb-c-attitude-listener" --nosuch
expect_usage "C listener: another vendor" "Cyclone DDS only" "$bin/plumb-c-attitude-listener" --transport fastdds
expect_usage "C listener: bad PLUMB_DOMAIN_ID" "PLUMB_DOMAIN_ID" env PLUMB_DOMAIN_ID=abc "$bin/plumb-c-attitude-listener"
# Usage errors found after parsing are usage errors too; a runtime error stays exit status 1.
expect_usage "plumb-sim: --csv and --serial" "^plumb-sim: give --csv or --serial, not both" "$bin/plumb-sim" --csv "$work/x" --serial "$work/y"
expect_usage "plumb-sim --wits faster than real time" "^plumb-sim: --wits plays the rig in real time" "$bin/plumb-sim" --scenario drilling-survey --wits 127.0.0.1:5000 --rate x20
expect_usage "plumb-sim --wits without a rig" "^plumb-sim: --wits needs a drilling run" "$bin/plumb-sim" --wits 127.0.0.1:5000
expect_usage "plumb-sim --wits to no port" "^plumb-sim: --wits: port '99999' is not a number" "$bin/plumb-sim" --scenario drilling --wits 127.0.0.1:99999
expect_usage "plumb-bridge: neither --device nor --replay" "^plumb-bridge: give either --device" "$bin/plumb-bridge"
expect_usage "plumb topic pub: not FIELD=VALUE" "is not FIELD=VALUE" "$bin/plumb" topic pub plumb/attitude/x novalue --wait 0
expect_usage "plumb-wits: no feed named" "^plumb-wits: say where the feed comes from" "$bin/plumb-wits"
expect_usage "plumb-wits: a bad item code" "^plumb-wits: --bit-item: expected a WITS item code" "$bin/plumb-wits" --listen 5000 --bit-item 1x08
expect_usage "plumb-wits-send: nowhere to send" "^plumb-wits-send: say where to send" "$bin/plumb-wits-send"
expect_usage "plumb launch: a missing file" "^plumb launch: cannot read launch file '$work/none.yaml'" "$bin/plumb" launch "$work/none.yaml"
rc=0
"$bin/plumb" estimate --estimator static --input "$work/missing.csv" 2> /dev/null || rc=$?
[ $rc -eq 1 ] && pass "a missing input file is a runtime error (exit 1)" || fail "missing input: exit $rc"
for exe in "plumb topic echo" plumb-sim plumb-estimator plumb-bridge plumb-calibrate; do
  output_matches "--param\|--transport" $bin/$exe --help && pass "$exe --help lists its options" || fail "$exe --help"
done
grammar="--param.*\[PLUGIN.\]KEY=VALUE"
output_matches "$grammar" "$bin/plumb" estimate --help && output_matches "$grammar" "$bin/plumb" compare --help &&
  output_matches "$grammar" "$bin/plumb-estimator" --help &&
  pass "one --param [PLUGIN.]KEY=VALUE on estimate, compare and the host" || fail "--param grammar differs"

# --- --transport works on plumb transports too.
out=$("$bin/plumb" transports --transport fastdds 2>&1) && printf '%s' "$out" | grep -q '^\* fastdds' &&
  pass "plumb transports --transport fastdds marks fastdds" || fail "plumb transports --transport fastdds: $out"
expect_error "plumb transports: unknown vendor" "unknown transport 'nosuch'" "$bin/plumb" transports --transport nosuch

# --- Unknown names answered with the closest known ones.
expect_error "a typo in a fixed topic name" "did you mean plumb/status\?" timeout 30 "$bin/plumb" topic echo plumb/statu --wait 1
rc=0
timeout 60 "$bin/plumb" topic echo plumb/attitude/compensate --timeout 4 > /dev/null 2> "$work/typo.txt" || rc=$?
[ $rc -eq 1 ] && pass "echo --timeout with nothing received exits 1" || fail "echo --timeout with nothing: exit $rc"
grep -q "nothing on plumb/attitude/compensate for 3 s.*did you mean plumb/attitude/compensated?" "$work/typo.txt" &&
  pass "a typo in a plugin's topic: $(head -1 "$work/typo.txt")" || fail "typo in a plugin topic: $(cat "$work/typo.txt")"

# Every listener says what it waits for while nothing comes (nothing is published yet here).
timeout 60 "$bin/plumb-calibrate" --live --procedure 6pos --timeout 5 > /dev/null 2> "$work/cal_silent.txt"
grep -q "plumb-calibrate: nothing on plumb/sensor/raw for 3 s (0 writer(s) matched)" "$work/cal_silent.txt" &&
  pass "plumb-calibrate --live says it hears nothing: $(head -1 "$work/cal_silent.txt")" ||
  fail "plumb-calibrate --live silent: $(cat "$work/cal_silent.txt")"
timeout 60 "$bin/plumb-example-subscriber" --timeout 5 > /dev/null 2> "$work/ex_silent.txt"
grep -q "nothing on plumb/attitude/example for 3 s (0 writer(s) matched" "$work/ex_silent.txt" &&
  pass "the C++ example subscriber says it hears nothing" || fail "example subscriber silent: $(cat "$work/ex_silent.txt")"
timeout 60 "$bin/plumb-c-attitude-listener" --count 1 --timeout 5 plumb/attitude/c > /dev/null 2> "$work/c_silent.txt"
grep -q "nothing on plumb/attitude/c for 3 s (0 writer(s) matched" "$work/c_silent.txt" &&
  pass "the C example listener says it hears nothing" || fail "C listener silent: $(cat "$work/c_silent.txt")"

# --- Data for what follows: a simulated platform publishing plumb/sensor/raw until stopped.
"$bin/plumb-sim" --inclination 1 --azimuth 359.9999 --rpm 60 --loop --wait-subscribers 0 > "$work/sim.txt" 2>&1 &
pids+=($!)

# The estimator host, on its default input (plumb/sensor/calibrated, which nobody publishes here).
"$bin/plumb-estimator" --plugin static > "$work/host.txt" 2>&1 &
host=$!
pids+=($host)
if wait_for "$work/host.txt" "nothing on plumb/sensor/calibrated for 5 s" 60; then
  grep -q "sensor data is published on plumb/sensor/raw (choose it with --input)" "$work/host.txt" &&
    pass "the host's silence names the topic that carries data" || fail "host silence note: $(cat "$work/host.txt")"
else
  fail "the host said nothing about its silence: $(cat "$work/host.txt")"
fi
kill -INT $host
rc=0
wait $host || rc=$?
[ $rc -eq 1 ] && grep -q "no sample received on plumb/sensor/calibrated" "$work/host.txt" &&
  pass "the host stopped having received nothing: exit 1, said why" || fail "host with nothing: exit $rc, $(tail -1 "$work/host.txt")"

# Flags decoded; echo's summary on Ctrl-C.
"$bin/plumb" topic echo plumb/sensor/raw > "$work/echo.txt" 2> "$work/echo_err.txt" &
echo_pid=$!
pids+=($echo_pid)
if wait_for "$work/echo.txt" "^  flags: " 30; then
  grep -qE "^  flags: [0-9]+ \((HAS_GYRO|HAS_TEMPERATURE|none)" "$work/echo.txt" &&
    pass "flags decoded: $(grep -m1 '^  flags' "$work/echo.txt")" || fail "flags not decoded: $(grep -m1 flags "$work/echo.txt")"
else
  fail "echo received nothing from plumb-sim"
fi
kill -INT $echo_pid
rc=0
wait $echo_pid || rc=$?
[ $rc -eq 0 ] && grep -qE "^plumb topic echo: [0-9]+ message\(s\) on 'plumb/sensor/raw', interrupted after" "$work/echo_err.txt" &&
  pass "echo's summary on Ctrl-C: $(cat "$work/echo_err.txt")" || fail "echo on Ctrl-C: exit $rc, $(cat "$work/echo_err.txt")"

# hz: four significant digits, and a summary.
"$bin/plumb" topic hz plumb/sensor/raw --count 2 > "$work/hz.txt" 2> "$work/hz_err.txt" &&
  pass "hz ran" || fail "hz: $(cat "$work/hz_err.txt")"
if grep -q "average rate" "$work/hz.txt"; then
  ! grep -qE "[1-9](\.?[0-9]){4,}" "$work/hz.txt" && pass "hz figures have at most four significant digits: $(grep -m1 average "$work/hz.txt")" ||
    fail "hz prints long figures: $(grep -m1 average "$work/hz.txt")"
else
  fail "hz measured no rate: $(cat "$work/hz.txt")"
fi
grep -qE "^plumb topic hz: [0-9]+ message\(s\) on 'plumb/sensor/raw', .*average" "$work/hz_err.txt" &&
  pass "hz summary: $(cat "$work/hz_err.txt")" || fail "hz summary: $(cat "$work/hz_err.txt")"

# The host with --truth prints each estimate's error; angles in [0, 360).
"$bin/plumb-estimator" --plugin compensated --input plumb/sensor/raw --window 2 --truth --count 2 --timeout 60 > "$work/truth.txt" 2>&1 &&
  pass "host with --truth ran" || fail "host with --truth: $(tail -2 "$work/truth.txt")"
grep -qE "^compensated .*azi [0-9]+\.[0-9]{3} deg.*\| error inc [-+][0-9.]+ deg  azi [-+][0-9.]+ deg" "$work/truth.txt" &&
  pass "estimate with its error: $(grep -m1 '^compensated' "$work/truth.txt")" || fail "no error against the truth: $(cat "$work/truth.txt")"
! grep -qE "azi 360\.000|azi -" "$work/truth.txt" && pass "azimuth near north printed in [0, 360)" || fail "azimuth out of [0, 360): $(grep -m1 azi "$work/truth.txt")"

# A sensor capture replays and estimates offline.
timeout 60 "$bin/plumb" topic echo plumb/sensor/raw --csv --count 30 > "$work/capture.csv" 2> "$work/capture_err.txt" &&
  pass "sensor capture" || fail "sensor capture: $(cat "$work/capture_err.txt")"
head -1 "$work/capture.csv" | grep -qE "(^|,)t,fx,fy,fz,bx,by,bz(,|$)" && pass "capture header: $(head -1 "$work/capture.csv")" ||
  fail "capture header: $(head -1 "$work/capture.csv")"
"$bin/plumb" estimate --estimator compensated --input "$work/capture.csv" --window 0 > "$work/capture_att.csv" 2>&1 &&
  pass "plumb estimate reads the capture" || fail "plumb estimate on the capture: $(tail -2 "$work/capture_att.csv")"
timeout 60 "$bin/plumb-bridge" --replay "$work/capture.csv" --rate max --strict --wait-subscribers 0 > "$work/replay.txt" 2>&1 &&
  pass "plumb-bridge --replay --strict reads the capture" || fail "bridge replay of the capture: $(tail -2 "$work/replay.txt")"

# pub reports what it actually sent.
"$bin/plumb" topic pub plumb/attitude/x inclination_deg=1 --count 100 --rate 5 --wait 0 2> "$work/pub.txt" &
pub=$!
sleep 1  # at 5 messages a second, far fewer than 100 are sent by then, however loaded the machine
kill -INT $pub
wait $pub
grep -qE "published [0-9]+ of 100 message\(s\).*interrupted" "$work/pub.txt" &&
  pass "interrupted pub: $(cat "$work/pub.txt")" || fail "interrupted pub: $(cat "$work/pub.txt")"

# The C example honours PLUMB_DOMAIN_ID like every plumb program (it used domain 0 before).
"$bin/plumb-c-attitude-listener" --count 1 --timeout 30 plumb/attitude/c > "$work/c.txt" 2>&1 &
listener=$!
pids+=($listener)
for i in 1 2 3 4 5 6 7 8 9 10; do
  grep -q "tool=" "$work/c.txt" && break
  "$bin/plumb" topic pub plumb/attitude/c tool_id=C inclination_deg=2 --wait 2 > /dev/null 2>&1
done
rc=0
wait $listener || rc=$?
[ $rc -eq 0 ] && grep -q "tool=C" "$work/c.txt" && pass "the C listener heard domain $PLUMB_DOMAIN_ID from the environment" ||
  fail "C listener on \$PLUMB_DOMAIN_ID: exit $rc, $(cat "$work/c.txt")"

# plumb-sim --serial with nobody reading: honours --duration, counts what it drops.
rc=0
timeout 120 "$bin/plumb-sim" --serial "$work/board" --duration 8 > "$work/serial.txt" 2>&1 || rc=$?
[ $rc -eq 0 ] && grep -qE "[1-9][0-9]* dropped \(no reader\)" "$work/serial.txt" &&
  pass "plumb-sim --serial with no reader ended: $(tail -1 "$work/serial.txt")" || fail "plumb-sim --serial alone: exit $rc, $(cat "$work/serial.txt")"

# A missing serial device: retries reported with their count, at a growing interval.
rc=0
timeout 60 "$bin/plumb-bridge" --device "$work/nodevice" --backoff-min 0.01 --backoff-max 0.05 --duration 6 > "$work/retry.txt" 2>&1 || rc=$?
[ $rc -eq 1 ] && grep -q "no sample read from serial $work/nodevice" "$work/retry.txt" &&
  pass "a bridge that read nothing exits 1: $(tail -1 "$work/retry.txt")" || fail "bridge with no device: exit $rc, $(tail -1 "$work/retry.txt")"
grep -q "no sample from serial $work/nodevice .* for 5 s (not open)" "$work/retry.txt" &&
  pass "the bridge's silence is said" || fail "bridge silence: $(cat "$work/retry.txt")"
grep -q "(attempt 1)" "$work/retry.txt" && grep -q "(attempt 2)" "$work/retry.txt" && grep -q "(attempt 16)" "$work/retry.txt" &&
  ! grep -q "(attempt 3)" "$work/retry.txt" && pass "retries reported at 1, 2, 4, 8, 16...: $(grep -c attempt "$work/retry.txt") lines" ||
  fail "retry reports: $(cat "$work/retry.txt")"
finish
