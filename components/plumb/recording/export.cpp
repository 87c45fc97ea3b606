// plumb export: one recorded topic as CSV in the formats of docs/conventions.md: a sensor topic as the
// sensor CSV (plumb estimate and plumb-bridge --replay read it), an attitude topic as the attitude
// CSV, the truth as the truth CSV; any other topic as its flattened fields (as topic echo --csv).
#include <fstream>
#include <iostream>

#include "messages/csv_output.hpp"
#include "messages/topic_type.hpp"
#include "plumb/components/convert.hpp"
#include "plumb/mcap/reader.hpp"
#include "plumb/topics/cdr.hpp"
#include "plumb/topics/names.hpp"
#include "recording/recording.hpp"
#include "recording/recording_verbs.hpp"

namespace plumb::cli {
namespace {

struct ExportOptions {
  std::string input;
  std::string topic;
  std::string output;
};

// Writes the messages of one topic, decoded, in the CSV its type has.
template <class M> class TopicCsv {
 public:
  void write(std::ostream& out, const M& m) {
    if constexpr (std::is_same_v<M, topics::SensorBatch>) {
      sensor_.write(out, m);
    } else if constexpr (std::is_same_v<M, topics::Attitude>) {
      if (!header_) csv::write_attitude_header(out);
      header_ = true;
      csv::write_attitude_row(out, components::from_topic(m));
    } else if constexpr (std::is_same_v<M, topics::Truth>) {
      if (!header_) out << "t,inclination_deg,azimuth_deg,toolface_deg,rpm\n";
      header_ = true;
      out << format_number(components::ns_to_seconds(m.stamp_ns)) << ',' << format_number(m.inclination_deg) << ','
          << format_number(m.azimuth_deg) << ',' << format_number(m.toolface_deg) << ',' << format_number(m.rpm) << '\n';
    } else {
      flat_.write(out, m);
    }
  }

 private:
  SensorCsvWriter sensor_;
  FlatCsvWriter flat_;
  bool header_ = false;
};

int run_export(const ExportOptions& o) {
  mcap::Reader reader(o.input);
  if (!reader.has_summary()) reader.scan();  // learns the channels of a cut file
  // Default: the sensor topic, as plumb estimate --input takes it (calibrated when it holds
  // messages, else raw); a topic without messages is an error that names the ones with.
  const std::string topic = o.topic.empty() ? choose_sensor_topic("plumb export", reader, "") : o.topic;
  const mcap::Channel* channel = nullptr;
  for (const auto& [id, c] : reader.channels())
    if (c.topic == topic) channel = &c;
  if (!channel) throw std::invalid_argument(o.input + ": no topic '" + topic + "' in the recording (it holds " + describe_topic_counts(reader) + ")");
  require_messages(reader, topic);
  const auto* type = channel_type(reader, *channel);
  if (!type) throw std::runtime_error(o.input + ": topic '" + topic + "' is not a plumb CDR topic (schema unknown to this plumb)");

  std::ofstream file;
  if (!o.output.empty()) {
    file.open(o.output);
    if (!file) throw std::runtime_error("cannot write '" + o.output + "'");
  }
  std::ostream& out = o.output.empty() ? std::cout : file;
  const std::uint16_t id = channel->id;
  std::size_t messages = 0, skipped = 0;
  with_topic_type(*type, [&](auto proto) {
    using M = decltype(proto);
    M message;
    TopicCsv<M> csv;
    reader.scan([&](const mcap::Channel& c, const mcap::MessageView& m) {
      if (c.id != id) return;
      try {
        topics::cdr::deserialize(m.data, m.size, message);
      } catch (const topics::cdr::Error& e) {
        if (++skipped <= 3) std::cerr << "plumb export: warning: message " << m.sequence << " skipped: " << e.what() << '\n';
        return;
      }
      csv.write(out, message);
      ++messages;
    });
  });
  out.flush();
  if (!out) throw std::runtime_error("cannot write '" + (o.output.empty() ? std::string("standard output") : o.output) + "'");
  warn_problems("plumb export", reader);
  std::cerr << "plumb export: " << messages << " message(s) of '" << topic << "' from " << o.input;
  if (skipped) std::cerr << " (" << skipped << " undecodable, skipped)";
  std::cerr << '\n';
  return 0;
}

}  // namespace

void add_recording_export(CLI::App& app, Verbs& verbs) {
  auto o = std::make_shared<ExportOptions>();
  auto* cmd = app.add_subcommand("export", "Write one topic of an MCAP recording as CSV (the formats of docs/conventions.md)");
  cmd->add_option("file", o->input, "the recording (.mcap)")->required();
  cmd->add_option("-t,--topic", o->topic, "topic to export (default: plumb/sensor/calibrated when it holds messages, else plumb/sensor/raw)");
  cmd->add_option("-o,--output", o->output, "CSV file to write (default: standard output)");
  verbs.add(cmd, [o] { return run_export(*o); });
}

}  // namespace plumb::cli
