#!/usr/bin/env bash
# plumb-display under load and bad input, on one vendor: 20 WebSocket clients at once, 4 of them
# stalled (ws_clients.py says what is checked), estimates published at 100/s; a port that is
# taken, an address that is not this computer's, --help, an unknown path.
# usage: display_load.sh BIN_DIR TRANSPORT DOMAIN
set -uo pipefail
bin=$1 t=$2
export PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs

output_matches "0.0.0.0 exposes the page" "$bin/plumb-display" --help && pass "--help says what --bind 0.0.0.0 does" ||
  fail "--help lacks the --bind warning"

"$bin/plumb-display" --transport "$t" --port 0 --foxglove-port 0 > "$work/display.log" 2>&1 &
display=$!
pids+=($display)
wait_for "$work/display.log" "serving http://127.0.0.1:[0-9]+/" 20 || { cat "$work/display.log"; fail "plumb-display did not start"; finish; }
port=$(sed -nE 's|.*serving http://127\.0\.0\.1:([0-9]+)/.*|\1|p' "$work/display.log" | head -1)

expect_error "a second display on the same port" "plumb-display: cannot serve on 127\.0\.0\.1:$port: Address already in use .*choose another --port" \
  "$bin/plumb-display" --transport "$t" --port "$port" --no-foxglove
# With Foxglove to serve, the page's port taken costs the page only: the display says so, serves
# Foxglove, and runs (degraded) until its --duration.
rc=0
"$bin/plumb-display" --transport "$t" --port "$port" --foxglove-port 0 --duration 2 > "$work/half.out" 2> "$work/half.err" || rc=$?
[ $rc -eq 0 ] && grep -qE "^plumb-display: cannot serve on 127\.0\.0\.1:$port: Address already in use .*; serving the rest$" "$work/half.err" &&
  grep -qE "^plumb-display: the page is not served .*; Foxglove on ws://127\.0\.0\.1:[0-9]+/" "$work/half.out" &&
  pass "the page's port taken: Foxglove served alone, said on stderr and stdout" ||
  fail "the page's port taken, Foxglove free: exit $rc, $(cat "$work/half.err" "$work/half.out")"
expect_error "an address that is not this computer's" "plumb-display: cannot serve on 192\.0\.2\.1:0: .*not an address of this computer" \
  "$bin/plumb-display" --transport "$t" --port 0 --foxglove-port 0 --bind 192.0.2.1
expect_error "a --bind that is no address" "plumb-display: cannot serve on rig-floor:0: 'rig-floor' is not an IPv4 address" \
  "$bin/plumb-display" --transport "$t" --port 0 --foxglove-port 0 --bind rig-floor
expect_error "a port out of range" "plumb-display: --port.*(see plumb-display --help)" "$bin/plumb-display" --port 70000
code=$(python3 -c "import urllib.request, urllib.error
try: urllib.request.urlopen('http://127.0.0.1:$port/nosuch.html')
except urllib.error.HTTPError as e: print(e.code)")
[ "$code" = 404 ] && pass "an unknown path is 404" || fail "unknown path gave '$code'"
output_matches "plumb live" python3 -c "import urllib.request; print(urllib.request.urlopen('http://127.0.0.1:$port/').read().decode())" &&
  pass "the page is served at /" || fail "no page at /"

rate=300
"$bin/plumb" topic pub plumb/attitude/load tool_id=rig9 estimator=load inclination_deg=1.5 azimuth_deg=33 flags=7 \
  --transport "$t" --rate $rate --count 6000 > "$work/pub.log" 2>&1 &
pids+=($!)
# Ready when the display takes the new topic's estimates (it discovers topics twice a second).
taken() { python3 -c "import json, urllib.request; print(json.load(urllib.request.urlopen('http://127.0.0.1:$port/stats.json'))['attitudes'])"; }
for ((i = 0; i < 150; ++i)); do [ "$(taken 2>/dev/null || echo 0)" -gt 0 ] && break; sleep 0.1; done
[ "$(taken)" -gt 0 ] && pass "the display takes the published estimates" || fail "no estimate reached the display in 15 s"
python3 "$here/ws_clients.py" "127.0.0.1:$port" "$display" --clients 20 --slow 4 --seconds 8 --publish-rate $rate &&
  pass "20 browsers at once" || fail "20 browsers at once"
kill -0 "$display" 2>/dev/null && pass "plumb-display still running" || fail "plumb-display died"

# --max-browsers: one more is refused (its page retries), and gets in once a browser leaves.
"$bin/plumb-display" --transport "$t" --port 0 --foxglove-port 0 --max-browsers 2 > "$work/small.log" 2>&1 &
pids+=($!)
wait_for "$work/small.log" "serving http://127.0.0.1:[0-9]+/" 20 || fail "second plumb-display did not start"
small=$(sed -nE 's|.*serving http://127\.0\.0\.1:([0-9]+)/.*|\1|p' "$work/small.log" | head -1)
PYTHONPATH=$here python3 - "$small" > "$work/small.out" 2>&1 <<'EOF_PY'
import sys
from wsclient import WebSocket, Closed
url = f"ws://127.0.0.1:{sys.argv[1]}/ws"
two = [WebSocket(url) for _ in range(2)]
for ws in two:
    ws.recv()
try:
    WebSocket(url, timeout=5).recv()
    print("third browser served")
except (Closed, OSError):
    print("third browser refused")
two[0].close()
import time
for _ in range(50):
    try:
        WebSocket(url, timeout=5).recv()
        print("served after one left")
        break
    except (Closed, OSError):
        time.sleep(0.1)
EOF_PY
output_matches "third browser refused" cat "$work/small.out" && output_matches "served after one left" cat "$work/small.out" &&
  pass "--max-browsers 2: a third is refused, then served once one leaves" || fail "--max-browsers: $(cat "$work/small.out")"
finish
