#!/usr/bin/env python3
"""Judges a fault test from the watcher's log (plumb-test-faults-watch) and what the script did.

  check_faults.py link WATCH_LOG --linkem STATS --batch N --down T --up T --loss T --loss-end T --window-ns W
  check_faults.py restart WATCH_LOG --events EVENTS --window-ns W

Prints one "ok" or "FAIL" line per check and the measured numbers; exit status 1 on any failure.
"""
import argparse
import sys

fails = 0


def check(ok, text):
    global fails
    print(("ok   - " if ok else "FAIL - ") + text)
    if not ok:
        fails += 1


def read_log(path):
    """attitude: [(t, start_ns, end_ns, flags)], status: [(t, component, state, {counter: value})], calibration."""
    attitude, status, calibration, sensor = [], [], [], []
    summary = {}
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "attitude" and len(w) >= 6:
                attitude.append((float(w[1]), int(w[2]), int(w[3]), int(w[5])))
            elif w[0] == "status" and len(w) >= 4:
                counters = dict(kv.split("=", 1) for kv in w[4:] if "=" in kv)
                status.append((float(w[1]), w[2], w[3], {k: int(v) for k, v in counters.items()}))
            elif w[0] == "calibration":
                calibration.append((float(w[1]), w[2] if len(w) > 2 else ""))
            elif w[0].startswith("sensor_"):
                sensor.append((w[0], float(w[1]), [float(x) for x in w[2:]]))
            elif w[0] == "summary":
                summary = dict(kv.split("=", 1) for kv in w[1:])
    return attitude, status, calibration, sensor, summary


def window_gaps(attitude, window_ns):
    """[(t_arrival, missing windows)] where the next window does not follow the previous one, and the
    number of windows that came twice or out of order."""
    gaps, disorder = [], 0
    for prev, cur in zip(attitude, attitude[1:]):
        step = cur[1] - prev[1]
        if step <= 0:
            disorder += 1
            continue
        missing = round(step / window_ns) - 1
        if missing > 0:
            gaps.append((cur[0], missing, prev[2], cur[1]))
    return gaps, disorder


def last_status(status, component, having=None, before=None):
    for t, c, state, counters in reversed(status):
        if c == component and (having is None or having in counters) and (before is None or t < before):
            return t, state, counters
    return None


def read_stats(path):
    out = {}
    with open(path) as f:
        for line in f:
            if "=" in line:
                k, v = line.strip().split("=", 1)
                out[k] = v
    return out


def link(a):
    attitude, status, _, _, _ = read_log(a.log)
    check(len(attitude) > 20, f"{len(attitude)} attitude windows crossed the link")
    gaps, disorder = window_gaps(attitude, a.window_ns)
    during_down = sum(m for t, m, *_ in gaps if a.down <= t <= a.up + 30)
    during_loss = sum(m for t, m, *_ in gaps if a.loss <= t <= a.loss_end + 5)
    print(f"attitude windows lost: {during_down} across the 10 s outage, {during_loss} under 20 % loss + 50 ms, "
          f"{sum(m for _, m, *_ in gaps)} in all; {disorder} duplicated or out of order")
    tool_host = last_status(status, "plumb-estimator", "integral.estimates")
    tool_input_lost = tool_host[2].get("lost_samples", 0) if tool_host else 0
    # The tool-side host reads the sensor stream on its own computer: a window it never made (its own
    # input lost samples) is not the link's fault; a window it made and the surface never got is.
    check(sum(m for _, m, *_ in gaps) == 0 or tool_input_lost > 0,
          f"reliable attitude complete end to end (gaps: {[(round(t, 1), m) for t, m, *_ in gaps]})")
    check(disorder == 0, "no attitude window twice or out of order")
    after_up = [t for t, *_ in attitude if t > a.up]
    resume = after_up[0] - a.up if after_up else None
    check(resume is not None and resume < 5, f"attitude resumed {resume if resume is None else round(resume, 2)} s after the link came back")
    surface = last_status(status, "plumb-estimator", "static.estimates")
    check(surface is not None, "the surface host's status arrived")
    if surface is None:
        return
    c = surface[2]
    counted = c.get("lost_samples", 0) + c.get("silent_lost_samples", 0)
    stats = read_stats(a.linkem)
    dropped_frames = int(stats.get("a_to_b_dropped_big", 0))
    dropped = dropped_frames * a.batch
    print(f"surface host: lost_samples={c.get('lost_samples')} (in {c.get('seq_gaps')} gaps), "
          f"silent_lost_samples={c.get('silent_lost_samples')} (in {c.get('silent_gaps')} silences), "
          f"samples={c.get('samples')}; linkem dropped {dropped_frames} sensor-sized frames tool->surface "
          f"({stats.get('a_to_b_dropped_down')} while down, {stats.get('a_to_b_dropped_loss')} frames of all sizes to loss)")
    # Each sensor batch is one frame of about 1.2 kB (10 samples), the only frames of 1000 bytes or more
    # going to the surface; the outage and the loss start and end while the stream flows, so every
    # dropped batch is a gap the host counts. Tolerance: 2 batches, for a discovery or status frame
    # that grew past 1000 bytes; beyond the link's drops, also the datagrams the two hosts dropped
    # themselves (their kernels' UDP buffer errors; a loaded machine, seen once: 26 batches more).
    beyond = (2 + a.host_drops) * a.batch
    check(dropped - 2 * a.batch <= counted <= dropped + beyond,
          f"samples counted lost by plumb ({counted}) = samples in the frames linkem dropped ({dropped}), "
          f"within {2 * a.batch} below and {beyond} above ({a.host_drops} datagrams dropped by the hosts themselves)")
    check(c.get("source_restarts", 0) == 0 and c.get("seq_backwards", 0) == 0, "no restart seen by the surface host")


