# Assertion helpers shared by the integration test scripts.
fails=0
pass() { echo "ok   - $*"; }
fail() { echo "FAIL - $*"; fails=$((fails + 1)); }
# The EXIT trap of a test that starts programs in the background (their pids in the array `pids`) and
# works in the folder `$work`: stops what still runs, removes the folder. kill fails for a program
# that has already ended, as it should; that failure is ignored because it says nothing about the test.
# The test ends only once they have: a program's ports are its own until it exits (plumb-display's
# web server takes 2 s to let go of its page's port), and the next test may need them.
stop_programs_and_remove_work() {
  local p deadline=$((SECONDS + 10))
  # (|| true: a program that has already ended cannot be signalled, which is no failure of the test.)
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do
    while kill -0 "$p" 2>/dev/null && [ $SECONDS -lt $deadline ]; do sleep 0.1; done
    kill -KILL "$p" 2>/dev/null || true  # (the same: most have ended by now)
  done
  rm -rf "$work"
}
# A test that starts programs: the scratch folder `$work`, the empty array `pids`, and that EXIT trap.
# The estimator host's record for its next instance (docs/operations.md) goes into `$work` too:
# a test's host never reads what another test's host left.
start_work_with_programs() {
  work=$(mktemp -d); pids=(); trap stop_programs_and_remove_work EXIT
  export PLUMB_STATE_DIR="$work/state"
}
# output_matches "pattern" command...: the command's output (stdout and stderr) matches. The output
# is captured first: `cmd | grep -q` under pipefail fails at random, because grep quits at the first
# match and a long writer (any --help) then dies of SIGPIPE.
output_matches() {
  local pattern=$1 out; shift
  out=$("$@" 2>&1)
  grep -q -- "$pattern" <<< "$out"
}
# expect_error "description" "stderr pattern" command...: non-zero exit, one stderr line matching.
expect_error() {
  local what=$1 pattern=$2; shift 2
  local err rc=0
  err=$("$@" 2>&1 >/dev/null) || rc=$?
  if [ $rc -eq 0 ]; then fail "$what: exit 0 (expected an error)"; return; fi
  if [ $rc -gt 128 ]; then fail "$what: killed by signal $((rc - 128))"; return; fi
  if [ "$(printf '%s\n' "$err" | grep -c .)" -ne 1 ]; then fail "$what: expected one stderr line, got: $err"; return; fi
  if ! printf '%s' "$err" | grep -qE -- "$pattern"; then fail "$what: stderr '$err' lacks /$pattern/"; return; fi
  pass "$what: $err"
}
# expect_failure "description" "pattern" command...: non-zero exit, no crash, and the last stderr
# line matching (for tools that may warn before they fail).
expect_failure() {
  local what=$1 pattern=$2; shift 2
  local err rc=0
  err=$("$@" 2>&1 >/dev/null) || rc=$?
  if [ $rc -eq 0 ]; then fail "$what: exit 0 (expected an error)"; return; fi
  if [ $rc -gt 128 ]; then fail "$what: killed by signal $((rc - 128))"; return; fi
  if ! printf '%s' "$err" | grep -qE -- "$pattern"; then fail "$what: stderr '$err' lacks /$pattern/"; return; fi
  pass "$what: $(printf '%s' "$err" | tail -1)"
}
# A TCP port on loopback free now (the test's own listeners take it next).
free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
finish() { if [ $fails -ne 0 ]; then echo "$fails check(s) failed"; exit 1; fi; echo "all checks passed"; }

# expect_usage "description" "stderr pattern" command...: exit status 2 and one stderr line.
expect_usage() {
  local what=$1 pattern=$2; shift 2
  local err rc=0
  err=$("$@" 2>&1 >/dev/null) || rc=$?
  if [ $rc -ne 2 ]; then fail "$what: exit $rc (expected 2, a usage error): $err"; return; fi
  if [ "$(printf '%s\n' "$err" | grep -c .)" -ne 1 ]; then fail "$what: expected one stderr line, got: $err"; return; fi
  if ! printf '%s' "$err" | grep -qE -- "$pattern"; then fail "$what: stderr '$err' lacks /$pattern/"; return; fi
  pass "$what: $err"
}
