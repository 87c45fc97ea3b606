// plumb record: topics into an MCAP file; plumb record --repair: a cut file rewritten whole.
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "messages/fields.hpp"
#include "messages/topic_type.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/mcap/reader.hpp"
#include "plumb/mcap/writer.hpp"
#include "recording/recorder.hpp"
#include "recording/recording.hpp"
#include "recording/recording_verbs.hpp"

namespace plumb::cli {
namespace {

using Clock = std::chrono::steady_clock;
using components::g_stop;

struct RecordOptions {
  components::TransportOptions transport;
  std::vector<std::string> topics;
  std::string output;
  std::string repair;
  double duration_s = 0;      // 0 = until interrupted
  double flush_s = 1;         // a chunk at least this often: what a kill can lose
  std::size_t chunk_kb = 1024;
  bool reliable = false;
  bool uncompressed = false;
  double wait_s = 2;
};

std::string utc_time(std::chrono::system_clock::time_point t) {
  const std::time_t s = std::chrono::system_clock::to_time_t(t);
  std::tm tm{};
  gmtime_r(&s, &tm);
  std::ostringstream out;
  out << std::put_time(&tm, "%Y-%m-%dT%H:%M:%SZ");
  return out.str();
}

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

// The domain the connection used: the option, else $PLUMB_DOMAIN_ID, else 0 (as connect() does).
std::string domain_text(const components::TransportOptions& o) {
  if (o.domain_id >= 0) return std::to_string(o.domain_id);
  const char* d = std::getenv("PLUMB_DOMAIN_ID");
  return d && *d ? d : "0";
}

// A topic of the network worth recording when no list was given: a plumb name with a plumb type.
bool recordable(const transport::DiscoveredTopic& t) {
  return t.writers > 0 && t.name.rfind("plumb/", 0) == 0 && topics::find_type_support(t.type_name) != nullptr;
}

// The metadata record that opens a recording: who recorded it, where, on which domain, when.
void write_start_metadata(mcap::Writer& writer, const components::Connection& conn, const RecordOptions& o) {
  const auto start = std::chrono::system_clock::now();
  writer.write_metadata({kMetadataName,
                         {{"vendor", conn.transport->vendor_version()},
                          {"transport", conn.transport->name()},
                          {"host", host_name()},
                          {"domain", domain_text(o.transport)},
                          {"start_time", utc_time(start)},
                          {"start_time_ns", std::to_string(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                                               start.time_since_epoch()).count())},
                          {"sensor_qos", o.reliable ? "reliable keep_all" : "best_effort keep_last 64"}}});
}

using NamedTopics = std::vector<std::pair<std::string, const transport::TypeSupport*>>;

// What the recorder waits for, for the notes when nothing comes.
std::string waiting_for(const NamedTopics& named) {
  if (named.empty()) return "any plumb topic";
  std::string text;
  for (const auto& [topic, type] : named) text += (text.empty() ? "" : ", ") + topic;
  return text;
}

// What the network does carry, for the same notes.
std::string heard(transport::Participant& participant, const components::TransportOptions& options) {
  std::string with_writers;
  for (const auto& t : participant.discovered_topics())
    if (t.writers > 0) with_writers += (with_writers.empty() ? "" : ", ") + t.name;
  return with_writers.empty() ? "no topic has a writer on domain " + domain_text(options)
                              : "topics with writers on domain " + domain_text(options) + ": " + with_writers;
}

// Records until Ctrl-C or --duration: drains the readers, writes a chunk every --flush-interval,
// adds topics that appear later (without a list), and says at 3 s, 6 s, 12 s... when nothing came.
// Returns why the writer failed, empty when it did not.
std::string record_until_stopped(const RecordOptions& o, transport::Participant& participant, mcap::Writer& writer,
                                 Recorder& recorder, const NamedTopics& named, Clock::time_point t0) {
  double next_silence_note_s = 3;
  auto last_flush = t0, last_discovery = t0;
  while (!g_stop) {
    const auto now = Clock::now();
    if (const double silent_s = std::chrono::duration<double>(now - t0).count(); silent_s >= next_silence_note_s) {
      next_silence_note_s *= 2;
      if (recorder.messages() == 0)
        std::cerr << "plumb record: nothing received for " << static_cast<int>(silent_s) << " s on " << waiting_for(named)
                  << "; " << heard(participant, o.transport) << std::endl;
    }
    if (o.duration_s > 0 && std::chrono::duration<double>(now - t0).count() >= o.duration_s) break;
    try {
      recorder.drain();
      if (now - last_flush >= std::chrono::duration<double>(o.flush_s)) {
        writer.flush();
        last_flush = now;
      }
    } catch (const mcap::Error& e) {
      return e.what();
    }
    // Without a list: the estimator, navigation and sensor-stream topics that appear later too.
    if (named.empty() && now - last_discovery >= std::chrono::milliseconds(500)) {
      last_discovery = now;
      for (const auto& t : participant.discovered_topics()) {
        if (recordable(t) && !recorder.has(t.name)) recorder.add(t.name, *topics::find_type_support(t.type_name));
      }
    }
    recorder.wait(std::chrono::milliseconds(20));
  }
  try {
    recorder.drain();  // what arrived before the stop
  } catch (const mcap::Error& e) {
    return e.what();
  }
  return {};
}

int run_record(const RecordOptions& o) {
  if (o.flush_s <= 0) throw std::invalid_argument("--flush-interval must be > 0 seconds");
  if (o.chunk_kb == 0) throw std::invalid_argument("--chunk-size must be > 0 KiB");
  auto conn = components::connect(o.transport, "plumb-record");
  // Named topics are resolved before the file is created: a typo leaves no empty recording behind.
  NamedTopics named;
  for (const auto& t : o.topics) named.emplace_back(t, &resolve_topic_type(*conn.participant, t, o.wait_s));

  mcap::WriterOptions wo;
  wo.chunk_size = o.chunk_kb * 1024;
  wo.compress = !o.uncompressed;
  mcap::Writer writer(o.output, wo);
  write_start_metadata(writer, conn, o);
  Recorder recorder(*conn.participant, writer, o.reliable);
  for (const auto& [topic, type] : named) recorder.add(topic, *type);
  if (named.empty()) {
    for (const auto& e : topics::kTopicTable) {
      if (!e.prefix) recorder.add(e.name, *e.type);
    }
  }
  components::install_stop_handler();
  std::cerr << "plumb record: recording " << (named.empty() ? "every plumb topic" : std::to_string(named.size()) + " topic(s)")
            << " to " << o.output << " (Ctrl-C to stop)" << std::endl;

  const auto t0 = Clock::now();
  std::string failure = record_until_stopped(o, *conn.participant, writer, recorder, named, t0);
  const double elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
  try {
    writer.close();
  } catch (const mcap::Error& e) {
    failure = e.what();
  }
  std::size_t topics_with_data = 0;
  for (const auto& c : recorder.counts()) topics_with_data += c.messages > 0;
  if (!failure.empty()) {
    components::print_error("plumb record", "stopped: " + failure);
    std::cerr << "plumb record: " << writer.statistics().message_count << " message(s) kept in " << o.output << '\n';
    return 1;
  }
  if (writer.statistics().message_count == 0) {
    components::print_error("plumb record", "nothing recorded: no message on " + waiting_for(named) + " in " +
                                                format_measured(elapsed) + " s (" + heard(*conn.participant, o.transport) +
                                                "); " + o.output + " holds no message");
    return 1;
  }
  std::cerr << "plumb record: " << writer.statistics().message_count << " message(s) on " << topics_with_data
            << " topic(s) in " << format_measured(elapsed) << " s to " << o.output << " ("
            << format_measured(static_cast<double>(writer.bytes_written()) / 1e6) << " MB)" << std::endl;
  return 0;
}

// Reads what a cut file holds and writes it again with a summary: same schemas, channels,
// metadata and messages, in the same order.
int run_repair(const RecordOptions& o) {
  mcap::Reader reader(o.repair);
  // In place: written beside the file, then renamed over it once whole.
  const std::string out = o.output.empty() ? o.repair + ".repaired" : o.output;
  std::string what;
  {
    mcap::Writer writer(out);
    std::map<std::uint16_t, std::uint16_t> schema_ids, channel_ids;
    reader.scan([&](const mcap::Channel& channel, const mcap::MessageView& m) {
      auto c = channel_ids.find(channel.id);
      if (c == channel_ids.end()) {
        std::uint16_t schema_id = 0;
        if (const auto s = reader.schemas().find(channel.schema_id); s != reader.schemas().end()) {
          auto known = schema_ids.find(s->first);
          if (known == schema_ids.end())
            known = schema_ids.emplace(s->first, writer.add_schema(s->second.name, s->second.encoding, s->second.data)).first;
          schema_id = known->second;
        }
        c = channel_ids.emplace(channel.id, writer.add_channel(schema_id, channel.topic, channel.message_encoding, channel.metadata))
                .first;
      }
      mcap::MessageView copy = m;
      copy.channel_id = c->second;
      writer.write(copy);
    });
    for (const auto& md : reader.metadata()) writer.write_metadata(md);
    writer.close();
    what = std::to_string(writer.statistics().message_count) + " message(s) in " +
           std::to_string(writer.statistics().chunk_count) + " chunk(s)";
    if (reader.readable_bytes() < reader.file_size())
      what += "; bytes " + std::to_string(reader.readable_bytes()) + " to " + std::to_string(reader.file_size()) + " were not readable";
  }
  warn_problems("plumb record", reader);
  if (o.output.empty()) std::filesystem::rename(out, o.repair);
  std::cerr << "plumb record: repaired " << o.repair << (o.output.empty() ? " in place" : " -> " + o.output) << ": " << what
            << '\n';
  return 0;
}

}  // namespace

