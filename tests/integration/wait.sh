# Waiting on a log line instead of sleeping: discovery takes from milliseconds to many seconds
# depending on the machine's load, and a fixed sleep is either slow or flaky.
# wait_for FILE PATTERN SECONDS: 0 once FILE has a line matching PATTERN (grep -E).
wait_for() {
  local i
  for ((i = 0; i < $3 * 10; ++i)); do grep -qE "$2" "$1" 2>/dev/null && return 0; sleep 0.1; done
  return 1
}
# wait_bridge_matched LOG: a plumb-bridge started with --wait-subscribers has matched a reader and
# reads its line. Start a simulated board only then: a pseudo-terminal nobody reads drops samples
# after a few seconds, as a real board's line would.
wait_bridge_matched() { wait_for "$1" "[1-9][0-9]* sensor topic reader\(s\) matched" 40; }
