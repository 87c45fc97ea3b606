#!/usr/bin/env bash
# The README's walkthroughs as written: every ```sh block (but the top two commands) runs in order
# in one shell, from a scratch folder that sees the build as build/, on loopback. A command that
# fails, a block that hangs, or a background program the README leaves running fails the test, so a
# change that breaks the README breaks this test. usage: readme_walkthrough.sh SOURCE_DIR BUILD_DIR DOMAIN
set -uo pipefail
src=$1
build=$2
export PLUMB_DOMAIN_ID=$3
unset PLUMB_TRANSPORT PLUMB_INTERFACE  # the README's defaults
. "$(dirname "$0")/../lib.sh"

work=$(mktemp -d)
session=""
cleanup() {
  # Only what the README left behind (its own session), and only if it did.
  [ -n "$session" ] && pkill -KILL -s "$session" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
ln -s "$build" "$work/build"

if python3 "$(dirname "$0")/readme_blocks.py" "$src/README.md" "$work/walkthrough.sh"; then
  pass "README starts with its two commands; runnable blocks extracted"
else
  fail "README blocks"
  finish
fi

# Its own session, so that whatever the README starts in the background can be found afterwards.
# Its output goes through a FIFO to a reader that keeps each line's arrival time (the silence rule).
rules="$(dirname "$0")/walk_rules.py"
mkfifo "$work/out"
python3 -u "$rules" stamp "$work/log.txt" "$work/stamps.txt" < "$work/out" &
stamper=$!
start=$(date +%s)
(cd "$work" && exec setsid timeout 600 bash -euo pipefail -x walkthrough.sh) > "$work/out" 2>&1 &
runner=$!
session=$runner
wait $runner
rc=$?
echo "walkthrough: exit $rc after $(( $(date +%s) - start )) s"
if [ $rc -eq 0 ]; then
  pass "every README command ran and succeeded, in order"
else
  fail "README walkthrough stopped with exit $rc; the end of its log:"
  tail -40 "$work/log.txt"
fi
left=$(pgrep -s "$session" -a 2>/dev/null)
[ -z "$left" ] && pass "nothing left running after the README" || fail "the README left programs running: $left"
pkill -KILL -s "$session" 2>/dev/null  # they hold the FIFO open
wait $stamper

# The rules a new user meets on every step: nothing waits in silence, nothing ends with an empty result.
if python3 "$rules" silence "$work/stamps.txt" 6; then
  pass "no step waited longer than 6 s without a line of output"
else
  fail "a step waited in silence (above)"
fi
if python3 "$rules" results "$work"; then
  pass "every file the README's steps wrote has content"
else
  fail "a step ended with an empty result (above)"
fi

# What the blocks promise, checked on what they produced.
[ "$(grep -c '^inclination_deg' "$work/compensated.txt" 2>/dev/null)" = 2 ] &&
  pass "echo got two compensated estimates" || fail "compensated.txt: $(head -c 300 "$work/compensated.txt" 2>/dev/null)"
grep -qE '^compensated .*\| error inc' "$work/log.txt" &&
  pass "the estimator printed estimates with their error against the truth" ||
  fail "no estimate line with its error against the truth"
grep -qE '^static .*INVALID: ' "$work/log.txt" &&
  pass "the static plugin printed its reason instead of angles" || fail "no INVALID line with a reason"
[ "$(wc -l < "$work/att.csv" 2>/dev/null)" -ge 3 ] && pass "plumb estimate wrote att.csv" || fail "att.csv missing or empty"
ls "$work"/plots/*.png > /dev/null 2>&1 && pass "plumb compare drew plots" || fail "no plots/*.png"
head -1 "$work/capture.csv" 2>/dev/null | grep -qE '(^|,)t,fx,fy,fz,bx,by,bz(,|$)' &&
  pass "a sensor capture is a sensor CSV: $(head -1 "$work/capture.csv")" || fail "capture.csv header: $(head -1 "$work/capture.csv" 2>/dev/null)"
[ -s "$work/coeffs.txt" ] && pass "calibration wrote coeffs.txt before the bridge read it" || fail "no coeffs.txt"
grep -q '^\[launch\] sim ended (on_exit: shutdown)' "$work/log.txt" && grep -q '^\[survey\] ' "$work/log.txt" &&
  grep -q '^\[display\] .*serving http://127.0.0.1:8080/' "$work/log.txt" &&
  pass "plumb launch ran the one-machine chain, each line prefixed, the run's end stopping it" ||
  fail "plumb launch: no prefixed chain in the log"
[ -s "$work/nav-file.csv" ] && pass "plumb estimate with a parameters file wrote nav-file.csv" || fail "no nav-file.csv"
grep -qE '^compensated .*inc ' "$work/log.txt" && grep -q 'plumb-estimator: .*compensated: 1 estimates' "$work/log.txt" &&
  pass "an estimate from the bridge's calibrated topic" || fail "no estimate from plumb/sensor/calibrated"
[ -e "$work/board" ] && fail "plumb-sim left its pseudo-terminal link ./board" || pass "./board removed at the end"
finish
