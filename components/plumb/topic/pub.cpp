// plumb topic pub: publish a message built from FIELD=VALUE assignments.
#include <algorithm>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "messages/fields.hpp"
#include "messages/topic_type.hpp"
#include "topic/topic_verbs.hpp"

namespace plumb::cli {
namespace {

struct PubOptions {
  components::TransportOptions transport;
  std::string topic;
  std::vector<std::string> assignments;
  int count = 0;  // 0 = one message
  double rate_hz = 1;
  double wait_s = 2;
};

int run_pub(const PubOptions& o) {
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
    while (!components::g_stop && writer.matched_readers() == 0 && seconds_since(t0) < o.wait_s)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    // The writer knowing the reader does not mean the reader knows the writer yet: a volatile reader
    // drops what comes from a writer it has not matched (a Cyclone DDS reader behind a Fast DDS writer
    // lost the first of three attitudes). Give the reader's side of discovery a moment to finish.
    if (writer.matched_readers() > 0) std::this_thread::sleep_for(std::chrono::milliseconds(250));
    const int count = o.count > 0 ? o.count : 1;
    const auto period = std::chrono::duration<double>(1.0 / std::max(o.rate_hz, 1e-3));
    auto next = Clock::now();
    int sent = 0;
    for (int i = 0; i < count && !components::g_stop; ++i) {
      writer.write(msg);
      ++sent;
      next += std::chrono::duration_cast<Clock::duration>(period);
      // Sleep in short steps: Ctrl-C during a slow --rate must not wait for the next message.
      while (i + 1 < count && !components::g_stop && Clock::now() < next)
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

}  // namespace

void add_topic_pub(CLI::App& topic, Verbs& verbs) {
  auto o = std::make_shared<PubOptions>();
  auto* pub = topic.add_subcommand("pub", "Publish a message built from FIELD=VALUE assignments");
  pub->footer("Fields by path: tool_id=T1 inclination_deg=1.5 accelerometer.bias=0.1,0,0 samples.0.fz=-9.8");
  components::add_transport_options(*pub, o->transport);
  pub->add_option("topic", o->topic, "topic name")->required();
  pub->add_option("fields", o->assignments, "FIELD=VALUE assignments; unset fields are zero/empty");
  pub->add_option("--count", o->count, "messages to publish (default 1)");
  pub->add_option("--rate", o->rate_hz, "messages per second")->capture_default_str();
  pub->add_option("--wait", o->wait_s, "seconds to wait for a subscriber before publishing")->capture_default_str();
  verbs.add(pub, [o] { return run_pub(*o); });
}

}  // namespace plumb::cli
