#!/usr/bin/env bash
# Parameters files as a new user runs them: the shipped drilling MEMS file on a simulated MEMS
# drilling run (plumb estimate --params-file, end position against the simulator's truth), a
# --param on top of the file, and every program that takes --param refusing a key its plugin does
# not declare with the file and the line, exit status 2. No DDS: plumb-estimator refuses before it
# connects.
# usage: params_files.sh BIN_DIR PARAMS_DIR
set -uo pipefail
bin=$1
params=$2
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export PATH=$bin:$PATH

plumb-sim --scenario drilling --grade mems --rate-hz 100 --csv "$work/drill" > "$work/sim.log" 2>&1 ||
  { cat "$work/sim.log"; fail "plumb-sim"; finish; }
if plumb estimate --estimator strapdown --params-file "$params/drilling-mems.yaml" --input "$work/drill/sensor.csv" \
  --output "$work/nav.csv" > "$work/estimate.log" 2>&1; then
  python3 - "$work/nav.csv" "$work/drill/truth.csv" <<'PY' && pass "drilling-mems.yaml: the MEMS drilling run ends within 0.5 % of its length" ||
import csv, math, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["valid"] == "1"]
truth = list(csv.DictReader(open(sys.argv[2])))
end, t = rows[-1], min(truth, key=lambda r: abs(float(r["t"]) - float(rows[-1]["t"])))
err = math.dist([float(end[k]) for k in ("north_m", "east_m", "down_m")], [float(t[k]) for k in ("north_m", "east_m", "down_m")])
drilled = float(truth[-1]["depth_m"]) - float(truth[0]["depth_m"])
print(f"drilling-mems.yaml: end position {err:.3f} m off after {drilled:.1f} m drilled")
sys.exit(0 if err < 0.005 * drilled else 1)
PY
    fail "drilling-mems.yaml: end position"
else
  cat "$work/estimate.log"; fail "plumb estimate --params-file drilling-mems.yaml"
fi

# A --param on top of the file replaces the file's value: a grade that does not exist is refused.
expect_usage "--param overrides the file" "imu_grade" plumb estimate --estimator strapdown \
  --params-file "$params/drilling-mems.yaml" --param imu_grade=none --input "$work/drill/sensor.csv" --output "$work/x.csv"

# A typo in a file: refused with file and line by every program that takes --param.
printf 'strapdown:\n  latitude_deg: 35\n  gravty: 9.81\n' > "$work/typo.yaml"
line="typo\.yaml:3: 'gravty': strapdown has no such parameter"
expect_usage "plumb estimate: unknown key" "$line" plumb estimate --estimator strapdown \
  --params-file "$work/typo.yaml" --input "$work/drill/sensor.csv"
expect_usage "plumb-estimator: unknown key" "$line" plumb-estimator --plugin strapdown --params-file "$work/typo.yaml"
expect_usage "plumb compare: unknown key" "$line" plumb compare --scenario drilling -e strapdown \
  --params-file "$work/typo.yaml"
expect_usage "plumb survey: unknown key" "$line" plumb survey --input "$work/drill/sensor.csv" -e strapdown --gravity 9.80665 --total-field 50 --dip 60 \
  --params-file "$work/typo.yaml"
printf 'compensated:\n  window: 2\n' > "$work/other.yaml"
expect_usage "a plugin not selected" "other\.yaml:2: estimator 'compensated' is not selected" \
  plumb estimate --estimator static --params-file "$work/other.yaml" --input "$work/drill/sensor.csv"
printf 'static:\n  window: [1, 2]\n' > "$work/list.yaml"
expect_usage "a list as a value" "list\.yaml:2: 'static\.window' needs one value" \
  plumb estimate --estimator static --params-file "$work/list.yaml" --input "$work/drill/sensor.csv"
expect_usage "a missing file" "cannot read parameters file '$work/none.yaml'" \
  plumb estimate --estimator static --params-file "$work/none.yaml" --input "$work/drill/sensor.csv"
finish
