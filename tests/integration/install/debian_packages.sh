#!/usr/bin/env bash
# The Debian packages as a field engineer gets them: `cpack -G DEB` from the build tree, their
# contents and dependencies checked with dpkg-deb, then the tool computer's packages (plumb-tool and
# the plumb-* packages it depends on) unpacked into an empty folder and run from there: plumb-sim
# writes a recording, plumb-bridge replays it onto DDS, `plumb topic echo` reads it back. Also: a
# vendor library missing at run time is one line naming it and its Debian package.
# The systemd units: every unit verified by systemd-analyze against the unpacked packages, the
# maintainer scripts parsed, and the shipped environment files run as systemd runs them (no systemd
# runs in a container: systemd_exec.py reads EnvironmentFile= and ExecStart= as it does).
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
contains plumb-tool bin/plumb-bridge bin/plumb-sim share/plumb/systemd/env/bridge-board.env
contains plumb-surface bin/plumb-estimator bin/plumb-calibrate lib/libplumb_estimator_compensated.so \
  lib/libplumb_estimator_strapdown.so bin/plumb-wits bin/plumb-wits-send share/plumb/systemd/env/wits.env
for unit in plumb-estimator plumb-survey plumb-wits; do
  grep -q " \./lib/systemd/system/$unit\.service\$" "$work/plumb-surface.list" || fail "plumb-surface lacks $unit.service"
done
grep -q " \./lib/systemd/system/plumb-bridge@\.service\$" "$work/plumb-tool.list" || fail "plumb-tool lacks plumb-bridge@.service"
if [ -x "$build/bin/plumb-display" ]; then contains plumb-surface bin/plumb-display; fi  # built where civetweb is
contains plumb-common bin/plumb lib/libplumb_plugin.so lib/libplumb_transport.so share/plumb/idl/attitude.idl \
  share/plumb/params/drilling-mems.yaml share/plumb/launch/one-machine.yaml share/plumb/systemd/env/plumb.env \
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

# The surface computer's packages beside the tool's: the units of both, verified by systemd against
# what the packages installed (its own targets copied beside them, so that nothing else is missing).
dpkg-deb -x "$(deb plumb-surface)" "$root" || fail "dpkg-deb -x plumb-surface"
units=$(cd "$root" && ls lib/systemd/system/plumb-*.service)
echo "units: $(echo $units)"
if command -v systemd-analyze > /dev/null; then
  cp -n /lib/systemd/system/*.target "$root/lib/systemd/system/" 2>/dev/null
  for unit in $units; do
    out=$(systemd-analyze verify --man=no --root="$root" "/$unit" 2>&1); rc=$?
    [ $rc -eq 0 ] && [ -z "$out" ] && pass "systemd-analyze verify $unit: clean" || fail "verify $unit (exit $rc): $out"
  done
  for unit in $units; do
    grep -q "^Restart=on-failure$" "$root/$unit" && grep -q "^User=plumb$" "$root/$unit" && grep -q "^NoNewPrivileges=yes$" "$root/$unit" &&
      grep -q "^ProtectSystem=strict$" "$root/$unit" && grep -q "^EnvironmentFile=/etc/plumb/plumb.env$" "$root/$unit" ||
      fail "$unit lacks the restart policy, its user, the hardening or the environment file"
  done
  exposure=$(systemd-analyze security --offline=yes --root="$root" "/lib/systemd/system/plumb-estimator.service" 2>&1 | tail -1)
  echo "systemd-analyze security: $exposure"
else
  fail "systemd-analyze not found (systemd: .ci/install-deps installs it)"
fi
for package in plumb-tool plumb-surface; do
  mkdir -p "$work/control-$package" && dpkg-deb -e "$(deb $package)" "$work/control-$package"
  for script in postinst prerm postrm; do
    sh -n "$work/control-$package/$script" 2> "$work/sh.err" || fail "$package $script: $(cat "$work/sh.err")"
  done
  grep -q "adduser --system --group" "$work/control-$package/postinst" && pass "$package makes the plumb user in postinst" ||
    fail "$package postinst makes no user"
done
field_has "plumb-tool depends on adduser (postinst)" plumb-tool "(^|, )adduser( |,|$)"
grep -q "plumb-bridge@\*\.service" "$work/control-plumb-tool/prerm" && pass "plumb-tool's prerm stops its bridge instances" ||
  fail "plumb-tool prerm: $(cat "$work/control-plumb-tool/prerm")"

# The shipped environment files, as an administrator sets them (/etc/plumb from the templates, the
# domain edited in plumb.env), run through the units as systemd would.
mkdir -p "$root/etc/plumb"
cp "$root"/opt/plumb/share/plumb/systemd/env/*.env "$root/etc/plumb/"
sed -i "s/^PLUMB_DOMAIN_ID=.*/PLUMB_DOMAIN_ID=$PLUMB_DOMAIN_ID/" "$root/etc/plumb/plumb.env"
unit_run() { env -i python3 "$here/systemd_exec.py" "$root" "$root/lib/systemd/system/$1" > "$work/$1.log" 2>&1 & }
unit_run plumb-estimator.service; estimator_pid=$!; pids+=($estimator_pid)
unit_run plumb-wits.service; wits_pid=$!; pids+=($wits_pid)
run plumb status --wait 8 --domain "$PLUMB_DOMAIN_ID" > "$work/status.txt" 2>&1
grep -q "plumb-estimator" "$work/status.txt" && grep -q "plumb-wits/board" "$work/status.txt" &&
  pass "plumb-estimator and plumb-wits from their units' environment files, on plumb.env's domain" ||
  fail "plumb status: $(cat "$work/status.txt") estimator: $(cat "$work/plumb-estimator.service.log") wits: $(cat "$work/plumb-wits.service.log")"
run plumb topic echo plumb/depth --count 3 --timeout 30 --domain "$PLUMB_DOMAIN_ID" > "$work/depth.txt" 2>&1 &
echo_pid=$!; pids+=($echo_pid)
sleep 1
run plumb-wits-send --connect 127.0.0.1:5000 --count 3 --interval 0.2 > "$work/send.log" 2>&1 || fail "plumb-wits-send"
wait $echo_pid && [ "$(grep -c 'depth_m: 1000' "$work/depth.txt")" -eq 3 ] &&
  pass "wits.env's --listen 5000: three depths from a rig on plumb/depth" || fail "depth echo: $(cat "$work/depth.txt")"
# systemctl stop: SIGTERM. plumb-wits ends with 0; the estimator host, which never got a sample
# here, ends saying so with status 1 (a run that received nothing is not a success).
kill -TERM $estimator_pid $wits_pid
wait $wits_pid && pass "plumb-wits stops on SIGTERM (systemctl stop), exit status 0" ||
  fail "plumb-wits on SIGTERM: $(tail -n 3 "$work/plumb-wits.service.log")"
wait $estimator_pid; rc=$?
[ $rc -le 1 ] && grep -q "no sample received on plumb/sensor/calibrated" "$work/plumb-estimator.service.log" &&
  pass "plumb-estimator stops on SIGTERM, saying it received nothing (exit status $rc)" ||
  fail "plumb-estimator on SIGTERM: exit $rc, $(tail -n 3 "$work/plumb-estimator.service.log")"
finish
