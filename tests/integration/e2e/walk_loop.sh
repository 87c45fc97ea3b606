#!/usr/bin/env bash
# The closed-loop walk: a foot-mounted MEMS IMU at 400 Hz (plumb-sim --scenario walk, stance
# periods of 0.05-0.3 s) through `plumb estimate --estimator strapdown` without a magnetometer,
# initial azimuth given. The loop closes in truth; the navigator's end point must lie within 0.3 %
# of the distance walked (3-D, from the truth's own path). usage: walk_loop.sh BIN_DIR
set -uo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for length in 25 60; do
  for seed in 1 2; do
    run="$work/walk${length}_$seed"
    "$bin/plumb-sim" --scenario walk --walk-length $length --seed $seed --latitude 35 --no-mag --csv "$run" \
      > "$run.log" 2>&1 || { cat "$run.log"; fail "plumb-sim walk $length"; continue; }
    "$bin/plumb" estimate --estimator strapdown --input "$run/sensor.csv" --output "$run/nav.csv" \
      --param latitude_deg=35 --param gravity=9.80665 --param imu_grade=mems --param min_still_s=0.05 \
      --param initial_azimuth_deg=315 --param align_s=8 2> "$run.err" || { cat "$run.err"; fail "plumb estimate"; continue; }
    python3 - "$run/nav.csv" "$run/truth.csv" <<'PY' && pass "walk $length m seed $seed closes within 0.3 %" ||
import csv, math, sys
nav = list(csv.DictReader(open(sys.argv[1])))
truth = list(csv.DictReader(open(sys.argv[2])))
pos = [[float(r[k]) for k in ("north_m", "east_m", "down_m")] for r in truth]
walked = sum(math.dist(a, b) for a, b in zip(pos, pos[1:]))
end = [float(nav[-1][k]) for k in ("north_m", "east_m", "down_m")]
err = math.dist(end, pos[-1])
print(f"walked {walked:.2f} m, end error {err:.3f} m ({100 * err / walked:.3f} %), "
      f"azimuth reference {nav[-1]['azimuth_reference']}")
sys.exit(0 if nav[-1]["valid"] == "1" and err < 0.003 * walked and nav[-1]["azimuth_reference"] == "relative" else 1)
PY
      fail "walk $length m seed $seed"
  done
done
finish
