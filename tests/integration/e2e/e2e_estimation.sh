#!/usr/bin/env bash
# End to end: plumb-sim (transport S) -> DDS -> plumb-estimator with the static, integral and
# compensated plugins (transport H) -> `plumb topic echo` (transport E), estimates checked
# against the truth. usage: e2e_estimation.sh BIN_DIR S H E DOMAIN
set -euo pipefail
bin=$1 sim_t=$2 host_t=$3 echo_t=$4
export PLUMB_DOMAIN_ID=$5
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
pids=()
# On exit: stop the programs still running (kill fails, harmlessly, for one that already ended).
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; rm -rf "$work"; }
trap cleanup EXIT

# Truth: I = 2 deg, A = 200 deg, 60 rpm. High SNR (40 dB) so that the tolerances below are the
# algorithms' physics, not noise: the small-angle (integral) azimuth is off by about
# sin(I) tan(dip) sin(A) = -0.70 deg here, the compensated one by noise only (~0.02 deg).
inc=2 azi=200
for est in static integral compensated; do
  "$bin/plumb" topic echo "plumb/attitude/$est" --csv --count 2 --timeout 120 --transport "$echo_t" \
    > "$work/$est.csv" 2> "$work/$est.err" &
  pids+=($!)
done
"$bin/plumb-estimator" --transport "$host_t" --input plumb/sensor/raw --reliable \
  --plugin static --plugin integral --plugin compensated --window 5 --count 2 --timeout 120 -q \
  > "$work/host.out" 2>&1 &
host=$!
pids+=($host)
sleep 2
"$bin/plumb-sim" --transport "$sim_t" --inclination $inc --azimuth $azi --rpm 60 --duration 10.5 \
  --snr-accel 40 --snr-mag 40 --g 10 --field 48.4 --dip 45.5 --rate x4 --reliable --wait-subscribers 20 \
  > "$work/sim.out" 2>&1 || { cat "$work/sim.out"; exit 1; }
status=0
wait "$host" || { echo "plumb-estimator failed:"; cat "$work/host.out"; status=1; }
for i in 0 1 2; do wait "${pids[$i]}" || { echo "echo ${i} failed:"; cat "$work"/*.err; status=1; }; done
python3 "$here/check_estimates.py" "$work/compensated.csv" --inclination $inc --azimuth $azi \
  --inc-tol 0.02 --azi-tol 0.3 --min-rows 2 || status=1
# The integral plugin must show the paper's small-angle error, sin(I) tan(dip) sin(A) rad.
offset=$(python3 -c "import math; r=math.radians; print(math.degrees(math.sin(r($inc))*math.tan(r(45.5))*math.sin(r($azi))))")
python3 "$here/check_estimates.py" "$work/integral.csv" --inclination $inc --azimuth $azi \
  --inc-tol 0.02 --azi-offset "$offset" --azi-tol 0.2 --min-rows 2 || status=1
python3 "$here/check_estimates.py" "$work/static.csv" --inclination $inc --azimuth $azi \
  --expect-invalid --min-rows 2 || status=1
exit $status
