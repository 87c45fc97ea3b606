#!/usr/bin/env bash
# Builds the libFuzzer targets with clang in their own build directory and runs each for a
# bounded time. usage: tests/fuzz/run.sh [SECONDS_PER_TARGET (default 60)] [BUILD_DIR]
# Exit status non-zero if a target finds a crash (the reproducer is left in BUILD_DIR/fuzz-out).
set -euo pipefail
seconds=${1:-60}
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${2:-$src/build-fuzz}
cc=$(command -v clang-14 || command -v clang || true)
cxx=$(command -v clang++-14 || command -v clang++ || true)
if [ -z "$cc" ] || [ -z "$cxx" ]; then
  echo "fuzz: clang not found (apt-get install -y clang-14 libclang-rt-14-dev)" >&2
  exit 1
fi
mkdir -p "$build"
cmake -S "$src" -B "$build" -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPLUMB_BUILD_FUZZERS=ON -DPLUMB_BUILD_TESTS=ON -DPLUMB_BUILD_BENCHMARKS=OFF > "$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; exit 1; }
targets=(plumb_fuzz_frame_parser plumb_fuzz_csv_reader plumb_fuzz_mcap_reader plumb_fuzz_wits_parser)
cmake --build "$build" -j2 --target "${targets[@]}"
out=$build/fuzz-out
mkdir -p "$out"
status=0
for t in "${targets[@]}"; do
  corpus=$out/$t-corpus
  mkdir -p "$corpus"
  cp -n "$src/tests/fuzz/seeds/${t#plumb_}"/* "$corpus/" 2>/dev/null || true
  echo "fuzz: $t for ${seconds}s"
  if ! (cd "$out" && "$build/bin/$t" -max_total_time="$seconds" -rss_limit_mb=2048 -max_len=4096 \
        -artifact_prefix="$out/$t-" "$corpus" > "$out/$t.log" 2>&1); then
    echo "fuzz: $t FAILED; see $out/$t.log"; tail -40 "$out/$t.log"; status=1
  else
    tail -2 "$out/$t.log"
  fi
done
exit $status
