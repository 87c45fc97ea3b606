#!/usr/bin/env bash
# Lossless recording at 10 kHz: plumb-sim publishes full batches (32 samples, ~310 a second)
# reliable for SECONDS, plumb record --reliable records them; every sequence number must be in
# the file once, in order. Label "long" (10 minutes by default): not part of the integration run.
# usage: record_soak.sh BIN_DIR SIM_T REC_T DOMAIN [SECONDS]
set -uo pipefail
bin=$1 sim_t=$2 rec_t=$3
export PLUMB_DOMAIN_ID=$4
seconds=${5:-600}
here=$(dirname "$0")
. "$here/../lib.sh"
. "$here/../wait.sh"
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT

"$bin/plumb" record plumb/sensor/raw --reliable -o "$work/soak.mcap" --transport "$rec_t" > "$work/rec.log" 2>&1 &
rec=$!
wait_for "$work/rec.log" "recording" 30 || fail "recorder did not start: $(cat "$work/rec.log")"
"$bin/plumb-sim" --inclination 30 --azimuth 45 --rpm 60 --rate-hz 10000 --duration "$seconds" --batch 32 --no-truth \
  --reliable --wait-subscribers 20 --linger 5 --transport "$sim_t" > "$work/sim.log" 2>&1 || fail "sim: $(cat "$work/sim.log")"
kill -INT $rec
wait $rec || fail "recorder: $(cat "$work/rec.log")"
"$bin/plumb" export "$work/soak.mcap" -o "$work/soak.csv" 2> "$work/export.err" || fail "export: $(cat "$work/export.err")"
expected=$((seconds * 10000))
python3 - "$work/soak.csv" "$expected" <<'PY' && pass "10 kHz for $seconds s: every sample recorded once, in order ($(tail -1 "$work/rec.log"))" || fail "soak: $(cat "$work/rec.log" "$work/sim.log")"
import sys
expected = int(sys.argv[2])
seqs = [int(line.split(",", 1)[0]) for line in open(sys.argv[1]) if line[:1].isdigit()]
gaps = sum(1 for a, b in zip(seqs, seqs[1:]) if b != a + 1)
print(f"{len(seqs)} samples of {expected}, {gaps} gap(s), first {seqs[0] if seqs else None}, last {seqs[-1] if seqs else None}")
sys.exit(0 if len(seqs) == expected and gaps == 0 and seqs[0] == 0 else 1)
PY
finish
