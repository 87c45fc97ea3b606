// plumb-bench-transport: one-way latency (ping-pong, round trip / 2: median and p99) and throughput
// of SensorBatch (32 samples) and Attitude messages over plumb's transports on loopback, for every
// writer/reader vendor pair, beside the native programs of the same vendors with the same IDL types
// (plumb-bench-native-cyclone, plumb-bench-native-fastdds) and Cyclone DDS's ddsperf, all run in
// the same way in the same run.
// Every measurement runs between two child processes (this program in a --role).
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <optional>
#include <iostream>
#include <sstream>
#include <thread>

#include "child_process.hpp"
#include "ddsperf_baseline.hpp"
#include "machine_load.hpp"
#include "payloads.hpp"
#include "plumb/transport/loader.hpp"
#include "report.hpp"
#include "roles.hpp"
#include "sides.hpp"

namespace {

using namespace plumb::bench;
using Seconds = std::chrono::duration<double>;

struct MessageKind {
  std::string type;   // role argument
  std::string label;  // table label
  std::size_t payload_bytes;
};

std::string first_line_with(const std::string& file, const std::string& prefix) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(prefix, 0) == 0) return line.substr(line.find(':') + 1);
  }
  return "?";
}

// The first `words` words of the first line of a file.
std::string file_words(const std::string& file, int words) {
  std::ifstream in(file);
  std::string word, text;
  for (int i = 0; i < words && in >> word; ++i) text += (i > 0 ? " " : "") + word;
  return text;
}

void print_machine(const std::vector<std::string>& transports) {
  std::cout << "- CPU:" << first_line_with("/proc/cpuinfo", "model name") << ", "
            << std::thread::hardware_concurrency() << " hardware threads\n"
            << "- kernel: " << file_words("/proc/sys/kernel/osrelease", 1) << "\n";
  for (const auto& name : transports) {
    try {
      std::cout << "- " << name << ": " << plumb::transport::load_transport(name)->vendor_version() << "\n";
    } catch (const std::exception& e) {
      std::cout << "- " << name << ": " << e.what() << "\n";
    }
  }
}

struct Pair {
  Side writer, reader;
  std::string label() const { return writer.label() + " -> " + reader.label(); }
};

std::chrono::steady_clock::duration timeout(double seconds) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(Seconds(seconds));
}

void report_failure(const char* what, const Pair& pair, const ChildProcess::Outcome& outcome) {
  std::cerr << what << " " << pair.label() << " failed (exit code " << outcome.exit_code << ")" << std::endl;
}

ChildProcess start(const Programs& programs, const Side& side, const std::string& role, const MessageKind& kind,
                   int domain, double seconds) {
  auto command = programs.command(side, role, kind.type, domain, seconds);
  const std::string program = command.front();
  command.erase(command.begin());
  return ChildProcess(program, command);
}

RowKind kind_of(const Pair& pair) { return pair.writer.native ? RowKind::Native : RowKind::Plumb; }

LatencyRow measure_latency(const Programs& programs, const MessageKind& kind, const Pair& pair, int domain,
                           double seconds) {
  LatencyRow row{kind.label, kind.payload_bytes, kind_of(pair), pair.label(), {}, {}, {}, {}, {}, {}};
  ChildProcess pong = start(programs, pair.reader, "pong", kind, domain, seconds);
  ChildProcess ping = start(programs, pair.writer, "ping", kind, domain, seconds);
  const auto outcome = ping.finish(timeout(seconds + 40));
  const auto pong_outcome = pong.finish(timeout(5));
  double median = 0, p99 = 0, ping_cpu = 0, pong_cpu = 0;
  if (outcome.exit_code == 0 && result_value(outcome.output, "median_us", median) && result_value(outcome.output, "p99_us", p99)) {
    row.median_us = median;
    row.p99_us = p99;
    if (result_value(outcome.output, "cpu_us", ping_cpu) && result_value(pong_outcome.output, "cpu_us", pong_cpu) && pong_cpu > 0) {
      row.cpu_us = ping_cpu + pong_cpu;
    }
  } else {
    report_failure("latency", pair, outcome);
  }
  return row;
}

ThroughputRow measure_throughput(const Programs& programs, const MessageKind& kind, const Pair& pair, int domain,
                                 double seconds) {
  ThroughputRow row{kind.label, kind.payload_bytes, kind_of(pair), pair.label(), {}, {}, {}, {}, {}, {}};
  ChildProcess sink = start(programs, pair.reader, "sink", kind, domain, seconds);
  ChildProcess source = start(programs, pair.writer, "source", kind, domain, seconds);
  const auto source_outcome = source.finish(timeout(seconds + 40));
  const auto outcome = sink.finish(timeout(10));
  double received = 0, sent = 0, elapsed = 0, source_cpu = 0, sink_cpu = 0;
  if (outcome.exit_code == 0 && result_value(outcome.output, "received", received) &&
      result_value(outcome.output, "sent", sent) && result_value(outcome.output, "seconds", elapsed) && elapsed > 0) {
    row.messages_per_s = received / elapsed;
    row.loss_percent = sent > 0 ? 100.0 * (sent - received) / sent : 0.0;
    if (result_value(source_outcome.output, "cpu_us", source_cpu) && result_value(outcome.output, "cpu_us", sink_cpu)) {
      row.cpu_us = source_cpu + sink_cpu;
    }
  } else {
    report_failure("throughput", pair, outcome);
  }
  return row;
}