void add_recording_record(CLI::App& app, Verbs& verbs) {
  auto o = std::make_shared<RecordOptions>();
  auto* cmd = app.add_subcommand("record", "Record topics into an MCAP file (every plumb topic unless named)");
  cmd->footer(
      "The file: IDL text as schema (omgidl), CDR messages, zstd chunks written at least every --flush-interval, "
      "index and summary at the end, metadata (vendor, host, domain, start time). A recorder killed or stopped by a "
      "full disk leaves its written chunks readable; --repair rewrites such a file with its summary. docs/recording.md");
  components::add_transport_options(*cmd, o->transport);
  cmd->add_option("topics", o->topics, "topics to record (default: every plumb topic, including ones that appear later)");
  auto* output = cmd->add_option("-o,--output", o->output, "the MCAP file to write (with --repair: where to write the repaired file)");
  cmd->add_option("--duration", o->duration_s, "stop after this many seconds (default: until Ctrl-C)");
  cmd->add_option("--flush-interval", o->flush_s, "seconds between chunk writes: at most this much is lost when killed")
      ->capture_default_str();
  cmd->add_option("--chunk-size", o->chunk_kb, "KiB of messages per chunk before it is written")->capture_default_str();
  cmd->add_flag("--reliable", o->reliable,
                "read sensor topics reliable keep-all: nothing lost from writers that publish reliable "
                "(plumb-sim --reliable, plumb-bridge --reliable)");
  cmd->add_flag("--uncompressed", o->uncompressed, "store chunks without zstd compression");
  cmd->add_option("--wait", o->wait_s, "seconds to wait for discovery of a named topic outside plumb's names")->capture_default_str();
  auto* repair = cmd->add_option("--repair", o->repair, "rewrite this recording (e.g. one cut by kill -9) with a summary, in place unless -o")
                     ->check(CLI::ExistingFile);
  repair->excludes("topics");
  verbs.add(cmd, [o, output, repair] {
    if (repair->count() > 0) return run_repair(*o);
    if (output->count() == 0) throw std::invalid_argument("plumb record needs -o FILE.mcap (or --repair FILE)");
    return run_record(*o);
  });
}

}  // namespace plumb::cli
