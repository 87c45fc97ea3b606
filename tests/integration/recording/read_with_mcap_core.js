// An independent reader of a plumb recording: the MCAP TypeScript library (@mcap/core) reads every
// record of the file twice, as a stream (each record, CRCs checked) and through its summary and
// indexes; the OMG IDL parser and CDR reader of Foxglove decode every message with the schema text
// the file carries. Prints one JSON line of what it found; exits 1 on any error.
// usage: node read_with_mcap_core.js FILE.mcap
"use strict";
const fs = require("fs");
const { McapStreamReader, McapIndexedReader } = require("@mcap/core");
const { decompress } = require("fzstd");
const { parseIDL } = require("@foxglove/omgidl-parser");
const { MessageReader } = require("@foxglove/omgidl-serialization");

const decompressHandlers = {
  zstd: (buffer, size) => decompress(buffer, new Uint8Array(Number(size))),
};

async function main() {
  const bytes = fs.readFileSync(process.argv[2]);
  const result = { records: {}, schemas: [], topics: {}, indexed: {}, decoded: 0, first: {} };

  const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  stream.append(bytes);
  const schemas = new Map();
  const channels = new Map();
  const readers = new Map();
  let record;
  while ((record = stream.nextRecord()) !== undefined) {
    result.records[record.type] = (result.records[record.type] || 0) + 1;
    if (record.type === "Schema") {
      schemas.set(record.id, record);
      result.schemas.push({ name: record.name, encoding: record.encoding });
    } else if (record.type === "Channel") {
      channels.set(record.id, record);
    } else if (record.type === "Message") {
      const channel = channels.get(record.channelId);
      result.topics[channel.topic] = (result.topics[channel.topic] || 0) + 1;
      let reader = readers.get(channel.id);
      if (!reader) {
        const schema = schemas.get(channel.schemaId);
        reader = new MessageReader(schema.name, parseIDL(new TextDecoder().decode(schema.data)));
        readers.set(channel.id, reader);
      }
      const message = reader.readMessage(record.data);
      result.decoded += 1;
      if (!(channel.topic in result.first)) result.first[channel.topic] = message;
    }
  }
  if (!stream.done()) throw new Error("stream reader did not reach the end of the file");

  const indexed = await McapIndexedReader.Initialize({
    readable: {
      size: async () => BigInt(bytes.length),
      read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
    },
    decompressHandlers,
  });
  result.indexed.message_count = Number(indexed.statistics.messageCount);
  result.indexed.chunks = indexed.chunkIndexes.length;
  result.indexed.metadata = [];
  for await (const m of indexed.readMetadata()) result.indexed.metadata.push(m.name);
  let n = 0;
  for await (const m of indexed.readMessages()) n += m ? 1 : 0;
  result.indexed.read = n;
  console.log(JSON.stringify(result, (k, v) => (typeof v === "bigint" ? v.toString() : v)));
}

main().catch((e) => {
  console.error("mcap/core: " + (e && e.stack ? e.stack : e));
  process.exit(1);
});