// The median of the values that were measured; nullopt if none was.
std::optional<double> median_of(const std::vector<std::optional<double>>& values) {
  std::vector<double> measured;
  for (const auto& value : values)
    if (value) measured.push_back(*value);
  if (measured.empty()) return std::nullopt;
  std::sort(measured.begin(), measured.end());
  const std::size_t n = measured.size();
  return n % 2 == 1 ? measured[n / 2] : (measured[n / 2 - 1] + measured[n / 2]) / 2;
}

template <class Row, class Field> std::optional<double> median_field(const std::vector<Row>& rows, Field field) {
  std::vector<std::optional<double>> values;
  for (const auto& row : rows) values.push_back(row.*field);
  return median_of(values);
}

LatencyRow median_row(const std::vector<LatencyRow>& runs) {
  LatencyRow row = runs.front();
  row.median_us = median_field(runs, &LatencyRow::median_us);
  row.p99_us = median_field(runs, &LatencyRow::p99_us);
  row.cpu_us = median_field(runs, &LatencyRow::cpu_us);
  return row;
}

ThroughputRow median_row(const std::vector<ThroughputRow>& runs) {
  ThroughputRow row = runs.front();
  row.messages_per_s = median_field(runs, &ThroughputRow::messages_per_s);
  row.loss_percent = median_field(runs, &ThroughputRow::loss_percent);
  row.cpu_us = median_field(runs, &ThroughputRow::cpu_us);
  return row;
}

