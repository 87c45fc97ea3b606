// plumb play: a recording back onto its topics, with the recorded timing (log times), faster, or
// as fast as possible; reports how far the sends were from their schedule.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <thread>

#include "messages/fields.hpp"
#include "messages/topic_type.hpp"
#include "plumb/components/cli.hpp"
#include "plumb/mcap/reader.hpp"
#include "plumb/topics/cdr.hpp"
#include "recording/recording.hpp"
#include "recording/recording_verbs.hpp"

namespace plumb::cli {
namespace {

using Clock = std::chrono::steady_clock;
using components::g_stop;

struct PlayOptions {
  components::TransportOptions transport;
  std::string input;
  std::string rate = "1";
  std::vector<std::string> topics;
  bool loop = false;
  bool reliable = false;
  double wait_s = 2;
};

// --rate: "max", "x10", "10", "0.5": a speed factor; 0 for as fast as possible.
double parse_rate(const std::string& text) {
  if (text == "max") return 0;
  const std::string number = (!text.empty() && (text[0] == 'x' || text[0] == 'X')) ? text.substr(1) : text;
  try {
    std::size_t used = 0;
    const double v = std::stod(number, &used);
    if (used == number.size() && v > 0 && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument("--rate '" + text + "' is not a speed factor (x10, 10, 0.5) or max");
}

// One topic's writer: decodes the recorded CDR into its plumb type and publishes it.
struct Publisher {
  virtual ~Publisher() = default;
  virtual void publish(const std::uint8_t* data, std::size_t size) = 0;
  virtual std::size_t matched() const = 0;
  std::uint64_t sent = 0, undecodable = 0;
};

template <class M> struct TypedPublisher final : Publisher {
  explicit TypedPublisher(transport::Writer<M> w) : writer(std::move(w)) {}
  void publish(const std::uint8_t* data, std::size_t size) override {
    try {
      topics::cdr::deserialize(data, size, message);
    } catch (const topics::cdr::Error&) {
      ++undecodable;
      return;
    }
    writer.write(message);
    ++sent;
  }
  std::size_t matched() const override { return writer.matched_readers(); }
  transport::Writer<M> writer;
  M message;
};

int run_play(const PlayOptions& o) {
  const double rate = parse_rate(o.rate);
  mcap::Reader reader(o.input);
  if (!reader.has_summary()) reader.scan();  // the channels of a cut file
  std::set<std::string> wanted(o.topics.begin(), o.topics.end());
  for (const auto& t : wanted) {
    bool found = false;
    for (const auto& [id, c] : reader.channels()) found = found || c.topic == t;
    if (!found) throw std::invalid_argument(o.input + ": no topic '" + t + "' in the recording (plumb info " + o.input + " lists them)");
  }

  auto conn = components::connect(o.transport, "plumb-play");
  std::map<std::uint16_t, std::unique_ptr<Publisher>> publishers;
  for (const auto& [id, c] : reader.channels()) {
    if (!wanted.empty() && !wanted.count(c.topic)) continue;
    const auto* type = channel_type(reader, c);
    if (!type) {
      std::cerr << "plumb play: warning: '" << c.topic << "' is not a plumb CDR topic: not played\n";
      continue;
    }
    auto qos = transport::default_qos_for_topic(c.topic);
    if (o.reliable && *type == topics::type_support<topics::SensorBatch>()) qos = transport::Qos::reliable_stream();
    const std::string topic = c.topic;
    publishers[id] = with_topic_type(*type, [&](auto proto) -> std::unique_ptr<Publisher> {
      using M = decltype(proto);
      return std::make_unique<TypedPublisher<M>>(transport::make_writer<M>(*conn.participant, topic, qos));
    });
  }
  if (publishers.empty()) throw std::runtime_error(o.input + ": nothing to play");
  components::install_stop_handler();
  // Let subscribers match first, as plumb topic pub does: the first messages would go nowhere.
  const auto wait_until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.wait_s));
  while (!g_stop && Clock::now() < wait_until &&
         std::any_of(publishers.begin(), publishers.end(), [](const auto& p) { return p.second->matched() == 0; }))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  // Nothing lost in silence: a topic no reader matched within --wait is played into nothing.
  std::string unmatched;
  for (const auto& [id, c] : reader.channels()) {
    const auto p = publishers.find(id);
    if (p != publishers.end() && p->second->matched() == 0) unmatched += (unmatched.empty() ? "" : ", ") + c.topic;
  }
  if (!unmatched.empty() && !g_stop)
    std::cerr << "plumb play: warning: no reader matched " << unmatched << " within --wait " << o.wait_s
              << " s: playing to none (start the readers first, or wait longer)\n";
  // A writer sees the match before the reader has finished matching it: reliable data sent in
  // that moment is dropped by the reader (volatile: it was not there yet). Half a second settled
  // it on an idle machine; across vendors on a loaded one (CI, two cores) the reader took longer
  // and lost all 200 batches of a recording played in 0.1 s. A second and a half.
  if (std::any_of(publishers.begin(), publishers.end(), [](const auto& p) { return p.second->matched() > 0; }))
    components::sleep_while_running(1.5);

  double error_sum = 0, error_max = 0;
  std::uint64_t timed = 0, passes = 0;
  const auto t_play = Clock::now();
  do {
    const auto t0 = Clock::now();
    std::uint64_t first_log = 0;
    bool started = false;
    reader.scan([&](const mcap::Channel& c, const mcap::MessageView& m) {
      if (g_stop) return;
      const auto p = publishers.find(c.id);
      if (p == publishers.end()) return;
      if (!started) {
        first_log = m.log_time;
        started = true;
      }
      if (rate > 0) {
        const double offset_s = static_cast<double>(m.log_time - std::min(m.log_time, first_log)) * 1e-9 / rate;
        const auto due = t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(offset_s));
        while (!g_stop && Clock::now() < due)
          std::this_thread::sleep_for(std::min<Clock::duration>(due - Clock::now(), std::chrono::milliseconds(20)));
        const double late = std::chrono::duration<double>(Clock::now() - due).count();
        error_sum += std::abs(late);
        error_max = std::max(error_max, std::abs(late));
        ++timed;
      }
      p->second->publish(m.data, m.size);
    });
    ++passes;
  } while (o.loop && !g_stop);
  const double elapsed = std::chrono::duration<double>(Clock::now() - t_play).count();

