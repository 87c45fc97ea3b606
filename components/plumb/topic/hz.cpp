// plumb topic hz: measure the publishing rate of a topic, once a second.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <type_traits>
#include <vector>

#include "messages/fields.hpp"
#include "messages/topic_type.hpp"
#include "plumb/components/topic_wait.hpp"
#include "topic/topic_verbs.hpp"

namespace plumb::cli {
namespace {

struct HzOptions {
  components::TransportOptions transport;
  std::string topic;
  int count = 0;         // one-second reports; 0 = until interrupted
  double timeout_s = 0;  // 0 = none
  double wait_s = 2;
};

int run_hz(const HzOptions& o) {
  auto conn = components::connect(o.transport, "plumb-topic-hz");
  const auto& type = resolve_topic_type(*conn.participant, o.topic, o.wait_s);
  return with_topic_type(type, [&](auto proto) {
    using M = decltype(proto);
    auto qos = transport::default_qos_for_topic(o.topic);
    if (std::is_same_v<M, topics::SensorBatch>) qos = transport::Qos::sensor_stream();
    auto reader = transport::make_reader<M>(*conn.participant, o.topic, qos);
    components::install_stop_handler();
    const auto t0 = Clock::now();
    auto last_report = t0;
    std::vector<double> arrivals;  // seconds since t0, within the current report
    std::size_t samples = 0, total = 0, total_samples = 0;
    double first_arrival = 0, last_arrival = 0;
    int reports = 0;
    components::SilenceNotes silence("plumb topic hz", o.topic, conn.options.security.empty());
    std::vector<M> taken;  // reused by every batched take
    while (!components::g_stop && (o.count == 0 || reports < o.count)) {
      if (o.timeout_s > 0 && seconds_since(t0) > o.timeout_s) break;
      reader.wait(std::chrono::milliseconds(50));
      while (reader.take(taken, kTakeBatch) > 0) {
        // One arrival time per batch: every message of it was taken at that instant.
        const double now = seconds_since(t0);
        for (const M& msg : taken) {
          last_arrival = now;
          if (total == 0) first_arrival = last_arrival;
          arrivals.push_back(now);
          ++total;
          silence.received();
          if constexpr (std::is_same_v<M, topics::SensorBatch>) {
            samples += msg.samples.size();
            total_samples += msg.samples.size();
          }
        }
      }
      silence.check(*conn.participant, reader.matched_writers());
      if (std::chrono::duration<double>(Clock::now() - last_report).count() < 1.0) continue;
      const double span = std::chrono::duration<double>(Clock::now() - last_report).count();
      last_report = Clock::now();
      ++reports;
      if (arrivals.size() < 2) {
        std::cout << "no rate yet: " << arrivals.size() << " message(s) in the last " << format_measured(span) << " s"
                  << std::endl;
        arrivals.clear();
        samples = 0;
        continue;
      }
      double min_dt = 1e9, max_dt = 0, sum = 0, sum2 = 0;
      for (std::size_t i = 1; i < arrivals.size(); ++i) {
        const double dt = arrivals[i] - arrivals[i - 1];
        min_dt = std::min(min_dt, dt);
        max_dt = std::max(max_dt, dt);
        sum += dt;
        sum2 += dt * dt;
      }
      const double n = static_cast<double>(arrivals.size() - 1);
      const double mean = sum / n;
      std::cout << "average rate: " << format_measured(1.0 / mean) << " Hz  min: " << format_measured(min_dt)
                << " s  max: " << format_measured(max_dt) << " s  std dev: "
                << format_measured(std::sqrt(std::max(0.0, sum2 / n - mean * mean))) << " s  window: " << arrivals.size();
      if constexpr (std::is_same_v<M, topics::SensorBatch>) std::cout << "  samples/s: " << format_measured(samples / span);
      std::cout << std::endl;
      arrivals.clear();
      samples = 0;
    }
    const double elapsed_s = seconds_since(t0);
    if (total == 0) {
      std::cerr << "plumb topic hz: no message on '" << o.topic << "', " << end_reason(o.timeout_s, elapsed_s) << " ("
                << reader.matched_writers() << " writer(s) matched)" << std::endl;
      return 1;
    }
    // The whole run in one line: what a person wants after Ctrl-C.
    std::cerr << "plumb topic hz: " << total << " message(s) on '" << o.topic << "', " << end_reason(o.timeout_s, elapsed_s);
    if (total > 1) std::cerr << ", average " << format_measured((total - 1) / (last_arrival - first_arrival)) << " Hz";
    if constexpr (std::is_same_v<M, topics::SensorBatch>) std::cerr << ", " << total_samples << " samples";
    std::cerr << std::endl;
    return 0;
  });
}

}  // namespace

void add_topic_hz(CLI::App& topic, Verbs& verbs) {
  auto o = std::make_shared<HzOptions>();
  auto* hz = topic.add_subcommand("hz", "Measure the publishing rate of a topic, once a second");
  components::add_transport_options(*hz, o->transport);
  hz->add_option("topic", o->topic, "topic name")->required();
  hz->add_option("--count", o->count, "exit after this many one-second reports");
  hz->add_option("--timeout", o->timeout_s, "exit after this many seconds");
  hz->add_option("--wait", o->wait_s, "seconds to wait for discovery of a topic outside plumb's names")->capture_default_str();
  verbs.add(hz, [o] { return run_hz(*o); });
}

}  // namespace plumb::cli
