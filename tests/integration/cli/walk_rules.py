#!/usr/bin/env python3
"""The rules a new user's walk through the README must keep, checked on what the walk printed and wrote.

usage:
  walk_rules.py stamp LOG STAMPS     copies stdin to LOG and, with each line's arrival time, to STAMPS
  walk_rules.py silence STAMPS SECS  fails when a command printed nothing for longer than SECS
  walk_rules.py results DIR          fails when a file the walk wrote there is empty (or a CSV has no row)

Silence: the walk runs under `bash -x`, so every command's start is a `+ ` line; a gap longer than
SECS between two lines belongs to the command that ran last. `sleep` is the README's own pause, not a
program waiting in silence, and is not counted.
"""
import os
import sys
import time


def stamp(log_path, stamps_path):
    with open(log_path, "w", encoding="utf-8", errors="replace") as log, \
         open(stamps_path, "w", encoding="utf-8", errors="replace") as stamps:
        for line in sys.stdin:
            log.write(line)
            log.flush()
            stamps.write(f"{time.monotonic():.3f} {line}")
            stamps.flush()


def silence(stamps_path, limit):
    entries = []
    with open(stamps_path, encoding="utf-8", errors="replace") as f:
        for raw in f:
            t, _, text = raw.partition(" ")
            entries.append((float(t), text.rstrip("\n")))
    offenders, command = [], "(start)"
    for (t0, text), (t1, _) in zip(entries, entries[1:]):
        if text.startswith("+"):
            command = text.lstrip("+ ")
        gap = t1 - t0
        if gap > limit and not command.startswith("sleep"):
            offenders.append(f"{gap:.1f} s without a line after `{text[:120]}` (running: {command[:120]})")
    for o in offenders:
        print(o)
    print(f"{len(entries)} lines; {len(offenders)} silent wait(s) over {limit:g} s")
    return 1 if offenders else 0


def results(folder):
    empty = []
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if not os.path.isfile(path) or os.path.islink(path) or name in ("walkthrough.sh", "log.txt", "stamps.txt", "out"):
            continue
        size = os.path.getsize(path)
        if size == 0:
            empty.append(f"{name}: empty")
        elif name.endswith(".csv"):
            with open(path, encoding="utf-8", errors="replace") as f:
                rows = [line for line in f if line.strip() and not line.startswith("#")]
            if len(rows) < 2:
                empty.append(f"{name}: a header and no row")
    for e in empty:
        print(e)
    print(f"{len(empty)} empty result(s) in {folder}")
    return 1 if empty else 0


def main():
    mode = sys.argv[1] if len(sys.argv) > 1 else ""
    if mode == "stamp" and len(sys.argv) == 4:
        stamp(sys.argv[2], sys.argv[3])
        return 0
    if mode == "silence" and len(sys.argv) == 4:
        return silence(sys.argv[2], float(sys.argv[3]))
    if mode == "results" and len(sys.argv) == 3:
        return results(sys.argv[2])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
