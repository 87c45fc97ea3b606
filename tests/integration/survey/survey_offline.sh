#!/usr/bin/env bash
# Surveys offline: `plumb survey` on the simulator's stop-and-go drilling run (sensor CSV with
# measured depth, through the default estimator) and on a station list; the survey CSV written
# whole and its plot drawn (PNG); bad inputs refused with one line: depth backwards, a duplicate station, an angle
# out of range, a missing reference, a true survey without declination.
# usage: survey_offline.sh BIN_DIR
set -euo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ref=(--gravity 9.80665 --total-field 50 --dip 60)

"$bin/plumb-sim" --scenario drilling-survey --csv "$work/run" > /dev/null
if "$bin/plumb" survey --input "$work/run/sensor.csv" "${ref[@]}" --reference true --declination 4 \
     -o "$work/survey.csv" --plot "$work/survey.png" 2> "$work/survey.err"; then
  pass "plumb survey on a sensor CSV: $(tail -1 "$work/survey.err")"
else
  fail "plumb survey failed: $(cat "$work/survey.err")"
fi
python3 - "$work/survey.csv" "$work/run/truth.csv" <<'PY' && pass "seven stations at the stops (every window of each), true azimuths, QC passed, ISCWSA MWD sigmas" || fail "survey CSV content"
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith('#')))
truth = list(csv.DictReader(open(sys.argv[2])))
assert [int(r["station"]) for r in rows] == list(range(7)), len(rows)
assert all(abs(float(r["md_m"]) - 1.5 * k) < 0.02 for k, r in enumerate(rows))
assert all(r["azimuth_reference"] == "true" and r["qc"] == "pass" for r in rows)
# true = magnetic + 4 deg; the simulated azimuth is magnetic.
for r in rows:
    assert abs((float(r["azimuth_deg"]) - float(r["magnetic_azimuth_deg"]) - 4 + 180) % 360 - 180) < 1e-9
# A 30 s stop through 5 s windows: five or more windows a station (the alignment's 60 s: more).
assert all(int(r["windows"]) >= 5 for r in rows), [r["windows"] for r in rows]
# The MWD model's total sigma of a station's angles is far above its measured noise.
assert all(float(r["inclination_total_sd_deg"]) > 3 * float(r["inclination_sd_deg"]) for r in rows)
assert all(r["error_model"].startswith("MWD") for r in rows)
assert all(r["gravity_toolface_deg"] not in ("", "nan") for r in rows)
PY
# The same run as an attitude CSV and a depth log: the same stations.
"$bin/plumb" estimate --estimator compensated --input "$work/run/sensor.csv" --window 5 --output "$work/att.csv" 2> /dev/null
python3 - "$work/run/sensor.csv" "$work/depth.csv" <<'PY'
import csv, sys
rows = csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith('#'))
with open(sys.argv[2], "w") as out:
    out.write("t,depth_m\n")
    for k, r in enumerate(rows):
        if k % 10 == 0: out.write(f"{r['t']},{r['depth_m']}\n")
PY
"$bin/plumb" survey --attitude "$work/att.csv" --depth "$work/depth.csv" --window 5 "${ref[@]}" -o "$work/survey2.csv" 2> /dev/null
python3 - "$work/survey.csv" "$work/survey2.csv" <<'PY' && pass "attitude CSV + depth log: the same stations" || fail "attitude CSV + depth log differ"
import csv, sys
a, b = ([r for r in csv.DictReader(l for l in open(p) if not l.startswith('#'))] for p in sys.argv[1:])
assert len(a) == len(b) == 7
for x, y in zip(a, b):
    assert abs(float(x["md_m"]) - float(y["md_m"])) < 1e-9
    assert abs(float(x["inclination_deg"]) - float(y["inclination_deg"])) < 1e-6
    assert abs(float(x["magnetic_azimuth_deg"]) - float(y["magnetic_azimuth_deg"])) < 1e-6
