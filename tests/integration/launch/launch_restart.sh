#!/usr/bin/env bash
# plumb launch's policies, on plumb-wits-send (no DDS: waits for a reader for ever, or fails at
# once on a bad option). A required program with restart: on-failure is killed with SIGKILL and
# comes back as a new process, each time, until its limit; then it has failed for good: plumb
# launch stops the others and exits 1. A program that is not required fails alone: the others go
# on, and plumb launch exits 1 when they end. A usage error (exit 2) is never restarted. SIGINT
# (Ctrl-C) and SIGTERM stop every program: exit 0, no process left. Launch arguments (NAME:=VALUE)
# reach the command lines; errors name the line that is wrong.
# usage: launch_restart.sh BIN_DIR
set -uo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
export PATH=$bin:$PATH
pid_of() { sed -nE "s/^\[launch\] started $1 \(pid ([0-9]+)\).*/\1/p" "$2" | tail -1; }
alive() { kill -0 "$1" 2>/dev/null; }

cat > "$work/restart.yaml" <<YAML
launch:
  - name: rig
    cmd: plumb-wits-send --listen $(free_port)
    required: true
    restart: on-failure
    restart_limit: 2
    restart_delay: 0.2
  - name: other
    cmd: [plumb-wits-send, --listen, "$(free_port)"]
YAML
plumb launch "$work/restart.yaml" > "$work/out.txt" 2>&1 &
launch=$!; pids+=($launch)
wait_for "$work/out.txt" "^\[rig\] plumb-wits-send: waiting for a WITS reader" 10 &&
  wait_for "$work/out.txt" "^\[other\] plumb-wits-send: waiting for a WITS reader" 10 &&
  pass "both started, each line prefixed with its name" || { cat "$work/out.txt"; fail "no prefixed output"; finish; }
first=$(pid_of rig "$work/out.txt")
other=$(pid_of other "$work/out.txt")
for n in 1 2; do
  before=$(pid_of rig "$work/out.txt")
  kill -9 "$before"
  if wait_for "$work/out.txt" "^\[launch\] rig failed \(killed by SIGKILL\); restart $n of 2" 5 &&
     wait_for "$work/out.txt" "^\[launch\] started rig \(pid [0-9]+\)" 5 && sleep 0.5 &&
     now=$(pid_of rig "$work/out.txt") && [ "$now" != "$before" ] && alive "$now"; then
    pass "kill -9 of rig: restarted as pid $now (restart $n of 2)"
  else
    cat "$work/out.txt"; fail "kill -9 of rig ($n): no restart"
  fi
done
alive "$other" && pass "the other program kept running" || fail "the other program is gone"
kill -9 "$(pid_of rig "$work/out.txt")"
wait "$launch"; rc=$?
[ $rc -eq 1 ] && grep -q "^\[launch\] rig failed (killed by SIGKILL) after 2 restarts (required): stopping the others" "$work/out.txt" &&
  pass "the third kill: failed for good, exit status 1" || { cat "$work/out.txt"; fail "after the limit: exit $rc"; }
! alive "$other" && ! alive "$first" && grep -q "^\[launch\] other ended" "$work/out.txt" &&
  pass "the others were stopped" || fail "a program outlived plumb launch"

# A usage error (exit 2), restart: on-failure all the same: not restarted, and, not required, it
# fails alone: the other program goes on until Ctrl-C, then exit status 1 says what failed.
printf 'launch:\n  - cmd: plumb-wits-send --listen %s\n  - name: bad\n    restart: on-failure\n    cmd: plumb-wits-send --bogus\n' \
  "$(free_port)" > "$work/alone.yaml"
plumb launch "$work/alone.yaml" > "$work/alone.txt" 2>&1 &
launch=$!; pids+=($launch)
if wait_for "$work/alone.txt" "^\[launch\] bad failed \(exit status 2: a usage error, not restarted; its command is at .*alone\.yaml:5\): the others go on \(not required\)" 10 &&
   sleep 1 && alive "$(pid_of plumb-wits-send "$work/alone.txt")" && [ "$(grep -c "started bad" "$work/alone.txt")" -eq 1 ]; then
  pass "a usage error: not restarted, failed alone, the other still runs"
else
  cat "$work/alone.txt"; fail "a usage error in a program that is not required"
fi
kill -INT "$launch"
wait "$launch"; rc=$?
[ $rc -eq 1 ] && grep -q "^\[launch\] every program ended; failed alone: bad failed (exit status 2" "$work/alone.txt" &&
  pass "after Ctrl-C: exit status 1, the failure said again" || { cat "$work/alone.txt"; fail "failed alone: exit $rc"; }

# Launch arguments: declared with a default, given as NAME:=VALUE.
port=$(free_port)
printf 'arguments:\n  port: "1"\nlaunch:\n  - cmd: plumb-wits-send --listen $(var port)\n' > "$work/args.yaml"
plumb launch "$work/args.yaml" port:=$port > "$work/args.txt" 2>&1 &
launch=$!; pids+=($launch)
wait_for "$work/args.txt" "started plumb-wits-send \(pid [0-9]+\): plumb-wits-send --listen $port\$" 10 &&
  pass "port:=$port reaches the command line" || { cat "$work/args.txt"; fail "launch argument"; }
kill -INT "$launch"; wait "$launch"
expect_usage "an argument the file does not declare" "launch argument 'prot' is not declared in .*args\.yaml \(declared: port\)" \
  plumb launch "$work/args.yaml" prot:=1
expect_usage "an argument without :=" "'port=1': a launch argument is NAME:=VALUE" plumb launch "$work/args.yaml" port=1
printf 'launch:\n  - cmd: plumb-wits-send --listen $(var prot)\n' > "$work/undeclared.yaml"
expect_usage "a \$(var NAME) not declared" "undeclared\.yaml:2: .*var prot.: no launch argument 'prot'" plumb launch "$work/undeclared.yaml"

# Ctrl-C and SIGTERM stop everything, exit status 0.
for sig in INT TERM; do
  plumb launch "$work/restart.yaml" > "$work/stop.txt" 2>&1 &
  launch=$!; pids+=($launch)
  wait_for "$work/stop.txt" "^\[other\] plumb-wits-send: waiting" 10 || { cat "$work/stop.txt"; fail "SIG$sig: no start"; continue; }
  children="$(pid_of rig "$work/stop.txt") $(pid_of other "$work/stop.txt")"
  kill -s "$sig" "$launch"
  wait "$launch"; rc=$?
  left=""
  for c in $children; do alive "$c" && left="$left $c"; done
  [ $rc -eq 0 ] && [ -z "$left" ] && pass "SIG$sig: every program stopped, exit status 0" ||
    { cat "$work/stop.txt"; fail "SIG$sig: exit $rc, still running:$left"; }
done

sed 's/restart_delay/restrat/' "$work/restart.yaml" > "$work/typo.yaml"
expect_usage "a launch file with an unknown key" "typo\.yaml:7: unknown key 'restrat'" plumb launch "$work/typo.yaml"
printf 'launch:\n  - name: nothing\n    restart: never\n    cmd: plumb-nothing --x\n' > "$work/missing.yaml"
expect_usage "a program that does not exist, at its cmd line" "missing\.yaml:4: program 'plumb-nothing' not found" plumb launch "$work/missing.yaml"
finish
