#!/usr/bin/env bash
# The rig's WITS feed to plumb/depth, with the faults of a real line, over each link at once:
# plumb-wits as a TCP server (the rig connects), as a TCP client (the rig serves, in feet) and on a
# pseudo-terminal (a serial line, the sensor 10 m behind the bit), each fed by plumb-wits-send with
# a line of noise before every 7th frame, frame 11 cut off and the connection dropped after frame 19.
# Checked: every depth of every whole frame reaches plumb/depth in order (read by plumb topic echo
# on the other vendor), nothing lost, nothing added, the moving flag as the depths say; the noise
# and the cut frame counted exactly, on plumb/status and in the log.
# usage: wits_feed.sh BIN_DIR READER_TRANSPORT ECHO_TRANSPORT DOMAIN
set -uo pipefail
bin=$1 reader_t=$2 echo_t=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
export PATH=$bin:$PATH
frames=30
faults=(--count $frames --interval 0.03 --garbage-every 7 --cut-frame 11 --drop-after 19 --stop-every 8 --stop-frames 3)
expected=$((3 * (frames - 1)))

plumb topic echo plumb/depth --csv --count $expected --timeout 60 --transport "$echo_t" > "$work/depth.csv" 2> "$work/echo.err" &
echo_pid=$!; pids+=($echo_pid)
plumb topic echo plumb/status --csv --transport "$echo_t" > "$work/status.csv" 2> /dev/null &
status_pid=$!; pids+=($status_pid)
reader() {  # reader TOOL LINK-OPTIONS...: a plumb-wits that ends after the depths of the whole frames
  local tool=$1; shift
  # --moving-window 0: the feed plays 33 frames a second, its whole run inside one window; MOVING is
  # then the step between two frames, checked below frame by frame (the window: the decoder's tests).
  plumb-wits --transport "$reader_t" --tool-id "$tool" --count $((frames - 1)) --wait-subscribers 30 \
    --reconnect-max 0.2 --moving-window 0 "$@" > "$work/$tool.log" 2>&1 &
  pids+=($!)
  readers+=($!)
}
readers=()
port_a=$(free_port)
port_b=$(free_port)
reader server --listen "127.0.0.1:$port_a"
reader client --connect "127.0.0.1:$port_b" --units ft
reader serial --device "$work/wits-line" --sensor-offset 10
for tool in server client serial; do
  wait_for "$work/$tool.log" "reading WITS level 0" 40 || { cat "$work/$tool.log" "$work/echo.err"; fail "$tool: no reader of plumb/depth"; finish; }
done
# Each reader's status (once a second while it waits) has reached the echo: its last one, published
# as it stops, will too. (Across vendors on a loaded machine, plumb/status matched after a reader
# had already stopped: its only status was lost, seen once in CI.)
for tool in server client serial; do
  wait_for "$work/status.csv" "plumb-wits/$tool" 40 || fail "$tool: no status on plumb/status while waiting"
done
plumb-wits-send --connect "127.0.0.1:$port_a" "${faults[@]}" > "$work/server.sent" 2>&1 &
senders=($!)
plumb-wits-send --listen "$port_b" --units ft --start-depth 3000 "${faults[@]}" > "$work/client.sent" 2>&1 &
senders+=($!)
plumb-wits-send --serial "$work/wits-line" "${faults[@]}" > "$work/serial.sent" 2>&1 &
senders+=($!)
pids+=("${senders[@]}")
for p in "${senders[@]}"; do wait "$p" || fail "plumb-wits-send failed"; done
for p in "${readers[@]}"; do wait "$p" || fail "plumb-wits failed"; done
wait "$echo_pid" || fail "plumb topic echo plumb/depth: $(cat "$work/echo.err")"
sleep 1.5  # the readers' last status, published as they stop, then the status echo ends (Ctrl-C)
kill -INT "$status_pid"; wait "$status_pid"

for tool in server client serial; do
  log=$work/$tool.log
  python3 - "$work/depth.csv" "$work/$tool.sent" "$tool" <<'PY' && pass "$tool: every depth of $((frames - 1)) whole frames, in order" ||
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["tool_id"] == sys.argv[3]]
unit = {"m": 1.0, "ft": 0.3048}
offset = 10.0 if sys.argv[3] == "serial" else 0.0
sent = []
for line in open(sys.argv[2]):
    words = line.split()
    if len(words) >= 6 and words[1] == "frame" and words[-1] == "sent":
        sent.append(float(words[4]) * unit[words[5]] - offset)
got = [float(r["depth_m"]) for r in rows]
print(f"{sys.argv[3]}: {len(sent)} whole frames sent, {len(got)} depths received")
ok = len(got) == len(sent) and all(abs(a - b) < 0.004 for a, b in zip(got, sent))
if not ok:
    print("sent:", sent, "\nreceived:", got)
moving = [int(r["flags"]) & 2 != 0 for r in rows]
expect = [False] + [abs(b - a) > 0.01 for a, b in zip(sent, sent[1:])]
if moving != expect:
    print("moving flags:", moving, "\nexpected:    ", expect)
    ok = False
valid = all(int(r["flags"]) & 1 for r in rows)
sys.exit(0 if ok and valid and any(moving) and not all(moving) else 1)
PY
    fail "$tool: depths on plumb/depth"
  noise=$(sed -nE 's/.* noise lines \(([0-9]+) bytes\).*/\1/p' "$work/$tool.sent")
  # The cut frame leaves its partial last line ("0110" and two digits) before the next "&&": a
  # fifth run of garbage after the four noise lines.
  garbage=$((noise + 6))
  if grep -qE " $garbage garbage bytes in 5 runs, 0 bad lines, 1 cut frames, 0 frames without depth, 0 depths out of range, 0 depth jumps refused, 2 connections" "$log"; then
    pass "$tool: noise and the cut frame counted exactly, the dropped connection reopened: $(tail -1 "$log")"
  else
    fail "$tool: counts (expected $garbage garbage bytes, 1 cut frame, 2 connections): $(cat "$log")"
  fi
  python3 - "$work/status.csv" "plumb-wits/$tool" "$garbage" <<'PY' && pass "$tool: plumb/status carries the counts" ||
import csv, sys
# One row per counter of each status message (docs/operations.md); the last message counts.
rows = [r for r in csv.DictReader(open(sys.argv[1])) if (r.get("component") or r.get("_component")) == sys.argv[2]]
last = rows[-1]["stamp_ns"] if rows else None
counters = {r["counters.name"]: r["counters.value"] for r in rows if r["stamp_ns"] == last}
want = {"garbage_bytes": sys.argv[3], "cut_frames": "1", "depths_published": "29", "reconnects": "1"}
got = {k: counters.get(k) for k in want}
print(f"{sys.argv[2]}: {len(set(r['stamp_ns'] for r in rows))} status messages, the last {rows[-1]['state'] if rows else None}: {got}")
sys.exit(0 if got == want else 1)
PY
    fail "$tool: plumb/status"
done
finish