PY
# The strapdown navigator's rows (1 s, at the zero-velocity updates when the string stands) serve too.
"$bin/plumb" survey --input "$work/run/sensor.csv" --estimator strapdown --param latitude_deg=35 --param gravity=9.80665 \
  "${ref[@]}" -o "$work/strapdown.csv" 2> /dev/null
python3 - "$work/survey.csv" "$work/strapdown.csv" "$work/run/truth.csv" <<'PY' && pass "strapdown navigator: the same stops, QC passed, inclination within 4 sigma of the truth, the gyro model of its own figures" || fail "strapdown survey"
import bisect, csv, sys
a, b = ([r for r in csv.DictReader(l for l in open(p) if not l.startswith('#'))] for p in sys.argv[1:3])
truth = list(csv.DictReader(open(sys.argv[3])))
ts = [float(t["t"]) for t in truth]
assert len(a) == len(b) == 7
for x, y in zip(a, b):
    assert abs(float(x["md_m"]) - float(y["md_m"])) < 1e-9 and y["qc"] == "pass"
    t = truth[min(bisect.bisect_left(ts, float(y["t"])), len(truth) - 1)]
    # The navigator estimates the accelerometer biases the static formula cannot: within 4 of its sigmas.
    err = abs(float(y["inclination_deg"]) - float(t["inclination_deg"]))
    assert err < 4 * float(y["inclination_sd_deg"]), (y["t"], err, y["inclination_sd_deg"])
    # --error-model auto: the ISCWSA gyro model of the navigator's grade (tactical by default),
    # initialised by its magnetometer, never narrower than the navigator's own sigma.
    assert y["error_model"] == "GYRO:navigator (tactical; magnetic az 0.689 deg)", y["error_model"]
    assert float(y["azimuth_total_sd_deg"]) >= 0.999 * float(y["azimuth_sd_deg"]), (y["azimuth_total_sd_deg"], y["azimuth_sd_deg"])
PY
# No depth at all: a pipe tally numbers the stops (valid, non-rotating windows); corrections per stop.
printf 'joint_m,correction_m\n1.5,0\n1.5,0.01\n1.5,0\n1.5,0\n1.5,-0.02\n1.5,0\n1.5,0\n' > "$work/tally.csv"
"$bin/plumb" survey --attitude "$work/att.csv" --tally "$work/tally.csv" --start-md 100 "${ref[@]}" -o "$work/tally_survey.csv" 2> /dev/null
python3 - "$work/tally_survey.csv" <<'PY' && pass "pipe tally: stops at start + joints + corrections" || fail "pipe tally survey"
import csv, sys
rows = [r for r in csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith('#'))]
want = [100, 101.51, 103, 104.5, 105.98, 107.5, 109]
got = [float(r["md_m"]) for r in rows]
assert len(got) == 7 and all(abs(g - w) < 1e-9 for g, w in zip(got, want)), got
PY
if [ "$(head -c 4 "$work/survey.png" | tail -c 3)" = "PNG" ]; then pass "plot drawn (PNG)"; else fail "no PNG plot"; fi
if [ ! -e "$work/survey.csv.tmp" ]; then pass "no temporary file left"; else fail "survey.csv.tmp left behind"; fi