def restart(a):
    attitude, status, calibration, sensor, summary = read_log(a.log)
    events = []
    with open(a.events) as f:
        for line in f:
            w = line.split()
            if len(w) >= 3:
                events.append((w[0], w[1], float(w[2])))  # kill|start COMPONENT T
    check(len(attitude) > 10, f"{len(attitude)} attitude windows")
    gaps, disorder = window_gaps(attitude, a.window_ns)
    check(disorder == 0, "no attitude window twice or out of order")
    starts = {c: t for what, c, t in events if what == "start"}
    kills = [(c, t) for what, c, t in events if what == "kill"]
    for component, t_kill in kills:
        t_start = max(t for what, c, t in events if what == "start" and c == component and t > t_kill)
        if component == "plumb-estimator":
            after = [t for t, *_ in attitude if t > t_start]
            resume = after[0] - t_start if after else None
            lost = [(t, m, e, s) for t, m, e, s in gaps if t_kill <= t <= (after[0] + 0.1 if after else 1e18)]
            missing = sum(m for _, m, *_ in lost)
            span = (lost[0][3] - lost[0][2]) / 1e9 if lost else 0
            print(f"plumb-estimator: first attitude {resume if resume is None else round(resume, 2)} s after the restart; "
                  f"{missing} window(s) lost ({span:.2f} s of data between the last window before the kill and the first after)")
            check(resume is not None and resume < 10, "the estimator host resumed")
            window_s = a.window_ns / 1e9
            outage = t_start - t_kill
            check(missing <= outage / window_s + 4, f"no more windows lost than the outage ({outage:.1f} s) and the restart explain")
            # The new host read its previous instance's record and counted what the bridge sent in
            # between: the outage, and at most 4 s more (its start and discovery).
            host = last_status(status, "plumb-estimator", "lost_while_down")
            counted = host[2]["lost_while_down"] if host else None
            print(f"plumb-estimator: lost_while_down {counted} ({outage:.2f} s down at {a.rate_hz:g} Hz)")
            check(counted is not None and outage * a.rate_hz - 100 <= counted <= (outage + 4) * a.rate_hz,
                  "the new host counted the samples sent while it was down")
        elif component == "plumb-bridge":
            after = [e for e in sensor if e[0] in ("sensor_resume", "sensor_gap") and e[1] > t_kill]
            resumed = [e for e in sensor if e[0] == "sensor_resume" and e[1] > t_start]
            resume = resumed[0][1] - t_start if resumed else None
            lost = sum(int(e[2][1] - e[2][0]) for e in sensor if e[0] == "sensor_gap" and t_kill <= e[1] <= t_start + 15)
            outage = t_start - t_kill
            print(f"plumb-bridge: calibrated samples again {resume if resume is None else round(resume, 2)} s after the restart; "
                  f"{lost} samples missing across it ({lost / a.rate_hz:.2f} s of data for {outage:.2f} s without a bridge)")
            check(resume is not None and resume < 10, "the bridge resumed")
            # What the board sent while no bridge read it, and what the killed bridge had read and
            # not yet published (up to a batch): the outage, give or take the bridge's start.
            check(outage * a.rate_hz - 100 <= lost <= (outage + 4) * a.rate_hz,
                  "samples missing across the bridge's restart match the time without a bridge (+ at most 4 s to start: discovery, coefficients)")
            host = last_status(status, "plumb-estimator", "samples")
            if host:
                counted = host[2].get("lost_samples", 0) + host[2].get("silent_lost_samples", 0)
                # Each reader counts what it missed, and either of them may match the restarted bridge
                # later than the other (discovery takes 0.1 to 4 s; a volatile topic keeps nothing for
                # a late reader): both must count the time without a bridge, and at most 4 s more.
                seen = int(summary.get("lost", -1))
                check(outage * a.rate_hz - 100 <= counted <= (outage + 4) * a.rate_hz,
                      f"the estimator host counted the samples lost ({counted}; the watcher saw {seen} missing): "
                      f"the time without a bridge ({outage:.2f} s) and at most 4 s more (discovery)")
        elif component == "plumb-calibrate":
            again = [t for t, _ in calibration if t > t_start]
            resume = again[0] - t_start if again else None
            print(f"plumb-calibrate: coefficients again {resume if resume is None else round(resume, 2)} s after the restart")
            check(resume is not None and resume < 10, "the calibration was published again")
        else:
            again = [t for t, c, state, _ in status if c == component and t > t_start and state == "running"]
            resume = again[0] - t_start if again else None
            print(f"{component}: status 'running' {resume if resume is None else round(resume, 2)} s after the restart")
            check(resume is not None and resume < 10, f"{component} resumed")
    # An outage of the bridge costs attitude windows too (their samples never came).
    outages = [(t, min([s for w, c2, s in events if w == "start" and c2 == c and s > t] + [t]) + 10) for c, t in kills
               if c in ("plumb-estimator", "plumb-bridge")]
    elsewhere = [(round(t, 1), m) for t, m, *_ in gaps if not any(k <= t <= e for k, e in outages)]
    check(not elsewhere, f"no attitude window lost but across the estimator's and the bridge's restarts ({elsewhere})")
    seen = sum(m for t, m, *_ in gaps)
    survey_kill = [t for c, t in kills if c == "plumb-survey"]
    survey = last_status(status, "plumb-survey", "attitude_windows_missing", before=survey_kill[0] if survey_kill else None)
    if survey:
        before = sum(m for t, m, *_ in gaps if not survey_kill or t < survey_kill[0])
        got = survey[2]["attitude_windows_missing"]
        print(f"plumb-survey counted {got} attitude windows missing in {survey[2].get('attitude_gaps')} gaps "
              f"(the watcher: {before}, {seen} in all)")
        # Each reader counts what it missed, and one that matches the restarted estimator host later
        # (discovery takes 0.1 to 4 s) also misses the windows published before: allow 2 s of windows.
        slack = round(2e9 / a.window_ns)
        check(abs(got - before) <= slack,
              f"plumb-survey counts the attitude windows the restarts cost (within {slack}: its own discovery)")
    gaps_elsewhere = [e for e in sensor if e[0] == "sensor_gap" and not any(
        c == "plumb-bridge" and t <= e[1] <= starts.get("plumb-bridge", t) + 15 for c, t in kills)]
    check(not gaps_elsewhere, f"no calibrated sample lost but across the bridge's restart ({len(gaps_elsewhere)} gaps elsewhere)")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("mode", choices=["link", "restart"])
    p.add_argument("log")
    p.add_argument("--linkem")
    p.add_argument("--batch", type=int, default=10)
    p.add_argument("--host-drops", type=int, default=0, help="UDP datagrams the hosts' kernels dropped during the run")
    p.add_argument("--down", type=float)
    p.add_argument("--up", type=float)
    p.add_argument("--loss", type=float)
    p.add_argument("--loss-end", type=float)
    p.add_argument("--window-ns", type=int, default=500000000)
    p.add_argument("--events")
    p.add_argument("--rate-hz", type=float, default=1000)
    a = p.parse_args()
    (link if a.mode == "link" else restart)(a)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
