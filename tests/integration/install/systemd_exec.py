#!/usr/bin/env python3
"""Runs a systemd unit's ExecStart as systemd would, without systemd: the EnvironmentFile= files
(read as systemd reads them: KEY=VALUE lines, '#' comments, quotes removed) and Environment= lines
(a path under /var/lib/plumb taken inside ROOT), %i replaced by the
instance, $VAR and ${VAR} words replaced by their value split into words, StateDirectory= made, and
the program started with that environment. Paths of the unit (the environment files, the program,
and arguments under /etc/plumb and /var/lib/plumb) are taken inside ROOT, where the packages were
unpacked. For the package and unit tests, where no systemd runs.
usage: systemd_exec.py ROOT UNIT_FILE [INSTANCE]
"""
import os
import re
import shlex
import sys

root, unit = sys.argv[1], sys.argv[2]
instance = sys.argv[3] if len(sys.argv) > 3 else ""
env = {"PATH": "/usr/bin:/bin"}
exec_start = None
for line in open(unit):
    line = line.strip().replace("%i", instance)
    if line.startswith("EnvironmentFile="):
        path = line.split("=", 1)[1]
        optional = path.startswith("-")
        path = root + path.lstrip("-")
        if not os.path.exists(path):
            if optional:
                continue
            sys.exit(f"{unit}: environment file {path} is missing")
        for text in open(path):
            text = text.strip()
            if not text or text.startswith("#"):
                continue
            key, value = text.split("=", 1)
            env[key.strip()] = " ".join(shlex.split(value)) if value.strip() else ""
    elif line.startswith("Environment="):
        key, value = line.split("=", 1)[1].split("=", 1)
        env[key] = root + value if value.startswith(("/etc/plumb/", "/var/lib/plumb/")) else value
    elif line.startswith("StateDirectory="):
        for d in line.split("=", 1)[1].split():
            os.makedirs(f"{root}/var/lib/{d}", exist_ok=True)
    elif line.startswith("ExecStart="):
        exec_start = line.split("=", 1)[1]
if exec_start is None:
    sys.exit(f"{unit}: no ExecStart")
argv = []
for word in exec_start.split():
    match = re.fullmatch(r"\$\{?(\w+)\}?", word)
    argv += env.get(match.group(1), "").split() if match else [word]
argv[0] = root + argv[0]
argv = [root + a if a.startswith(("/etc/plumb/", "/var/lib/plumb/")) else a for a in argv]
print("systemd_exec: " + " ".join(shlex.quote(a) for a in argv), flush=True)
os.execve(argv[0], argv, env)
