# Shared by the bridge integration tests: a work dir, background processes killed on exit,
# and counter checks against the checker's status file.
source "$(dirname "${BASH_SOURCE[0]}")/../wait.sh"
work=$(mktemp -d)
pids=()
# On exit: stop the programs still running (kill fails, harmlessly, for one that already ended).
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; rm -rf "$work"; }
trap cleanup EXIT
fails=0
# expect_counter FILE NAME VALUE
expect_counter() {
  local got
  got=$(grep -E "^$2=" "$1" | head -1 | cut -d= -f2)
  if [ "$got" = "$3" ]; then echo "ok   - $2 = $3"; else echo "FAIL - $2 = '${got}', expected $3"; fails=$((fails + 1)); fi
}
show_logs() { for f in "$work"/*.out; do echo "--- $f"; cat "$f"; done; }
