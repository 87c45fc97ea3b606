#!/usr/bin/env bash
# plumb compare --scenario drilling over the depth families a user runs it on: each family once (a
# tactical run at 10 Hz, one seed), its row named and its errors and coverage printed as finite
# numbers; the families' figures refused in one line with exit status 2 when out of range or given
# for a family not run. No DDS: compare drives the plugin in its own process.
# usage: compare_drilling.sh BIN_DIR
set -uo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export PATH=$bin:$PATH
one_run=(compare --scenario drilling --grade tactical --drilling-rate-hz 10 --seeds 1)

# The run's row of its family: 15 numbers (errors, drilled length, velocities, six coverages), all
# finite, then valid/estimates with at least 900 valid rows (it aligned).
check_row() {
  local what=$1 family=$2 out=$3
  awk -v family="$family" '
    $1 == "tactical" && $3 == family {
      found = 1
      gsub(/\|/, " ")
      n = split($0, f, " ")
      if (n != 20) { print "expected 20 fields, got " n ": " $0; exit 1 }
      for (i = 5; i <= 19; ++i) if (f[i] !~ /^-?[0-9]+(\.[0-9]+)?$/) { print "field " i " not a finite number: " f[i]; exit 1 }
      for (i = 14; i <= 19; ++i) if (f[i] + 0 <= 0) { print "coverage " i " not above 0: " f[i]; exit 1 }
      split(f[20], v, "/")
      if (v[1] + 0 < 900) { print "only " f[20] " valid rows"; exit 1 }
    }
    END { if (!found) { print "no row with depth " family; exit 1 } }' "$out" > "$work/why" &&
    grep -q "c.att c.pos c.end" "$out" && pass "$what: the $family row, its errors and coverage" ||
    fail "$what: $(cat "$work/why") $(cat "$out")"
}

run_family() {
  local what=$1 family=$2 said=$3; shift 3
  local out="$work/$family.out" start end
  start=$(date +%s.%N)
  if ! plumb "${one_run[@]}" "$@" > "$out" 2> "$work/$family.err"; then
    fail "$what: exit status $?: $(cat "$work/$family.err")"
    return
  fi
  end=$(date +%s.%N)
  echo "    $what: $(echo "$end - $start" | bc) s"
  check_row "$what" "$family" "$out"
  grep -qF -- "$said" "$out" && pass "$what: the table says '$said'" || fail "$what: '$said' not in $(cat "$out")"
}

run_family "depth with 3 cm of noise" yes "with 0.03 m of noise" --depth yes --depth-sd 0.03
run_family "no depth" no "c.end at the last row" --depth no
run_family "rig depth, 0.1 ft, late, empty between reports" rig "rounded to 0.03048 m, 0.7 s late, empty between reports" \
  --depth rig --depth-sd 0.02 --rig-quantum 0.03048 --rig-late 0.7 --rig-empty
run_family "pipe tally only" tally "measured to 0.02 m (pipe_tally_m" --depth tally
run_family "sensors noisier than the grade" yes "noise 3x their grade's preset" --depth yes --noisier 3

# Several families in one command: one row each, in the order given.
plumb "${one_run[@]}" --depth rig,tally > "$work/two.out" 2>&1 &&
  [ "$(awk '$1 == "tactical" { printf "%s ", $3 }' "$work/two.out")" = "rig tally " ] &&
  pass "--depth rig,tally: a rig row, then a tally row" || fail "--depth rig,tally: $(cat "$work/two.out")"

expect_usage "an unknown family" "--depth takes yes, no, both, rig, tally or all, not 'wet'" plumb compare --scenario drilling --depth wet
expect_usage "a negative depth noise" "--depth-sd \(m\) must be between 0 and 1" plumb compare --scenario drilling --depth-sd -0.01
expect_usage "a rig figure without the rig family" "--rig-late applies to --depth rig" plumb compare --scenario drilling --depth yes --rig-late 1
expect_usage "a delay past a minute" "--rig-late \(s\) must be between 0 and 60" plumb compare --scenario drilling --depth rig --rig-late 61
expect_usage "a tally figure without the tally" "--tally-sd applies to --depth tally" plumb compare --scenario drilling --tally-sd 0.05
expect_usage "a noise multiplier of 0" "--noisier must be above 0" plumb compare --scenario drilling --noisier 0
expect_usage "a drilling option on the platform grid" "--noisier applies to --scenario drilling" plumb compare --noisier 2
finish
