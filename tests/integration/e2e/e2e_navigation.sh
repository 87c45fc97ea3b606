#!/usr/bin/env bash
# End to end for the navigator: plumb-sim's 16-minute drilling run (transport S, with the
# rig's measured depth on plumb/depth) -> plumb-estimator --plugin strapdown (transport H) ->
# `plumb topic echo plumb/navigation/strapdown` (transport E). The last navigation message must hold
# the truth's end position within 1 % of the drilled length and its attitude within 0.2 deg: a
# depth that did not arrive shows as a position error of several metres (15-35 % without depth).
# usage: e2e_navigation.sh BIN_DIR S H E DOMAIN
set -euo pipefail
bin=$1 sim_t=$2 host_t=$3 echo_t=$4
export PLUMB_DOMAIN_ID=$5
work=$(mktemp -d)
pids=()
# Processes that already ended cannot be killed: that is not an error here.
# On exit: stop the programs still running (kill fails, harmlessly, for one that already ended).
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; rm -rf "$work"; }
trap cleanup EXIT
run=(--scenario drilling --grade tactical --rate-hz 10 --latitude 35 --seed 3)

# The same run as files, for the truth.
"$bin/plumb-sim" "${run[@]}" --csv "$work/truth" > "$work/sim_csv.out" 2>&1 || { cat "$work/sim_csv.out"; exit 1; }

"$bin/plumb" topic echo plumb/navigation/strapdown --csv --count 960 --timeout 150 --transport "$echo_t" \
  > "$work/nav.csv" 2> "$work/echo.err" &
echo_pid=$!
pids+=($echo_pid)
"$bin/plumb-estimator" --transport "$host_t" --input plumb/sensor/raw --reliable --plugin strapdown \
  --param latitude_deg=35 --param gravity=9.80665 --count 960 --timeout 150 -q > "$work/host.out" 2>&1 &
host=$!
pids+=($host)
sleep 2
"$bin/plumb-sim" "${run[@]}" --transport "$sim_t" --rate x100 --reliable --wait-subscribers 20 \
  > "$work/sim.out" 2>&1 || { cat "$work/sim.out"; exit 1; }
status=0
wait "$host" || { echo "plumb-estimator failed:"; cat "$work/host.out"; status=1; }
wait "$echo_pid" || { echo "echo failed:"; cat "$work/echo.err"; status=1; }
python3 - "$work/nav.csv" "$work/truth/truth.csv" <<'PY' || status=1
import csv, math, sys
nav = list(csv.DictReader(open(sys.argv[1])))
truth = list(csv.DictReader(open(sys.argv[2])))
last, end = nav[-1], truth[-1]
valid = [r for r in nav if int(r["flags"]) & 1]
err = math.dist([float(last[k]) for k in ("north_m", "east_m", "down_m")],
                [float(end[k]) for k in ("north_m", "east_m", "down_m")])
drilled = float(end["depth_m"])
d = lambda a, b: abs((float(a) - float(b) + 180) % 360 - 180)
att = max(d(last["inclination_deg"], end["inclination_deg"]), d(last["azimuth_deg"], end["azimuth_deg"]))
print(f"{len(nav)} navigation messages, {len(valid)} valid, zero-velocity updates {last['zero_velocity_updates']}, "
      f"end position error {err:.3f} m of {drilled:.1f} m drilled, attitude error {att:.4f} deg")
ok = len(valid) > 800 and int(last["zero_velocity_updates"]) >= 4 and err < 0.01 * drilled and att < 0.2
sys.exit(0 if ok else 1)
PY
exit $status
