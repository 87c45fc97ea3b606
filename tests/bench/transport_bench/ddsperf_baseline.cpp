#include "ddsperf_baseline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::bench {
namespace {

using namespace std::chrono_literals;

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

// "... 50% 11.057us 90% ..." -> 11.057 for the word "50%".
bool number_after(const std::string& line, const std::string& word, double& value) {
  std::istringstream words(line);
  std::string current;
  while (words >> current) {
    if (current == word && (words >> current)) {
      try {
        value = std::stod(current);  // stops at the "us" suffix
        return true;
      } catch (const std::exception&) {
        return false;
      }
    }
  }
  return false;
}

std::vector<std::string> lines_with(const std::string& output, const std::string& marker) {
  std::vector<std::string> found;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.find(marker) != std::string::npos) found.push_back(line);
  }
  return found;
}

std::map<std::string, std::string> environment() { return {{"CYCLONEDDS_URI", loopback_cyclone_config()}}; }

std::string seconds_text(double seconds) { return std::to_string(static_cast<int>(std::ceil(seconds))); }

}  // namespace

std::string loopback_cyclone_config() {
  return "<CycloneDDS><Domain Id=\"any\">"
         "<General><Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
         "<AllowMulticast>false</AllowMulticast></General>"
         "<Discovery><ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>40</MaxAutoParticipantIndex>"
         "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>"
         "<SharedMemory><Enable>false</Enable></SharedMemory>"
         "</Domain></CycloneDDS>";
}

std::optional<DdsperfLatency> ddsperf_latency(const std::string& ddsperf, int domain_id, std::size_t payload_bytes,
                                              double seconds) {
  const std::string domain = std::to_string(domain_id);
  // Two extra seconds: ddsperf prints once a second, the first second includes discovery and the
  // last one may be cut short.
  const std::string run_for = seconds_text(seconds + 2);
  try {
    ChildProcess pong(ddsperf, {"-i", domain, "-D", seconds_text(seconds + 15), "pong"}, environment());
    ChildProcess ping(ddsperf, {"-i", domain, "-D", run_for, "-Qminmatch:1", "-Qinitwait:10", "ping", "size",
                                std::to_string(payload_bytes)},
                      environment());
    const auto outcome = ping.finish(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(seconds + 20)));
    std::vector<double> medians, p99s;
    const auto lines = lines_with(outcome.output, " 50% ");
    // The first second holds discovery and the warm-up; leave it out when there is more.
    for (std::size_t i = lines.size() > 1 ? 1 : 0; i < lines.size(); ++i) {
      double m = 0, p = 0;
      if (number_after(lines[i], "50%", m) && number_after(lines[i], "99%", p)) {
        medians.push_back(m);
        p99s.push_back(p);
      }
    }
    if (medians.empty()) {
      std::cerr << "ddsperf ping printed no latency (exit code " << outcome.exit_code << ")" << std::endl;
      return std::nullopt;
    }
    return DdsperfLatency{median(medians), median(p99s), medians.size()};
  } catch (const std::exception& e) {
    std::cerr << "ddsperf: " << e.what() << std::endl;
    return std::nullopt;
  }
}

std::optional<DdsperfThroughput> ddsperf_throughput(const std::string& ddsperf, int domain_id, std::size_t payload_bytes,
                                                    double seconds) {
  const std::string domain = std::to_string(domain_id);
  try {
    // -k: the same history as plumb's reliable_stream profile (ddsperf's default, keep-all, makes
    // the writer wait for a slow reader instead of overwriting).
    const std::string depth = std::to_string(plumb::transport::Qos::reliable_stream().depth);
    ChildProcess sub(ddsperf, {"-i", domain, "-D", seconds_text(seconds + 3), "-k", depth, "-Qminmatch:1", "-Qinitwait:10", "sub"},
                     environment());
    ChildProcess pub(ddsperf, {"-i", domain, "-D", seconds_text(seconds + 2), "-k", depth, "-Qminmatch:1", "-Qinitwait:10", "pub", "size",
                               std::to_string(payload_bytes)},
                     environment());
    pub.finish(std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds + 20)));
    const auto outcome =
        sub.finish(std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds + 10)));
    std::vector<double> rates;
    const auto lines = lines_with(outcome.output, " rate ");
    for (std::size_t i = lines.size() > 1 ? 1 : 0; i < lines.size(); ++i) {
      double kilo_samples = 0;
      if (number_after(lines[i], "rate", kilo_samples) && kilo_samples > 0) rates.push_back(kilo_samples * 1000);
    }
    if (rates.empty()) {
      std::cerr << "ddsperf sub printed no rate (exit code " << outcome.exit_code << ")" << std::endl;
      return std::nullopt;
    }
    return DdsperfThroughput{median(rates)};
  } catch (const std::exception& e) {
    std::cerr << "ddsperf: " << e.what() << std::endl;
    return std::nullopt;
  }
}

}  // namespace plumb::bench
