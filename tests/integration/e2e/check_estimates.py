#!/usr/bin/env python3
"""Checks attitude CSV rows printed by `plumb topic echo --csv` against the simulated truth.

usage: check_estimates.py FILE --inclination I --azimuth A [--inc-tol D] [--azi-tol D] [--azi-offset D] [--no-azimuth]
                          [--expect-invalid]
The tolerances are the caller's physics budget (see e2e_estimation.sh)."""
import argparse
import csv
import math
import sys


def angle_diff(a, b):
    return (a - b + 180.0) % 360.0 - 180.0


def number(text):
    """A CSV cell: empty is a value not measured (NaN)."""
    return float(text) if text else float("nan")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("file")
    p.add_argument("--inclination", type=float, required=True)
    p.add_argument("--azimuth", type=float, required=True)
    p.add_argument("--inc-tol", type=float, default=0.1)
    p.add_argument("--azi-tol", type=float, default=1.0)
    p.add_argument("--azi-offset", type=float, default=0.0,
                   help="expected azimuth error (a known bias of the method), deg")
    p.add_argument("--expect-invalid", action="store_true")
    p.add_argument("--no-azimuth", action="store_true",
                   help="the plugin estimates no azimuth: its cell must be empty (not measured)")
    p.add_argument("--min-rows", type=int, default=1)
    a = p.parse_args()
    with open(a.file, newline="") as f:
        rows = list(csv.DictReader(f))
    if len(rows) < a.min_rows:
        print(f"{a.file}: {len(rows)} estimates, expected at least {a.min_rows}")
        return 1
    bad = 0
    for r in rows:
        valid = int(r["flags"]) & 1
        name = r["estimator"]
        if a.expect_invalid:
            if valid or not r["reason"]:
                print(f"{name}: expected invalid with a reason, got flags={r['flags']} reason='{r['reason']}'")
                bad += 1
            else:
                print(f"{name}: invalid as expected: {r['reason']}")
            continue
        di = number(r["inclination_deg"]) - a.inclination
        da = angle_diff(number(r["azimuth_deg"]), a.azimuth) - a.azi_offset
        if a.no_azimuth:
            azimuth_ok = math.isnan(number(r["azimuth_deg"]))
        else:
            azimuth_ok = abs(da) <= a.azi_tol and math.isfinite(number(r["azimuth_deg"]))
        ok = valid and abs(di) <= a.inc_tol and azimuth_ok and all(
            math.isfinite(number(r[k])) for k in ("inclination_deg", "rpm"))
        print(f"{name}: inc {number(r['inclination_deg']):.4f} (err {di:+.4f}, tol {a.inc_tol}) "
              f"azi {number(r['azimuth_deg']):.3f} (err {da + a.azi_offset:+.3f}, expected {a.azi_offset:+.3f} +- {a.azi_tol}) rpm {number(r['rpm']):.1f} "
              f"{'ok' if ok else 'FAIL'}")
        bad += not ok
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
