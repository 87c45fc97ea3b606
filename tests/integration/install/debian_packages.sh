#!/usr/bin/env bash
# The Debian packages as a field engineer gets them: `cpack -G DEB` from the build tree, their
# contents and dependencies checked with dpkg-deb, then the tool computer's packages (plumb-tool and
# the plumb-* packages it depends on) unpacked into an empty folder and run from there: plumb-sim
# writes a recording, plumb-bridge replays it onto DDS, `plumb topic echo` reads it back. Also: a
# vendor library missing at run time is one line naming it and its Debian package.
# usage: debian_packages.sh BUILD_DIR DOMAIN
set -uo pipefail
build=$1
export PLUMB_DOMAIN_ID=$2
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
command -v dpkg-deb > /dev/null || { echo "dpkg-deb not found: skipped"; exit 77; }

start=$(date +%s)
(cd "$work" && cpack -G DEB -B "$work/debs" --config "$build/CPackConfig.cmake") > "$work/cpack.log" 2>&1 ||
  { tail -30 "$work/cpack.log"; fail "cpack -G DEB"; finish; }
echo "cpack: $(( $(date +%s) - start )) s"
ls -l "$work"/debs/*.deb | awk '{print $5, $9}' | sed "s|$work/debs/||"
deb() { ls "$work"/debs/"$1"_*.deb 2>/dev/null | head -1; }
for p in plumb-common plumb-tool plumb-surface plumb-dev plumb-transport-cyclonedds plumb-transport-fastdds; do
  [ -n "$(deb $p)" ] || fail "no package $p"
done

# Contents: each computer's programs in its package, nothing twice.
contains() {  # contains PACKAGE PATH...: every PATH is in the package
  local p=$1 f; shift
  dpkg-deb -c "$(deb "$p")" > "$work/$p.list"
  for f in "$@"; do grep -q " \./opt/plumb/$f\$" "$work/$p.list" || fail "$p lacks $f"; done
}
contains plumb-tool bin/plumb-bridge bin/plumb-sim
contains plumb-surface bin/plumb-estimator bin/plumb-calibrate lib/libplumb_estimator_compensated.so \
  lib/libplumb_estimator_strapdown.so
if [ -x "$build/bin/plumb-display" ]; then contains plumb-surface bin/plumb-display; fi  # built where civetweb is
contains plumb-common bin/plumb lib/libplumb_plugin.so lib/libplumb_transport.so share/plumb/idl/attitude.idl \
  share/plumb/config/fastdds-loopback.xml share/plumb/config/cyclonedds-loopback.xml share/doc/plumb/README.md
contains plumb-transport-cyclonedds lib/libplumb_transport_cyclonedds.so
contains plumb-transport-fastdds lib/libplumb_transport_fastdds.so
contains plumb-dev include/plumb/transport/transport.hpp include/plumb/estimator/estimator.hpp lib/cmake/plumb/plumbConfig.cmake
if grep -q "plumb-estimator" "$work/plumb-tool.list"; then fail "plumb-tool carries the estimator host"; fi
dups=$(cat "$work"/*.list | awk '$1 !~ /^d/ {print $NF}' | sort | uniq -d)
[ -z "$dups" ] && pass "package contents: each file in one package" || fail "files in two packages: $dups"

# Dependencies: the vendor libraries (from dpkg-shlibdeps), plumb's own packages at this version.
depends() { dpkg-deb -f "$(deb "$1")" Depends; }
field_has() {  # field_has WHAT PACKAGE REGEX
  local d; d=$(depends "$2")
  if grep -qE -- "$3" <<< "$d"; then pass "$1"; else fail "$1: Depends: $d"; fi
}
field_has "Cyclone transport depends on libddsc0debian" plumb-transport-cyclonedds "(^|, )libddsc0debian( |,|$)"
field_has "Fast DDS transport depends on libfastrtps2.9" plumb-transport-fastdds "(^|, )libfastrtps2\.9( |,|$)"
field_has "Fast DDS transport depends on libfastcdr1" plumb-transport-fastdds "(^|, )libfastcdr1( |,|$)"
field_has "plumb-tool depends on plumb-common and a transport" plumb-tool \
  "plumb-common \(= [0-9.]+\).*plumb-transport-(cyclonedds|fastdds)"
field_has "plumb-surface depends on plumb-common and a transport" plumb-surface \
  "plumb-common \(= [0-9.]+\).*plumb-transport-(cyclonedds|fastdds)"
field_has "plumb-common depends on the C++ runtime" plumb-common "libstdc\+\+6"
if depends plumb-common | grep -qE "libddsc|libfastrtps"; then fail "plumb-common depends on a DDS vendor"; fi
recommends=$(dpkg-deb -f "$(deb plumb-common)" Recommends)
grep -qE "(^|, )openssl( |,|$)" <<< "$recommends" && pass "plumb-common recommends openssl (plumb security create-*)" ||
  fail "plumb-common Recommends: $recommends"

# The tool computer: plumb-tool and the plumb packages it depends on (first alternative, as apt
# picks), unpacked into an empty root; nothing from the build tree.
root=$work/root
mkdir -p "$root"
wanted=(plumb-tool)
for dep in $(depends plumb-tool | tr ',' '\n' | sed 's/|.*//; s/(.*//' | tr -d ' ' | grep '^plumb-'); do wanted+=("$dep"); done
# Recommends: the other transport too, for the missing-library check below.
[ -n "$(deb plumb-transport-fastdds)" ] && wanted+=(plumb-transport-fastdds)
for p in "${wanted[@]}"; do dpkg-deb -x "$(deb "$p")" "$root" || fail "dpkg-deb -x $p"; done
echo "tool computer unpacked: ${wanted[*]}"
bin=$root/opt/plumb/bin
run() { env -u LD_LIBRARY_PATH -u PLUMB_TRANSPORT_PATH -u PLUMB_ESTIMATOR_PATH PATH="$bin:/usr/bin:/bin" "$@"; }
[ -e "$bin/plumb-estimator" ] && fail "the tool computer got the estimator host"
transport=cyclonedds  # the first alternative of plumb-tool's Depends, unpacked above
run plumb-sim --csv "$work/rec" --inclination 2 --azimuth 30 --duration 2 > "$work/sim.log" 2>&1 &&
  [ -s "$work/rec/sensor.csv" ] && pass "plumb-sim from the package wrote a recording" || fail "plumb-sim: $(cat "$work/sim.log")"
run plumb topic echo plumb/sensor/raw --count 3 --timeout 60 --reliable --transport "$transport" \
  > "$work/echo.out" 2> "$work/echo.err" &
echo_pid=$!; pids+=($echo_pid)
run plumb-bridge --replay "$work/rec/sensor.csv" --rate x4 --reliable --wait-subscribers 30 --transport "$transport" \
  > "$work/bridge.log" 2>&1 || fail "plumb-bridge --replay from the package: $(tail -3 "$work/bridge.log")"
wait $echo_pid && pass "plumb-bridge -> DDS -> plumb topic echo, all from the tool packages ($transport)" ||
  fail "echo: $(cat "$work/echo.err")"

# A vendor library missing at run time (here: made unreadable in a private mount namespace).
fastrtps=$(ldconfig -p | awk '/libfastrtps\.so\.2\.9 /{print $NF; exit}')
if [ -n "$fastrtps" ] && [ -e "$root/opt/plumb/lib/libplumb_transport_fastdds.so" ] && unshare -m true 2> /dev/null; then
  expect_error "missing libfastrtps names it and its package" "libfastrtps\.so\.2\.9.*Debian package libfastrtps2\.9" \
    unshare -m sh -c "mount --bind /dev/null '$fastrtps' && exec env PATH='$bin:/usr/bin:/bin' plumb topic list --transport fastdds"
fi
finish
