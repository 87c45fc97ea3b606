#!/usr/bin/env bash
# plumb-survey restarted on a survey file whose last row was cut (the writer died in the
# middle of it) resumes with the valid rows, says which line was damaged, keeps the file as found
# beside it, and rewrites the survey whole; a file that is not a survey is refused and left alone.
# usage: survey_damaged_file.sh BIN_DIR DOMAIN
set -euo pipefail
bin=$1
export PLUMB_DOMAIN_ID=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
skip=(--skip-check gravity --skip-check field --skip-check dip)
printf 'md_m,inclination_deg,azimuth_deg\n0,10,20\n10,12,22\n20,13,23\n30,14,24\n' > "$work/list.csv"
"$bin/plumb" survey --stations "$work/list.csv" "${skip[@]}" -o "$work/full.csv" 2> /dev/null
head -c -25 "$work/full.csv" > "$work/survey.csv"   # the last row cut short
# --count 3: the three valid stations are the whole survey; it exits once loaded.
"$bin/plumb-survey" --tool-id t1 --file "$work/survey.csv" "${skip[@]}" --count 3 --linger 0 -q \
  > "$work/out" 2> "$work/err" || fail "plumb-survey failed: $(cat "$work/err")"
if grep -q "survey.csv:8: last line truncated.*resuming with the 3 valid station" "$work/err"; then
  pass "truncated row named: $(grep truncated "$work/err")"
else
  fail "no truncation message: $(cat "$work/err")"
fi
if cmp -s "$work/survey.csv.damaged" <(head -c -25 "$work/full.csv"); then pass "the file as found kept as survey.csv.damaged"; else fail "no .damaged copy"; fi
if [ "$(grep -c '^[0-9]' "$work/survey.csv")" -eq 3 ] && [ "$(tail -c 1 "$work/survey.csv" | od -An -c | tr -d ' ')" = '\n' ]; then
  pass "survey file rewritten with the three valid rows"
else
  fail "rewritten file: $(cat "$work/survey.csv")"
fi
printf 't,inclination_deg\n1,2\n' > "$work/other.csv"
expect_error "not a survey file" "not a plumb survey file" "$bin/plumb-survey" --tool-id t1 --file "$work/other.csv" "${skip[@]}" --count 1
if [ "$(cat "$work/other.csv")" = "$(printf 't,inclination_deg\n1,2')" ]; then pass "foreign file left alone"; else fail "foreign file changed"; fi
finish
