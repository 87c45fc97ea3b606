#!/usr/bin/env python3
"""Display latency and rate (docs/benchmarks.md, "Display"). plumb-bench-display-source publishes
estimates stamped with their publication time; in the same run, on this computer:
  - baseline: `plumb topic echo` receives them (DDS to a plain reader, printed; this script timestamps each line);
  - a WebSocket client of plumb-display receives them in its frames (DDS -> display -> WebSocket);
  - headless Chromium shows them (DDS -> display -> WebSocket -> page painted), measured in the page.
usage: display_bench.py BIN_DIR [--rate HZ] [--seconds S] [--transport T] [--domain D]"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "integration", "display"))
from wsclient import WebSocket, Closed  # noqa: E402
import browser as chromium_page  # noqa: E402


def summary(values):
    if not values:
        return "-", "-", 0
    v = sorted(values)
    return f"{statistics.median(v):.2f}", f"{v[int(len(v) * 0.95)]:.2f}", len(v)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("bin")
    p.add_argument("--rate", type=float, default=20)
    p.add_argument("--seconds", type=float, default=15)
    p.add_argument("--transport", default="cyclonedds")
    p.add_argument("--domain", default="36")
    a = p.parse_args()
    env = dict(os.environ, PLUMB_DOMAIN_ID=a.domain, PLUMB_TRANSPORT=a.transport)
    work = tempfile.mkdtemp(prefix="plumb-display-bench-")
    procs = []
    try:
        log = open(os.path.join(work, "display.log"), "w+")
        display = subprocess.Popen([os.path.join(a.bin, "plumb-display"), "--port", "0", "--foxglove-port", "0"], stdout=log, stderr=subprocess.STDOUT, env=env)
        procs.append(display)
        port = None
        for _ in range(200):
            log.seek(0)
            m = re.search(r"serving http://127\.0\.0\.1:(\d+)/", log.read())
            if m:
                port = m.group(1)
                break
            time.sleep(0.1)
        if not port:
            sys.exit("plumb-display did not start")

        echo_lat, ws_lat, ws_from_rx = [], [], []
        echo = subprocess.Popen([os.path.join(a.bin, "plumb"), "topic", "echo", "plumb/attitude/bench"],
                                stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=env, text=True, bufsize=1)
        procs.append(echo)

        def read_echo():
            for line in echo.stdout:
                if line.lstrip().startswith("window_end_ns:"):
                    echo_lat.append((time.time_ns() - int(line.split(":")[1])) / 1e6)

        def read_ws():
            try:
                ws = WebSocket(f"ws://127.0.0.1:{port}/ws", timeout=60)
                while True:
                    m = json.loads(ws.recv())
                    now = time.time() * 1e3
                    for att in m.get("att", []):
                        if att["est"] == "bench":
                            ws_lat.append(now - att["t"] * 1e3)
                            ws_from_rx.append(now - att["rx"])
            except (OSError, Closed):
                pass

        threading.Thread(target=read_echo, daemon=True).start()
        threading.Thread(target=read_ws, daemon=True).start()
        profile = tempfile.mkdtemp(prefix="plumb-chromium-", dir=work)
        page = chromium_page.Chromium(profile)
        page.call("Page.navigate", url=f"http://127.0.0.1:{port}/")
        time.sleep(3)  # discovery between the programs
        source = subprocess.Popen([os.path.join(a.bin, "plumb-bench-display-source"), "--rate", str(a.rate),
                                   "--seconds", str(a.seconds + 2)], env=env, stderr=subprocess.PIPE, text=True)
        procs.append(source)
        time.sleep(a.seconds)
        # The page's own figures over its last 200 estimates (and 2 s for the rate), read while the stream runs.
        state = page.eval("({age: document.getElementById('age').textContent, latency: document.getElementById('latency').textContent,"
                          " rate: document.getElementById('rate').textContent})")
        if source.wait(30):
            sys.exit("source failed: " + source.stderr.read())
        page.close()
        time.sleep(0.5)
        published = int((a.seconds + 2) * a.rate)
        print(f"display latency, {a.transport}, {a.rate:g} estimates/s for {a.seconds + 2:g} s ({published} published), "
              f"load average {os.getloadavg()[0]:.2f}")
        print("| path | median ms | p95 ms | received | vs baseline (median) |")
        print("|---|---:|---:|---:|---:|")
        base = statistics.median(echo_lat) if echo_lat else float("nan")
        med, p95, n = summary(echo_lat)
        print(f"| publication -> `plumb topic echo` (baseline) | {med} | {p95} | {n} | 1.00 |")
        med, p95, n = summary(ws_lat)
        print(f"| publication -> WebSocket client of plumb-display | {med} | {p95} | {n} | {statistics.median(ws_lat) / base:.1f} |")
        med, p95, n = summary(ws_from_rx)
        print(f"| display's receipt -> WebSocket client | {med} | {p95} | {n} | |")
        page_age = re.match(r"([\d.]+) \(([\d.]+)\)", state["age"])
        ratio = f"{float(page_age.group(1)) / base:.1f}" if page_age else "-"
        print(f"| publication -> page painted (Chromium, last 200) | {page_age.group(1) if page_age else '-'} | "
              f"{page_age.group(2) if page_age else '-'} | | {ratio} |")
        print(f"page: updates/s {state['rate']}, display's receipt -> paint ms {state['latency']}")
    finally:
        for proc in procs:
            proc.terminate()
        for proc in procs:
            try:
                proc.wait(5)
            except subprocess.TimeoutExpired:
                proc.kill()
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
