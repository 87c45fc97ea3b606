#!/usr/bin/env bash
# Bad input to the command-line tools: one clear stderr line and a non-zero exit, never a crash
# or a hang. usage: cli_errors.sh BIN_DIR DOMAIN
set -uo pipefail
bin=$1
export PLUMB_DOMAIN_ID=$2
. "$(dirname "$0")/../lib.sh"

for exe in plumb plumb-plot plumb-sim plumb-estimator plumb-bridge plumb-calibrate plumb-survey plumb-wits plumb-wits-send; do
  if [ -x "$bin/$exe" ]; then
    "$bin/$exe" --help > /dev/null 2>&1 && pass "$exe --help" || fail "$exe --help"
  else
    fail "$exe is not built"
  fi
done
for sub in "topic list" "topic echo" "topic hz" "topic pub" transports plugins estimate compare record play info export survey status \
    "component list" "component load" "component unload" "param get" "param set" "param dump" launch; do
  "$bin/plumb" $sub --help > /dev/null 2>&1 && pass "plumb $sub --help" || fail "plumb $sub --help"
done

for t in cyclonedds fastdds; do
  expect_error "unknown topic ($t)" "unknown topic 'no/such/topic'" \
    timeout 30 "$bin/plumb" topic echo no/such/topic --wait 1 --transport $t
  expect_error "malformed pub value ($t)" "inclination_deg.*not a number" \
    timeout 30 "$bin/plumb" topic pub plumb/attitude/x inclination_deg=abc --transport $t
  expect_error "unknown field ($t)" "unknown field 'nosuch'" \
    timeout 30 "$bin/plumb" topic pub plumb/attitude/x nosuch=1 --transport $t
  expect_error "integer out of range ($t)" "samples_used" \
    timeout 30 "$bin/plumb" topic pub plumb/attitude/x samples_used=-1 --transport $t
  expect_error "over-long string ($t)" "tool_id" \
    timeout 30 "$bin/plumb" topic pub plumb/attitude/x tool_id=$(printf 'x%.0s' $(seq 40)) --transport $t
  expect_error "domain out of range ($t)" "domain id 300 is out of range" \
    timeout 30 "$bin/plumb" topic list --domain 300 --wait 0 --transport $t
  expect_error "vendor fails to start: no such interface ($t)" "nosuch0" \
    timeout 30 "$bin/plumb" topic list --interface nosuch0 --wait 0 --transport $t
done
expect_error "unknown transport" "unknown transport 'nosuch'.*cyclonedds.*fastdds|unknown transport 'nosuch'.*fastdds.*cyclonedds" \
  timeout 30 "$bin/plumb" topic list --transport nosuch --wait 0
expect_error "unknown transport from the environment" "unknown transport 'alsonot'" \
  env PLUMB_TRANSPORT=alsonot timeout 30 "$bin/plumb" topic list --wait 0
expect_error "bad domain in the environment" "PLUMB_DOMAIN_ID" \
  env PLUMB_DOMAIN_ID=abc timeout 30 "$bin/plumb" topic list --wait 0
expect_error "unknown estimator plugin" "nosuch.*(static|integral|compensated)" \
  timeout 30 "$bin/plumb-estimator" --plugin nosuch
expect_error "estimator host: a parameter no plugin has" "--param 'windw'" \
  timeout 30 "$bin/plumb-estimator" --plugin static --param windw=3
expect_error "estimate: a parameter no plugin has" "--param 'windw'" \
  timeout 30 "$bin/plumb" estimate --estimator static --input /dev/null --param windw=3
expect_error "estimate: missing input" "cannot open" \
  timeout 30 "$bin/plumb" estimate --estimator compensated --input /nonexistent.csv
nogyro=$(mktemp --suffix=.csv)
printf 't,fx,fy,fz,bx,by,bz\n0,0,0,-9.8,20,0,40\n' > "$nogyro"
expect_error "estimate: a navigator on a file without gyros" "estimator 'strapdown' needs gyros, and .* has no wx, wy, wz columns" \
  timeout 30 "$bin/plumb" estimate --estimator strapdown --input "$nogyro"
expect_error "compare: a navigator on a file without gyros" "estimator 'strapdown' needs gyros" \
  timeout 30 "$bin/plumb" compare --input "$nogyro" -e compensated -e strapdown
rm -f "$nogyro"
expect_error "compare: missing input" "cannot open" \
  timeout 30 "$bin/plumb" compare --input /nonexistent.csv
expect_error "compare: a simulation option with a recorded run" "--seeds describes simulated runs" \
  timeout 30 "$bin/plumb" compare --input /nonexistent.csv --seeds 3
expect_error "compare: a recorded-run option without one" "--window applies to --input" \
  timeout 30 "$bin/plumb" compare --window 3

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf 't,fx,fy,fz,bx,by,bz\n0,0,0,-10,20,0,30\n0.01,0,zz,-10,20,0,30\n' > "$work/bad.csv"
expect_error "estimate: bad number names line and column" "bad.csv:3: column 'fy': bad number 'zz'" \
  timeout 30 "$bin/plumb" estimate --estimator static --input "$work/bad.csv"
printf 't,fx,fy,fz,bx,by\n' > "$work/nocol.csv"
expect_error "estimate: missing column named" "nocol.csv:1: .*bz" \
  timeout 30 "$bin/plumb" estimate --estimator static --input "$work/nocol.csv"
"$bin/plumb" transports > "$work/transports.txt" 2>&1 && grep -q cyclonedds "$work/transports.txt" &&
  grep -q fastdds "$work/transports.txt" && pass "plumb transports lists both vendors" ||
  fail "plumb transports: $(cat "$work/transports.txt")"
"$bin/plumb" plugins > "$work/plugins.txt" 2>&1 && grep -q '^static' "$work/plugins.txt" &&
  grep -q '^integral' "$work/plugins.txt" && grep -q '^compensated' "$work/plugins.txt" &&
  pass "plumb plugins lists the three estimators" || fail "plumb plugins: $(cat "$work/plugins.txt")"
finish
