#!/usr/bin/env bash
# Calibration end to end: a sensor package with bias and scale errors is calibrated on the
# simulated turntable (6-position accelerometers, then magnetometer with the dip constraint); the
# platform simulator with the same errors -> serial -> bridge (applying the coefficients) -> DDS ->
# estimator (static plugin, 0 rpm) -> plumb topic echo. The estimate's error must return to the
# error-free run's, while without calibration it is far larger.
# usage: calibration_e2e.sh BIN_DIR TRANSPORT DOMAIN
set -uo pipefail
bin=$1 transport=$2
export PLUMB_DOMAIN_ID=$3
source "$(dirname "$0")/../wait.sh"
work=$(mktemp -d)
pids=()
# On exit: stop the programs still running (kill fails, harmlessly, for one that already ended).
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; rm -rf "$work"; }
trap cleanup EXIT
show_logs() { for f in "$work"/*.out; do echo "--- $f"; cat "$f"; done; }
for tool in plumb-sim plumb-estimator plumb-bridge plumb plumb-calibrate; do
  [ -x "$bin/$tool" ] || { echo "$tool not built"; exit 1; }
done
cd "$work"

# The package's errors, as plumb-sim takes them (measured = (I + diag(scale)) true + bias), and the
# same package as a calibration truth (raw = S^-1 true + bias): S = diag(1 / (1 + scale)).
ab=0.05,-0.03,0.04 as=0.003,-0.002,0.0025 mb=1.5,-0.8,1.2 ms=0.01,-0.008,0.005
awk -v ab=$ab -v as=$as -v mb=$mb -v ms=$ms 'BEGIN {
  split(ab, a, ","); split(as, s, ","); split(mb, m, ","); split(ms, t, ",");
  print "format plumb-calibration 1"; print "tool_id sim"; print "reference_temp_c 25";
  printf "accel.bias %.17g %.17g %.17g\n", a[1], a[2], a[3];
  printf "accel.sensitivity %.17g 0 0 0 %.17g 0 0 0 %.17g\n", 1/(1+s[1]), 1/(1+s[2]), 1/(1+s[3]);
  printf "mag.bias %.17g %.17g %.17g\n", m[1], m[2], m[3];
  printf "mag.sensitivity %.17g 0 0 0 %.17g 0 0 0 %.17g\n", 1/(1+t[1]), 1/(1+t[2]), 1/(1+t[3]);
}' > truth.txt
printf 'format plumb-calibration 1\ntool_id sim\ncalibration_id identity\n' > identity.txt

cal=$bin/plumb-calibrate
$cal --procedure 6pos --sim-truth truth.txt --write-simulation acc_ > cal.out 2>&1 &&
  $cal --procedure 6pos --input acc_sensor.csv --stations acc_stations.csv --output acc.txt --tool-id sim >> cal.out 2>&1 &&
  $cal --procedure mag --sim-truth truth.txt --write-simulation mag_ >> cal.out 2>&1 &&
  $cal --procedure mag --input mag_sensor.csv --stations mag_stations.csv --base acc.txt --output coeffs.txt \
    --tool-id sim --calibration-id e2e-cal >> cal.out 2>&1 || { show_logs; echo "FAIL - calibration"; exit 1; }

inc=30 azi=200 tf=40
# run NAME COEFFS [sim error options...]: writes "inclination_error azimuth_error" of the estimate
# to NAME.err; any failure stops the whole script with the logs.
run() {
  local name=$1 coeffs=$2; shift 2
  local link=$work/board_$name
  "$bin/plumb" topic echo plumb/attitude/static --csv --count 1 --timeout 120 --transport "$transport" \
    > "$name.csv" 2> "echo_$name.out" &
  local echo_pid=$!
  pids+=($echo_pid)
  "$bin/plumb-estimator" --transport "$transport" --input plumb/sensor/calibrated --reliable --plugin static \
    --window 10 --count 1 --timeout 120 --flush-after-idle 2 -q > "host_$name.out" 2>&1 &
  local host=$!
  pids+=($host)
  "$bin/plumb-bridge" --transport "$transport" --device "$link" --tool-id sim --reliable --calibration "$coeffs" \
    --no-calibration-topic --backoff-min 0.05 --backoff-max 0.2 --wait-subscribers 20 > "bridge_$name.out" 2>&1 &
  local bridge=$!
  pids+=($bridge)
  wait_bridge_matched "bridge_$name.out" ||
    { show_logs; echo "FAIL - $name: the estimator's reader never matched the bridge"; exit 1; }
  "$bin/plumb-sim" --serial "$link" --inclination $inc --azimuth $azi --toolface $tf --rpm 0 --duration 10 \
    --sigma-accel 0.002 --sigma-mag 0.02 --g 9.80665 --field 48.4 --dip 45.5 --rate x4 --no-truth --tool-id sim \
    --temp 25 --seed 5 "$@" > "sim_$name.out" 2>&1 || { show_logs; exit 1; }
  wait "$host" || { show_logs; echo "FAIL - $name: plumb-estimator"; exit 1; }
  wait "$echo_pid" || { show_logs; echo "FAIL - $name: plumb topic echo"; exit 1; }
  kill -INT "$bridge"; wait "$bridge"
  awk -F, -v inc=$inc -v azi=$azi 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    NF > 1 { di = $c["inclination_deg"] - inc; da = $c["azimuth_deg"] - azi; while (da > 180) da -= 360;
             while (da <= -180) da += 360; printf "%.6f %.6f\n", (di < 0 ? -di : di), (da < 0 ? -da : da); exit }' \
    "$name.csv" > "$name.err"
}
errors=(--accel-bias $ab --accel-scale $as --mag-bias $mb --mag-scale $ms)
run free identity.txt
run raw identity.txt "${errors[@]}"
run calibrated coeffs.txt "${errors[@]}"
read -r free_i free_a < free.err
read -r raw_i raw_a < raw.err
read -r cal_i cal_a < calibrated.err
echo "static estimator, I=$inc A=$azi: |error| inclination / azimuth (deg)"
echo "  error-free sensors     $free_i / $free_a"
echo "  errors, uncalibrated   $raw_i / $raw_a"
echo "  errors, calibrated     $cal_i / $cal_a"
grep -q "e2e-cal" bridge_calibrated.out || echo "note: the bridge log does not name the calibration"
# Tolerances: the calibration's residual errors (bias sd ~1e-5 m/s^2, scale ~1e-6) are below
# 0.001 deg; the estimator's noise over 1000 samples is ~0.001 deg; the same seed makes the noise
# nearly identical in the three runs.
awk -v fi="$free_i" -v fa="$free_a" -v ri="$raw_i" -v ra="$raw_a" -v ci="$cal_i" -v ca="$cal_a" 'BEGIN {
  ok = 1
  if (ci == "" || fi == "" || ri == "") { print "FAIL - missing estimate"; exit 1 }
  if (ci > fi + 0.005) { print "FAIL - calibrated inclination error " ci " > error-free " fi " + 0.005"; ok = 0 }
  if (ca > fa + 0.02) { print "FAIL - calibrated azimuth error " ca " > error-free " fa " + 0.02"; ok = 0 }
  if (!(ri > 0.05 || ra > 0.5)) { print "FAIL - the sensor errors do not show without calibration"; ok = 0 }
  if (ok) print "all checks passed"; exit !ok }'
