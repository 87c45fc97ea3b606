#!/usr/bin/env bash
# plumb-display's Foxglove WebSocket server against an independent client: plumb-sim (transport S,
# 1 kHz, one sample per message) -> plumb-estimator (transport H) -> plumb-display (transport D)
# -> a node client on Foxglove's own npm packages (foxglove_client.js), beside `plumb topic echo
# --csv` of the same topics on D. foxglove_compare.py checks the protocol, the channels, the share
# of the 1 kHz stream received and every decoded value against echo's.
# The npm packages are installed by this test into NODE_DIR (a build folder, reused by later runs);
# without npm or the registry it is skipped (77).
# usage: foxglove_live.sh BIN_DIR S H D DOMAIN NODE_DIR
set -uo pipefail
bin=$1 sim_t=$2 host_t=$3 display_t=$4
export PLUMB_DOMAIN_ID=$5
node_dir=$6
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"

packages=(@foxglove/ws-protocol@0.8 ws@8 @foxglove/omgidl-parser@1 @foxglove/omgidl-serialization@1)
have_packages() {
  for p in ws-protocol omgidl-parser omgidl-serialization; do [ -f "$node_dir/node_modules/@foxglove/$p/package.json" ] || return 1; done
  [ -f "$node_dir/node_modules/ws/package.json" ]
}
if ! command -v node > /dev/null || ! command -v npm > /dev/null; then
  echo "skipped: node and npm are needed for the Foxglove client (apt-get install nodejs npm)"
  exit 77
fi
if ! have_packages; then
  mkdir -p "$node_dir"
  # A lock: the tests of this folder may run at once and share the folder.
  if ! (flock 9; have_packages || timeout 300 npm install --prefix "$node_dir" --no-audit --no-fund --no-save \
        "${packages[@]}" > "$node_dir/npm-install.log" 2>&1) 9> "$node_dir/.lock" || ! have_packages; then
    echo "skipped: npm could not install ${packages[*]} (registry not reachable?): $(tail -2 "$node_dir/npm-install.log" 2>/dev/null)"
    exit 77
  fi
fi
export NODE_PATH=$node_dir/node_modules
start_work_with_programs

"$bin/plumb-display" --transport "$display_t" --port 0 --foxglove-port 0 > "$work/display.log" 2>&1 &
pids+=($!)
wait_for "$work/display.log" "Foxglove on ws://127.0.0.1:[0-9]+/" 20 || { cat "$work/display.log"; fail "plumb-display did not start"; finish; }
port=$(sed -nE 's|.*Foxglove on ws://127\.0\.0\.1:([0-9]+)/.*|\1|p' "$work/display.log" | head -1)
pass "plumb-display serves Foxglove on port $port ($display_t)"
output_matches "plumb-display: Foxglove WebSocket server" python3 -c \
  "import urllib.request; print(urllib.request.urlopen('http://127.0.0.1:$port/').read().decode())" &&
  pass "a plain HTTP request on the Foxglove port says what it is" || fail "plain HTTP on the Foxglove port"
# A second display on the same Foxglove port serves its page alone, and says why.
rc=0
"$bin/plumb-display" --transport "$display_t" --port 0 --foxglove-port "$port" --duration 1 > "$work/second.out" 2> "$work/second.err" || rc=$?
[ $rc -eq 0 ] &&
  grep -qE "^plumb-display: cannot serve Foxglove on 127\.0\.0\.1:$port: Address already in use .*choose another --foxglove-port.*; serving the rest$" "$work/second.err" &&
  grep -qE "^plumb-display: serving http://127\.0\.0\.1:[0-9]+/ .*; Foxglove not served" "$work/second.out" &&
  pass "a second display on the same Foxglove port serves its page alone and says why" ||
  fail "a second display on the same Foxglove port: exit $rc, $(cat "$work/second.err" "$work/second.out")"
output_matches "Foxglove off" "$bin/plumb-display" --transport "$display_t" --port 0 --no-foxglove --duration 1 &&
  pass "--no-foxglove serves the page only, and says so" || fail "--no-foxglove"

