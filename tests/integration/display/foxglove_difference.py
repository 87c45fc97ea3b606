#!/usr/bin/env python3
"""Two plugins of one tool on plumb-display's Foxglove server: the channel
plumb-display/difference/TOOL/PLUGIN (JSON) is advertised, and its messages, decoded, give the
plugin's difference from REFERENCE within the tolerances. A plain client (wsclient.py, the
foxglove.websocket.v1 subprotocol), so that it runs without the npm registry. usage:
  foxglove_difference.py URL TOOL PLUGIN REFERENCE [--inc-tol D] [--azi-tol D] [--messages N] [--handshake DIR]
--handshake: once those checks are done, writes DIR/foxglove-ready, waits for DIR/unloaded (the test
unloaded PLUGIN), and then the channel is unadvertised (its topic has no writer any more).
Prints "ok   - ..." / "FAIL - ..." lines; exit 1 if any failed."""
import argparse
import json
import os
import struct
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wsclient import WebSocket  # noqa: E402

fails = 0


def check(ok, what):
    global fails
    print(("ok   - " if ok else "FAIL - ") + what, flush=True)
    if not ok:
        fails += 1


def main():
    p = argparse.ArgumentParser()
    p.add_argument("url")
    p.add_argument("tool")
    p.add_argument("plugin")
    p.add_argument("reference")
    p.add_argument("--inc-tol", type=float, default=0.1)
    p.add_argument("--azi-tol", type=float, default=1.5)
    p.add_argument("--messages", type=int, default=5)
    p.add_argument("--handshake")
    a = p.parse_args()
    topic = f"plumb-display/difference/{a.tool}/{a.plugin}"
    ws = WebSocket(a.url, timeout=20, protocol="foxglove.websocket.v1")
    channel, got = None, []
    deadline = time.time() + 20
    while time.time() < deadline and len(got) < a.messages:
        m = ws.recv()
        if isinstance(m, str):
            op = json.loads(m)
            if op.get("op") == "advertise" and channel is None:
                for c in op["channels"]:
                    if c["topic"] == topic:
                        channel = c
                        ws.send(json.dumps({"op": "subscribe", "subscriptions": [{"id": 7, "channelId": c["id"]}]}))
        elif m[0] == 1 and struct.unpack_from("<I", m, 1)[0] == 7:
            got.append(json.loads(m[13:].decode()))
    check(channel is not None and channel["encoding"] == "json" and channel["schemaEncoding"] == "jsonschema",
          f"channel {topic} advertised as JSON: {channel and {k: channel[k] for k in ('encoding', 'schemaName')}}")
    check(len(got) >= a.messages, f"{len(got)} difference messages received")
    inc = [g["inclination"]["deg"] for g in got if g.get("inclination")]
    azi = [g["azimuth"]["deg"] for g in got if g.get("azimuth")]
    check(all(g["reference"] == a.reference for g in got) and got, f"against {a.reference}: {sorted({g['reference'] for g in got})}")
    check(bool(inc) and max(abs(v) for v in inc) <= a.inc_tol, f"inclination difference within {a.inc_tol} deg: {inc}")
    check(bool(azi) and max(abs(v) for v in azi) <= a.azi_tol, f"azimuth difference within {a.azi_tol} deg: {azi}")
    if a.handshake and channel is not None:
        open(os.path.join(a.handshake, "foxglove-ready"), "w").close()
        unloaded = os.path.join(a.handshake, "unloaded")
        deadline = time.time() + 40
        gone, others = False, set()
        while time.time() < deadline and not gone:
            m = ws.recv()  # its messages keep coming until the channel goes
            if not isinstance(m, str):
                continue
            op = json.loads(m)
            if op.get("op") == "unadvertise":
                gone = channel["id"] in op["channelIds"]
                others |= set(op["channelIds"]) - {channel["id"]}
        check(gone and os.path.exists(unloaded),
              f"{topic} unadvertised after {a.plugin} was unloaded (seen by the client after the unload: "
              f"{os.path.exists(unloaded)}, {time.time() - os.path.getmtime(unloaded) if os.path.exists(unloaded) else -1:.1f} s after)")
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
