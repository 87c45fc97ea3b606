#!/bin/bash
# Live calibration checks every station's orientation before recording it, with
# the offline rule and message. The simulated operator puts position 1 (+x up) with the z axis
# pointing down; the procedure refuses it in one line, asks again, and records it once right.
# Usage: calibration_live_orientation.sh BIN_DIR TRANSPORT DOMAIN
set -u
bin=$1 transport=$2 domain=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
export PLUMB_DOMAIN_ID=$domain
rc=0
"$bin/plumb-calibrate" --transport "$transport" --live --simulate-turntable --procedure 6pos --sim-speed 25 \
  --station-seconds 10 --linger 0 --timeout 150 --sim-misplace 1 --tool-id T1 --output live.txt >out.txt 2>err.txt || rc=$?
n=$(grep -c "NOT RECORDED: station 'p+x' (+x): the tool reads as if at -z" out.txt)
[ "$n" = 1 ] && pass "the misplaced station was refused once: $(grep -m1 'NOT RECORDED' out.txt)" ||
  fail "expected one refusal of p+x, got $n: $(cat out.txt err.txt)"
grep -c "recorded p+x" out.txt | grep -qx 1 && pass "p+x recorded once, after it was put right" || fail "p+x not recorded once"
[ $rc -eq 0 ] && pass "procedure completed, exit 0" || fail "exit $rc: $(cat err.txt)"
grep -q '^accel_units V$' live.txt 2>/dev/null && pass "coefficients state the simulated package's units (V)" ||
  fail "no accel_units line in the coefficients"
grep -q '^tool_id T1$' live.txt 2>/dev/null && pass "coefficients bound to tool T1" || fail "no tool_id T1"
finish
