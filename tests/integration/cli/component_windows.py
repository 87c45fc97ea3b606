#!/usr/bin/env python3
"""Checks the windows of one plugin's attitude rows (`plumb topic echo --csv`): back to back, none
missing, and their lengths as a run-time change should have made them.

usage: component_windows.py FILE --sample-period S [--length L] [--then-length L2] [--min-rows N]
  --length L          every window (but a last, partial one) spans L s, to within one sample period
  --then-length L2    windows of L, then at most one shorter one (the open window ended by the
                      change), then windows of L2 (and a last partial one), at least two of each
Prints one line: what it found."""
import argparse
import csv
import sys


def main():
    p = argparse.ArgumentParser()
    p.add_argument("file")
    p.add_argument("--sample-period", type=float, required=True)
    p.add_argument("--length", type=float)
    p.add_argument("--then-length", type=float)
    p.add_argument("--min-rows", type=int, default=2)
    a = p.parse_args()
    with open(a.file, newline="") as f:
        rows = [r for r in csv.DictReader(f)]
    if len(rows) < a.min_rows:
        print(f"{a.file}: {len(rows)} rows, expected at least {a.min_rows}")
        return 1
    start = [int(r["window_start_ns"]) * 1e-9 for r in rows]
    end = [int(r["window_end_ns"]) * 1e-9 for r in rows]
    dt = a.sample_period
    # Back to back: the next window starts one sample after the previous one ended.
    for i in range(1, len(rows)):
        step = start[i] - end[i - 1]
        if not (0 < step < 1.5 * dt):
            print(f"{a.file}: window {i} starts {step:.4f} s after window {i - 1} ended "
                  f"({end[i - 1]:.3f} -> {start[i]:.3f}): a window missing or overlapping")
            return 1
    spans = [e - s + dt for s, e in zip(start, end)]  # a window of n samples spans n sample periods
    full = spans[:-1]  # the last one may be the stream's end, partial
    def near(x, length):
        return abs(x - length) <= 1.01 * dt
    if a.then_length is None:
        bad = [(i, s) for i, s in enumerate(full) if not near(s, a.length)]
        if bad:
            print(f"{a.file}: window {bad[0][0]} spans {bad[0][1]:.3f} s, not {a.length}")
            return 1
        print(f"{a.file}: {len(rows)} windows of {a.length} s back to back, {start[0]:.2f} to {end[-1]:.2f} s")
        return 0
    i = 0
    while i < len(full) and near(full[i], a.length):
        i += 1
    before = i
    partial = 0
    if i < len(full) and full[i] < a.length and not near(full[i], a.then_length):
        partial = 1
        i += 1
    after = 0
    while i < len(full) and near(full[i], a.then_length):
        i += 1
        after += 1
    if i != len(full) or before < 2 or after < 2:
        print(f"{a.file}: spans {[round(s, 3) for s in spans]}: expected >= 2 of {a.length} s, at most one shorter, "
              f">= 2 of {a.then_length} s")
        return 1
    print(f"{a.file}: {before} windows of {a.length} s, {partial} ended early by the change at "
          f"{end[before + partial - 1]:.2f} s, then {after} of {a.then_length} s, back to back")
    return 0


if __name__ == "__main__":
    sys.exit(main())
