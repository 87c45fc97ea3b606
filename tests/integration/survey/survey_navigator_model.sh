#!/usr/bin/env bash
# The navigator's own gyro model, live and offline. plumb-sim's stop-and-go drilling run
# (transport S) -> plumb-estimator --plugin strapdown --name gyro-host-DOMAIN (S) -> plumb-survey
# --plugin strapdown --error-model auto (transport V), which reads the navigator's parameters as that
# host writes them (plumb/component/parameters/HOST/strapdown) and surveys with the ISCWSA gyro model
# of its figures. Beside it, a second plumb-survey reads a host that is not there: it falls back to
# plumb's own terms and says so in its log and on plumb/status, naming the options that fix it.
# Then `plumb survey` offline on the same run's sensor CSV with the same --param: the same model
# name, and at each station the same covariance. And against the simulator's truth: every station's
# position error within 3 sigma of the model, and the RMS of error/sigma over the stations said.
# A third plumb-survey, in true north with a sidetrack that kicks off the well at MD 3.75 m, surveys
# the well drilled again from there through the navigator's gyro model; without the navigator's
# parameters a sidetrack is refused, saying why.
# usage: survey_navigator_model.sh BIN_DIR S V DOMAIN
set -euo pipefail
bin=$1 sim_t=$2 survey_t=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
source "$here/../wait.sh"
start_work_with_programs
tool=drilling-survey
host=gyro-host-$PLUMB_DOMAIN_ID
navigator=(--param latitude_deg=35 --param gravity=9.80665)
ref=(--gravity 9.80665 --total-field 50 --dip 60)
survey_args=(--transport "$survey_t" --tool-id "$tool" --plugin strapdown "${ref[@]}" --depth-clock-offset 0)

"$bin/plumb-estimator" --transport "$sim_t" --name "$host" --input plumb/sensor/raw --reliable --plugin strapdown \
  "${navigator[@]}" -q > "$work/estimator.out" 2>&1 &
pids+=($!)
"$bin/plumb-survey" "${survey_args[@]}" --file "$work/live.csv" --estimator-host "$host" --count 7 --timeout 150 \
  > "$work/live.out" 2> "$work/live.err" &
live=$!
pids+=($live)
"$bin/plumb-survey" "${survey_args[@]}" --file "$work/fallback.csv" --estimator-host "nobody-$PLUMB_DOMAIN_ID" \
  --estimator-wait 2 > "$work/fallback.out" 2> "$work/fallback.err" &
pids+=($!)
python3 "$here/write_sidetrack.py" "$work/sidetrack-1.csv"
sidetrack_args=(--reference true --declination 0 --sidetrack "$work/sidetrack-1.csv" --reference-radius 0.1 --offset-radius 0.1)
"$bin/plumb-survey" "${survey_args[@]}" "${sidetrack_args[@]}" --file "$work/sidetrack.csv" --estimator-host "$host" \
  --count 7 --timeout 150 > "$work/sidetrack.out" 2> "$work/sidetrack.err" &
sidetrack=$!
pids+=($sidetrack)
# (After its line saying whom it reads: a usage error, exit 2, once the wait is over.)
rc=0
"$bin/plumb-survey" "${survey_args[@]}" "${sidetrack_args[@]}" --file "$work/refused.csv" \
  --estimator-host "nobody-$PLUMB_DOMAIN_ID" --estimator-wait 1 > /dev/null 2> "$work/refused.err" || rc=$?
if [ $rc -eq 2 ] && tail -1 "$work/refused.err" | grep -q "^plumb-survey: --sidetrack with --error-model auto surveys the well drilled again through the navigator's gyro model, which needs its parameters: no estimator host named 'nobody-$PLUMB_DOMAIN_ID' wrote its strapdown parameters.*(--estimator-host names"; then
  pass "a sidetrack without the navigator's parameters: refused, saying why ($(tail -1 "$work/refused.err"))"
else
  fail "a sidetrack without the navigator's parameters: exit $rc, $(cat "$work/refused.err")"
fi
for log in live fallback sidetrack; do
  wait_for "$work/$log.err" "attitude writer matched" 60 || { echo "$log plumb-survey never matched the estimator:"; cat "$work/$log.err" "$work/estimator.out"; exit 1; }
done
"$bin/plumb-sim" --scenario drilling-survey --transport "$sim_t" --rate x20 --reliable --wait-subscribers 20 \
  > "$work/sim.out" 2>&1 &
sim=$!
pids+=($sim)

if grep -q "error model: the strapdown navigator's parameters from estimator host '$host'" "$work/live.err" &&
   grep -q "error model GYRO:navigator (tactical; magnetic az 0.689 deg): each station's own sigma counts by its excess" "$work/live.err"; then
  pass "live: the navigator's parameters from its host, the gyro model of its figures"
else
  fail "live: no gyro model from the host: $(cat "$work/live.err")"
fi
if grep -q "no estimator host named 'nobody-$PLUMB_DOMAIN_ID' wrote its strapdown parameters .* within 2 s.*plumb's own terms instead (--error-model GYRO:tactical.*--estimator-host" "$work/fallback.err" &&
   grep -q "error model plumb$" "$work/fallback.err"; then
  pass "without the host's parameters: plumb's own terms, said in the log with the options that fix it"
