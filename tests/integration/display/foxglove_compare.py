#!/usr/bin/env python3
"""What the independent Foxglove client decoded (foxglove_client.js's JSON) against what
`plumb topic echo --csv` printed of the same topics, and the protocol's checks: the subprotocol,
serverInfo, every channel's encoding (cdr), schema encoding (omgidl) and IDL type name, the share of
the 1 kHz sensor stream received (>= 99 %, or every loss counted by plumb-display's
foxglove_dropped), no message after unsubscribing. Prints ok/FAIL lines; exit 1 on any failure.
The shipped Foxglove layout's message paths are checked against what was decoded: each names an
advertised topic and a field its messages have; among them the difference of two plugins, on
plumb-display's JSON channel plumb-display/difference/<tool>/<plugin>.
usage: foxglove_compare.py CLIENT.json RAW_ECHO.csv ATTITUDE_ECHO.csv RAW_TOPIC ATTITUDE_TOPIC INCLINATION LAYOUT.json"""
import csv
import json
import math
import re
import sys

client_path, raw_csv, att_csv, raw_topic, att_topic, inclination, layout_path = sys.argv[1:8]
inclination = float(inclination)
r = json.load(open(client_path))
fails = 0


def check(ok, what):
    global fails
    print(("ok   - " if ok else "FAIL - ") + what)
    if not ok:
        fails += 1


def close(a, b, rel=1e-8):
    """Equal to the CSV's 10 significant digits; a number not measured (NaN: JSON null, an empty
    cell) only equals another such."""
    a = math.nan if a is None else a
    b = math.nan if b is None else b
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= rel * max(1.0, abs(a), abs(b))


check(r["protocol"] == "foxglove.websocket.v1", f"subprotocol negotiated: {r['protocol']!r}")
info = r["serverInfo"] or {}
check(info.get("name") == "plumb-display" and isinstance(info.get("capabilities"), list),
      f"serverInfo: name {info.get('name')!r}, capabilities {info.get('capabilities')}")
check(not r["problems"], "no client error, undecodable message or server status" +
      ("" if not r["problems"] else ": " + "; ".join(r["problems"][:5])))
channels = {c["topic"]: c for c in r["channels"]}
expected_types = {raw_topic: "plumb::msg::SensorBatch", att_topic: "plumb::msg::Attitude", "plumb/status": "plumb::msg::ComponentStatus"}
for topic, type_name in expected_types.items():
    c = channels.get(topic)
    check(c is not None and c["encoding"] == "cdr" and c["schemaEncoding"] == "omgidl" and c["schemaName"] == type_name
          and c["schemaLength"] > 0, f"channel {topic}: {c}")
# The DDS topics: CDR with their IDL; the display's own channels (plumb-display/...): JSON.
own = [c for c in r["channels"] if c["topic"].startswith("plumb-display/")]
check(all(c["encoding"] == "json" and c["schemaEncoding"] == "jsonschema" and c["schemaName"] == "plumb.display.AttitudeDifference"
          for c in own), f"the display's own channels JSON: {sorted(c['topic'] for c in own)}")
check(all(c["encoding"] == "cdr" and c["schemaEncoding"] == "omgidl" and c["schemaName"].startswith("plumb::msg::")
          for c in r["channels"] if c not in own), f"{len(r['channels']) - len(own)} DDS channels, all cdr / omgidl / plumb::msg::*: " +
      ", ".join(sorted(t for t in channels if not t.startswith("plumb-display/"))))

# The 1 kHz stream: every sample by its sequence number.
raw = r["topics"].get(raw_topic, {"messages": 0, "values": []})
samples = {s["seq"]: s for batch in raw["values"] for s in batch["samples"]}
if samples:
    span = max(samples) - min(samples) + 1
    lost = span - len(samples)
    display = [s for k, s in r["statuses"].items() if k.startswith("plumb-display@")]
    counters = {c["name"]: c["value"] for c in display[-1]["counters"]} if display else {}
    dropped = counters.get("foxglove_dropped", 0)
    rate = raw["messages"] / max(1e-9, (raw["last_rx_ns"] - raw["first_rx_ns"]) * 1e-9)
    print(f"     {raw_topic}: {raw['messages']} messages ({rate:.0f}/s), samples {len(samples)} of {span} "
          f"({100.0 * len(samples) / span:.2f} %), lost {lost}; plumb-display: foxglove_dropped {dropped}, "
          f"foxglove_messages {counters.get('foxglove_messages')}")
    check(len(samples) >= 0.99 * span or lost <= dropped,
          f"{raw_topic}: {len(samples)} of {span} samples received (>= 99 %, or the {lost} lost counted by the server)")
    check(rate > 800, f"{raw_topic}: about 1 kHz received ({rate:.0f} messages/s)")
