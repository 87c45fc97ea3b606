// plumb info: what a recording holds, the way `ros2 bag info` says it: duration, counts and rates
// per topic, the metadata, and any damage with its byte offset.
#include <cstdio>
#include <ctime>
#include <iomanip>
#include <iostream>

#include "messages/fields.hpp"
#include "plumb/mcap/reader.hpp"
#include "recording/recording.hpp"
#include "recording/recording_verbs.hpp"

namespace plumb::cli {
namespace {

std::string size_text(std::uint64_t bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB"};
  double v = static_cast<double>(bytes);
  int u = 0;
  while (v >= 1024 && u < 3) {
    v /= 1024;
    ++u;
  }
  return format_measured(v) + " " + units[u];
}

std::string time_text(std::uint64_t ns) {
  const std::time_t s = static_cast<std::time_t>(ns / 1000000000u);
  std::tm tm{};
  gmtime_r(&s, &tm);
  char text[64];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &tm);
  char frac[16];
  std::snprintf(frac, sizeof frac, ".%09llu", static_cast<unsigned long long>(ns % 1000000000u));
  return std::string(text) + frac + " UTC (" + std::to_string(ns) + " ns)";
}

int run_info(const std::string& path) {
  mcap::Reader reader(path);
  // A closed file answers from its summary; a cut one is scanned, and so is a damaged one.
  if (!reader.has_summary()) reader.scan();
  const auto& st = reader.statistics();
  const double duration = st.message_count ? static_cast<double>(st.message_end_time - st.message_start_time) * 1e-9 : 0;
  std::cout << "Files:             " << path << '\n'
            << "Bag size:          " << size_text(reader.file_size()) << '\n'
            << "Storage id:        mcap\n"
            << "Duration:          " << std::fixed << std::setprecision(3) << duration << "s\n";
  std::cout.unsetf(std::ios::floatfield);
  if (st.message_count) {
    std::cout << "Start:             " << time_text(st.message_start_time) << '\n'
              << "End:               " << time_text(st.message_end_time) << '\n';
  }
  std::cout << "Messages:          " << st.message_count << '\n'
            << "Chunks:            " << st.chunk_count << '\n'
            << "Summary:           "
            << (reader.has_summary() ? "yes" : "no: recovered by reading the file through (the recorder did not close it)")
            << '\n';
  for (const auto& m : reader.metadata()) {
    std::cout << "Metadata " << m.name << ":";
    for (const auto& [k, v] : m.entries) std::cout << "\n  " << k << ": " << v;
    std::cout << '\n';
  }
  std::cout << "Topic information:";
  bool first = true;
  for (const auto& [id, channel] : reader.channels()) {
    const auto count = st.channel_message_counts.count(id) ? st.channel_message_counts.at(id) : 0;
    const auto schema = reader.schemas().find(channel.schema_id);
    std::cout << (first ? " " : "\n                   ") << "Topic: " << channel.topic
              << " | Type: " << (schema != reader.schemas().end() ? schema->second.name : "(none)") << " | Count: " << count
              << " | Rate: " << (duration > 0 && count > 1 ? format_measured(static_cast<double>(count) / duration) : "-")
              << " Hz | Serialization Format: " << channel.message_encoding;
    first = false;
  }
  std::cout << '\n';
  if (!reader.problems().empty()) {
    std::cout << "Problems:";
    for (const auto& p : reader.problems()) std::cout << "\n  " << p;
    std::cout << "\n  read " << reader.readable_bytes() << " of " << reader.file_size() << " bytes\n";
  }
  std::cout.flush();
  warn_problems("plumb info", reader);
  return 0;
}

}  // namespace

void add_recording_info(CLI::App& app, Verbs& verbs) {
  auto path = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand("info", "Summarise an MCAP recording: topics, types, counts, duration, rates, metadata");
  cmd->add_option("file", *path, "the recording (.mcap)")->required();
  verbs.add(cmd, [path] { return run_info(*path); });
}

}  // namespace plumb::cli
