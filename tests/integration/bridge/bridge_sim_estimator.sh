#!/usr/bin/env bash
# sim -> serial (pseudo-terminal) -> bridge (calibration applied) -> DDS -> estimator host
# (compensated plugin on the calibrated topic) -> plumb topic echo; the estimates must match
# the simulator's truth. No hardware anywhere.
# usage: bridge_sim_estimator.sh BIN_DIR TRANSPORT DOMAIN
set -euo pipefail
bin=$1 transport=$2
export PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
link=$work/board
for tool in plumb-sim plumb-estimator plumb; do
  [ -x "$bin/$tool" ] || { echo "$tool not built"; exit 1; }
done
cat > "$work/identity.cal" <<'CAL'
format plumb-calibration 1
tool_id sim
calibration_id identity-e2e
CAL

# I = 2 deg, A = 200 deg, 60 rpm, 40 dB SNR (as the DDS-only e2e test): the compensated
# estimate is within noise (~0.02 deg) plus the float32 rounding of the frame (relative 6e-8,
# far below it).
inc=2 azi=200
"$bin/plumb" topic echo plumb/attitude/compensated --csv --count 2 --timeout 120 --transport "$transport" \
  > "$work/compensated.csv" 2> "$work/echo.out" &
echo_pid=$!
pids+=($echo_pid)
"$bin/plumb-estimator" --transport "$transport" --input plumb/sensor/calibrated --reliable \
  --plugin compensated --window 5 --count 2 --timeout 120 -q > "$work/host.out" 2>&1 &
host=$!
pids+=($host)
"$bin/plumb-bridge" --transport "$transport" --device "$link" --tool-id sim --reliable --calibration "$work/identity.cal" \
  --no-calibration-topic --backoff-min 0.05 --backoff-max 0.2 --wait-subscribers 20 > "$work/bridge.out" 2>&1 &
bridge=$!
pids+=($bridge)
wait_bridge_matched "$work/bridge.out" || { show_logs; echo "FAIL - no reader matched the bridge"; exit 1; }
"$bin/plumb-sim" --serial "$link" --inclination $inc --azimuth $azi --rpm 60 --duration 10.5 \
  --snr-accel 40 --snr-mag 40 --g 10 --field 48.4 --dip 45.5 --rate x4 --no-truth --tool-id sim \
  > "$work/sim.out" 2>&1 || { show_logs; exit 1; }
status=0
wait "$host" || { echo "plumb-estimator failed"; status=1; }
wait "$echo_pid" || { echo "plumb topic echo failed"; status=1; }
kill -INT "$bridge"
wait "$bridge" || { echo "plumb-bridge failed"; status=1; }
[ $status -eq 0 ] || { show_logs; exit 1; }
grep -q "calibration 'identity-e2e'" "$work/bridge.out" || { show_logs; echo "FAIL - calibration not applied"; exit 1; }
python3 "$here/../e2e/check_estimates.py" "$work/compensated.csv" --inclination $inc --azimuth $azi \
  --inc-tol 0.02 --azi-tol 0.3 --min-rows 2 || { show_logs; exit 1; }
echo "all checks passed"
