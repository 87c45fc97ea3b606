// An independent Foxglove WebSocket client of plumb-display, on the npm packages Foxglove itself
// uses: @foxglove/ws-protocol (the client), ws (the socket), @foxglove/omgidl-parser and
// @foxglove/omgidl-serialization (the channel's IDL schema, the CDR decoding). Connects, checks
// serverInfo and every advertised channel, subscribes to the given topics, decodes each message
// with the channel's own schema, unsubscribes the first topic near the end and checks that it
// stops, and writes what it decoded as JSON for the comparison with `plumb topic echo --csv`. A JSON
// channel (plumb-display's own: the difference of two plugins) is decoded as JSON.
// usage: NODE_PATH=DIR/node_modules node foxglove_client.js URL SECONDS OUT.json TOPIC...
// TOPIC "*" subscribes to every channel (the benchmark's client); SIGTERM ends it early, writing the JSON.
"use strict";
const { FoxgloveClient } = require("@foxglove/ws-protocol");
const WebSocket = require("ws");
const { parseIDL } = require("@foxglove/omgidl-parser");
const { MessageReader } = require("@foxglove/omgidl-serialization");
const fs = require("fs");

const [url, secondsText, outPath, ...topics] = process.argv.slice(2);
const seconds = Number(secondsText);
const problems = [];
const result = { serverInfo: null, protocol: null, channels: [], topics: {}, statuses: {}, problems, afterUnsubscribe: 0 };
const readers = new Map();  // channel id -> { topic, reader }
const bySubscription = new Map();  // subscription id -> topic
let unsubscribedAt = null;

function plain(v) {  // BigInt (64-bit integers) to Number, typed arrays to arrays
  if (typeof v === "bigint") return Number(v);
  if (ArrayBuffer.isView(v)) return Array.from(v, plain);
  if (Array.isArray(v)) return v.map(plain);
  if (v && typeof v === "object") {
    const o = {};
    for (const [k, x] of Object.entries(v)) o[k.replace(/^_/, "")] = plain(x);
    return o;
  }
  return v;
}

const ws = new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
const client = new FoxgloveClient({ ws });
ws.on("open", () => { result.protocol = ws.protocol; });
client.on("error", (e) => problems.push(`client error: ${e && e.message}`));
client.on("serverInfo", (info) => { result.serverInfo = info; });
client.on("status", (s) => problems.push(`server status ${s.level}: ${s.message}`));
client.on("advertise", (channels) => {
  for (const c of channels) {
    result.channels.push({ id: c.id, topic: c.topic, encoding: c.encoding, schemaName: c.schemaName,
                           schemaEncoding: c.schemaEncoding, schemaLength: c.schema.length });
    let reader = null;
    try {
      // A channel the display computes itself (its difference of two plugins) is JSON, as Foxglove reads it.
      reader = c.encoding === "json" ? { readMessage: (bytes) => JSON.parse(Buffer.from(bytes).toString("utf8")) }
                                     : new MessageReader(c.schemaName, parseIDL(c.schema));
    } catch (e) {
      problems.push(`${c.topic}: schema ${c.schemaName} not accepted: ${e.message}`);
      continue;
    }
    readers.set(c.id, { topic: c.topic, reader });
    if (topics.includes(c.topic) || topics.includes("*")) {
      bySubscription.set(client.subscribe(c.id), c.topic);
    }
  }
});
client.on("unadvertise", (ids) => { for (const id of ids) readers.delete(id); });
client.on("message", ({ subscriptionId, timestamp, data }) => {
  const topic = bySubscription.get(subscriptionId);
  if (topic === undefined) { problems.push(`message for unknown subscription ${subscriptionId}`); return; }
  if (unsubscribedAt !== null && topic === topics[0] && Date.now() - unsubscribedAt > 500) ++result.afterUnsubscribe;
  const channel = [...readers.values()].find((r) => r.topic === topic);
  let m;
  try {
    m = plain(channel.reader.readMessage(new Uint8Array(data.buffer, data.byteOffset, data.byteLength)));
  } catch (e) {
    problems.push(`${topic}: message not decoded: ${e.message}`);
    return;
  }
  const t = (result.topics[topic] ??= { messages: 0, first_rx_ns: Number(timestamp), values: [] });
  ++t.messages;
  t.last_rx_ns = Number(timestamp);
  if (topic === "plumb/status") result.statuses[`${m.component}@${m.host}`] = m;
  else if (!topics.includes("*")) t.values.push(m);
});

setTimeout(() => {
  // The first topic is unsubscribed for the last second: nothing of it may come after that.
  for (const [id, topic] of bySubscription) if (topic === topics[0]) { client.unsubscribe(id); unsubscribedAt = Date.now(); }
}, Math.max(0, seconds - 1.5) * 1000);
function end() {
  client.close();
  fs.writeFileSync(outPath, JSON.stringify(result));
  process.exit(0);
}
setTimeout(end, seconds * 1000);
process.on("SIGTERM", end);
