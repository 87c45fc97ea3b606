// plumb-bench-transport: one-way latency (ping-pong, round trip / 2: median and p99) and throughput
// of SensorBatch (32 samples) and Attitude messages over plumb's transports on loopback, for every
// writer/reader vendor pair, beside Cyclone DDS's ddsperf run in the same way in the same run.
// Every measurement runs between two child processes (this program in a --role).
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "child_process.hpp"
#include "ddsperf_baseline.hpp"
#include "payloads.hpp"
#include "plumb/transport/loader.hpp"
#include "report.hpp"
#include "roles.hpp"

namespace {

using namespace plumb::bench;
using Seconds = std::chrono::duration<double>;

struct MessageKind {
  std::string type;   // role argument
  std::string label;  // table label
  std::size_t payload_bytes;
};

std::string self_path() {
  char path[4096];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) throw std::runtime_error("cannot find this program's path in /proc/self/exe");
  return std::string(path, static_cast<std::size_t>(n));
}

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
            << "- kernel: " << file_words("/proc/sys/kernel/osrelease", 1) << "; load average at start: "
            << file_words("/proc/loadavg", 3) << "\n";
  for (const auto& name : transports) {
    try {
      std::cout << "- " << name << ": " << plumb::transport::load_transport(name)->vendor_version() << "\n";
    } catch (const std::exception& e) {
      std::cout << "- " << name << ": " << e.what() << "\n";
    }
  }
}

struct Pair {
  std::string writer, reader;
  std::string label() const { return writer + " -> " + reader; }
};

std::vector<std::string> role_arguments(const std::string& role, const std::string& transport, const MessageKind& kind,
                                        int domain, double seconds) {
  return {"--role", role, "--transport", transport, "--type", kind.type, "--domain", std::to_string(domain),
          "--seconds", std::to_string(seconds)};
}

std::chrono::steady_clock::duration timeout(double seconds) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(Seconds(seconds));
}

void report_failure(const char* what, const Pair& pair, const ChildProcess::Outcome& outcome) {
  std::cerr << what << " " << pair.label() << " failed (exit code " << outcome.exit_code << ")" << std::endl;
}

LatencyRow measure_latency(const std::string& self, const MessageKind& kind, const Pair& pair, int domain, double seconds) {
  LatencyRow row{kind.label, kind.payload_bytes, pair.label(), {}, {}, {}};
  ChildProcess pong(self, role_arguments("pong", pair.reader, kind, domain, seconds));
  ChildProcess ping(self, role_arguments("ping", pair.writer, kind, domain, seconds));
  const auto outcome = ping.finish(timeout(seconds + 40));
  pong.finish(timeout(5));
  double median = 0, p99 = 0;
  if (outcome.exit_code == 0 && result_value(outcome.output, "median_us", median) && result_value(outcome.output, "p99_us", p99)) {
    row.median_us = median;
    row.p99_us = p99;
  } else {
    report_failure("latency", pair, outcome);
  }
  return row;
}

ThroughputRow measure_throughput(const std::string& self, const MessageKind& kind, const Pair& pair, int domain,
                                 double seconds) {
  ThroughputRow row{kind.label, kind.payload_bytes, pair.label(), {}, {}, {}};
  ChildProcess sink(self, role_arguments("sink", pair.reader, kind, domain, seconds));
  ChildProcess source(self, role_arguments("source", pair.writer, kind, domain, seconds));
  source.finish(timeout(seconds + 40));
  const auto outcome = sink.finish(timeout(10));
  double received = 0, sent = 0, elapsed = 0;
  if (outcome.exit_code == 0 && result_value(outcome.output, "received", received) &&
      result_value(outcome.output, "sent", sent) && result_value(outcome.output, "seconds", elapsed) && elapsed > 0) {
    row.messages_per_s = received / elapsed;
    row.loss_percent = sent > 0 ? 100.0 * (sent - received) / sent : 0.0;
  } else {
    report_failure("throughput", pair, outcome);
  }
  return row;
}

int orchestrate(const std::vector<std::string>& transports, const std::vector<std::string>& types, double seconds,
                int domain, const std::string& ddsperf) {
  const std::string self = self_path();
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
  std::vector<Pair> pairs;
  for (const auto& writer : transports)
    for (const auto& reader : transports) pairs.push_back({writer, reader});

  std::cout << "## Transport benchmark (loopback, domain " << domain << ", " << seconds << " s per measurement)\n\n";
  print_machine(transports);
  std::cout << std::endl;

  std::vector<LatencyRow> latency;
  std::vector<ThroughputRow> throughput;
  for (const auto& kind : kinds) {
    std::cerr << "measuring " << kind.label << ": ddsperf" << std::endl;
    const auto baseline = ddsperf_latency(ddsperf, domain, kind.payload_bytes, seconds);
    const auto baseline_rate = ddsperf_throughput(ddsperf, domain, kind.payload_bytes, seconds);
    LatencyRow base{kind.label, kind.payload_bytes, "ddsperf", {}, {}, {}};
    ThroughputRow base_rate{kind.label, kind.payload_bytes, "ddsperf", {}, {}, {}};
    if (baseline) {
      base.median_us = baseline->median_us;
      base.p99_us = baseline->p99_us;
    }
    if (baseline_rate) base_rate.messages_per_s = baseline_rate->messages_per_s;
    latency.push_back(base);
    throughput.push_back(base_rate);
    for (const auto& pair : pairs) {
      std::cerr << "measuring " << kind.label << ": " << pair.label() << std::endl;
      auto row = measure_latency(self, kind, pair, domain, seconds);
      row.baseline_median_us = base.median_us;
      latency.push_back(row);
      auto rate = measure_throughput(self, kind, pair, domain, seconds);
      rate.baseline_messages_per_s = base_rate.messages_per_s;
      throughput.push_back(rate);
    }
  }
  std::cout << "### Latency (ping-pong, one-way = round trip / 2, reliable keep-last, data callbacks)\n\n";
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
               "writer/reader vendor pair, beside Cyclone DDS's ddsperf measured in the same run. Prints Markdown."};
  std::vector<std::string> transports{"cyclonedds", "fastdds"};
  std::vector<std::string> types{"sensor", "attitude"};
  double seconds = 2;
  // A domain of its own (from the process id) keeps other plumb processes on this host out.
  int domain = 100 + static_cast<int>(getpid() % 100);
  std::string ddsperf = "ddsperf";
  RoleOptions role;
  app.add_option("--transports", transports, "vendors to pair with each other")->delimiter(',');
  app.add_option("--types", types, "message types: sensor, attitude")->delimiter(',');
  app.add_option("--seconds", seconds, "measuring time of each measurement")->check(CLI::Range(0.2, 60.0));
  app.add_option("--domain", domain, "DDS domain id (default: 100 + pid % 100)")->check(CLI::Range(0, 232));
  app.add_option("--ddsperf", ddsperf, "the ddsperf program of Cyclone DDS");
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
    return orchestrate(transports, types, seconds, domain, ddsperf);
  } catch (const std::exception& e) {
    std::cerr << "plumb-bench-transport: " << e.what() << std::endl;
    return 1;
  }
}
