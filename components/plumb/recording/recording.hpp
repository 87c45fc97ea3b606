// What plumb's recordings (MCAP files) hold and how the record / play / info / export commands
// agree on it: one schema per topic type (its IDL text, encoding "omgidl", named by the scoped IDL
// name), one channel per topic (message encoding "cdr": the XCDR1 bytes DDS carries), a "plumb"
// metadata record (vendor, host, domain, start time). See docs/recording.md.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "plumb/mcap/reader.hpp"
#include "plumb/topics/all.hpp"

namespace plumb::cli {

inline constexpr const char* kSchemaEncoding = "omgidl";
inline constexpr const char* kMessageEncoding = "cdr";
inline constexpr const char* kMetadataName = "plumb";

// The plumb type of a channel (by its schema's name), or nullptr: a channel of another tool's
// file, or a CDR channel of a type this build of plumb does not have.
const topics::TypeSupport* channel_type(const mcap::Reader& reader, const mcap::Channel& channel);

// Opens a recording for reading; a file without summary (a recorder that was killed) is fine.
// Throws mcap::Error when it is not an MCAP file at all.
// Prints "<program>: warning: <file>: <problem>" lines for damage found by the last scan, and
// says how much of the file was read.
void warn_problems(const std::string& program, const mcap::Reader& reader);

// True when `path` starts with the MCAP magic (plumb estimate and compare take recordings and CSV).
bool is_recording(const std::string& path);

// Every topic of the recording with its message count (from the summary, else from the last scan:
// scan a file without summary first), in the order of the channels.
std::vector<std::pair<std::string, std::uint64_t>> topic_message_counts(const mcap::Reader& reader);
// "plumb/sensor/raw (3000 messages), plumb/status (12 messages)", or "no topic at all".
std::string describe_topic_counts(const mcap::Reader& reader);

// The sensor topic to read from a recording: `requested` when given, else plumb/sensor/calibrated
// when it holds messages, else plumb/sensor/raw when it does, else the one other sensor topic that
// does. Prints "<program>: reading <topic> (N messages...)" when the choice was made here. Throws
// std::invalid_argument for a requested topic the file lacks or an ambiguous choice, and
// std::runtime_error naming the topics the file holds, with their counts, when the topic chosen
// has no message (a recording made while only plumb-sim ran has an empty calibrated topic).
std::string choose_sensor_topic(const std::string& program, const mcap::Reader& reader, const std::string& requested);

// Throws std::runtime_error naming the topics the file holds, with their counts, when `topic`
// holds no message in the recording.
void require_messages(const mcap::Reader& reader, const std::string& topic);

// Calls `on_batch` with every sensor batch of a recording, oldest first, from the topic
// choose_sensor_topic() picks; returns the topic read.
std::string read_recorded_batches(const std::string& program, const std::string& path, const std::string& topic,
                                  const std::function<void(const topics::SensorBatch&)>& on_batch);

}  // namespace plumb::cli
