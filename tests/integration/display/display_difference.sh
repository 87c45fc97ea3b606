#!/usr/bin/env bash
# Two plugins of one tool side by side on the live page, the second loaded while the tool turns
# (the comparison people watch): plumb-sim and plumb-estimator --plugin compensated (transport H) -> plumb
# component load integral, then static (the commands and plumb-display on transport D) -> headless
# Chromium: integral's card shows its difference from compensated, small and live; static's (no
# angle while turning) shows "-" for each; compensated's none; and a plain Foxglove client gets
# integral's difference on plumb-display/difference/rig1/integral. Then integral is unloaded: its card
# leaves the open page and its channel is unadvertised. Exit 77 without Chromium.
# usage: display_difference.sh BIN_DIR H D DOMAIN ARTIFACT_DIR
set -uo pipefail
bin=$1 host_t=$2 display_t=$3
export PLUMB_DOMAIN_ID=$4
artifacts=$5
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
if ! command -v chromium > /dev/null && ! command -v chromium-browser > /dev/null; then
  echo "skipped: chromium is not installed (apt-get install chromium)"
  exit 77
fi
start_work_with_programs
mkdir -p "$artifacts"
name=diff-host-$4

"$bin/plumb-display" --transport "$display_t" --port 0 --foxglove-port 0 > "$work/display.log" 2>&1 &
pids+=($!)
wait_for "$work/display.log" "Foxglove on ws://127.0.0.1:[0-9]+/" 20 || { cat "$work/display.log"; fail "plumb-display did not start"; finish; }
port=$(sed -nE 's|.*serving http://127\.0\.0\.1:([0-9]+)/.*|\1|p' "$work/display.log" | head -1)
fox_port=$(sed -nE 's|.*Foxglove on ws://127\.0\.0\.1:([0-9]+)/.*|\1|p' "$work/display.log" | head -1)

# I = 2 deg, A = 200 deg, 240 rpm: compensated and integral both valid on 0.5 s windows, static never.
"$bin/plumb-estimator" --transport "$host_t" --name "$name" --input plumb/sensor/raw --plugin compensated \
  --window 0.5 --tool-id rig1 -q > "$work/host.log" 2>&1 &
pids+=($!)
"$bin/plumb-sim" --transport "$host_t" --tool-id rig1 --inclination 2 --azimuth 200 --rpm 240 --duration 200 \
  --snr-accel 40 --snr-mag 40 --g 10 --field 48.4 --dip 45.5 --rate x5 --wait-subscribers 20 > "$work/sim.log" 2>&1 &
pids+=($!)
for p in integral static; do
  out=$("$bin/plumb" component load "$name" $p --transport "$display_t" --wait 20 2>&1) &&
    pass "load $p while the tool turns: $out" || fail "load $p: $out"
done
# Both watch while integral is unloaded: its card leaves the open page, its Foxglove channel is
# unadvertised (its topic has no writer any more).
hs=$work/handshake
mkdir -p "$hs"
python3 "$here/browser_difference.py" "http://127.0.0.1:$port/" --key rig1/integral --reference compensated \
  --inc-tol 0.1 --azi-tol 1.5 --invalid rig1/static --gone rig1/integral --handshake "$hs" \
  --screenshot "$artifacts/display_difference_${host_t}_${display_t}.png" > "$work/browser.log" 2>&1 &
browser=$!
# The same difference on the display's Foxglove server, a JSON channel of its own.
python3 "$here/foxglove_difference.py" "ws://127.0.0.1:$fox_port/" rig1 integral compensated --inc-tol 0.1 --azi-tol 1.5 \
  --handshake "$hs" > "$work/foxglove.log" 2>&1 &
foxglove=$!
for _ in $(seq 400); do
  [ -e "$hs/browser-ready" ] && [ -e "$hs/foxglove-ready" ] && break
  kill -0 $browser 2>/dev/null || kill -0 $foxglove 2>/dev/null || break
  sleep 0.1
done
if [ -e "$hs/browser-ready" ] && [ -e "$hs/foxglove-ready" ]; then
  out=$("$bin/plumb" component unload "$name" integral --transport "$display_t" --wait 20 2>&1) &&
    pass "unload integral: $out" || fail "unload integral: $out"
fi
touch "$hs/unloaded"
wait $browser
rc=$?
cat "$work/browser.log"
[ $rc -eq 77 ] && exit 77
[ $rc -eq 0 ] || fail "browser checks (exit $rc)"
wait $foxglove || fail "Foxglove difference channel"
cat "$work/foxglove.log"
[ $fails -eq 0 ] || { tail -5 "$work/host.log"; tail -5 "$work/display.log"; }
finish
