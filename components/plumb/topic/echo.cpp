// plumb topic echo: print the messages of a topic, YAML-like or as CSV.
#include <algorithm>
#include <iostream>
#include <memory>
#include <type_traits>
#include <vector>

#include "messages/csv_output.hpp"
#include "messages/fields.hpp"
#include "messages/topic_type.hpp"
#include "plumb/components/topic_wait.hpp"
#include "topic/topic_verbs.hpp"

namespace plumb::cli {
namespace {

struct EchoOptions {
  components::TransportOptions transport;
  std::string topic;
  bool csv = false;
  int count = 0;         // 0 = until interrupted
  double timeout_s = 0;  // 0 = none
  double wait_s = 2;
  bool reliable = false;
};

int run_echo(const EchoOptions& o) {
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
    while (!components::g_stop && (o.count == 0 || received < o.count)) {
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
                << "', " << end_reason(o.timeout_s, elapsed_s) << std::endl;
      return 1;
    }
    if (received == 0) {  // Ctrl-C or --timeout with nothing: the command did not do its job
      std::cerr << "plumb topic echo: no message on '" << o.topic << "', " << end_reason(o.timeout_s, elapsed_s) << " ("
                << reader.matched_writers() << " writer(s) matched)" << std::endl;
      return 1;
    }
    if (o.count == 0)
      std::cerr << "plumb topic echo: " << received << " message(s) on '" << o.topic << "', "
                << end_reason(o.timeout_s, elapsed_s) << std::endl;
    return 0;
  });
}

}  // namespace

void add_topic_echo(CLI::App& topic, Verbs& verbs) {
  auto o = std::make_shared<EchoOptions>();
  auto* echo = topic.add_subcommand("echo", "Print the messages of a topic (YAML-like, or CSV with --csv)");
  components::add_transport_options(*echo, o->transport);
  echo->add_option("topic", o->topic, "topic name, e.g. plumb/attitude/compensated")->required();
  echo->add_flag("--csv", o->csv,
                 "print CSV: a header, then one row per message; sensor topics give the sensor CSV of docs/conventions.md "
                 "(t,fx,fy,fz,bx,by,bz[,wx,wy,wz][,temp_c]), which plumb estimate and plumb-bridge --replay read");
  echo->add_option("--count", o->count, "exit after this many messages (exit 1 if fewer arrive)");
  echo->add_option("--timeout", o->timeout_s, "give up after this many seconds (exit 1 if nothing arrived)");
  echo->add_option("--wait", o->wait_s, "seconds to wait for discovery of a topic outside plumb's names")->capture_default_str();
  echo->add_flag("--reliable", o->reliable, "reliable reader on sensor topics (default best-effort)");
  verbs.add(echo, [o] { return run_echo(*o); });
}

}  // namespace plumb::cli
