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

// Calls `on_batch` with every sensor batch of a recording, oldest first, from `topic`, or when
// empty from the one sensor topic it has (calibrated preferred over raw); returns the topic read.
// Throws std::invalid_argument naming the sensor topics when the choice is ambiguous or there is none.
std::string read_recorded_batches(const std::string& program, const std::string& path, const std::string& topic,
                                  const std::function<void(const topics::SensorBatch&)>& on_batch);

}  // namespace plumb::cli
