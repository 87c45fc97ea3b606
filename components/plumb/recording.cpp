#include "recording.hpp"

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

std::string read_recorded_batches(const std::string& program, const std::string& path, const std::string& topic,
                                  const std::function<void(const topics::SensorBatch&)>& on_batch) {
  mcap::Reader reader(path);
  struct {
    std::string topic;
  } out{topic};
  const auto& sensor = topics::type_support<topics::SensorBatch>();
  if (out.topic.empty()) {
    if (!reader.has_summary()) reader.scan();  // the channels of a file without summary
    std::vector<std::string> found;
    for (const auto& [id, channel] : reader.channels()) {
      const auto* type = channel_type(reader, channel);
      if (type && *type == sensor) found.push_back(channel.topic);
    }
    for (const char* preferred : {topics::names::kSensorCalibrated, topics::names::kSensorRaw}) {
      if (out.topic.empty() && std::find(found.begin(), found.end(), preferred) != found.end()) out.topic = preferred;
    }
    if (out.topic.empty() && found.size() == 1) out.topic = found[0];
    if (out.topic.empty()) {
      std::string names;
      for (const auto& f : found) names += (names.empty() ? "" : ", ") + f;
      throw std::invalid_argument(path + ": " + (found.empty() ? "no sensor topic in the recording"
                                                                : "several sensor topics (" + names + "): choose one with --topic"));
    }
  }
  bool seen = false;
  topics::SensorBatch batch;
  reader.scan([&](const mcap::Channel& channel, const mcap::MessageView& m) {
    if (channel.topic != out.topic) return;
    seen = true;
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
  if (!seen) {
    bool exists = false;
    for (const auto& [id, channel] : reader.channels()) exists = exists || channel.topic == out.topic;
    if (!exists) throw std::invalid_argument(path + ": no topic '" + out.topic + "' in the recording (plumb info " + path + " lists them)");
  }
  return out.topic;
}

}  // namespace plumb::cli