# Truth: I = 2 deg, A = 200 deg, 240 rpm (two turns a window), 1000 samples a second, one a message:
# a 1 kHz topic. Windows of 0.5 s: two estimates a second. The compensated and integral estimators
# side by side: the ones the shipped Foxglove layout plots, with their difference.
inc=2 azi=200 run_s=14
"$bin/plumb-estimator" --transport "$host_t" --input plumb/sensor/raw --plugin compensated --plugin integral --window 0.5 --tool-id rig1 -q \
  > "$work/host.log" 2>&1 &
pids+=($!)
"$bin/plumb" topic echo plumb/sensor/raw --csv --transport "$display_t" --timeout $((run_s + 6)) > "$work/raw.csv" 2> "$work/raw.err" &
echo_raw=$!
pids+=($echo_raw)
"$bin/plumb" topic echo plumb/attitude/compensated --csv --transport "$display_t" --wait 20 --timeout $((run_s + 6)) \
  > "$work/attitude.csv" 2> "$work/attitude.err" &
echo_att=$!
pids+=($echo_att)
"$bin/plumb-sim" --transport "$sim_t" --tool-id rig1 --inclination $inc --azimuth $azi --rpm 240 --duration $run_s \
  --rate-hz 1000 --batch 1 --rate realtime --snr-accel 40 --snr-mag 40 --g 10 --field 48.4 --dip 45.5 \
  --wait-subscribers 20 > "$work/sim.log" 2>&1 &
pids+=($!)
# The client starts once the sensor topic is there (discovery: the channel is advertised), and
# stays for most of the run.
wait_for "$work/raw.csv" "^[0-9]+," 30 || fail "no sensor data reached plumb topic echo"
node "$here/foxglove_client.js" "ws://127.0.0.1:$port/" $((run_s - 5)) "$work/client.json" \
  plumb/sensor/raw plumb/attitude/compensated plumb/status plumb-display/difference/rig1/integral > "$work/client.log" 2>&1 || fail "the node client failed: $(tail -5 "$work/client.log")"
wait "$echo_raw" "$echo_att"
if [ -s "$work/client.json" ]; then
  python3 "$here/foxglove_compare.py" "$work/client.json" "$work/raw.csv" "$work/attitude.csv" plumb/sensor/raw \
    plumb/attitude/compensated $inc "$here/../../../examples/foxglove/plumb-layout.json" || fail "Foxglove client against plumb topic echo"
else
  fail "the client wrote nothing"
fi
# The simulator has ended: its topic's channel goes once discovery says its last writer left (at
# once on a clean exit; a vendor that learns it only from the participant's lease takes up to 30 s),
# and the estimator's stays.
gone="" polled_from=$SECONDS
for ((i = 0; i < 20; ++i)); do
  node "$here/foxglove_client.js" "ws://127.0.0.1:$port/" 1 "$work/after.json" > "$work/after.log" 2>&1
  if python3 - "$work/after.json" <<'PY'
import json, sys
topics = {c["topic"] for c in json.load(open(sys.argv[1]))["channels"]}
sys.exit(0 if "plumb/sensor/raw" not in topics and "plumb/attitude/compensated" in topics else 1)
PY
  then gone=$((SECONDS - polled_from)); break; fi
  sleep 1
done
[ -n "$gone" ] && pass "after the simulator: plumb/sensor/raw unadvertised (after ${gone} s of polling), plumb/attitude/compensated still there" ||
  fail "after the simulator: channels $(python3 -c "import json,sys; print(sorted(c['topic'] for c in json.load(open(sys.argv[1]))['channels']))" "$work/after.json")"
# The display's own counters on plumb/status after the client has gone.
"$bin/plumb" topic echo plumb/status --transport "$display_t" --timeout 5 > "$work/status.txt" 2>&1
grep -q "foxglove_clients_total" "$work/status.txt" && pass "plumb-display's plumb/status counts Foxglove clients" ||
  fail "no foxglove_* counters on plumb/status"
[ $fails -eq 0 ] || tail -n 5 "$work/display.log" "$work/host.log" "$work/sim.log" "$work/raw.err" "$work/attitude.err" "$work/client.log"
finish
