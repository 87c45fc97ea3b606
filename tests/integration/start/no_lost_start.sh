#!/usr/bin/env bash
# No lost start: a reader started FIRST gets the whole of a fast replay and the
# first depth of a rig's feed, with the publishers' default bounded wait for a reader. Before it, a
# replay at --rate max published before discovery had matched the echo (nothing, or sample 256 of
# 500 on), and plumb-wits lost the first depths of a feed that was already sending.
#   bridge: plumb topic echo plumb/sensor/raw, then plumb-bridge --replay (500 samples, --rate max):
#           the echo gets seq 0..499, each once, in order.
#   wits:   plumb topic echo plumb/depth, then plumb-wits-send --listen (the rig already sending
#           when plumb-wits connects), then plumb-wits --connect: the echo gets every frame's depth,
#           the first one first.
# usage: no_lost_start.sh BIN_DIR WHAT(bridge|wits) PUBLISHER_TRANSPORT ECHO_TRANSPORT DOMAIN [EXTRA PUBLISHER OPTION...]
set -uo pipefail
bin=$1 what=$2 pub_t=$3 echo_t=$4
export PLUMB_DOMAIN_ID=$5
shift 5
extra=("$@")  # e.g. --wait-subscribers 0: the test must then fail (checked by hand)
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
export PATH=$bin:$PATH

if [ "$what" = bridge ]; then
  n=500
  python3 - "$work/sensor.csv" $n <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("seq,t,fx,fy,fz,bx,by,bz\n")
    for i in range(int(sys.argv[2])):
        f.write(f"{i},{i * 0.001:.3f},0.1,0.2,-9.8,20,1,40\n")
PY
  # Reliable on both sides: this checks what discovery loses, not what a best-effort link may drop.
  plumb topic echo plumb/sensor/raw --csv --reliable --timeout 40 --transport "$echo_t" > "$work/echo.csv" 2> "$work/echo.err" &
  echo_pid=$!; pids+=($echo_pid)
  # The echo's reader exists before the replay starts (the echo prints nothing until data; its start
  # takes well under this, and a slower one only makes the replay's wait matter more).
  sleep 2
  plumb-bridge --replay "$work/sensor.csv" --rate max --reliable --transport "$pub_t" "${extra[@]}" \
    > "$work/bridge.log" 2>&1 || fail "plumb-bridge: $(cat "$work/bridge.log")"
  kill -INT "$echo_pid"; wait "$echo_pid"
  grep -E "waiting up to|matched|no reader" "$work/bridge.log" | sed 's/^/     /'
  python3 - "$work/echo.csv" $n <<'PY' && pass "bridge $pub_t -> echo $echo_t: all $n samples from seq 0, in order" ||
import csv, sys
seqs = [int(r["seq"]) for r in csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#"))]
n = int(sys.argv[2])
print(f"     {len(seqs)} samples received, first seq {seqs[0] if seqs else None}")
sys.exit(0 if seqs == list(range(n)) else 1)
PY
    fail "bridge $pub_t -> echo $echo_t: samples lost: $(cat "$work/bridge.log" "$work/echo.err")"
else
  n=20
  port=$(free_port)
  plumb topic echo plumb/depth --csv --count $n --timeout 15 --transport "$echo_t" > "$work/depth.csv" 2> "$work/echo.err" &
  echo_pid=$!; pids+=($echo_pid)
  sleep 2  # the echo's reader first, as above
  # The rig is already sending when plumb-wits connects: its first frames wait in the socket.
  plumb-wits-send --listen "$port" --count $n --interval 0.01 --start-depth 1000 > "$work/sent.log" 2>&1 &
  send_pid=$!; pids+=($send_pid)
  plumb-wits --connect "127.0.0.1:$port" --count $n --tool-id board --transport "$pub_t" "${extra[@]}" \
    > "$work/wits.log" 2>&1 || fail "plumb-wits: $(cat "$work/wits.log")"
  wait "$send_pid" || fail "plumb-wits-send: $(cat "$work/sent.log")"
  wait "$echo_pid" || fail "plumb topic echo: $(cat "$work/echo.err")"
  grep -E "waiting up to|matched|no reader" "$work/wits.log" | sed 's/^/     /'
  python3 - "$work/depth.csv" "$work/sent.log" <<'PY' && pass "plumb-wits $pub_t -> echo $echo_t: every depth from the first frame on" ||
import csv, sys
got = [float(r["depth_m"]) for r in csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#"))]
sent = [float(w[4]) for w in (l.split() for l in open(sys.argv[2])) if len(w) >= 6 and w[1] == "frame" and w[-1] == "sent"]
print(f"     {len(sent)} frames sent, {len(got)} depths received, first {got[0] if got else None} m (sent first {sent[0] if sent else None} m)")
sys.exit(0 if sent and len(got) == len(sent) and all(abs(a - b) < 0.004 for a, b in zip(got, sent)) else 1)
PY
    fail "plumb-wits $pub_t -> echo $echo_t: depths lost: $(cat "$work/wits.log" "$work/echo.err")"
fi
finish
