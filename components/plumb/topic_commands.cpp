// plumb topic list | echo | hz | pub
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <thread>

#include "commands.hpp"
#include "fields.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/components/convert.hpp"
#include "plumb/components/topic_wait.hpp"
#include "csv_output.hpp"
#include "topic_type.hpp"

namespace plumb::cli {
namespace {

// Messages per batched take: one vendor call for everything that arrived, up to this many.
constexpr std::size_t kTakeBatch = 64;

using Clock = std::chrono::steady_clock;
using components::g_stop;

struct TopicOptions {
  components::TransportOptions transport;
  std::string topic;
  bool csv = false;
  int count = 0;          // 0 = until interrupted
  double timeout_s = 0;   // 0 = none
  double wait_s = 2;
  double rate_hz = 1;
  std::vector<std::string> assignments;
  bool reliable = false;
};

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Why a receiving command ended, for its summary line.
std::string end_reason(const TopicOptions& o, double elapsed_s) {
  if (g_stop) return "interrupted after " + format_measured(elapsed_s) + " s";
  if (o.timeout_s > 0 && elapsed_s >= o.timeout_s) return "timed out after " + format_measured(elapsed_s) + " s";
  return "in " + format_measured(elapsed_s) + " s";
}

int run_echo(const TopicOptions& o) {
  auto conn = components::connect(o.transport, "plumb-topic-echo");
  const auto& type = resolve_topic_type(*conn.participant, o.topic, o.wait_s);
  return with_topic_type(type, [&](auto proto) {
    using M = decltype(proto);
    auto qos = transport::default_qos_for_topic(o.topic);
    if (std::is_same_v<M, topics::SensorBatch> && !o.reliable) qos = transport::Qos::sensor_stream();
    auto reader = transport::make_reader<M>(*conn.participant, o.topic, qos);
    components::install_stop_handler();
    const auto t0 = Clock::now();
    int received = 0;
    SensorCsvWriter sensor_csv;
    FlatCsvWriter flat_csv;
    components::SilenceNotes silence("plumb topic echo", o.topic, conn.options.security.empty());
    std::vector<M> taken;  // reused by every batched take
    while (!g_stop && (o.count == 0 || received < o.count)) {
      if (o.timeout_s > 0 && seconds_since(t0) > o.timeout_s) break;
      reader.wait(std::chrono::milliseconds(100));
      // Batched takes, never more than --count still wants (the rest stays for another reader).
      for (;;) {
        const std::size_t wanted = o.count == 0 ? kTakeBatch : std::min<std::size_t>(kTakeBatch, static_cast<std::size_t>(o.count - received));
        if (wanted == 0 || reader.take(taken, wanted) == 0) break;
        for (const M& msg : taken) {
          ++received;
          silence.received();
          if (!o.csv) {
            print_yaml(std::cout, msg);
            std::cout << "---" << std::endl;
            continue;
          }
          if constexpr (std::is_same_v<M, topics::SensorBatch>) {
            sensor_csv.write(std::cout, msg);
          } else {
            flat_csv.write(std::cout, msg);
          }
        }
      }
      silence.check(*conn.participant, reader.matched_writers());
    }
    const double elapsed_s = seconds_since(t0);
    if (o.count > 0 && received < o.count) {
      std::cerr << "plumb topic echo: received " << received << " of " << o.count << " messages on '" << o.topic
                << "', " << end_reason(o, elapsed_s) << std::endl;
      return 1;
    }
    if (received == 0) {  // Ctrl-C or --timeout with nothing: the command did not do its job
      std::cerr << "plumb topic echo: no message on '" << o.topic << "', " << end_reason(o, elapsed_s) << " ("
                << reader.matched_writers() << " writer(s) matched)" << std::endl;
      return 1;
    }
    if (o.count == 0)
      std::cerr << "plumb topic echo: " << received << " message(s) on '" << o.topic << "', "
                << end_reason(o, elapsed_s) << std::endl;
    return 0;
  });
}

int run_hz(const TopicOptions& o) {
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
    while (!g_stop && (o.count == 0 || reports < o.count)) {
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
      std::cerr << "plumb topic hz: no message on '" << o.topic << "', " << end_reason(o, elapsed_s) << " ("
                << reader.matched_writers() << " writer(s) matched)" << std::endl;
      return 1;
    }
    // The whole run in one line: what a person wants after Ctrl-C.
    std::cerr << "plumb topic hz: " << total << " message(s) on '" << o.topic << "', " << end_reason(o, elapsed_s);
    if (total > 1) std::cerr << ", average " << format_measured((total - 1) / (last_arrival - first_arrival)) << " Hz";
    if constexpr (std::is_same_v<M, topics::SensorBatch>) std::cerr << ", " << total_samples << " samples";
    std::cerr << std::endl;
    return 0;
  });
}

