#!/usr/bin/env bash
# The independent reader: a plumb recording (every topic: sensor, truth, attitude; metadata) read
# by the MCAP TypeScript library under node, its messages decoded with the IDL schema the file
# carries. Skipped (77) without node and npm; npm installs the libraries into the build folder.
# usage: mcap_core_check.sh BIN_DIR NPM_DIR TRANSPORT DOMAIN
set -uo pipefail
bin=$1 npm_dir=$2
export PLUMB_TRANSPORT=$3 PLUMB_DOMAIN_ID=$4
here=$(dirname "$0")
. "$here/../lib.sh"
. "$here/../wait.sh"
if ! command -v node > /dev/null || ! command -v npm > /dev/null; then
  echo "skipped: node and npm are needed (apt-get install nodejs npm)"
  exit 77
fi
packages=(@mcap/core fzstd @foxglove/omgidl-parser @foxglove/omgidl-serialization)
if [ ! -d "$npm_dir/node_modules/@foxglove/omgidl-serialization" ]; then
  timeout 300 npm install --prefix "$npm_dir" --no-audit --no-fund --loglevel=error "${packages[@]}" > "$npm_dir.log" 2>&1 ||
    { echo "skipped: npm install failed: $(tail -3 "$npm_dir.log")"; exit 77; }
fi
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT

"$bin/plumb" record --reliable -o "$work/all.mcap" > "$work/rec.log" 2>&1 &
rec=$!
wait_for "$work/rec.log" "recording" 30 || fail "recorder did not start: $(cat "$work/rec.log")"
"$bin/plumb" topic pub plumb/attitude/test tool_id=T7 estimator=test inclination_deg=1.25 azimuth_deg=271.5 flags=3 \
  reason=fine --count 3 --rate 20 --wait 15 > /dev/null 2>&1 || fail "pub attitude"
timeout 60 "$bin/plumb-sim" --inclination 2 --azimuth 45 --rpm 60 --count 500 --batch 10 --rate x20 --reliable \
  --wait-subscribers 20 --linger 2 > "$work/sim.log" 2>&1 || fail "sim: $(cat "$work/sim.log")"
kill -INT $rec
wait $rec || fail "recorder: $(cat "$work/rec.log")"
"$bin/plumb" info "$work/all.mcap" > "$work/info.txt" 2>&1

NODE_PATH="$npm_dir/node_modules" node "$here/read_with_mcap_core.js" "$work/all.mcap" > "$work/node.json" 2> "$work/node.err" ||
  fail "mcap/core could not read the recording: $(cat "$work/node.err")"
python3 - "$work/node.json" "$work/info.txt" <<'PY' && pass "mcap/core read every record, schema and message as plumb info counts them" || fail "mcap/core: $(cat "$work/node.json" "$work/node.err") $(cat "$work/info.txt")"
import json, re, sys
r = json.load(open(sys.argv[1]))
info = open(sys.argv[2]).read()
counts = {m[0]: int(m[1]) for m in re.findall(r"Topic: (\S+) \| Type: \S+ \| Count: (\d+)", info)}
total = int(re.search(r"Messages: +(\d+)", info).group(1))
recorded = {t: n for t, n in counts.items() if n > 0}
problems = []
if r["topics"] != recorded: problems.append(f"per topic {r['topics']} != {recorded}")
if r["decoded"] != total: problems.append(f"decoded {r['decoded']} of {total}")
if r["indexed"]["message_count"] != total or r["indexed"]["read"] != total: problems.append(f"indexed {r['indexed']}")
if r["indexed"]["metadata"] != ["plumb"]: problems.append(f"metadata {r['indexed']['metadata']}")
if not all(s["encoding"] == "omgidl" for s in r["schemas"]): problems.append(f"schemas {r['schemas']}")
a = r["first"].get("plumb/attitude/test", {})
if a.get("inclination_deg") != 1.25 or a.get("azimuth_deg") != 271.5 or a.get("tool_id") != "T7" or a.get("reason") != "fine":
    problems.append(f"attitude decoded as {a}")
b = r["first"].get("plumb/sensor/raw", {})
if len(b.get("samples", [])) != 10: problems.append(f"sensor batch decoded as {b}")
if recorded.get("plumb/sensor/raw") != 50 or recorded.get("plumb/attitude/test") != 3: problems.append(f"recorded {recorded}")
print("; ".join(problems) if problems else f"{r['records']}")
sys.exit(1 if problems else 0)
PY
finish
