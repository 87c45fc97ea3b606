#!/usr/bin/env bash
# Each vendor can be left out at build time: configure plumb with -DPLUMB_WITH_<VENDOR>=OFF into a
# scratch folder and check that nothing of that vendor is left: no target, no package, no link
# to its libraries. (Configure only: the build is the same code as the full build's.)
# usage: single_vendor.sh SOURCE_DIR LEFT_OUT(cyclonedds|fastdds)
set -uo pipefail
src=$1 out=$2
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
upper=$(tr a-z A-Z <<< "$out")
keep=cyclonedds; [ "$out" = cyclonedds ] && keep=fastdds
if cmake -S "$src" -B "$work" -DPLUMB_WITH_$upper=OFF -DPLUMB_BUILD_TESTS=OFF -DPLUMB_BUILD_BENCHMARKS=OFF \
     > "$work/configure.log" 2>&1; then
  pass "configures without $out"
else
  fail "configure without $out: $(tail -20 "$work/configure.log")"; finish
fi
cmake --build "$work" --target help > "$work/targets" 2>&1
grep -q "plumb_transport_$keep\$" "$work/targets" && pass "the $keep transport is still built" || fail "no plumb_transport_$keep target"
if grep -qE "plumb_transport_$out|plumb_idl_$out" "$work/targets"; then fail "a $out target is left"; else pass "no $out target"; fi
grep -q "plumb-transport-$out" "$work/CPackConfig.cmake" && fail "CPack still packages plumb-transport-$out" ||
  pass "no plumb-transport-$out package"
vendor_lib=ddsc; [ "$out" = fastdds ] && vendor_lib=fastrtps
if grep -rlq "$vendor_lib" "$work"/CMakeFiles/*.dir/link.txt "$work"/*/CMakeFiles/*.dir/link.txt \
     "$work"/*/*/CMakeFiles/*.dir/link.txt 2>/dev/null; then
  fail "something still links $vendor_lib"
else
  pass "nothing links $vendor_lib"
fi
# Both off is refused, in one line that says why.
rc=0
cmake -S "$src" -B "$work/none" -DPLUMB_WITH_CYCLONEDDS=OFF -DPLUMB_WITH_FASTDDS=OFF > "$work/none.log" 2>&1 || rc=$?
[ $rc -ne 0 ] && grep -q "are both OFF" "$work/none.log" && pass "both vendors off is refused" ||
  fail "both vendors off: exit $rc"
finish