int run_pub(const TopicOptions& o) {
  auto conn = components::connect(o.transport, "plumb-topic-pub");
  const auto& type = resolve_topic_type(*conn.participant, o.topic, 0.5);
  return with_topic_type(type, [&](auto proto) {
    using M = decltype(proto);
    M msg = proto;
    for (const auto& a : o.assignments) {
      const auto eq = a.find('=');
      if (eq == std::string::npos || eq == 0)
        throw std::invalid_argument("'" + a + "' is not FIELD=VALUE (e.g. inclination_deg=1.5)");
      set_field(msg, a.substr(0, eq), a.substr(eq + 1));
    }
    auto writer = transport::make_writer<M>(*conn.participant, o.topic, transport::default_qos_for_topic(o.topic));
    components::install_stop_handler();
    // Give subscribers a moment to match so the first message is not sent into the void.
    const auto t0 = Clock::now();
    while (!g_stop && writer.matched_readers() == 0 && seconds_since(t0) < o.wait_s)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const int count = o.count > 0 ? o.count : 1;
    const auto period = std::chrono::duration<double>(1.0 / std::max(o.rate_hz, 1e-3));
    auto next = Clock::now();
    int sent = 0;
    for (int i = 0; i < count && !g_stop; ++i) {
      writer.write(msg);
      ++sent;
      next += std::chrono::duration_cast<Clock::duration>(period);
      // Sleep in short steps: Ctrl-C during a slow --rate must not wait for the next message.
      while (i + 1 < count && !g_stop && Clock::now() < next)
        std::this_thread::sleep_for(std::min<Clock::duration>(next - Clock::now(), std::chrono::milliseconds(20)));
    }
    // What was actually sent, not what was asked for.
    std::cerr << "plumb topic pub: published " << sent << (sent < count ? " of " + std::to_string(count) : std::string())
              << " message(s) on '" << o.topic << "' (" << writer.matched_readers() << " subscriber(s) matched)"
              << (sent < count ? ", interrupted" : "") << std::endl;
    // Reliable writers keep unacknowledged data only while they live: linger briefly.
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    return 0;
  });
}

int run_list(const TopicOptions& o) {
  auto conn = components::connect(o.transport, "plumb-topic-list");
  std::this_thread::sleep_for(std::chrono::duration<double>(o.wait_s));
  auto topics = conn.participant->discovered_topics();
  std::sort(topics.begin(), topics.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  if (topics.empty()) std::cerr << "plumb topic list: no topics seen within " << o.wait_s << " s" << std::endl;
  for (const auto& t : topics) {
    std::cout << t.name << "  [" << t.type_name << "]  writers: " << t.writers << "  readers: " << t.readers << '\n';
  }
  return 0;
}

}  // namespace

void add_topic_commands(CLI::App& app) {
  auto* topic = app.add_subcommand("topic", "List, print, measure and publish topics");
  topic->require_subcommand(1);
  auto o = std::make_shared<TopicOptions>();

  auto* list = topic->add_subcommand("list", "List the topics seen through DDS discovery");
  components::add_transport_options(*list, o->transport);
  list->add_option("--wait", o->wait_s, "seconds to listen for discovery")->capture_default_str();
  list->callback([o] { g_exit_code = run_list(*o); });

  auto* echo = topic->add_subcommand("echo", "Print the messages of a topic (YAML-like, or CSV with --csv)");
  components::add_transport_options(*echo, o->transport);
  echo->add_option("topic", o->topic, "topic name, e.g. plumb/attitude/compensated")->required();
  echo->add_flag("--csv", o->csv,
                 "print CSV: a header, then one row per message; sensor topics give the sensor CSV of docs/conventions.md "
                 "(t,fx,fy,fz,bx,by,bz[,wx,wy,wz][,temp_c]), which plumb estimate and plumb-bridge --replay read");
  echo->add_option("--count", o->count, "exit after this many messages (exit 1 if fewer arrive)");
  echo->add_option("--timeout", o->timeout_s, "give up after this many seconds (exit 1 if nothing arrived)");
  echo->add_option("--wait", o->wait_s, "seconds to wait for discovery of a topic outside plumb's names")->capture_default_str();
  echo->add_flag("--reliable", o->reliable, "reliable reader on sensor topics (default best-effort)");
  echo->callback([o] { g_exit_code = run_echo(*o); });

  auto* hz = topic->add_subcommand("hz", "Measure the publishing rate of a topic, once a second");
  components::add_transport_options(*hz, o->transport);
  hz->add_option("topic", o->topic, "topic name")->required();
  hz->add_option("--count", o->count, "exit after this many one-second reports");
  hz->add_option("--timeout", o->timeout_s, "exit after this many seconds");
  hz->add_option("--wait", o->wait_s, "seconds to wait for discovery of a topic outside plumb's names")->capture_default_str();
  hz->callback([o] { g_exit_code = run_hz(*o); });

  auto* pub = topic->add_subcommand("pub", "Publish a message built from FIELD=VALUE assignments");
  pub->footer("Fields by path: tool_id=T1 inclination_deg=1.5 accelerometer.bias=0.1,0,0 samples.0.fz=-9.8");
  components::add_transport_options(*pub, o->transport);
  pub->add_option("topic", o->topic, "topic name")->required();
  pub->add_option("fields", o->assignments, "FIELD=VALUE assignments; unset fields are zero/empty");
  pub->add_option("--count", o->count, "messages to publish (default 1)");
  pub->add_option("--rate", o->rate_hz, "messages per second")->capture_default_str();
  pub->add_option("--wait", o->wait_s, "seconds to wait for a subscriber before publishing")->capture_default_str();
  pub->callback([o] { g_exit_code = run_pub(*o); });
}

}  // namespace plumb::cli
