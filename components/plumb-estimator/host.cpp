// The host loop: subscription (samples per tool, sequence accounting) -> one runner (the plugins)
// per tool id -> publication (attitude topics, each estimate with its tool's id), with the shared
// status reporter.
#include "host.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <span>

#include "estimate_line.hpp"

#include "plumb/components/status_reporter.hpp"
#include "plumb/estimator/loader.hpp"
#include "publication.hpp"
#include "subscription.hpp"
#include "tool_streams.hpp"
#include "truth_lookup.hpp"

namespace plumb::estimator_component {
namespace {

using Clock = std::chrono::steady_clock;

// With several tools on the topic each line names its tool (" tool 'T1'" at the end).
void print_estimate(const Estimate& e, TruthLookup* truth, const std::string& tool_note) {
  std::optional<topics::Truth> t;
  if (truth) {
    truth->update();
    t = truth->at(e.t_end);
  }
  std::printf("%s%s\n", estimate_line(e, t).c_str(), tool_note.c_str());
  std::fflush(stdout);
}

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Said when nothing arrives: what the host waits for, and which sensor topics do carry data.
void explain_silence(transport::Participant& participant, const SensorSubscription& input, const std::string& topic,
                     double silent_s) {
  std::cerr << "plumb-estimator: nothing on " << topic << " for " << static_cast<int>(silent_s) << " s ("
            << input.matched_writers() << " writer(s) matched)";
  std::string others;
  for (const auto& t : participant.discovered_topics()) {
    if (t.name != topic && t.writers > 0 && t.name.starts_with(transport::topic_names::kSensorPrefix))
      others += (others.empty() ? "" : ", ") + t.name;
  }
  if (!others.empty()) std::cerr << "; sensor data is published on " << others << " (choose it with --input)";
  std::cerr << std::endl;
}

}  // namespace

int run_host(const HostOptions& o) {
  if (o.window_s < 0) throw std::invalid_argument("--window must be >= 0");
  // One runner per tool id: the first is made now so that a bad plugin or parameter fails before
  // anything runs; every further tool gets a copy made the same way.
  const auto make_runner = [&] {
    estimator::Runner r = estimator::load_runner(o.plugins);
    r.configure(o.params, o.window_s);
    return r;
  };
  estimator::Runner first_runner = make_runner();
  std::map<std::string, estimator::Runner> runners;  // tool id -> its runner
  auto conn = components::connect(o.transport, "plumb-estimator");
  EstimatePublication publication(*conn.participant);
  for (const auto& slot : first_runner.slots()) publication.add(slot.name, slot.estimator->info().uses_gyro);
  SensorSubscription input(*conn.participant, {o.input_topic, o.tool_id, o.reliable});
  components::StatusReporter status(*conn.participant, "plumb-estimator");
  std::unique_ptr<TruthLookup> truth;
  if (o.compare_truth) truth = std::make_unique<TruthLookup>(*conn.participant, o.truth_topic);
  components::install_stop_handler();

  std::cerr << "plumb-estimator: " << conn.transport->name() << ", reading " << o.input_topic
            << (o.tool_id.empty() ? " (each tool separately)" : " (tool '" + o.tool_id + "' only)") << ", plugins:";
  for (const auto& slot : first_runner.slots())
    std::cerr << ' ' << slot.name << " -> " << transport::topic_names::attitude(slot.name);
  std::cerr << std::endl;

  const auto runner_for = [&](const std::string& tool) -> estimator::Runner& {
    auto it = runners.find(tool);
    if (it != runners.end()) return it->second;
    if (runners.empty()) return runners.emplace(tool, std::move(first_runner)).first->second;
    return runners.emplace(tool, make_runner()).first->second;
  };
  const auto publisher_for = [&](const std::string& tool) {
    return [&, tool](const estimator::Runner::Slot&, Estimate& e) {
      publication.publish(e, tool);
      if (!o.quiet) print_estimate(e, truth.get(), input.tools() > 1 ? " tool '" + tool + "'" : std::string());
    };
  };
  std::string last_notice;  // the latest thing a plugin had to say, on plumb/status too
  const auto say_notices = [&](estimator::Runner& runner, const std::string& tool) {
    for (std::string& text : runner.take_notices()) {
      std::cerr << "plumb-estimator: " << (input.tools() > 1 ? "tool '" + tool + "': " : std::string()) << text << std::endl;
      last_notice = std::move(text);
    }
  };
  std::map<std::string, std::optional<double>> last_t;  // tool id -> time of its last sample
  std::uint64_t new_runs = 0;
  const auto counters = [&] {
    components::CounterList all = input.counters();
    all.emplace_back("new_runs", new_runs);
    // Summed over the tools, in the plugins' order: the per-plugin counters keep their names.
    const std::size_t own = all.size();
    if (runners.empty())
      for (auto& c : first_runner.counters()) all.push_back(std::move(c));
    for (const auto& [tool, runner] : runners)
      for (auto& [name, value] : runner.counters()) {
        auto it = std::find_if(all.begin() + static_cast<std::ptrdiff_t>(own), all.end(),
                               [&](const auto& c) { return c.first == name; });
        if (it == all.end()) all.emplace_back(name, value);
        else it->second += value;
      }
    return all;
  };
  const auto enough = [&] {
    if (o.max_estimates <= 0 || runners.empty()) return false;
    for (const auto& [tool, runner] : runners)
      for (const auto& slot : runner.slots())
        if (slot.estimates < static_cast<std::uint64_t>(o.max_estimates)) return false;
    return true;
  };

  const auto t0 = Clock::now();
  auto last_sample_time = t0;
  double next_silence_note_s = 5;
  bool pending = false;  // samples pushed since the last estimate or flush
  bool checked_gyro = false;
  SensorSubscription::ToolChunks chunks;
  status.publish("running", counters());
  while (!components::g_stop && !enough()) {
    if (o.timeout_s > 0 && seconds_since(t0) > o.timeout_s) {
      status.publish("failed", counters(), "timed out");
      components::print_error("plumb-estimator", "timed out before " + std::to_string(o.max_estimates) + " estimates per plugin");
      return 1;
    }
    input.wait(std::chrono::milliseconds(100));
    if (input.take(chunks)) {
      for (auto& [tool, chunk] : chunks) {
        if (chunk.empty()) continue;
        estimator::Runner& runner = runner_for(tool);
        if (!checked_gyro) {
          for (const auto& name : runner.needing_gyro())
            if ((chunk.front().flags & flags::kHasGyro) == 0)
              std::cerr << "plumb-estimator: " << name << " needs gyros, and " << o.input_topic << " carries none"
                        << std::endl;
          checked_gyro = true;
        }
        // A source that started again (its clock back at the beginning) is a new run: what the
        // old run's windows hold is published, and the plugins start afresh.
        std::span<const Sample> rest(chunk);
        for (std::size_t cut; (cut = new_run_start(rest, last_t[tool])) < rest.size();) {
          const double before = cut > 0 ? rest[cut - 1].t : last_t[tool].value_or(0.0);
          runner.push(rest.first(cut), publisher_for(tool));
          runner.flush(publisher_for(tool));
          runner.reset();
          ++new_runs;
          std::cerr << "plumb-estimator: tool '" << tool << "': time went back from " << before << " s to "
                    << rest[cut].t << " s: a new run, estimated afresh" << std::endl;
          last_t[tool].reset();
          rest = rest.subspan(cut);
        }
        runner.push(rest, publisher_for(tool));
        say_notices(runner, tool);
        last_t[tool] = rest.back().t;
        chunk.clear();
      }
      pending = true;
      last_sample_time = Clock::now();
      next_silence_note_s = 5;
    }
    const double silent_s = seconds_since(last_sample_time);
    if (pending && o.idle_flush_s > 0 && silent_s > o.idle_flush_s) {
      // The stream stopped: report what the open windows hold rather than keep it forever.
      for (auto& [tool, runner] : runners) {
        runner.flush(publisher_for(tool));
        say_notices(runner, tool);
      }
      pending = false;
      input.restart_sequence();
    }
    if (silent_s > next_silence_note_s) {
      explain_silence(*conn.participant, input, o.input_topic, silent_s);
      next_silence_note_s *= 2;  // 5, 10, 20, ... s: said, not shouted
    }
    if (status.due()) status.publish("running", counters(), last_notice);
  }
  status.publish("stopping", counters());
  std::cerr << "plumb-estimator: " << input.batches() << " batches, " << input.samples() << " samples ("
            << input.lost_samples() << " lost in transit, " << input.silent_lost_samples() << " lost while silent)";
  for (const auto& [tool, runner] : runners)
    for (const auto& slot : runner.slots())
      std::cerr << ", " << slot.name << (runners.size() > 1 ? " (tool '" + tool + "')" : std::string()) << ": "
                << slot.estimates << " estimates";
  std::cerr << std::endl;
  if (input.samples() == 0) {
    // Stopped having received nothing: not a success, and the silence notes above said why.
    components::print_error("plumb-estimator", "no sample received on " + o.input_topic + " (" +
                                       std::to_string(input.matched_writers()) + " writer(s) matched)");
    return 1;
  }
  if (enough()) components::sleep_while_running(o.linger_s);
  return 0;
}

}  // namespace plumb::estimator_component
