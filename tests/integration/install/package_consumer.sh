#!/usr/bin/env bash
# Another team's view of plumb: install it, then with a separate cmake configure build examples/
# and an estimator plugin of its own (plugin/) against the installed CMake package only, run the
# examples across vendors and load the plugin in the installed plumb-estimator.
# usage: package_consumer.sh SOURCE_DIR BUILD_DIR DOMAIN
set -uo pipefail
src=$1 build=$2
export PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; finish; }

# Configure and build as another team would: only CMAKE_PREFIX_PATH points at plumb. (ccache, if
# the machine has it, keeps repeated runs short.)
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
consume() {  # consume NAME SOURCE
  if cmake -S "$2" -B "$work/$1" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
       > "$work/$1.log" 2>&1 && cmake --build "$work/$1" -j2 >> "$work/$1.log" 2>&1; then
    pass "$1 built against the installed package"
  else
    fail "$1 against the installed package: $(tail -20 "$work/$1.log")"
  fi
}
consume examples "$src/examples"
consume plugin "$here/plugin"

# The examples' programs, built outside, find the installed transports (next to libplumb_plugin.so).
run() { env -u LD_LIBRARY_PATH -u PLUMB_TRANSPORT_PATH PATH="$prefix/bin:/usr/bin:/bin" "$@"; }
sub=$(find "$work/examples" -name plumb-example-subscriber -type f | head -1)
pub=$(find "$work/examples" -name plumb-example-publisher -type f | head -1)
if [ -n "$sub" ] && [ -n "$pub" ]; then
  run "$sub" --transport cyclonedds --count 3 --timeout 40 > "$work/sub.out" 2>&1 &
  sub_pid=$!; pids+=($sub_pid)
  wait_for "$work/sub.out" "listening" 20
  run "$pub" --transport fastdds --count 3 > "$work/pub.out" 2>&1 || fail "external publisher: $(cat "$work/pub.out")"
  wait $sub_pid && [ "$(grep -c inclination "$work/sub.out")" -eq 3 ] &&
    pass "external examples exchanged 3 attitudes (fastdds -> cyclonedds)" || fail "external subscriber: $(cat "$work/sub.out")"
fi

# The plugin, built outside, in the installed host.
export PLUMB_ESTIMATOR_PATH=$work/plugin
output_matches "level" run plumb plugins -v && pass "plumb plugins -v opens the out-of-tree plugin" ||
  fail "plumb plugins -v: $(run plumb plugins -v 2>&1)"
run plumb topic echo plumb/attitude/level --csv --count 1 --timeout 60 > "$work/att.csv" 2> "$work/echo.err" &
echo_pid=$!; pids+=($echo_pid)
run plumb-estimator --plugin level --input plumb/sensor/raw --reliable --count 3 --timeout 60 -q > "$work/host.log" 2>&1 &
host_pid=$!; pids+=($host_pid)
run plumb-sim --inclination 3 --azimuth 45 --rpm 0 --duration 4 --snr-accel 40 --snr-mag 40 --rate x4 --reliable \
  --wait-subscribers 30 > "$work/sim.log" 2>&1 || fail "plumb-sim: $(cat "$work/sim.log")"
wait $host_pid && pass "installed plumb-estimator ran the out-of-tree plugin" || fail "host: $(cat "$work/host.log")"
wait $echo_pid && python3 "$here/../e2e/check_estimates.py" "$work/att.csv" --inclination 3 --azimuth 45 \
  --inc-tol 0.05 --no-azimuth && pass "its attitude reached plumb topic echo (no azimuth: an empty cell)" ||
  fail "echo: $(cat "$work/echo.err" "$work/att.csv")"
finish