int orchestrate(const std::vector<std::string>& transports, const std::vector<std::string>& types, double seconds,
                int repeats, int domain, const std::string& ddsperf, bool with_native) {
  const Programs programs = find_programs();
  std::vector<MessageKind> kinds;
  for (const auto& type : types) {
    if (type == "sensor") {
      kinds.push_back({"sensor", "SensorBatch (32 samples)", serialized_size(make_payload<plumb::topics::SensorBatch>())});
    } else if (type == "attitude") {
      kinds.push_back({"attitude", "Attitude", serialized_size(make_payload<plumb::topics::Attitude>())});
    } else {
      std::cerr << "plumb-bench-transport: unknown message type '" << type << "' (sensor, attitude)" << std::endl;
      return 1;
    }
  }
  for (const auto& name : transports) {
    try {
      plumb::transport::load_transport(name);
    } catch (const std::exception& e) {
      std::cerr << "plumb-bench-transport: " << e.what() << std::endl;
      return 1;
    }
    if (with_native && programs.native_program(name).empty()) {
      std::cerr << "plumb-bench-transport: no native program for " << name << " next to this program (build "
                << "plumb-bench-native-*, or run with --no-native)" << std::endl;
      return 1;
    }
  }
  // Per writer -> reader vendor pair: the native programs, then plumb (its ratio is against them).
  std::vector<Pair> pairs;
  for (const auto& writer : transports)
    for (const auto& reader : transports) {
      if (with_native) pairs.push_back({{true, writer}, {true, reader}});
      pairs.push_back({{false, writer}, {false, reader}});
    }

  std::cout << "## Transport benchmark (loopback, domain " << domain << ", " << seconds << " s per measurement, median of "
            << repeats << " interleaved run(s))\n\n";
  print_machine(transports);
  std::cout << std::flush;
  MachineLoad load;

  std::vector<LatencyRow> latency;
  std::vector<ThroughputRow> throughput;
  for (const auto& kind : kinds) {
    // Repeats are interleaved (ddsperf, then every pair native and plumb, ddsperf, ...) so that a
    // busy spell of the machine hits both sides; each figure is the median over the repeats.
    std::vector<std::vector<LatencyRow>> latency_runs(pairs.size() + 1);
    std::vector<std::vector<ThroughputRow>> throughput_runs(pairs.size() + 1);
    for (int repeat = 0; repeat < repeats; ++repeat) {
      std::cerr << "measuring " << kind.label << ": ddsperf" << std::endl;
      load.sample();
      LatencyRow base{kind.label, kind.payload_bytes, RowKind::Ddsperf, "ddsperf", {}, {}, {}, {}, {}, {}};
      if (const auto baseline = ddsperf_latency(ddsperf, domain, kind.payload_bytes, seconds)) {
        base.median_us = baseline->median_us;
        base.p99_us = baseline->p99_us;
      }
      ThroughputRow base_rate{kind.label, kind.payload_bytes, RowKind::Ddsperf, "ddsperf", {}, {}, {}, {}, {}, {}};
      if (const auto rate = ddsperf_throughput(ddsperf, domain, kind.payload_bytes, seconds)) {
        base_rate.messages_per_s = rate->messages_per_s;
      }
      latency_runs[0].push_back(base);
      throughput_runs[0].push_back(base_rate);
      for (std::size_t i = 0; i < pairs.size(); ++i) {
        std::cerr << "measuring " << kind.label << ": " << pairs[i].label() << std::endl;
        load.sample();
        latency_runs[i + 1].push_back(measure_latency(programs, kind, pairs[i], domain, seconds));
        throughput_runs[i + 1].push_back(measure_throughput(programs, kind, pairs[i], domain, seconds));
      }
    }
    const LatencyRow ddsperf_row = median_row(latency_runs[0]);
    const ThroughputRow ddsperf_rate = median_row(throughput_runs[0]);
    latency.push_back(ddsperf_row);
    throughput.push_back(ddsperf_rate);
    std::optional<double> native_median, native_rate, native_latency_cpu, native_rate_cpu;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      LatencyRow row = median_row(latency_runs[i + 1]);
      ThroughputRow rate = median_row(throughput_runs[i + 1]);
      if (row.kind == RowKind::Native) {
        native_median = row.median_us;
        native_rate = rate.messages_per_s;
        native_latency_cpu = row.cpu_us;
        native_rate_cpu = rate.cpu_us;
      }
      row.native_cpu_us = native_latency_cpu;
      rate.native_cpu_us = native_rate_cpu;
      row.native_median_us = native_median;  // the native pair just before this plumb pair
      row.ddsperf_median_us = ddsperf_row.median_us;
      rate.native_messages_per_s = native_rate;
      rate.ddsperf_messages_per_s = ddsperf_rate.messages_per_s;
      latency.push_back(row);
      throughput.push_back(rate);
    }
  }
  std::cout << "\n### Machine load during the run\n\n";
  load.print_summary(std::cout);
  std::cout << "\n### Latency (ping-pong, one-way = round trip / 2, reliable keep-last 64, data callbacks)\n\n";
  print_latency_table(std::cout, latency);
  std::cout << "\n### Throughput (writer as fast as possible, reliable keep-last 4096)\n\n";
  print_throughput_table(std::cout, throughput);
  std::cout << std::flush;
  for (const auto& row : latency)
    if (!row.median_us) return 1;
  for (const auto& row : throughput)
    if (!row.messages_per_s) return 1;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Transport benchmark: latency and throughput of plumb's transports on loopback, for every "
               "writer/reader vendor pair, beside native Cyclone DDS and Fast DDS programs with the same IDL types and "
               "Cyclone DDS's ddsperf, measured in the same run. Prints Markdown."};
  std::vector<std::string> transports{"cyclonedds", "fastdds"};
  std::vector<std::string> types{"sensor", "attitude"};
  double seconds = 1;
  int repeats = 2;
  // A domain of its own (from the process id) keeps other plumb processes on this host out.
  int domain = 100 + static_cast<int>(getpid() % 100);
  std::string ddsperf = "ddsperf";
  bool no_native = false;
  RoleOptions role;
  app.add_option("--transports", transports, "vendors to pair with each other")->delimiter(',');
  app.add_option("--types", types, "message types: sensor, attitude")->delimiter(',');
  app.add_option("--seconds", seconds, "measuring time of each measurement")->check(CLI::Range(0.2, 60.0));
  app.add_option("--repeats", repeats, "interleaved runs of every measurement; the table shows their median")
      ->check(CLI::Range(1, 10));
  app.add_option("--domain", domain, "DDS domain id (default: 100 + pid % 100)")->check(CLI::Range(0, 232));
  app.add_option("--ddsperf", ddsperf, "the ddsperf program of Cyclone DDS");
  app.add_flag("--no-native", no_native, "leave out the native baseline programs (plumb-bench-native-*)");
  // Internal: the child processes of a measurement.
  app.add_option("--role", role.role, "internal: run as ping, pong, source or sink")->group("");
  app.add_option("--transport", role.transport, "internal: vendor of the role")->group("");
  app.add_option("--type", role.type, "internal: message type of the role")->group("");
  CLI11_PARSE(app, argc, argv);

  try {
    if (!role.role.empty()) {
      role.domain_id = domain;
      role.seconds = seconds;
      return run_role(role);
    }
    return orchestrate(transports, types, seconds, repeats, domain, ddsperf, !no_native);
  } catch (const std::exception& e) {
    std::cerr << "plumb-bench-transport: " << e.what() << std::endl;
    return 1;
  }
}
