#include "recording/recording.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>

#include "plumb/topics/cdr.hpp"
#include "plumb/topics/names.hpp"

namespace plumb::cli {

const topics::TypeSupport* channel_type(const mcap::Reader& reader, const mcap::Channel& channel) {
  if (channel.message_encoding != kMessageEncoding) return nullptr;
  const auto schema = reader.schemas().find(channel.schema_id);
  if (schema == reader.schemas().end()) return nullptr;
  return topics::find_type_support(schema->second.name);
}

void warn_problems(const std::string& program, const mcap::Reader& reader) {
  for (const auto& p : reader.problems()) std::cerr << program << ": warning: " << reader.path() << ": " << p << '\n';
  if (reader.readable_bytes() < reader.file_size())
    std::cerr << program << ": warning: " << reader.path() << ": read " << reader.readable_bytes() << " of "
              << reader.file_size() << " bytes; the messages before byte " << reader.readable_bytes() << " are used"
              << (reader.has_summary() ? "" : " (plumb record --repair rewrites the file whole)") << '\n';
}

bool is_recording(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[sizeof mcap::kMagic] = {};
  in.read(magic, sizeof magic);
  return in.gcount() == sizeof magic && std::equal(magic, magic + sizeof magic, reinterpret_cast<const char*>(mcap::kMagic));
}

std::vector<std::pair<std::string, std::uint64_t>> topic_message_counts(const mcap::Reader& reader) {
  std::vector<std::pair<std::string, std::uint64_t>> out;
  const auto& counts = reader.statistics().channel_message_counts;
  for (const auto& [id, channel] : reader.channels()) {
    const auto n = counts.find(id);
    out.emplace_back(channel.topic, n == counts.end() ? 0 : n->second);
  }
  return out;
}

std::string describe_topic_counts(const mcap::Reader& reader) {
  std::string text;
  for (const auto& [topic, n] : topic_message_counts(reader))
    text += (text.empty() ? "" : ", ") + topic + " (" + std::to_string(n) + (n == 1 ? " message)" : " messages)");
  return text.empty() ? "no topic at all" : text;
}

namespace {

std::uint64_t message_count(const mcap::Reader& reader, const std::string& topic) {
  std::uint64_t total = 0;
  for (const auto& [t, n] : topic_message_counts(reader))
    if (t == topic) total += n;
  return total;
}

std::string no_messages(const mcap::Reader& reader, const std::string& what) {
  return reader.path() + ": " + what + "; the recording holds " + describe_topic_counts(reader) + " (plumb info " +
         reader.path() + ")";
}

}  // namespace

void require_messages(const mcap::Reader& reader, const std::string& topic) {
  if (message_count(reader, topic) == 0) throw std::runtime_error(no_messages(reader, "no message on '" + topic + "'"));
}

std::string choose_sensor_topic(const std::string& program, const mcap::Reader& reader, const std::string& requested) {
  if (!requested.empty()) {
    bool exists = false;
    for (const auto& [id, channel] : reader.channels()) exists = exists || channel.topic == requested;
    if (!exists)
      throw std::invalid_argument(reader.path() + ": no topic '" + requested + "' in the recording (it holds " +
                                  describe_topic_counts(reader) + ")");
    require_messages(reader, requested);
    return requested;
  }
  const auto& sensor = topics::type_support<topics::SensorBatch>();
  std::vector<std::string> found;  // sensor topics, each once
  for (const auto& [id, channel] : reader.channels()) {
    const auto* type = channel_type(reader, channel);
    if (type && *type == sensor && std::find(found.begin(), found.end(), channel.topic) == found.end())
      found.push_back(channel.topic);
  }
  const auto has = [&](const std::string& t) { return std::find(found.begin(), found.end(), t) != found.end(); };
  const std::string calibrated = topics::names::kSensorCalibrated, raw = topics::names::kSensorRaw;
  std::string chosen, why;
  if (has(calibrated) && message_count(reader, calibrated) > 0) {
    chosen = calibrated;
  } else if (has(raw) && message_count(reader, raw) > 0) {
    chosen = raw;
    if (has(calibrated)) why = "; " + calibrated + " holds none";
  } else {
    std::vector<std::string> others;
    for (const auto& f : found)
      if (f != calibrated && f != raw && message_count(reader, f) > 0) others.push_back(f);
    if (others.size() > 1) {
      std::string names;
      for (const auto& f : others) names += (names.empty() ? "" : ", ") + f;
      throw std::invalid_argument(reader.path() + ": several sensor topics (" + names + "): choose one with --topic");
    }
    if (others.empty()) {
      std::string names;  // the preferred ones first
      for (const auto& f : {calibrated, raw})
        if (has(f)) names += (names.empty() ? "" : " or ") + f;
      for (const auto& f : found)
        if (f != calibrated && f != raw) names += (names.empty() ? "" : " or ") + f;
      throw std::runtime_error(no_messages(reader, found.empty() ? "no sensor topic" : "no sensor message on " + names));
    }
    chosen = others.front();
  }
  std::cerr << program << ": reading " << chosen << " (" << message_count(reader, chosen) << " messages" << why << ")"
            << std::endl;
  return chosen;
}

std::string read_recorded_batches(const std::string& program, const std::string& path, const std::string& topic,
                                  const std::function<void(const topics::SensorBatch&)>& on_batch) {
  mcap::Reader reader(path);
  if (!reader.has_summary()) reader.scan();  // the channels and counts of a file without summary
  const std::string chosen = choose_sensor_topic(program, reader, topic);
  topics::SensorBatch batch;
  reader.scan([&](const mcap::Channel& channel, const mcap::MessageView& m) {
    if (channel.topic != chosen) return;
    try {
      topics::cdr::deserialize(m.data, m.size, batch);
    } catch (const topics::cdr::Error& e) {
      std::cerr << program << ": warning: " << path << ": message " << m.sequence << " on '" << channel.topic
                << "' skipped: " << e.what() << '\n';
      return;
    }
    on_batch(batch);
  });
  warn_problems(program, reader);
  return chosen;
}

}  // namespace plumb::cli
