#!/usr/bin/env bash
# Another logger's file read as it is (docs/import.md): plumb estimate with --column, --units and
# --axes gives the estimate of the equivalent plumb file; a mapping the header lacks, an unknown
# unit and bad axes are one line and a non-zero exit; accelerometers in g declared m/s^2 are said so.
# usage: import_files.sh BIN_DIR
set -uo pipefail
bin=$1
. "$(dirname "$0")/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$bin/plumb-sim" --csv "$work/run" --inclination 20 --azimuth 75 --rpm 60 --duration 6 --snr-accel 40 --snr-mag 40 \
  > "$work/sim.log" 2>&1 || { cat "$work/sim.log"; fail "plumb-sim --csv"; finish; }

# The same run as SomeLogger exports it: quoted headers (one with a comma), its own column order,
# time in ms, accelerometers in g, gyros in deg/s, magnetometers in gauss, sensor axes x,-y,-z of
# the tool's, extra columns, no seq.
python3 - "$work/run/sensor.csv" "$work/other.csv" "$work/in_g.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
with open(sys.argv[2], "w") as out:
    out.write('# SomeLogger 4.2 export\n"Time (ms)","Battery, main (V)","Accel X (g)","Accel Y (g)","Accel Z (g)",'
              '"Mag X (G)","Mag Y (G)","Mag Z (G)","Gyroscope X (deg/s)","Gyroscope Y (deg/s)","Gyroscope Z (deg/s)",'
              '"Temp (C)"\r\n')
    for r in rows:
        v = lambda k, s, scale: repr(s * float(r[k]) / scale)
        fields = [repr(float(r["t"]) * 1000), "3.71"]
        fields += [v("fx", 1, 9.80665), v("fy", -1, 9.80665), v("fz", -1, 9.80665)]
        fields += [v("bx", 1, 100), v("by", -1, 100), v("bz", -1, 100)]
        fields += [v("wx", 1, math.pi / 180), v("wy", -1, math.pi / 180), v("wz", -1, math.pi / 180)]
        fields += ['"%s"' % r["temp_c"]]
        out.write(",".join(fields) + "\r\n")
with open(sys.argv[3], "w") as out:
    out.write("t,fx,fy,fz,bx,by,bz\n")
    for r in rows:
        out.write(",".join([r["t"]] + [repr(float(r[k]) / 9.80665) for k in ("fx", "fy", "fz")] +
                           [r[k] for k in ("bx", "by", "bz")]) + "\n")
PY

but_wx=(--column "t=Time (ms)" --column "fx=Accel X (g)" --column "fy=Accel Y (g)" --column "fz=Accel Z (g)"
        --column "wy=Gyroscope Y (deg/s)" --column "wz=Gyroscope Z (deg/s)"
        --column "bx=Mag X (G)" --column "by=Mag Y (G)" --column "bz=Mag Z (G)" --column "temp_c=Temp (C)"
        --units accel=g,gyro=deg/s,mag=gauss --units time=ms --axes x,-y,-z)
import=("${but_wx[@]}" --column 'wx="Gyroscope X (deg/s)"')
"$bin/plumb" estimate -e compensated -i "$work/run/sensor.csv" -o "$work/plumb_att.csv" 2> "$work/a.log" ||
  fail "plumb estimate on the plumb file: $(cat "$work/a.log")"
if "$bin/plumb" estimate -e compensated -i "$work/other.csv" -o "$work/other_att.csv" "${import[@]}" 2> "$work/b.log"; then
  pass "plumb estimate reads the other logger's file with --column, --units, --axes"
else
  fail "plumb estimate on the other logger's file: $(cat "$work/b.log")"
fi
grep -q "warning" "$work/b.log" && fail "correct units gave a warning: $(cat "$work/b.log")" ||
  pass "correct units: no unit warning"
python3 - "$work/plumb_att.csv" "$work/other_att.csv" <<'PY' && pass "same estimate as the plumb file, and the truth" || fail "estimates differ"
import csv, sys
a, b = (next(csv.DictReader(open(p))) for p in sys.argv[1:3])
d = lambda x, y: abs((float(x) - float(y) + 180) % 360 - 180)
print("plumb file:", a["inclination_deg"], a["azimuth_deg"], a["toolface_deg"], "other:", b["inclination_deg"],
      b["azimuth_deg"], b["toolface_deg"])
ok = (b["valid"] == "1" and all(d(a[k], b[k]) < 1e-6 for k in ("inclination_deg", "azimuth_deg", "toolface_deg", "rpm"))
      and abs(float(b["inclination_deg"]) - 20) < 0.05 and d(b["azimuth_deg"], 75) < 0.2)
sys.exit(0 if ok else 1)
PY

expect_error "estimate: a mapped column the header lacks" \
  "other.csv:2: column 'wx': mapped to 'Gyro X \(deg/s\)', which the header lacks \(closest: 'Gyroscope X \(deg/s\)'" \
  timeout 30 "$bin/plumb" estimate -e compensated -i "$work/other.csv" "${but_wx[@]}" --column "wx=Gyro X (deg/s)"
expect_error "estimate: unknown unit" "--units: unknown gyro unit 'deg/min' \(accepted: rad/s, deg/s" \
  timeout 30 "$bin/plumb" estimate -e compensated -i "$work/other.csv" --units gyro=deg/min
expect_error "estimate: a reflection as axes" "--axes 'x,y,-z': a reflection" \
  timeout 30 "$bin/plumb" estimate -e compensated -i "$work/other.csv" --axes x,y,-z
expect_error "estimate: an unknown plumb column" "--column: 'gx' is not a plumb column" \
  timeout 30 "$bin/plumb" estimate -e compensated -i "$work/other.csv" --column "gx=Gyroscope X (deg/s)"
expect_error "bridge replay: a mapped column the header lacks" "column 'fx': mapped to 'AccX'" \
  timeout 30 "$bin/plumb-bridge" --replay "$work/other.csv" --column fx=AccX
output_matches "--axes" "$bin/plumb" estimate --help && output_matches "--column" "$bin/plumb-bridge" --help &&
  pass "--help of plumb estimate and plumb-bridge lists the import options" || fail "import options not in --help"

# Accelerometers in g in a file that says nothing: the estimate runs, and stderr says why it is wrong.
"$bin/plumb" estimate -e compensated -i "$work/in_g.csv" > /dev/null 2> "$work/g.log"
grep -q "warning: accelerometers look like they are in g (|f| ≈ 1.0); give --units accel=g" "$work/g.log" &&
  pass "g declared m/s^2 is said: $(grep warning "$work/g.log")" || fail "no g warning: $(cat "$work/g.log")"
"$bin/plumb" estimate -e compensated -i "$work/in_g.csv" --units accel=g > /dev/null 2> "$work/g2.log"
grep -q warning "$work/g2.log" && fail "--units accel=g still warns: $(cat "$work/g2.log")" ||
  pass "with --units accel=g the warning is gone"
finish
