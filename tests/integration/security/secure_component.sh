#!/usr/bin/env bash
# plumb component / plumb param on a secured domain (loopback): the plumb-operator
# identity loads and tunes a secured estimator host's plugins; the plumb-monitor identity may not
# send a request (one line saying so, nothing applied), but reads the parameters the host writes;
# the plumb-survey identity reads the navigator's (its gyro error model) without asking; an
# unsecured plumb reaches no host.
# The host on VENDOR, the commands on CLI_VENDOR (default: the same).
# usage: secure_component.sh BIN_DIR VENDOR DOMAIN [CLI_VENDOR]
set -uo pipefail
bin=$1
export PLUMB_TRANSPORT=$2 PLUMB_DOMAIN_ID=$3
cli_t=${4:-$2}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
start_work_with_programs
ks=$work/keystore
"$bin/plumb" security create-keystore "$ks" --domains "$3-$3" > /dev/null || fail "create-keystore"
for n in plumb-estimator plumb-operator plumb-monitor plumb-survey; do
  "$bin/plumb" security create-identity "$ks" $n > /dev/null || fail "create-identity $n"
done
id() { echo "$ks/enclaves/$1"; }
"$bin/plumb-estimator" --transport "$2" --security "$(id plumb-estimator)" --name secured --plugin static --quiet > "$work/host.out" 2>&1 &
pids+=($!)

out=$(env PLUMB_TRANSPORT="$cli_t" "$bin/plumb" component load secured integral --security "$(id plumb-operator)" --wait 15 2>&1) &&
  pass "operator: $out" || fail "operator's load: $out"
out=$(env PLUMB_TRANSPORT="$cli_t" "$bin/plumb" param set secured integral window 4 --security "$(id plumb-operator)" --wait 15 2>&1) &&
  pass "operator: $out" || fail "operator's param set: $out"
expect_failure "the monitor identity may not send requests" "plumb: .*this identity may not send requests" \
  env PLUMB_TRANSPORT="$cli_t" "$bin/plumb" component unload secured integral --security "$(id plumb-monitor)" --wait 3
expect_failure "an unsecured plumb reaches no secured host" "no estimator host named 'secured' answered" \
  env PLUMB_TRANSPORT="$cli_t" "$bin/plumb" component unload secured integral --wait 3
out=$(env PLUMB_TRANSPORT="$cli_t" "$bin/plumb" component list secured --security "$(id plumb-operator)" --wait 15 2>&1)
grep -q "integral" <<< "$out" && pass "integral still loaded: neither refused request was applied" ||
  fail "component list: $out"
requests=3
# Across vendors only some pairs of identities authenticate (the handshake's roles follow their
# subjects: docs/security.md, "Across vendors"); the operator's and the host's do, the monitor's and
# the survey's do not.
if [ "$cli_t" = "$2" ]; then
  out=$(env PLUMB_TRANSPORT="$cli_t" "$bin/plumb" topic echo plumb/component/parameters/secured/integral --count 1 --timeout 15 \
    --security "$(id plumb-monitor)" 2>&1)
  grep -A1 'name: "window"' <<< "$out" | grep -q 'value: "4"' && pass "the monitor reads the host's parameters (integral window 4)" ||
    fail "monitor's read of the parameters: $(head -12 <<< "$out")"
  out=$(env PLUMB_TRANSPORT="$cli_t" "$bin/plumb" component load secured strapdown --security "$(id plumb-operator)" --wait 15 2>&1) &&
    pass "operator: $out" || fail "operator's load of strapdown: $out"
  env PLUMB_TRANSPORT="$cli_t" "$bin/plumb-survey" --security "$(id plumb-survey)" --tool-id secured --plugin strapdown \
    --gravity 9.80665 --total-field 50 --dip 60 --depth-clock-offset 0 --file "$work/survey.csv" --estimator-host secured \
    --estimator-wait 15 --timeout 1 > /dev/null 2> "$work/survey.err"
  grep -q "error model: the strapdown navigator's parameters from estimator host 'secured' (" "$work/survey.err" &&
    grep -q "error model GYRO:navigator" "$work/survey.err" &&
    pass "plumb-survey's identity reads the navigator's parameters: its gyro model" ||
    fail "secured plumb-survey: $(cat "$work/survey.err")"
  requests=4
fi
n=$(grep -c "(from " "$work/host.out")
[ "$n" -eq $requests ] && pass "the host answered the operator's $requests requests only" || fail "host log: $(cat "$work/host.out")"
finish
