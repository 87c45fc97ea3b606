#!/usr/bin/env bash
# The C++ examples other teams copy: publisher on one vendor, subscriber on another.
# usage: run_examples.sh BIN_DIR PUB_T SUB_T DOMAIN
set -uo pipefail
bin=$1 pub_t=$2 sub_t=$3 domain=$4
. "$(dirname "$0")/../lib.sh"
out=$(mktemp)
trap 'kill $(jobs -p) 2>/dev/null; rm -f "$out"' EXIT
timeout 60 "$bin/plumb-example-subscriber" --transport "$sub_t" --domain "$domain" --count 3 --timeout 50 > "$out" 2>&1 &
sub=$!
sleep 1
timeout 60 "$bin/plumb-example-publisher" --transport "$pub_t" --domain "$domain" --count 3 > /dev/null 2>&1 ||
  fail "publisher exited with an error"
wait $sub && [ "$(grep -c 'inclination' "$out")" -eq 3 ] && pass "subscriber printed the 3 attitudes" ||
  fail "subscriber: $(cat "$out")"
finish
