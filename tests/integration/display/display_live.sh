#!/usr/bin/env bash
# The live display in a real browser: plumb-sim (transport S) -> plumb-estimator (transport H) ->
# plumb-display (transport D) -> headless Chromium. Checks what the page shows against the
# simulated truth (inclination, azimuth), the update rate measured in the page, the status rows of
# every component, a screenshot (desktop and phone) kept in BUILD_DIR/artifacts/, and that the page
# recovers by itself when the server is restarted. Exit 77 without Chromium.
# usage: display_live.sh BIN_DIR S H D DOMAIN ARTIFACT_DIR
set -uo pipefail
bin=$1 sim_t=$2 host_t=$3 display_t=$4
export PLUMB_DOMAIN_ID=$5
artifacts=$6
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
if ! command -v chromium > /dev/null && ! command -v chromium-browser > /dev/null; then
  echo "skipped: chromium is not installed (apt-get install chromium)"
  exit 77
fi
start_work_with_programs
mkdir -p "$artifacts"

start_display() {  # start_display PORT LOG: background plumb-display; its pid in $display
  "$bin/plumb-display" --transport "$display_t" --port "$1" --foxglove-port 0 > "$2" 2>&1 &
  display=$!
  pids+=($display)
  wait_for "$2" "serving http://127.0.0.1:[0-9]+/" 20
}
start_display 0 "$work/display.log" || { cat "$work/display.log"; fail "plumb-display did not start"; finish; }
port=$(sed -nE 's|.*serving http://127\.0\.0\.1:([0-9]+)/.*|\1|p' "$work/display.log" | head -1)
pass "plumb-display serves port $port ($display_t)"

# Truth: I = 2 deg, A = 200 deg, 240 rpm (two turns a window: both plugins valid), high SNR. Windows of 0.5 s of simulated time at x5:
# each plugin publishes 10 estimates a second, two plugins 20.
inc=2 azi=200
"$bin/plumb-estimator" --transport "$host_t" --input plumb/sensor/raw --plugin compensated --plugin integral \
  --window 0.5 --tool-id rig1 -q > "$work/host.log" 2>&1 &
pids+=($!)
"$bin/plumb-sim" --transport "$sim_t" --tool-id rig1 --inclination $inc --azimuth $azi --rpm 240 --duration 200 \
  --snr-accel 40 --snr-mag 40 --g 10 --field 48.4 --dip 45.5 --rate x5 --wait-subscribers 20 > "$work/sim.log" 2>&1 &
pids+=($!)

# Two survey stations, as plumb-survey publishes them (reliable, transient-local: kept for the page).
for i in 0 1; do
  "$bin/plumb" topic pub plumb/survey/rig1 tool_id=rig1 source=compensated index=$i md_m=$((120 + 30 * i)).5 \
    inclination_deg=2.01 azimuth_deg=199.9 azimuth_reference=magnetic tvd_m=$((120 + 30 * i)) flags=3 --wait 10 \
    --transport "$host_t" > "$work/station$i.log" 2>&1 || fail "station $i not published: $(cat "$work/station$i.log")"
done

# The browser checks, then (handshake through files) the server is stopped and started again on
# the same port while the page stays open.
python3 "$here/browser.py" "http://127.0.0.1:$port/" --screenshot "$artifacts/display_${sim_t}_${host_t}_${display_t}.png" \
  --expect-key rig1/compensated --inclination $inc --azimuth $azi --inc-tol 0.1 --azi-tol 1.5 --min-rate 10 \
  --stations "rig1|0|120.50|2.01;rig1|1|150.50|2.01" --restart-handshake "$work" > "$work/browser.log" 2>&1 &
browser=$!
pids+=($browser)
for ((i = 0; i < 900; ++i)); do  # up to 90 s: the browser's own checks come first
  [ -e "$work/ready" ] && break
  kill -0 "$browser" 2>/dev/null || break
  sleep 0.1
done
if [ -e "$work/ready" ]; then
  kill "$display"
  wait "$display" 2>/dev/null  # its status is the signal's: not the test's business
  sleep 1                      # the page notices and retries while nobody serves
  start_display "$port" "$work/display2.log" || { cat "$work/display2.log"; fail "plumb-display did not restart on port $port"; }
  touch "$work/restarted"
fi
rc=0
wait "$browser" || rc=$?
cat "$work/browser.log"
if [ $rc -eq 77 ]; then exit 77; fi
[ $rc -eq 0 ] && pass "the page showed what the simulator did" || {
  fail "browser checks"; tail -n 5 "$work/display.log" "$work/host.log" "$work/sim.log"; }
finish