else
  fail "fallback not said: $(cat "$work/fallback.err")"
fi
# Every component's reports as they come (plumb status would merge the two plumb-surveys of this
# computer into one row).
# (|| true: echo exits 1 when fewer than 12 reports came within 30 s; what counts is whether the
# fallback's report is among those that came, which the grep below checks.)
"$bin/plumb" topic echo plumb/status --csv --count 12 --timeout 30 --transport "$survey_t" > "$work/status.txt" 2>&1 || true
if grep -E "plumb-survey.*degraded.*error model plumb \(--estimator-host NAME or --error-model GYRO:tactical\): estimator host 'nobody-$PLUMB_DOMAIN_ID' wrote no parameters" "$work/status.txt" > /dev/null; then
  pass "without the host's parameters: plumb/status degraded, saying why"
else
  fail "fallback not on plumb/status: $(cat "$work/status.txt")"
fi

wait "$live" || { echo "live survey failed:"; cat "$work/live.err" "$work/sim.out"; exit 1; }
wait "$sidetrack" || { echo "survey with the sidetrack failed:"; cat "$work/sidetrack.err"; exit 1; }
if grep -q "a sidetrack of the well drilled from MD 3.75 m: scanned below it, both wells' uncertainty from there (the well surveyed again through GYRO:navigator (tactical" "$work/sidetrack.err" &&
   [ "$(grep -c "^[0-9]" "$work/sidetrack.csv")" -eq 7 ] && grep -q "clearance .* at MD .*against sidetrack-1" "$work/sidetrack.err"; then
  pass "a sidetrack, surveyed again through the navigator's gyro model: seven stations, the clearance below the kick-off"
else
  fail "sidetrack with the navigator's model: $(grep -i "sidetrack\|clearance\|error model" "$work/sidetrack.err")"
fi
wait "$sim" || { echo "plumb-sim failed:"; cat "$work/sim.out"; exit 1; }
"$bin/plumb-sim" --scenario drilling-survey --csv "$work/run" > /dev/null
"$bin/plumb" survey --input "$work/run/sensor.csv" --estimator strapdown "${navigator[@]}" "${ref[@]}" \
  -o "$work/offline.csv" 2> "$work/offline.err" || { echo "offline survey failed:"; cat "$work/offline.err"; exit 1; }

python3 - "$work/live.csv" "$work/offline.csv" "$work/fallback.csv" "$work/run/truth.csv" <<'PY' || fail "live against offline and truth"
import bisect, csv, math, sys
read = lambda p: [r for r in csv.DictReader(l for l in open(p) if not l.startswith('#'))]
live, offline, fallback, truth = read(sys.argv[1]), read(sys.argv[2]), read(sys.argv[3]), list(csv.DictReader(open(sys.argv[4])))
ok = True
def check(cond, what):
    global ok
    print(("ok   - " if cond else "FAIL - ") + what)
    ok = ok and cond
names = {r["error_model"] for r in live} | {r["error_model"] for r in offline}
check(names == {"GYRO:navigator (tactical; magnetic az 0.689 deg)"}, f"live and offline: one model name {sorted(names)}")
check(len(fallback) > 0 and all(r["error_model"] == "plumb" for r in fallback), f"fallback rows: plumb ({len(fallback)} rows)")
check(len(live) == len(offline) == 7, f"seven stations live and offline ({len(live)}, {len(offline)})")
keys = ("cov_nn", "cov_ne", "cov_nd", "cov_ee", "cov_ed", "cov_dd")
worst = 0
for a, b in zip(live, offline):
    scale = max(abs(float(b[k])) for k in keys) or 1
    worst = max(worst, max(abs(float(a[k]) - float(b[k])) for k in keys) / scale)
worst_md = max(abs(float(a["md_m"]) - float(b["md_m"])) for a, b in zip(live, offline))
check(worst < 0.01 and worst_md < 0.01, f"live covariance = offline at every station (largest difference {worst:.2e} of the "
      f"station's largest term; depths within {worst_md:.3f} m)")
# The model against the truth: each station's position error in its own covariance's metric.
ts = [float(t["t"]) for t in truth]
ratios = []
for r in offline:
    t = truth[min(bisect.bisect_left(ts, float(r["t"])), len(truth) - 1)]
    err = [float(r["north_m"]) - float(t["north_m"]), float(r["east_m"]) - float(t["east_m"]), float(r["tvd_m"]) - float(t["down_m"])]
    for k, key in enumerate(("north_sd_m", "east_sd_m", "tvd_sd_m")):
        sd = float(r[key])
        if sd > 0: ratios.append(err[k] / sd)
rms = math.sqrt(sum(x * x for x in ratios) / len(ratios))
check(all(abs(x) < 3 for x in ratios), f"every station's position within 3 sigma of the truth (worst {max(map(abs, ratios)):.2f}); "
      f"RMS(error/sigma) {rms:.2f} over {len(ratios)} axes")
sys.exit(0 if ok else 1)
PY
finish
