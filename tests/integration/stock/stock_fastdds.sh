#!/usr/bin/env bash
# A stock Fast DDS application and plumb, on one computer: the examples `fastddsgen -example CMake`
# generates from idl/attitude.idl and idl/sensor.idl (code nobody on the team wrote), changed only
# as adapt_fastddsgen.sh says and run with the shipped profile (transports/config/fastdds-loopback.xml),
# against plumb on each of its transports:
#   plumb topic pub plumb/attitude/test -> stock subscriber (prints the inclination it got);
#   stock publisher -> plumb/sensor/raw -> plumb-estimator (static plugin) -> plumb topic echo.
# usage: stock_fastdds.sh SOURCE_DIR BIN_DIR DOMAIN
set -uo pipefail
src=$1 bin=$2
export PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
. "$here/../multihost/netns.sh"
work=$(mktemp -d)
pids=()
cleanup() { exec 3>&- 2>/dev/null; for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done; netns_cleanup; rm -rf "$work"; }
trap cleanup EXIT
export FASTRTPS_DEFAULT_PROFILES_FILE=$src/transports/config/fastdds-loopback.xml

launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
for name in attitude sensor; do
  mkdir -p "$work/$name"
  topic=plumb/attitude/test
  [ $name = sensor ] && topic=plumb/sensor/raw
  if fastddsgen -example CMake -d "$work/$name" "$src/idl/$name.idl" > "$work/$name.log" 2>&1 &&
     "$here/adapt_fastddsgen.sh" "$work/$name" $name $topic >> "$work/$name.log" 2>&1 &&
     cmake -S "$work/$name" -B "$work/$name/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >> "$work/$name.log" 2>&1 &&
     cmake --build "$work/$name/build" -j2 >> "$work/$name.log" 2>&1; then
    pass "fastddsgen's $name example generated, adapted, built"
  else
    fail "$name example: $(tail -15 "$work/$name.log")"; finish
  fi
done

for t in cyclonedds fastdds; do
  # plumb -> stock subscriber. It stops when its standard input closes (it waits for Enter).
  mkfifo "$work/in.$t"
  "$work/attitude/build/attitude" subscriber < "$work/in.$t" > "$work/sub.$t" 2>&1 &
  pids+=($!); sub=$!
  exec 3> "$work/in.$t"
  "$bin/plumb" topic pub plumb/attitude/test inclination_deg=1.5 azimuth_deg=12 --count 3 --rate 5 --wait 20 \
    --transport $t > "$work/pub.$t" 2>&1 || fail "plumb topic pub ($t): $(cat "$work/pub.$t")"
  if wait_for "$work/sub.$t" "Sample received, count=3 inclination_deg=1.5" 20; then
    pass "stock Fast DDS subscriber got plumb's attitude from $t"
  else
    fail "stock subscriber, plumb on $t: $(cat "$work/pub.$t" "$work/sub.$t")"
  fi
  exec 3>&-
  wait $sub

  # Stock publisher -> plumb. It sends one batch, then one per "y" line, and stops at "n".
  "$bin/plumb" topic echo plumb/attitude/static --csv --count 1 --timeout 60 --transport $t > "$work/att.$t" 2> "$work/echo.$t" &
  pids+=($!); echo_pid=$!
  "$bin/plumb-estimator" --plugin static --window 2 --input plumb/sensor/raw --reliable --count 2 --timeout 60 -q \
    --transport $t > "$work/host.$t" 2>&1 &
  pids+=($!); host=$!
  # Paced, and long enough (8 s): the writer sends on its own match, while the reader side may match
  # only after Fast DDS repeats its discovery data (a heartbeat period, 3 s); earlier batches are lost.
  { for i in $(seq 1 80); do echo y; sleep 0.1; done; echo n; } | "$work/sensor/build/sensor" publisher > "$work/spub.$t" 2>&1 ||
    fail "stock publisher ($t): $(cat "$work/spub.$t")"
  wait $host && pass "plumb-estimator ($t) accepted the stock publisher's batches" || fail "host ($t): $(cat "$work/host.$t")"
  wait $echo_pid && python3 "$here/../e2e/check_estimates.py" "$work/att.$t" --inclination 2 --azimuth 30 \
    --inc-tol 0.01 --azi-tol 0.1 && pass "its estimate is the stock publisher's attitude ($t)" ||
    fail "echo ($t): $(cat "$work/echo.$t" "$work/att.$t")"
done

# Two computers: network namespaces joined by a veth pair; the stock programs use the shipped
# interface profile with the address edited (fastdds-interface.xml), plumb uses --interface, and the
# two sides use different plumb transports.
if ! netns_pair 10.233.0; then echo "network namespaces unavailable: two-computer part skipped"; finish; fi
for side in tool surface; do
  address=10.233.0.1; [ $side = surface ] && address=10.233.0.2
  sed "s|192.168.10.2|$address|" "$src/transports/config/fastdds-interface.xml" > "$work/$side.xml"
done
in_tool() { ip netns exec "$tool" env FASTRTPS_DEFAULT_PROFILES_FILE="$work/tool.xml" "$@"; }
in_surface() { ip netns exec "$surface" env FASTRTPS_DEFAULT_PROFILES_FILE="$work/surface.xml" "$@"; }

mkfifo "$work/in.hosts"
in_surface "$work/attitude/build/attitude" subscriber < "$work/in.hosts" > "$work/sub.hosts" 2>&1 &
exec 3> "$work/in.hosts"
in_tool "$bin/plumb" topic pub plumb/attitude/test inclination_deg=1.5 --count 3 --rate 5 --wait 20 --transport cyclonedds \
  --interface "$tool_if" > "$work/pub.hosts" 2>&1 || fail "plumb topic pub (tool side): $(cat "$work/pub.hosts")"
wait_for "$work/sub.hosts" "Sample received, count=3 inclination_deg=1.5" 20 &&
  pass "stock Fast DDS subscriber (surface) got plumb's attitude from the tool side (cyclonedds)" ||
  fail "stock subscriber across: $(cat "$work/pub.hosts" "$work/sub.hosts")"
exec 3>&-

in_surface "$bin/plumb" topic echo plumb/attitude/static --csv --count 1 --timeout 60 --transport fastdds \
  --interface "$surface_if" > "$work/att.hosts" 2> "$work/echo.hosts" &
echo_pid=$!
in_surface "$bin/plumb-estimator" --plugin static --window 2 --input plumb/sensor/raw --reliable --count 2 --timeout 60 -q \
  --transport fastdds --interface "$surface_if" > "$work/host.hosts" 2>&1 &
host=$!
{ for i in $(seq 1 80); do echo y; sleep 0.1; done; echo n; } | in_tool "$work/sensor/build/sensor" publisher > "$work/spub.hosts" 2>&1 ||
  fail "stock publisher (tool side): $(tail -c 300 "$work/spub.hosts")"
wait $host && pass "plumb-estimator (surface, fastdds) accepted the stock publisher's batches from the tool side" ||
  fail "host across: $(cat "$work/host.hosts")"
wait $echo_pid && python3 "$here/../e2e/check_estimates.py" "$work/att.hosts" --inclination 2 --azimuth 30 \
  --inc-tol 0.01 --azi-tol 0.1 && pass "its estimate is the stock publisher's attitude (across)" ||
  fail "echo across: $(cat "$work/echo.hosts" "$work/att.hosts")"
finish
