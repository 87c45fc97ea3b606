#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, the tree moved elsewhere (nothing may point back into
# the build tree or at the first prefix), then the main job run from there alone: plumb-sim
# (transport S) -> DDS -> plumb-estimator (transport H) -> `plumb topic echo` (transport H), the
# estimate checked against the truth. Also: an install into a prefix the user may not write.
# usage: install_tree.sh BUILD_DIR S H DOMAIN
set -uo pipefail
build=$1 sim_t=$2 host_t=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
start_work_with_programs

cmake --install "$build" --prefix "$work/first" > "$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; finish; }
mv "$work/first" "$work/moved"
prefix=$work/moved
for f in bin/plumb bin/plumb-plot bin/plumb-bridge bin/plumb-sim bin/plumb-estimator bin/plumb-calibrate bin/plumb-survey \
         lib/libplumb_plugin.so lib/libplumb_transport_cyclonedds.so lib/libplumb_transport_fastdds.so \
         lib/libplumb_estimator_compensated.so lib/libplumb_estimator_static.so lib/libplumb_estimator_integral.so \
         lib/libplumb_estimator_strapdown.so share/plumb/idl/attitude.idl share/plumb/idl/sensor.idl \
         share/plumb/config/fastdds-loopback.xml share/plumb/config/cyclonedds-loopback.xml \
         include/plumb/transport/transport.hpp include/plumb/transport/abi.hpp include/plumb/topics/all.hpp \
         include/plumb/estimator/estimator.hpp include/plumb/estimator/abi.hpp include/plumb/core/sample.hpp \
         lib/cmake/plumb/plumbConfig.cmake lib/cmake/plumb/plumbConfigVersion.cmake share/doc/plumb/README.md \
         share/doc/plumb/transports.md; do
  [ -e "$prefix/$f" ] || fail "installed tree lacks $f"
