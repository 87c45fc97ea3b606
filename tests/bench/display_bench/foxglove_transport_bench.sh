#!/usr/bin/env bash
# Does a Foxglove client slow DDS? plumb-bench-transport's latency and throughput, alternately
# without and with plumb-display on the benchmark's domain and one Foxglove client subscribed to
# every channel (the benchmark's own topics included), each run only while /proc/loadavg's 1-min
# figure is below 2.5. Prints each run's plumb rows (median / native) and the display's Foxglove
# counters; docs/benchmarks.md keeps the figures. No assertion: a measurement, not a test.
# The client is tests/integration/display/foxglove_client.js on Foxglove's npm packages, installed
# into NODE_DIR as the integration test does.
# usage: foxglove_transport_bench.sh BIN_DIR NODE_DIR PAIRS [plumb-bench-transport options...]
set -uo pipefail
bin=$1 node_dir=$2 pairs=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
client_js=$here/../../integration/display/foxglove_client.js
export NODE_PATH=$node_dir/node_modules
[ -f "$NODE_PATH/@foxglove/ws-protocol/package.json" ] || {
  npm install --prefix "$node_dir" --no-audit --no-fund --no-save @foxglove/ws-protocol@0.8 ws@8 \
    @foxglove/omgidl-parser@1 @foxglove/omgidl-serialization@1 > /dev/null 2>&1 || { echo "npm install failed"; exit 1; }
}
domain=$((100 + $$ % 100))
work=$(mktemp -d)
trap 'kill $display $client 2>/dev/null; rm -rf "$work"' EXIT
display="" client=""

quiet_machine() {  # waits until the 1-min load average is below 2.5
  while awk '{ exit !($1 >= 2.5) }' /proc/loadavg; do sleep 10; done
}

run_bench() {  # run_bench LABEL [plumb-bench-transport options...]
  quiet_machine
  echo "## $1 (load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%H:%M:%S))"
  shift
  "$bin/plumb-bench-transport" --domain "$domain" "$@" > "$work/bench.txt" 2>&1
  grep -E "^\| (SensorBatch|Attitude).*\| (native )?(cyclonedds|fastdds) -> " "$work/bench.txt"
  grep -E "load|busy" "$work/bench.txt" | head -3
}

with_foxglove() {
  "$bin/plumb-display" --domain "$domain" --port 0 --foxglove-port 0 > "$work/display.log" 2>&1 &
  display=$!
  for ((i = 0; i < 200; ++i)); do grep -q "Foxglove on ws://" "$work/display.log" && break; sleep 0.1; done
  port=$(sed -nE 's|.*Foxglove on ws://127\.0\.0\.1:([0-9]+)/.*|\1|p' "$work/display.log")
  node "$client_js" "ws://127.0.0.1:$port/" 3600 "$work/client.json" '*' > "$work/client.log" 2>&1 &
  client=$!
  sleep 1
  run_bench "with plumb-display and one Foxglove client subscribed to every channel" "${bench_args[@]}"
  "$bin/plumb" topic echo plumb/status --csv --domain "$domain" --count 1 --timeout 5 2>/dev/null | python3 -c "
import csv, sys
rows = [r for r in csv.DictReader(sys.stdin) if r.get('counters.name', '').startswith('foxglove_')]
print('display counters: ' + ' '.join(r['counters.name'] + '=' + r['counters.value'] for r in rows))"
  kill "$client"; wait "$client" 2>/dev/null
  python3 -c "import json; r = json.load(open('$work/client.json')); print('client: %d messages on %d channels (%s)' % (sum(t['messages'] for t in r['topics'].values()), len(r['channels']), ', '.join(sorted(r['topics']))))"
  kill "$display"; wait "$display" 2>/dev/null
  display="" client=""
}

bench_args=("$@")
for ((p = 1; p <= pairs; ++p)); do
  if ((p % 2)); then
    run_bench "pair $p: without Foxglove" "${bench_args[@]}"
    with_foxglove
  else
    with_foxglove
    run_bench "pair $p: without Foxglove" "${bench_args[@]}"
  fi
done