printf 'md_m,inclination_deg,azimuth_deg\n100,10,20\n110,12,22\n105,13,23\n' > "$work/backwards.csv"
printf 'md_m,inclination_deg,azimuth_deg\n100,10,20\n110,12,22\n110,12,22\n' > "$work/duplicate.csv"
printf 'md_m,inclination_deg,azimuth_deg\n100,10,20\n110,190,22\n' > "$work/range.csv"
printf 'md_m,inclination_deg,azimuth_deg\n100,10,20\n110,12,22\n' > "$work/good.csv"
skip=(--skip-check gravity --skip-check field --skip-check dip)
expect_error "depth going backwards" "backwards.csv: station 2 .*goes backwards" "$bin/plumb" survey --stations "$work/backwards.csv" "${skip[@]}" -o "$work/x.csv"
expect_error "duplicate station" "duplicate of station 1" "$bin/plumb" survey --stations "$work/duplicate.csv" "${skip[@]}" -o "$work/x.csv"
expect_error "inclination out of range" "range.csv:3: inclination 190 deg outside" "$bin/plumb" survey --stations "$work/range.csv" "${skip[@]}" -o "$work/x.csv"
expect_error "missing reference field" "missing reference total field" "$bin/plumb" survey --stations "$work/good.csv" --gravity 9.8 --dip 60 -o "$work/x.csv"
expect_error "true survey without declination" "needs --declination" "$bin/plumb" survey --stations "$work/good.csv" "${skip[@]}" --reference true -o "$work/x.csv"
if [ ! -e "$work/x.csv" ]; then pass "nothing written by a failed survey"; else fail "a failed survey wrote x.csv"; fi
# A survey program: a gyro to 1200 m, MWD below; each station names the model that priced it, the
# stations above the MWD leg are as the gyro alone gives them, and the end is neither tool's alone.
python3 - "$work/well.csv" <<'PY'
import math, sys
with open(sys.argv[1], "w") as out:
    out.write("md_m,inclination_deg,azimuth_deg\n")
    for k in range(81):
        md = 30.0 * k
        out.write(f"{md},{0 if md <= 1200 else min(60, (md - 1200) / 10)},75\n")
PY
program=(--stations "$work/well.csv" "${skip[@]}" --reference true --declination 0 --latitude 60)
"$bin/plumb" survey "${program[@]}" --error-model GYRO-NS --error-model-from 1230:MWD -o "$work/program.csv" 2> "$work/program.err" &&
"$bin/plumb" survey "${program[@]}" --error-model GYRO-NS -o "$work/gyro.csv" 2> /dev/null &&
"$bin/plumb" survey "${program[@]}" --error-model MWD -o "$work/mwd.csv" 2> /dev/null ||
  fail "plumb survey --error-model-from failed"
python3 - "$work/program.csv" "$work/gyro.csv" "$work/mwd.csv" <<'PY' && pass "a survey program (--error-model-from 1230:MWD): each station's model named, the gyro's above, neither tool's alone at the end" || fail "survey program"
import csv, sys
program, gyro, mwd = ([r for r in csv.DictReader(l for l in open(p) if not l.startswith('#'))] for p in sys.argv[1:])
names = [r["error_model"].split()[0] for r in program]
assert names == ["GYRO-NS"] * 41 + ["MWD"] * 40, names
assert all(a["cov_nn"] == b["cov_nn"] and a["cov_ee"] == b["cov_ee"] for a, b in zip(program[:41], gyro[:41]))
end = [float(r[-1]["cov_ee"]) for r in (program, gyro, mwd)]
assert end[0] != end[1] and end[0] != end[2], end
PY
if grep -q "^plumb survey: error model GYRO-NS (.*); from MD 1230 m MWD (" "$work/program.err"; then
  pass "the program said: $(grep "error model" "$work/program.err")"
else
  fail "the program not said: $(cat "$work/program.err")"
fi
expect_error "a leg's unknown model" "--error-model-from 'NOPE': no such tool code file" "$bin/plumb" survey "${program[@]}" --error-model GYRO-NS --error-model-from 1230:NOPE -o "$work/x.csv"
expect_error "a leg below plumb's own terms" "--error-model-from needs an ISCWSA error model above its depth" "$bin/plumb" survey "${program[@]}" --error-model plumb --error-model-from 1230:MWD -o "$work/x.csv"
expect_error "a leg without its depth" "--error-model-from 'MWD': expected MD:MODEL" "$bin/plumb" survey "${program[@]}" --error-model GYRO-NS --error-model-from MWD -o "$work/x.csv"
rm -f "$work/x.csv"
# A station without its measured field fails QC and is kept, flagged.
"$bin/plumb" survey --stations "$work/good.csv" "${ref[@]}" -o "$work/flagged.csv" 2> /dev/null
if output_matches "no |B| measured" cat "$work/flagged.csv" && [ "$(grep -c ',fail,' "$work/flagged.csv")" -eq 2 ]; then
  pass "stations without a measured field kept and flagged"
else
  fail "flagged stations: $(cat "$work/flagged.csv")"
fi
finish
