#!/usr/bin/env python3
"""Drives headless Chromium over the DevTools protocol (standard library + wsclient.py) to check what
plumb-display's page shows. usage:
  browser.py URL --screenshot OUT.png --expect-key TOOL/ESTIMATOR --inclination I --azimuth A
             [--inc-tol D] [--azi-tol D] [--min-rate R] [--components a,b,...] [--seconds S]
             [--stations ROWS] [--restart-handshake DIR]
Prints one line per check ("ok   - ..." / "FAIL - ..."); exit 1 if any failed, 77 without Chromium.
With --restart-handshake DIR: after the checks it creates DIR/ready, waits for DIR/restarted (the
caller restarts the server meanwhile), then checks that the page reconnected and shows data again."""
import argparse
import base64
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import urllib.request

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wsclient import WebSocket  # noqa: E402

fails = 0


def check(ok, what):
    global fails
    print(("ok   - " if ok else "FAIL - ") + what, flush=True)
    if not ok:
        fails += 1


class Chromium:
    def __init__(self, profile):
        exe = shutil.which("chromium") or shutil.which("chromium-browser")
        # Debian's /usr/bin/chromium is a script that runs the browser as a child (and the browser
        # makes a process group of its own): the binary itself, so that terminate() reaches it.
        if exe and os.path.exists("/usr/lib/chromium/chromium"):
            exe = "/usr/lib/chromium/chromium"
        if not exe:
            print("skipped: chromium is not installed (apt-get install chromium)")
            sys.exit(77)
        args = [exe, "--headless", "--disable-gpu", "--no-first-run", "--no-default-browser-check",
                "--remote-debugging-port=0", "--remote-debugging-address=127.0.0.1", f"--user-data-dir={profile}",
                "--window-size=1600,1000", "--hide-scrollbars", "about:blank"]
        if os.geteuid() == 0:
            args.insert(1, "--no-sandbox")  # Chromium's sandbox refuses to run as root
        self.log = open(os.path.join(profile, "chromium.log"), "w+")
        self.proc = subprocess.Popen(args, stdout=self.log, stderr=subprocess.STDOUT)
        endpoint = None
        for _ in range(300):
            self.log.seek(0)
            m = re.search(r"DevTools listening on (ws://\S+)", self.log.read())
            if m:
                endpoint = m.group(1)
                break
            if self.proc.poll() is not None:
                break
            time.sleep(0.1)
        if not endpoint:
            self.log.seek(0)
            raise SystemExit("FAIL - chromium did not start: " + self.log.read()[-2000:])
        port = re.search(r":(\d+)/", endpoint).group(1)
        targets = json.load(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list"))
        page = next(t for t in targets if t["type"] == "page")
        self.ws = WebSocket(page["webSocketDebuggerUrl"], timeout=30)
        self.next_id = 0

    def call(self, method, **params):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            reply = json.loads(self.ws.recv())
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply["result"]

    def eval(self, expression):
        r = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        if "exceptionDetails" in r:
            raise RuntimeError(f"{expression}: {r['exceptionDetails']}")
        return r["result"].get("value")

    def screenshot(self, path, width, height, mobile=False):
        self.call("Emulation.setDeviceMetricsOverride", width=width, height=height, deviceScaleFactor=1, mobile=mobile)
        time.sleep(0.5)
        data = base64.b64decode(self.call("Page.captureScreenshot", format="png")["data"])
        with open(path, "wb") as f:
            f.write(data)
        return data

    def close(self):
        self.proc.terminate()  # the browser stops its own children
        try:
            self.proc.wait(5)
        except subprocess.TimeoutExpired:
            self.proc.kill()


# What the page shows, read from its DOM (not from its JavaScript state: the test checks the screen).
READ_PAGE = r"""(() => {
  const cards = {};
  for (const c of document.querySelectorAll('.card')) {
    const t = (cls) => c.querySelector(cls).textContent;
    cards[c.dataset.key] = {inc: t('.val-inc'), azi: t('.val-azi'), tf: t('.val-tf'), rpm: t('.val-rpm'),
                            stale: c.classList.contains('stale')};
  }
  const rows = [...document.querySelectorAll('#status tbody tr')].map(r => r.cells[0].textContent + '|' + r.cells[2].textContent);
  return {cards, rows, link: document.getElementById('link').textContent,
          rate: parseFloat(document.getElementById('rate').textContent), age: document.getElementById('age').textContent,
          latency: document.getElementById('latency').textContent,
          frames: parseInt(document.getElementById('frames').textContent),
          reconnects: parseInt(document.getElementById('reconnects').textContent),
          stations: [...document.querySelectorAll('#survey tbody tr')].map(r => [...r.cells].map(c => c.textContent).join('|'))};
})()"""


def read_page(browser):
    try:
        return browser.eval(READ_PAGE)
    except RuntimeError:  # the page is still loading
        return {"cards": {}, "rows": [], "link": "", "rate": 0, "age": "-", "latency": "-", "frames": 0, "reconnects": 0,
                "stations": []}


def wait_for(browser, predicate, seconds):
    deadline = time.time() + seconds
    state = read_page(browser)
    while not predicate(state) and time.time() < deadline:
        time.sleep(0.2)
        state = read_page(browser)
    return state


def angle_error(a, b):
    return abs((a - b + 180) % 360 - 180)


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def main():
    # The test's cleanup stops this script with SIGTERM: leave through `finally`, which stops Chromium.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(1))
    p = argparse.ArgumentParser()
    p.add_argument("url")
    p.add_argument("--screenshot", required=True)
    p.add_argument("--expect-key", required=True)
    p.add_argument("--inclination", type=float, required=True)
    p.add_argument("--azimuth", type=float, required=True)
    p.add_argument("--inc-tol", type=float, default=0.1)
    p.add_argument("--azi-tol", type=float, default=1.0)
    p.add_argument("--min-rate", type=float, default=10)
    p.add_argument("--components", default="plumb-display,plumb-estimator,plumb-sim")
    p.add_argument("--seconds", type=float, default=3, help="how long to sample the numbers")
    p.add_argument("--stations", default="", help="'|'-joined cells expected in the survey table, ';' between rows")
    p.add_argument("--restart-handshake")
    a = p.parse_args()

    profile = tempfile.mkdtemp(prefix="plumb-chromium-")
    browser = Chromium(profile)
    try:
        browser.call("Page.enable")
        browser.call("Page.navigate", url=a.url)
        key = a.expect_key
        state = wait_for(browser, lambda s: key in s["cards"] and s["cards"][key]["inc"] != "-", 20)
        check(key in state["cards"], f"the page shows a card for {key} (cards: {sorted(state['cards'])})")
        # Sample what the page shows for a few seconds: every reading within tolerance of the truth.
        incs, azis, rates = [], [], []
        t_end = time.time() + a.seconds
        while time.time() < t_end:
            s = read_page(browser)
            c = s["cards"].get(key)
            if c:
                incs.append(number(c["inc"]))
                azis.append(number(c["azi"]))
            rates.append(s["rate"])
            time.sleep(0.25)
        state = s
        inc_err = max((abs(v - a.inclination) for v in incs), default=float("inf"))
        azi_err = max((angle_error(v, a.azimuth) for v in azis), default=float("inf"))
        check(inc_err <= a.inc_tol, f"inclination shown {sorted(set(incs))[:5]}.. within {a.inc_tol} deg of {a.inclination} "
              f"(worst {inc_err:.3f}) over {len(incs)} readings")
        check(azi_err <= a.azi_tol, f"azimuth shown {sorted(set(azis))[:5]}.. within {a.azi_tol} deg of {a.azimuth} "
              f"(worst {azi_err:.3f})")
        distinct = len(set(zip(incs, azis)))
        check(distinct > 1, f"the numbers change while the page is open ({distinct} distinct readings)")
        rate = max(rates[len(rates) // 2:], default=0)
        check(rate >= a.min_rate, f"update rate measured in the page {rate}/s >= {a.min_rate}/s (latency ms: {state['latency']})")
        m = re.match(r"([\d.]+) \(([\d.]+)\)", state["latency"])
        median = float(m.group(1)) if m else float("inf")
        check(median < 100, f"median latency from the display's receipt to the paint {median} ms < 100 ms (p95 {m.group(2) if m else '-'})")
        for comp in filter(None, a.components.split(",")):
            check(any(r.startswith(comp + "|") for r in state["rows"]), f"status row of {comp} ({state['rows']})")
        for expected in filter(None, a.stations.split(";")):
            check(any(expected in r for r in state["stations"]), f"survey station shown: '{expected}' in {state['stations']}")
        png = browser.screenshot(a.screenshot, 1600, 1000)
        check(png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10000, f"screenshot {a.screenshot}: PNG of {len(png)} bytes")
        phone = re.sub(r"\.png$", "", a.screenshot) + "_phone.png"
        png = browser.screenshot(phone, 390, 844, mobile=True)
        width = browser.eval("document.documentElement.scrollWidth")
        check(png[:8] == b"\x89PNG\r\n\x1a\n" and width <= 390, f"phone layout: {phone}, page width {width} px <= 390")
        print(f"page: rate {rate}/s, latency ms {state['latency']}, frames {state['frames']}", flush=True)

        if a.restart_handshake:
            open(os.path.join(a.restart_handshake, "ready"), "w").close()
            deadline = time.time() + 30
            while not os.path.exists(os.path.join(a.restart_handshake, "restarted")) and time.time() < deadline:
                time.sleep(0.1)
            check(os.path.exists(os.path.join(a.restart_handshake, "restarted")), "the server was restarted")
            before = state["frames"]
            state = wait_for(browser, lambda s: s["reconnects"] >= 1 and s["link"] == "live" and s["frames"] > before + 20
                             and s["cards"].get(key, {}).get("stale") is False, 20)
            check(state["reconnects"] >= 1 and state["link"] == "live",
                  f"the page reconnected by itself (reconnects {state['reconnects']}, link '{state['link']}')")
            check(state["frames"] > before + 20 and not state["cards"].get(key, {}).get("stale", True),
                  f"and shows live data again (frames {before} -> {state['frames']})")
    finally:
        browser.close()
        shutil.rmtree(profile, ignore_errors=True)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
