#!/usr/bin/env bash
# The shipped launch file as a new user runs it: `plumb launch one-machine.yaml` in an empty folder
# starts the estimator host, the live survey, the display and the simulated drilling run; every
# output line carries its program's name; the run's end stops them all; the survey file holds the
# run's seven stations. VARIANT: cyclonedds or fastdds (PLUMB_TRANSPORT for every program), mixed
# (the file with the estimator host moved to Fast DDS, the rest on Cyclone DDS), or port-taken
# (Cyclone DDS, the display's ports, given as port:=P foxglove_port:=Q, held by another program: the display fails
# alone, the survey still gets its stations, and plumb launch's exit status 1 says what failed).
# usage: launch_chain.sh LAUNCH_FILE BIN_DIR VARIANT DOMAIN
set -uo pipefail
launch_file=$1 bin=$2 variant=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export PATH=$bin:$PATH
cd "$work" || exit 1
if [ "$variant" = mixed ]; then
  export PLUMB_TRANSPORT=cyclonedds
  sed 's/^\(    cmd: plumb-estimator .*\)$/\1\n    env: {PLUMB_TRANSPORT: fastdds}/' "$launch_file" > mixed.yaml
  grep -q "env: {PLUMB_TRANSPORT: fastdds}" mixed.yaml || { fail "mixed.yaml not made"; finish; }
  launch_file=$work/mixed.yaml
elif [ "$variant" = port-taken ]; then
  export PLUMB_TRANSPORT=cyclonedds
  # Both of the display's ports (the page's and Foxglove's): with one of them free it would serve
  # that one alone (the rig-day test has that case).
  python3 -c 'import socket, time
held = [socket.socket() for _ in range(2)]
for s in held: s.bind(("127.0.0.1", 0)); s.listen()
print(*(s.getsockname()[1] for s in held), flush=True); time.sleep(600)' > port.txt &
  holder=$!
  trap 'kill $holder 2>/dev/null; rm -rf "$work"' EXIT
  for ((i = 0; i < 50; ++i)); do [ -s port.txt ] && break; sleep 0.1; done
  read -r port foxglove_port < port.txt
else
  export PLUMB_TRANSPORT=$variant
fi
start=$(date +%s)
timeout 180 plumb launch "$launch_file" ${port:+port:=$port} ${foxglove_port:+foxglove_port:=$foxglove_port} > out.txt 2> err.txt
rc=$?
echo "plumb launch: exit $rc after $(( $(date +%s) - start )) s"
if [ "$variant" = port-taken ]; then
  [ $rc -eq 1 ] && grep -q "^\[launch\] display failed (exit status 1) after 3 restarts: the others go on (not required)" out.txt &&
    grep -q "^\[display\] .*cannot serve on 127.0.0.1:$port" out.txt err.txt &&
    grep -q "^\[launch\] every program ended; failed alone: display failed" out.txt &&
    pass "port $port taken: the display failed alone after its restarts, exit status 1 at the end" ||
    { tail -40 out.txt err.txt; fail "port taken: exit $rc"; }
  for name in estimator survey sim; do
    grep -q "^\[launch\] started $name (pid [0-9]*): plumb" out.txt && pass "$name started" || fail "$name: not started"
  done
  grep -q "^\[launch\] sim ended (on_exit: shutdown): stopping every program" out.txt &&
    pass "the end of the run stopped the others" || fail "no stop after the run: $(grep '^\[launch\]' out.txt)"
  stations=$(grep -cE "^[0-9]+," survey-live.csv 2>/dev/null)
  [ "${stations:-0}" -eq 7 ] && pass "the survey went on without the display: 7 stations" ||
    { grep "^\[survey\]" out.txt err.txt | tail -5; fail "survey-live.csv: ${stations:-no} stations"; }
  finish
  exit 0
fi
[ $rc -eq 0 ] && pass "plumb launch ended by itself with exit status 0" || { tail -40 out.txt err.txt; fail "plumb launch: exit $rc"; }
for name in estimator survey display sim; do
  grep -q "^\[launch\] started $name (pid [0-9]*): plumb" out.txt && grep -q "^\[$name\] " out.txt err.txt &&
    pass "$name started, its lines prefixed [$name]" || fail "$name: no started line or no prefixed output"
done
grep -q "^\[display\] .*serving http://127.0.0.1:8080/" out.txt err.txt && pass "the display served its page" ||
  fail "the display did not say where it serves: $(grep -h '^\[display\]' out.txt err.txt | head -5)"
grep -q "^\[launch\] sim ended (on_exit: shutdown): stopping every program" out.txt &&
  pass "the end of the run stopped the others" || fail "no stop after the run: $(grep '^\[launch\]' out.txt)"
if [ "$variant" = mixed ]; then
  grep -q "^\[estimator\] .*fastdds" out.txt err.txt && grep -q "^\[sim\] .*cyclonedds" out.txt err.txt &&
    pass "estimator on Fast DDS, simulator on Cyclone DDS" || fail "mixed vendors not seen in the logs"
fi
stations=$(grep -cE "^[0-9]+," survey-live.csv 2>/dev/null)
[ "${stations:-0}" -eq 7 ] && pass "survey-live.csv in the launch folder: 7 stations" ||
  { grep "^\[survey\]" out.txt err.txt | tail -5; fail "survey-live.csv: ${stations:-no} stations"; }
finish
