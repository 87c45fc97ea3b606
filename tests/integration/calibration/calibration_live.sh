#!/bin/bash
# Live calibration over DDS with the simulated turntable on one vendor; a late joiner on another
# (or the same) vendor receives the coefficients from plumb/calibration after the procedure ended.
# Usage: calibration_live.sh BIN_DIR CALIBRATE_TRANSPORT ECHO_TRANSPORT DOMAIN
set -u
bin=$1 tcal=$2 techo=$3 domain=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
work=$(mktemp -d)
pid=
trap '[ -n "$pid" ] && kill $pid 2>/dev/null; rm -rf "$work"' EXIT
cd "$work"
export PLUMB_DOMAIN_ID=$domain
"$bin/plumb-calibrate" --transport "$tcal" --live --simulate-turntable --procedure 6pos --sim-speed 25 \
  --station-seconds 10 --linger 8 --timeout 120 --calibration-id live-test-$domain --output live.txt \
  --report report.txt >out.txt 2>err.txt &
pid=$!
for _ in $(seq 1 600); do
  grep -q '^published coefficients' out.txt && break
  kill -0 $pid 2>/dev/null || break
  sleep 0.2
done
if grep -q '^published coefficients' out.txt; then
  pass "live procedure ran through the six positions ($(grep -c '^\[' out.txt) prompts)"
else
  fail "live procedure did not publish: $(tail -3 out.txt) $(cat err.txt)"
fi
grep -q '^format plumb-calibration 1' live.txt 2>/dev/null && pass "coefficients file written" || fail "no coefficients file"
# The late joiner: started after the publication.
if echo_out=$("$bin/plumb" topic echo plumb/calibration --transport "$techo" --count 1 --timeout 15 2>&1); then
  if printf '%s' "$echo_out" | grep -q "live-test-$domain"; then pass "late joiner on $techo got the coefficients"
  else fail "late joiner got something else: $echo_out"; fi
else
  fail "late joiner on $techo got nothing: $echo_out"
fi
wait $pid
rc=$?
pid=
[ $rc -eq 0 ] && pass "plumb-calibrate exit 0" || fail "plumb-calibrate exit $rc: $(cat err.txt)"
finish