done
# Nothing installed may look for libraries in the build tree (RUNPATH $ORIGIN/... only).
for f in "$prefix"/bin/* "$prefix"/lib/*.so; do
  readelf -d "$f" > "$work/dyn" 2>&1
  if grep -q "$build" "$work/dyn"; then fail "$(basename "$f") has a RUNPATH into the build tree"; fi
done
pass "installed tree complete, RUNPATH relative"

# From the prefix alone: no build tree on PATH, no LD_LIBRARY_PATH, no plugin path variables.
run() { env -u LD_LIBRARY_PATH -u PLUMB_TRANSPORT_PATH -u PLUMB_ESTIMATOR_PATH PATH="$prefix/bin:/usr/bin:/bin" "$@"; }
output_matches "cyclonedds" run plumb transports && output_matches "fastdds" run plumb transports &&
  pass "plumb transports finds both plugins in the prefix" || fail "plumb transports: $(run plumb transports 2>&1)"
output_matches "compensated" run plumb plugins && pass "plumb plugins finds the estimators in the prefix" ||
  fail "plumb plugins: $(run plumb plugins 2>&1)"

# The shipped configuration files for stock applications: the loopback ones are good here; an
# interface that is not on this computer, and a broken file, are one line each naming file and line.
config=$prefix/share/plumb/config
output_matches "ok, Cyclone DDS" run plumb config check "$config/cyclonedds-loopback.xml" &&
  output_matches "ok, Fast DDS" run plumb config check "$config/fastdds-loopback.xml" &&
  pass "plumb config check accepts the loopback files" || fail "plumb config check: $(run plumb config check "$config"/*loopback.xml 2>&1)"
sed 's/name="eth1"/name="nosuch0"/' "$config/cyclonedds-interface.xml" > "$work/wrong-if.xml"
expect_error "configuration naming a missing interface" "wrong-if\.xml:[0-9]+: network interface 'nosuch0' is not on this computer" \
  run plumb config check "$work/wrong-if.xml"
sed 's|</Discovery>|</Discovry>|' "$config/cyclonedds-loopback.xml" > "$work/broken.xml"
line=$(grep -n "<Discovery>" "$work/broken.xml" | cut -d: -f1)  # tinyxml2 names the element left unclosed
expect_error "broken configuration file" "broken\.xml:$line: not well-formed XML" run plumb config check "$work/broken.xml"

# Nobody on this domain yet: plumb status says so, and what to check, in one line.
expect_error "plumb status with nobody on the domain" "no plumb component seen.*domain $PLUMB_DOMAIN_ID.*same --domain" \
  run plumb status --wait 2 --transport "$host_t"

# The live display (built where civetweb is): its page is inside the executable, so the installed
# program serves it with nothing else from the build tree.
if [ -x "$build/bin/plumb-display" ]; then
  if [ -x "$prefix/bin/plumb-display" ]; then
    # env itself, not the function run(): $! must be the program's pid (env execs it) to stop it below.
    env -u LD_LIBRARY_PATH -u PLUMB_TRANSPORT_PATH -u PLUMB_ESTIMATOR_PATH PATH="$prefix/bin:/usr/bin:/bin" \
      plumb-display --transport "$host_t" --port 0 --foxglove-port 0 --duration 20 > "$work/display.log" 2>&1 &
    display=$!
    pids+=($display)
    for ((i = 0; i < 100; ++i)); do grep -q "serving http" "$work/display.log" && break; sleep 0.1; done
    port=$(sed -nE 's|.*serving http://127\.0\.0\.1:([0-9]+)/.*|\1|p' "$work/display.log")
    output_matches "plumb live" python3 -c "import urllib.request; print(urllib.request.urlopen('http://127.0.0.1:${port:-1}/').read().decode())" &&
      pass "the installed plumb-display serves its page" || fail "installed plumb-display: $(cat "$work/display.log")"
    kill "$display"  # it publishes plumb/status: the checks below want the domain to themselves
    wait "$display" 2>/dev/null
  else
    fail "installed tree lacks bin/plumb-display"
  fi
fi

run plumb topic echo plumb/attitude/compensated --csv --count 1 --timeout 60 --transport "$host_t" \
  > "$work/att.csv" 2> "$work/echo.err" &
echo_pid=$!; pids+=($echo_pid)
run plumb-estimator --plugin compensated --input plumb/sensor/raw --reliable --window 5 --count 3 --timeout 60 -q \
  --transport "$host_t" > "$work/host.log" 2>&1 &
host_pid=$!; pids+=($host_pid)
# The waiting host reports itself once a second: plumb status lists it with this host's name.
if output_matches "$(hostname) *plumb-estimator *running" run plumb status --wait 3 --transport "$sim_t"; then
  pass "plumb status lists the estimator host with its host and state"
else
  fail "plumb status: $(run plumb status --wait 3 --transport "$sim_t" 2>&1)"
fi
# --counters: the host's counters under its row, from its latest report.
if output_matches "^ .*samples=0 .*lost_samples=0" run plumb status --counters --wait 3 --transport "$sim_t"; then
  pass "plumb status --counters prints the host's counters"
else
  fail "plumb status --counters: $(run plumb status --counters --wait 3 --transport "$sim_t" 2>&1)"
fi
run plumb-sim --transport "$sim_t" --inclination 1 --azimuth 45 --rpm 60 --duration 15.5 --snr-accel 40 --snr-mag 40 \
  --rate x4 --reliable --wait-subscribers 30 > "$work/sim.log" 2>&1 || fail "plumb-sim from the prefix: $(cat "$work/sim.log")"
wait $host_pid && pass "plumb-estimator from the prefix estimated" || fail "plumb-estimator: $(cat "$work/host.log")"
wait $echo_pid && python3 "$here/../e2e/check_estimates.py" "$work/att.csv" --inclination 1 --azimuth 45 \
  --inc-tol 0.02 --azi-tol 0.3 && pass "plumb topic echo from the prefix got the right attitude" ||
  fail "echo: $(cat "$work/echo.err" "$work/att.csv")"

# A prefix the user cannot write: cmake stops with an error naming the folder, nothing half-done.
# Root runs it without its power over file modes (the capabilities that bypass them), as itself:
# the build tree stays readable wherever the checkout lives (a private 0700 folder, umask 077),
# which another user such as nobody could not read.
as_user() { "$@"; }
if [ "$(id -u)" -eq 0 ]; then
  if command -v setpriv > /dev/null; then as_user() { setpriv --bounding-set=-dac_override,-dac_read_search,-fowner "$@"; }
  else as_user() { return 77; }; fi
fi
mkdir -p "$work/readonly" && chmod 555 "$work/readonly"
rc=0
as_user cmake --install "$build" --prefix "$work/readonly/plumb" > "$work/ro.log" 2>&1 || rc=$?
if [ $rc -eq 77 ]; then pass "unwritable prefix: not checked (root without setpriv)"
elif [ $rc -ne 0 ] && grep -q "$work/readonly/plumb" "$work/ro.log" && [ ! -e "$work/readonly/plumb" ]; then
  pass "unwritable prefix refused, naming it"
else fail "unwritable prefix: exit $rc: $(head -3 "$work/ro.log")"; fi
finish