else:
    check(False, f"{raw_topic}: no sample received")
check(r["afterUnsubscribe"] == 0, f"{raw_topic}: {r['afterUnsubscribe']} messages later than 0.5 s after unsubscribing")

# The same samples, as plumb topic echo --csv printed them.
matched = mismatched = 0
with open(raw_csv) as f:
    for row in csv.DictReader(f):
        s = samples.get(int(row["seq"]))
        if s is None:
            continue
        matched += 1
        same = close(s["stamp_ns"] * 1e-9, float(row["t"]), 1e-11) and all(
            close(s[k], float(row[k])) for k in ("fx", "fy", "fz", "bx", "by", "bz"))
        if not same:
            mismatched += 1
            if mismatched <= 3:
                print(f"     sample {row['seq']}: Foxglove {s}, echo {row}")
check(matched >= 1000 and mismatched == 0, f"{raw_topic}: {matched} samples decoded from Foxglove equal echo's CSV ({mismatched} differ)")

# The attitudes, matched by their window's end.
att = r["topics"].get(att_topic, {"messages": 0, "values": []})
by_end = {a["window_end_ns"]: a for a in att["values"]}
matched = mismatched = 0
with open(att_csv) as f:
    for row in csv.DictReader(f):
        a = by_end.get(int(row["window_end_ns"]))
        if a is None:
            continue
        matched += 1
        same = all(close(a[k], float(row[k]) if row[k] else float("nan"), 1e-9)
                   for k in ("inclination_deg", "azimuth_deg", "gravity_toolface_deg"))
        same = same and a["tool_id"] == row["tool_id"] and a["estimator"] == row["estimator"]
        if not same:
            mismatched += 1
            if mismatched <= 3:
                print(f"     attitude {row['window_end_ns']}: Foxglove {a}, echo {row}")
check(matched >= 5 and mismatched == 0, f"{att_topic}: {matched} estimates decoded from Foxglove equal echo's CSV ({mismatched} differ)")
incs = [a["inclination_deg"] for a in att["values"] if a["flags"] & 1]
check(incs and all(abs(i - inclination) < 0.2 for i in incs),
      f"{att_topic}: inclination decoded within 0.2 deg of the simulated {inclination} deg "
      f"({len(incs)} valid, {min(incs, default=float('nan')):.3f} .. {max(incs, default=float('nan')):.3f})")

# The layout: every plot's path and the raw-message panel's topic, on what the client decoded.
layout = json.load(open(layout_path))
paths = [p["value"] for c in layout["configById"].values() for p in c.get("paths", [])]
paths += [c["topicPath"] for c in layout["configById"].values() if "topicPath" in c]
decoded = dict(r["topics"])
decoded["plumb/status"] = {"values": list(r["statuses"].values())}
bad = []
for path in paths:
    topic, _, rest = path.partition(".")
    if topic not in channels:
        bad.append(f"{path}: no channel {topic}")
        continue
    if not rest:
        continue
    values = decoded.get(topic, {}).get("values") or []
    if not values:
        bad.append(f"{path}: nothing decoded on {topic}")
        continue
    v = values[-1]
    for part in re.findall(r"[A-Za-z_][A-Za-z0-9_]*|\[\d+\]", rest):
        v = v[int(part[1:-1])] if part.startswith("[") else v.get(part) if isinstance(v, dict) else None
        if v is None:
            break
    if not isinstance(v, (int, float)):
        bad.append(f"{path}: not a number ({v!r})")
difference = [p for p in paths if p.startswith("plumb-display/difference/")]
check(difference and {p.partition(".")[0] for p in difference} <= set(decoded),
      f"the layout plots a difference of two plugins, on a channel decoded here: {sorted({p.partition('.')[0] for p in difference})}")
check(paths and not bad, f"the Foxglove layout's {len(paths)} paths name advertised topics and numeric fields" +
      ("" if not bad else ": " + "; ".join(bad)))
sys.exit(1 if fails else 0)
