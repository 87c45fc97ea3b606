#!/usr/bin/env python3
"""Writes the README's runnable shell blocks as one script, in the order they appear.

A fenced block opened with ```sh is runnable; ```text and unmarked blocks are shown, not run. The
first block is the README's two top-level commands (.ci/demo builds and runs the demo, .ci/test runs
this very test): it must be exactly those two, and is not run.

usage: readme_blocks.py README.md OUT.sh
"""
import sys

TOP_COMMANDS = ["bash .ci/demo", "bash .ci/test"]


def blocks(path):
    """(language, first line number, lines) of each fenced block."""
    found, inside, language, start, lines = [], False, "", 0, []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            stripped = line.rstrip("\n")
            if stripped.startswith("```"):
                if inside:
                    found.append((language, start, lines))
                    inside = False
                else:
                    inside, language, start, lines = True, stripped[3:].strip(), number + 1, []
                continue
            if inside:
                lines.append(stripped)
    if inside:
        sys.exit(f"{path}:{start - 1}: code block never closed")
    return found


def main():
    readme, out = sys.argv[1], sys.argv[2]
    runnable = [b for b in blocks(readme) if b[0] == "sh"]
    if not runnable:
        sys.exit(f"{readme}: no ```sh block")
    language, start, first = runnable[0]
    commands = [line.split("#")[0].strip() for line in first if line.strip()]
    if start != 2 or commands != TOP_COMMANDS:
        sys.exit(f"{readme}:{start}: the README must start with exactly `{TOP_COMMANDS[0]}` and `{TOP_COMMANDS[1]}`")
    with open(out, "w", encoding="utf-8") as f:
        f.write("# Generated from the README's ```sh blocks by readme_blocks.py; do not edit.\n")
        for _, start, lines in runnable[1:]:
            f.write(f"echo '== README.md line {start}'\n")
            f.write("\n".join(lines) + "\n")
    print(f"{len(runnable) - 1} runnable block(s) from {readme}")


if __name__ == "__main__":
    main()
