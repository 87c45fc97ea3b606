// plumb-bench-pipeline: latency from a sample's publication to the attitude that includes it,
// through DDS: this program publishes the simulated platform; plumb-estimator (another process)
// runs the plugins; this program takes the attitudes. The latency of an estimate is the time from
// publishing the batch holding the window's last sample to receiving the estimate. Baseline, in the
// same run and on the same transports: a mirror process that answers every batch at once with an
// attitude (same two DDS hops, no estimation), so the ratio is the price of the estimator host.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <thread>

#include "plumb/components/cli.hpp"
#include "plumb/components/convert.hpp"
#include "plumb/sim/platform.hpp"
#include "plumb/transport/topic_names.hpp"

extern char** environ;

namespace {

using namespace plumb;
using Clock = std::chrono::steady_clock;
namespace names = transport::topic_names;

struct Stats {
  double median_us = 0, p99_us = 0;
  std::size_t n = 0;
};

Stats stats(std::vector<double> v) {
  Stats s;
  s.n = v.size();
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.median_us = v[v.size() / 2];
  s.p99_us = v[std::min(v.size() - 1, static_cast<std::size_t>(0.99 * static_cast<double>(v.size())))];
  return s;
}

pid_t spawn(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // The children's chatter would break the table: their output goes to /dev/null.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " + args[0]);
  return pid;
}

void stop(pid_t pid) {
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
}

// Mirror mode: every sensor batch is answered at once by an attitude whose window ends at the
// batch's last sample.
int run_mirror(const components::TransportOptions& t) {
  auto conn = components::connect(t, "plumb-bench-mirror");
  auto reader = transport::make_reader<topics::SensorBatch>(*conn.participant, names::kSensorRaw, transport::Qos::reliable_stream());
  auto writer = transport::make_writer<topics::Attitude>(*conn.participant, names::attitude("mirror"), transport::Qos::attitude());
  components::install_stop_handler();
  topics::SensorBatch batch;
  while (!components::g_stop) {
    reader.wait(std::chrono::milliseconds(100));
    while (reader.take(batch)) {
      if (batch.samples.empty()) continue;
      topics::Attitude a;
      a.estimator = "mirror";
      a.window_end_ns = batch.samples.back().stamp_ns;
      writer.write(a);
    }
  }
  return 0;
}

// Publishes `seconds` of the simulated platform in real time; returns latencies (us) per estimator.
std::map<std::string, std::vector<double>> measure(const components::TransportOptions& t,
                                                   const std::vector<std::string>& estimators, double seconds,
                                                   double rate_hz) {
  auto conn = components::connect(t, "plumb-bench-pipeline");
  auto writer = transport::make_writer<topics::SensorBatch>(*conn.participant, names::kSensorRaw, transport::Qos::reliable_stream());
  std::vector<transport::Reader<topics::Attitude>> readers;
  for (const auto& e : estimators)
    readers.push_back(transport::make_reader<topics::Attitude>(*conn.participant, names::attitude(e), transport::Qos::attitude()));
  const auto wait_until = Clock::now() + std::chrono::seconds(20);
  auto matched = [&] {
    if (writer.matched_readers() == 0) return false;
    for (auto& r : readers)
      if (r.matched_writers() == 0) return false;
    return true;
  };
  while (!matched() && Clock::now() < wait_until) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  if (!matched()) throw std::runtime_error("the estimator process did not match within 20 s");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));

  sim::Scenario sc = sim::Scenario::reference(1, 120, 60, 20);
  sc.sample_rate_hz = rate_hz;
  sc.duration_s = seconds;
  sim::PlatformSimulator simulator(sc);
  const std::size_t per_batch = 10;
  std::map<std::int64_t, Clock::time_point> published;  // last sample stamp -> publication time
  std::map<std::string, std::vector<double>> latency;
  const auto period = std::chrono::duration<double>(static_cast<double>(per_batch) / rate_hz);
  auto next = Clock::now();
  auto drain = [&] {
    topics::Attitude a;
    for (std::size_t i = 0; i < readers.size(); ++i) {
      while (readers[i].take(a)) {
        const auto now = Clock::now();
        // The window's last sample is the newest published at or before window_end.
        auto it = published.upper_bound(a.window_end_ns);
        if (it == published.begin()) continue;
        --it;
        latency[estimators[i]].push_back(std::chrono::duration<double, std::micro>(now - it->second).count());
      }
    }
  };
  while (!simulator.done()) {
    topics::SensorBatch batch;
    batch.tool_id = "bench";
    for (std::size_t i = 0; i < per_batch && !simulator.done(); ++i) batch.samples.push_back(components::to_topic(simulator.next()));
    published[batch.samples.back().stamp_ns] = Clock::now();
    writer.write(batch);
    next += std::chrono::duration_cast<Clock::duration>(period);
    while (Clock::now() < next) {
      drain();
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }
  const auto end = Clock::now() + std::chrono::seconds(1);
  while (Clock::now() < end) {
    drain();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return latency;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"plumb-bench-pipeline: latency from a sample's publication to the attitude that includes it, "
               "through DDS and plumb-estimator, beside a no-estimation mirror measured in the same run"};
  components::TransportOptions mirror_t;
  bool mirror = false;
  double seconds = 20, rate_hz = 1000, window_s = 0.5;
  int domain = 88;
  app.add_flag("--mirror", mirror, "internal: run as the mirror process");
  components::add_transport_options(app, mirror_t);
  app.add_option("--seconds", seconds, "seconds of data per case")->capture_default_str();
  app.add_option("--rate-hz", rate_hz, "sample rate")->capture_default_str();
  app.add_option("--window", window_s, "estimator window, s")->capture_default_str();
  app.add_option("--bench-domain", domain, "DDS domain for the benchmark")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    if (mirror) return run_mirror(mirror_t);
    const auto bin = std::filesystem::canonical("/proc/self/exe").parent_path();
    const std::vector<std::string> plugins{"static", "integral", "compensated"};
    std::printf("%d Hz, %zu-sample batches, window %.2f s, %.0f s per case, loopback, domain %d\n", static_cast<int>(rate_hz),
                std::size_t{10}, window_s, seconds, domain);
    std::printf("%-24s %-12s %6s %12s %12s %14s\n", "publisher -> host", "estimator", "n", "median us", "p99 us",
                "median/mirror");
    for (const auto& [pub, host] : std::vector<std::pair<std::string, std::string>>{
             {"cyclonedds", "cyclonedds"}, {"fastdds", "fastdds"}, {"cyclonedds", "fastdds"}, {"fastdds", "cyclonedds"}}) {
      components::TransportOptions t{pub, domain, "", ""};
      const std::string d = std::to_string(domain);
      const pid_t m = spawn({(bin / "plumb-bench-pipeline").string(), "--mirror", "--transport", host, "--domain", d});
      const auto base = measure(t, {"mirror"}, seconds / 2, rate_hz);
      stop(m);
      std::vector<std::string> args{(bin / "plumb-estimator").string(), "--transport", host, "--domain", d, "--input",
                                    names::kSensorRaw, "--reliable", "-q", "--window", std::to_string(window_s)};
      for (const auto& p : plugins) args.insert(args.end(), {"--plugin", p});
      const pid_t h = spawn(args);
      const auto lat = measure(t, plugins, seconds, rate_hz);
      stop(h);
      const Stats b = stats(base.count("mirror") ? base.at("mirror") : std::vector<double>{});
      const std::string pair = pub + " -> " + host;
      std::printf("%-24s %-12s %6zu %12.0f %12.0f %14s\n", pair.c_str(), "(mirror)", b.n, b.median_us, b.p99_us, "1.00");
      for (const auto& p : plugins) {
        const Stats s = stats(lat.count(p) ? lat.at(p) : std::vector<double>{});
        std::printf("%-24s %-12s %6zu %12.0f %12.0f %14.2f\n", pair.c_str(), p.c_str(), s.n, s.median_us, s.p99_us,
                    b.median_us > 0 ? s.median_us / b.median_us : 0.0);
      }
      std::fflush(stdout);
      ++domain;
    }
  } catch (const std::exception& e) {
    components::print_error("plumb-bench-pipeline", e.what());
    return 1;
  }
  return 0;
}
