#!/usr/bin/env python3
"""What plumb-display's page shows for two or more plugins of one tool, in headless Chromium (the
Chromium driver of browser.py): each card but the reference's carries its difference from the
reference, live. usage:
  browser_difference.py URL --key TOOL/ESTIMATOR --reference ESTIMATOR [--inc-tol D] [--azi-tol D]
                        [--invalid TOOL/ESTIMATOR] [--seconds S] [--screenshot OUT.png]
                        [--gone TOOL/ESTIMATOR --handshake DIR]
--key: its card shows "minus REFERENCE: inclination ±d ± s°, azimuth ±d ± s°, toolface ..." with |d|
within the tolerances (--inc-tol, --azi-tol, --tf-tol), and the numbers change while the page is open. --invalid: a card whose plugin gives
no angle on a turning tool (static): its difference shows "-" for each angle. The reference's own
card shows none. --gone with --handshake: once those checks are done, writes DIR/browser-ready, waits
for DIR/unloaded (the test unloaded that plugin), and then its card leaves the open page while the
reference's stays. Prints "ok   - ..." / "FAIL - ..." lines; exit 1 if any failed, 77 without Chromium."""
import argparse
import os
import re
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from browser import Chromium  # noqa: E402

fails = 0


def check(ok, what):
    global fails
    print(("ok   - " if ok else "FAIL - ") + what, flush=True)
    if not ok:
        fails += 1


READ_DIFFS = r"""(() => {
  const out = {};
  for (const c of document.querySelectorAll('.card')) out[c.dataset.key] = c.querySelector('.diff').textContent;
  return out;
})()"""


def read_diffs(browser):
    try:
        return browser.eval(READ_DIFFS) or {}
    except RuntimeError:  # the page is still loading
        return {}


def signed(text):
    return float(text.replace("−", "-"))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("url")
    p.add_argument("--key", required=True)
    p.add_argument("--reference", required=True)
    p.add_argument("--inc-tol", type=float, default=0.1)
    p.add_argument("--azi-tol", type=float, default=1.5)
    p.add_argument("--tf-tol", type=float, default=10)
    p.add_argument("--invalid")
    p.add_argument("--seconds", type=float, default=3)
    p.add_argument("--screenshot")
    p.add_argument("--gone")
    p.add_argument("--handshake")
    a = p.parse_args()
    tool = a.key.split("/")[0]
    ref_key = tool + "/" + a.reference
    line = re.compile(r"^minus (\S+): inclination ([+−][\d.]+) ± ([\d.]+)°, azimuth ([+−][\d.]+) ± ([\d.]+)°, "
                      r"toolface (-|[+−][\d.]+)")
    profile = tempfile.mkdtemp(prefix="plumb-chromium-")
    browser = Chromium(profile)
    try:
        browser.call("Page.enable")
        browser.call("Page.navigate", url=a.url)
        deadline = time.time() + 20
        diffs = read_diffs(browser)
        while not line.match(diffs.get(a.key, "")) and time.time() < deadline:
            time.sleep(0.2)
            diffs = read_diffs(browser)
        check(bool(line.match(diffs.get(a.key, ""))), f"card {a.key} shows its difference: '{diffs.get(a.key)}' (cards {sorted(diffs)})")
        seen, refs, inc, azi, tf = set(), set(), [], [], []
        t_end = time.time() + a.seconds
        while time.time() < t_end:
            diffs = read_diffs(browser)
            m = line.match(diffs.get(a.key, ""))
            if m:
                seen.add(m.group(0))
                refs.add(m.group(1))
                inc.append(signed(m.group(2)))
                azi.append(signed(m.group(4)))
                if m.group(6) != "-":
                    tf.append(signed(m.group(6)))
            time.sleep(0.25)
        check(bool(inc) and max(abs(v) for v in inc) <= a.inc_tol,
              f"inclination difference within {a.inc_tol} deg over {len(inc)} readings: {sorted(set(inc))[:6]}")
        check(bool(azi) and max(abs(v) for v in azi) <= a.azi_tol,
              f"azimuth difference within {a.azi_tol} deg: {sorted(set(azi))[:6]}")
        # The toolface turns with the tool (240 rpm: 1440 deg/s), and a plugin loaded later has windows
        # ending at other times: carried to the reference's window end with the plugin's rpm, the two
        # agree within a few degrees (compared without carrying they differ by anything).
        check(bool(tf) and max(abs(v) for v in tf) <= a.tf_tol,
              f"toolface difference (carried to the reference's window end) within {a.tf_tol} deg: {sorted(set(tf))[:6]} ({len(tf)} readings)")
        check(refs == {a.reference}, f"always against {a.reference} (the tool's first estimator by name): {sorted(refs)}")
        check(len(seen) > 1, f"the difference changes while the page is open ({len(seen)} distinct lines)")
        check(diffs.get(ref_key) == "", f"the reference's card {ref_key} shows no difference: '{diffs.get(ref_key)}'")
        if a.invalid:
            want = f"minus {a.reference}: inclination -, azimuth -, toolface -"
            deadline = time.time() + 20
            while diffs.get(a.invalid) != want and time.time() < deadline:
                time.sleep(0.2)
                diffs = read_diffs(browser)
            check(diffs.get(a.invalid) == want, f"card {a.invalid} (no angle while turning): '{diffs.get(a.invalid)}'")
        if a.screenshot:
            browser.screenshot(a.screenshot, 1600, 1000)
            print(f"screenshot {a.screenshot}", flush=True)
        if a.gone and a.handshake:
            check(a.gone in read_diffs(browser), f"card {a.gone} shown before its plugin is unloaded")
            open(os.path.join(a.handshake, "browser-ready"), "w").close()
            unloaded = os.path.join(a.handshake, "unloaded")
            deadline = time.time() + 40
            while not os.path.exists(unloaded) and time.time() < deadline:
                time.sleep(0.1)
            t0 = time.time()
            diffs = read_diffs(browser)
            while a.gone in diffs and time.time() < t0 + 20:
                time.sleep(0.2)
                diffs = read_diffs(browser)
            check(os.path.exists(unloaded) and a.gone not in diffs,
                  f"card {a.gone} left the open page {time.time() - t0:.1f} s after its plugin was unloaded (cards {sorted(diffs)})")
            check(ref_key in diffs, f"the reference's card {ref_key} stays")
    finally:
        browser.close()
        shutil.rmtree(profile, ignore_errors=True)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
