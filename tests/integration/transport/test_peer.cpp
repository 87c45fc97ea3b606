// plumb-test-peer: one side of a cross-process (and cross-vendor) transport test. The writer
// publishes one message of every topic type of idl/'s topic table with every field set
// (test_messages.hpp); the reader receives them and checks each one field by field. Exit status 0
// means every check passed. A topic type added to idl/ is in the test without code here.
#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "plumb/transport/loader.hpp"
#include "plumb/transport/topic_names.hpp"
#include "test_messages.hpp"

namespace {

using namespace plumb;
using Clock = std::chrono::steady_clock;
namespace names = transport::topic_names;

constexpr const char* kProgram = "plumb-test-peer";
constexpr const char* kTestAttitudeTopic = "plumb/attitude/test";
constexpr const char* kReadyTopic = "plumb/test/ready";  // reader -> writer: "I see all your writers"

struct Options {
  std::string transport;
  int domain = 0;
  std::string role;
  std::string type = "all";
  std::string attitude_topic = kTestAttitudeTopic;
  std::string interface;  // empty: loopback only
  double timeout_s = 20;
};

// One topic of the test: where it goes, with which QoS, and how to write or check its message.
struct Case {
  std::string topic;
  transport::Qos qos;
  std::function<std::unique_ptr<transport::RawWriter>(transport::Participant&)> make_writer;
  std::function<void(transport::RawWriter&)> write;
  std::function<std::unique_ptr<transport::RawReader>(transport::Participant&, std::function<void()>)> make_reader;
  // Takes one message if there is one: nullopt when none, "" when it matched, else the difference.
  std::function<std::optional<std::string>(transport::RawReader&)> take_and_check;
};

template <class T> Case make_case(std::string topic, transport::Qos qos, T expected) {
  Case c;
  c.topic = topic;
  c.qos = qos;
  c.make_writer = [topic, qos](transport::Participant& p) {
    return p.create_writer(topics::type_support<T>(), topic, qos);
  };
  c.write = [expected](transport::RawWriter& w) { w.write(&expected); };
  c.make_reader = [topic, qos](transport::Participant& p, std::function<void()> on_data) {
    return p.create_reader(topics::type_support<T>(), topic, qos, std::move(on_data));
  };
  c.take_and_check = [expected](transport::RawReader& r) -> std::optional<std::string> {
    T got;
    if (!r.take(&got)) return std::nullopt;
    return test::first_difference(expected, got);
  };
  return c;
}

// The table's QoS, except that the test needs every message: best-effort topics become reliable.
transport::Qos test_qos(const std::string& topic) {
  const transport::Qos qos = transport::default_qos_for_topic(topic);
  return qos.reliability == transport::Reliability::BestEffort ? transport::Qos::reliable_stream() : qos;
}

// One full message of type T on the first topic of the table that carries it ("<prefix>test" for a prefix).
template <class T> Case table_case() {
  for (const auto& e : topics::kTopicTable) {
    if (*e.type != topics::type_support<T>()) continue;
    const std::string topic = e.prefix ? std::string(e.name) + "test" : e.name;
    return make_case(topic, test_qos(topic), test::full<T>());
  }
  throw transport::Error(std::string("no topic carries ") + topics::type_support<T>().type_name);
}

template <class... T> void add_table_cases(std::vector<Case>& cases, topics::TypeList<T...>) {
  (cases.push_back(table_case<T>()), ...);
}

std::vector<Case> cases_for(const Options& o) {
  std::vector<Case> cases;
  if (o.type == "all") {
    add_table_cases(cases, topics::TopicTypes{});
    // The other edge: no samples, empty strings.
    cases.push_back(make_case(names::kSensorCalibrated, test_qos(names::kSensorCalibrated), test::empty_sensor_batch()));
  } else if (o.type == "late-calibration") {
    cases.push_back(make_case(names::kCalibration, transport::default_qos_for_topic(names::kCalibration), test::full_calibration()));
  } else if (o.type == "attitude") {
    cases.push_back(make_case(o.attitude_topic, transport::default_qos_for_topic(o.attitude_topic), test::full_attitude()));
  }
  return cases;
}

void say(const std::string& message) {
  std::cout << kProgram << ": " << message << std::endl;  // flushed: the driver script watches it
}

// Set by SIGTERM/SIGINT: the driver script stops a lingering writer once the reader is done.
std::atomic<bool> g_stop{false};
extern "C" void request_stop(int) { g_stop = true; }

bool wait_until(Clock::time_point deadline, const std::function<bool()>& done) {
  while (!done()) {
    if (g_stop) return false;
    if (Clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

int run_writer(const Options& o, transport::Participant& participant, std::vector<Case>& cases) {
  std::vector<std::unique_ptr<transport::RawWriter>> writers;
  for (auto& c : cases) writers.push_back(c.make_writer(participant));
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.timeout_s));
  auto all_matched = [&] {
    for (auto& w : writers) if (w->matched_readers() == 0) return false;
    return true;
  };
  auto none_matched = [&] {
    for (auto& w : writers) if (w->matched_readers() != 0) return false;
    return true;
  };
  const bool late_joiner = o.type == "late-calibration";
  if (late_joiner) {
    // Publish before any reader exists; the driver starts the reader after this line and stops
    // us (SIGTERM) when it is done. A late reader may come and go between two polls, so
    // matching is not watched here: the reader's check is the test.
    for (std::size_t i = 0; i < cases.size(); ++i) cases[i].write(*writers[i]);
    say("wrote " + std::to_string(cases.size()) + " messages on " + o.transport);
    wait_until(deadline, [] { return false; });
    return 0;
  }
  if (!wait_until(deadline, all_matched)) {
    std::cerr << kProgram << ": no reader matched every topic within " << o.timeout_s << " s\n";
    return 1;
  }
  if (o.type == "attitude") {
    // For a reader that cannot say it is ready (the plain C listener): the same message again
    // every 100 ms until stopped, so the first one it can receive is as good as any.
    while (!g_stop && Clock::now() < deadline) {
      cases[0].write(*writers[0]);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    say("wrote the attitude until stopped on " + o.transport);
    return 0;
  }
  // A writer sees the reader before the reader sees the writer, and a volatile reader drops what
  // was written before it knew the writer. So wait for the reader's word that it matched every
  // writer (a transient-local message, so it cannot be missed either).
  auto ready = participant.create_reader(topics::type_support<topics::ComponentStatus>(), kReadyTopic,
                                         transport::Qos::calibration());
  auto reader_ready = [&] {
    plumb::topics::ComponentStatus status;
    return ready->take(&status);
  };
  if (!wait_until(deadline, reader_ready)) {
    std::cerr << kProgram << ": the reader did not report ready within " << o.timeout_s << " s\n";
    return 1;
  }
  for (std::size_t i = 0; i < cases.size(); ++i) cases[i].write(*writers[i]);
  say("wrote " + std::to_string(cases.size()) + " messages on " + o.transport);
  // Stay until the reader has gone (it leaves once it has checked everything) or we are
  // stopped, so that reliable repairs are served by a live writer.
  if (!wait_until(deadline, none_matched)) say("reader still present at the timeout or stopped; leaving");
  return 0;
}

int run_reader(const Options& o, transport::Participant& participant, std::vector<Case>& cases) {
  std::mutex mutex;
  std::condition_variable data;
  bool pending = false;
  auto notify = [&] {
    { const std::lock_guard lock(mutex); pending = true; }
    data.notify_one();
  };
  std::vector<std::unique_ptr<transport::RawReader>> readers;
  for (auto& c : cases) readers.push_back(c.make_reader(participant, notify));
  std::vector<int> received(cases.size(), 0);
  std::vector<std::string> failures;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.timeout_s));
  // Tell the writer once every reader knows its writer (see run_writer). Kept alive to the end.
  std::unique_ptr<transport::RawWriter> ready;
  if (o.type == "all") {
    auto all_matched = [&] {
      for (auto& r : readers) if (r->matched_writers() == 0) return false;
      return true;
    };
    if (!wait_until(deadline, all_matched)) {
      std::cerr << kProgram << ": FAILED no writer matched every topic within " << o.timeout_s << " s\n";
      return 1;
    }
    ready = participant.create_writer(topics::type_support<topics::ComponentStatus>(), kReadyTopic,
                                      transport::Qos::calibration());
    plumb::topics::ComponentStatus status;
    status.component = kProgram;
    status.state = "ready";
    ready->write(&status);
  }
  auto complete = [&] {
    for (int n : received) if (n == 0) return false;
    return true;
  };
  while (!complete() && Clock::now() < deadline) {
    {
      // Bounded wait: the callback only hints; every reader is polled anyway.
      std::unique_lock lock(mutex);
      data.wait_for(lock, std::chrono::milliseconds(100), [&] { return pending; });
      pending = false;
    }
    for (std::size_t i = 0; i < cases.size(); ++i) {
      while (auto result = cases[i].take_and_check(*readers[i])) {
        // The attitude writer repeats its message until stopped; elsewhere exactly one is sent.
        if (++received[i] > 1 && o.type != "attitude") failures.push_back(cases[i].topic + ": received more than one message");
        if (!result->empty()) failures.push_back(cases[i].topic + ": " + *result);
      }
    }
  }
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (received[i] == 0) failures.push_back(cases[i].topic + ": nothing received within " + std::to_string(o.timeout_s) + " s");
  }
  if (!failures.empty()) {
    for (const auto& f : failures) std::cerr << kProgram << ": FAILED " << f << "\n";
    return 1;
  }
  say("OK: " + std::to_string(cases.size()) + " messages received on " + o.transport + ", every field as sent");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  bool print_attitude = false;
  CLI::App app{"One side of a cross-process transport test: writes or checks one message of every topic type."};
  app.add_option("--transport", o.transport, "transport plugin (default: $PLUMB_TRANSPORT or cyclonedds)");
  app.add_option("--domain", o.domain, "DDS domain id")->check(CLI::Range(0, 232));
  app.add_option("--role", o.role, "writer or reader")->check(CLI::IsMember({"writer", "reader"}));
  app.add_option("--type", o.type, "all: every topic type; late-calibration: transient-local calibration for a late reader; "
                                   "attitude: one attitude repeated on --attitude-topic until stopped, for the C listener")
      ->check(CLI::IsMember({"all", "late-calibration", "attitude"}));
  app.add_option("--attitude-topic", o.attitude_topic, "topic of --type attitude");
  app.add_option("--interface", o.interface, "network interface name or IPv4 address (default: loopback only)");
  app.add_option("--timeout", o.timeout_s, "seconds to wait for peers and data")->check(CLI::Range(0.1, 3600.0));
  app.add_flag("--print-expected-attitude", print_attitude, "print the test attitude as the C listener prints it, and exit");
  CLI11_PARSE(app, argc, argv);

  if (print_attitude) {
    std::cout << test::attitude_line(test::full_attitude()) << "\n";
    return 0;
  }
  if (o.role.empty()) {
    std::cerr << kProgram << ": --role writer|reader is required\n";
    return 2;
  }
  std::signal(SIGTERM, request_stop);
  std::signal(SIGINT, request_stop);
  try {
    auto transport = transport::load_transport(o.transport);
    o.transport = transport->name();
    transport::ParticipantOptions po;
    po.domain_id = o.domain;
    po.interface = o.interface;
    po.name = std::string(kProgram) + "-" + o.role;
    auto participant = transport->create_participant(po);
    auto cases = cases_for(o);
    return o.role == "writer" ? run_writer(o, *participant, cases) : run_reader(o, *participant, cases);
  } catch (const std::exception& e) {
    std::cerr << kProgram << ": " << e.what() << "\n";
    return 1;
  }
}
