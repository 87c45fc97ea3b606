#!/usr/bin/env bash
# `plumb topic pub` on one vendor, `plumb topic echo` (YAML and CSV) and `plumb topic hz` and
# `plumb topic list` on another. usage: topic_roundtrip.sh BIN_DIR PUB_T ECHO_T DOMAIN
set -uo pipefail
bin=$1 pub_t=$2 echo_t=$3
export PLUMB_DOMAIN_ID=$4
. "$(dirname "$0")/../lib.sh"
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT

timeout 90 "$bin/plumb" topic echo plumb/attitude/test --count 1 --timeout 70 --transport "$echo_t" > "$work/yaml.txt" 2>&1 &
e1=$!
timeout 90 "$bin/plumb" topic echo plumb/sensor/calibrated --csv --count 1 --reliable --timeout 70 --transport "$echo_t" > "$work/batch.csv" 2> "$work/batch.err" &
e2=$!
sleep 1
# (Each publisher waits for its echo's reader: under a loaded suite, discovery has taken over 15 s.
# What it says, matched or not, goes into the failure's line.)
timeout 60 "$bin/plumb" topic pub plumb/attitude/test tool_id=T7 estimator=test inclination_deg=1.25 azimuth_deg=271.5 \
  flags=3 reason=fine --wait 30 --transport "$pub_t" > /dev/null 2> "$work/pub1.err" || fail "pub attitude: $(cat "$work/pub1.err")"
timeout 60 "$bin/plumb" topic pub plumb/sensor/calibrated tool_id=T7 samples.0.seq=5 samples.0.fz=-9.5 samples.1.seq=6 \
  samples.1.bx=21.25 --wait 30 --transport "$pub_t" > /dev/null 2> "$work/pub2.err" || fail "pub batch: $(cat "$work/pub2.err")"
wait $e1 && grep -q 'azimuth_deg: 271.5' "$work/yaml.txt" && grep -q 'tool_id: "T7"' "$work/yaml.txt" &&
  pass "echo YAML received the attitude" || fail "echo YAML: $(cat "$work/yaml.txt" "$work/pub1.err")"
# A sensor topic's CSV is the sensor CSV of docs/conventions.md: header, one row per sample.
wait $e2 && [ "$(grep -c . "$work/batch.csv")" -eq 3 ] && grep -q '^seq,t,fx,fy,fz,bx,by,bz' "$work/batch.csv" &&
  grep -q '^5,0,0,0,-9.5,' "$work/batch.csv" && grep -q '21.25' "$work/batch.csv" &&
  pass "echo CSV printed the sensor CSV, one row per sample" ||
  fail "echo CSV: $(cat "$work/batch.csv" "$work/batch.err" "$work/pub2.err")"

# A publisher alive for 6 s; hz and list run while it is (list shows live endpoints only).
timeout 60 "$bin/plumb" topic pub plumb/sim/truth rpm=60 --count 120 --rate 20 --wait 0 --transport "$pub_t" > /dev/null 2>&1 &
p=$!
timeout 60 "$bin/plumb" topic hz plumb/sim/truth --count 3 --transport "$echo_t" > "$work/hz.txt" 2>&1 &
h=$!
timeout 60 "$bin/plumb" topic list --wait 3 --transport "$echo_t" > "$work/list.txt" 2>&1 &
l=$!
wait $p
wait $h; grep -qE 'average rate: (1[6-9]|2[0-4])(\.[0-9]+)? Hz' "$work/hz.txt" && pass "hz measured about 20 Hz" ||
  fail "hz: $(cat "$work/hz.txt")"
wait $l; grep -q 'plumb/sim/truth  \[plumb::msg::Truth\]' "$work/list.txt" && pass "list shows the truth topic and type" ||
  fail "list: $(cat "$work/list.txt")"
finish