  std::uint64_t sent = 0, undecodable = 0;
  for (const auto& [id, p] : publishers) {
    sent += p->sent;
    undecodable += p->undecodable;
  }
  warn_problems("plumb play", reader);
  std::cerr << "plumb play: " << sent << " message(s) on " << publishers.size() << " topic(s) in " << format_measured(elapsed)
            << " s" << (passes > 1 ? " (" + std::to_string(passes) + " passes)" : "");
  if (timed) std::cerr << ", timing error mean " << format_measured(error_sum / static_cast<double>(timed) * 1e3) << " ms, max "
                       << format_measured(error_max * 1e3) << " ms";
  if (undecodable) std::cerr << ", " << undecodable << " undecodable message(s) skipped";
  if (g_stop) std::cerr << ", interrupted";
  std::cerr << std::endl;
  // Reliable writers keep unacknowledged data only while they live: linger briefly.
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  return 0;
}

}  // namespace

void add_recording_play(CLI::App& app, Verbs& verbs) {
  auto o = std::make_shared<PlayOptions>();
  auto* cmd = app.add_subcommand("play", "Publish an MCAP recording again, with its recorded timing");
  components::add_transport_options(*cmd, o->transport);
  cmd->add_option("file", o->input, "the recording (.mcap)")->required();
  cmd->add_option("--rate", o->rate, "speed: x10 (or 10) ten times faster, 0.5 half speed, max as fast as possible")
      ->capture_default_str();
  cmd->add_option("--topics", o->topics, "play only these topics (default: all)");
  cmd->add_flag("--loop", o->loop, "start again at the end, until Ctrl-C");
  cmd->add_flag("--reliable", o->reliable, "publish sensor topics reliable (for readers that must get every batch, --rate max)");
  cmd->add_option("--wait", o->wait_s, "seconds to wait for subscribers to match before playing")->capture_default_str();
  verbs.add(cmd, [o] { return run_play(*o); });
}

}  // namespace plumb::cli
