#!/usr/bin/env bash
# A real recording from an IMU nobody on plumb made (tests/data/walks: x-io's NGIMU on a
# foot, two closed loops of about 25 m and 60 m). `plumb estimate` reads the files as published,
# through --column/--units/--axes, without a magnetometer and with an initial azimuth; the loop
# closes in truth, so the end point is the error. Checked: every repeated row counted (the count
# taken from the file itself), the run valid to its end with a relative azimuth, and the end error
# within twice what the publisher reports for its own algorithm (82 mm and 421 mm).
# The sensor noise parameters are read off the recording's first still second (gyro 0.2-0.4 deg/s
# and accelerometer 0.003 g per sample at 400 Hz: ARW about 1 deg/sqrt(h), VRW 0.1 m/s/sqrt(h);
# gyro biases up to 0.4 deg/s), the GLRT threshold is OpenShoe's (3e4 at 0.01 m/s^2 and
# 0.1 deg/s) scaled to those sigmas. None of it is fitted to the loop closure. They are the shipped
# parameters file deploy/params/foot-mems.yaml, passed as a user passes it (--params-file).
# usage: walk_recording.sh BIN_DIR DATA_DIR PARAMS_FILE
set -uo pipefail
bin=$1
data=$2
params_file=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for case in "short_walk 0.082" "long_walk 0.421"; do
  read -r name published <<<"$case"
  csv="$work/$name.csv"
  xz -dc "$data/$name.csv.xz" > "$csv" || { fail "cannot decompress $name"; continue; }
  repeated=$(awk -F, 'NR > 2 && $1 == last { n++ } { last = $1 } END { print n + 0 }' "$csv")
  "$bin/plumb" estimate --estimator strapdown --input "$csv" --output "$work/$name.nav.csv" \
    --column "t=Time (s)" --column "wx=Gyroscope X (deg/s)" --column "wy=Gyroscope Y (deg/s)" \
    --column "wz=Gyroscope Z (deg/s)" --column "fx=Accelerometer X (g)" --column "fy=Accelerometer Y (g)" \
    --column "fz=Accelerometer Z (g)" --units accel=g,gyro=deg/s --axes x,-y,-z \
    --params-file "$params_file" > "$work/$name.out" 2>&1 ||
    { cat "$work/$name.out"; fail "plumb estimate $name"; continue; }
  if output_matches "$repeated repeated_time" cat "$work/$name.out"; then
    pass "$name: all $repeated repeated rows counted"
  else
    cat "$work/$name.out"
    fail "$name: repeated rows: the file has $repeated"
  fi
  python3 - "$work/$name.nav.csv" "$published" "$name" <<'PY' && pass "$name closes within twice the publisher's error" ||
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
published = float(sys.argv[2])
pos = [[float(r[k]) for k in ("north_m", "east_m", "down_m")] for r in rows if r["valid"] == "1"]
walked = sum(math.dist(a, b) for a, b in zip(pos, pos[1:]))
end = pos[-1]
err = math.dist(end, [0.0, 0.0, 0.0])
horizontal = math.hypot(end[0], end[1])
print(f"{sys.argv[3]}: walked {walked:.1f} m, end error {err:.3f} m ({100 * err / walked:.2f} %; "
      f"horizontal {horizontal:.3f} m, vertical {end[2]:+.3f} m); publisher {published:.3f} m")
last = rows[-1]
sys.exit(0 if last["valid"] == "1" and last["azimuth_reference"] == "relative" and err < 2 * published else 1)
PY
    fail "$name: end error"
done
finish
