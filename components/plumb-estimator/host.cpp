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
#include <string>
#include <utility>

#include "component_service.hpp"
#include "estimate_line.hpp"
#include "lineup.hpp"
#include "parameter_publication.hpp"

#include "plumb/components/status_reporter.hpp"
#include "plumb/estimator/loader.hpp"
#include "publication.hpp"
#include "resume_record.hpp"
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

// One runner per tool id, the topics in and out, and what the loop counts: the host as named
// steps (announce, take and push, flush when idle, explain silence, summarise).
class Host {
 public:
  // The first runner is made before anything connects, so that a bad plugin or parameter fails
  // before anything runs; every further tool gets a copy made the same way.
  explicit Host(const HostOptions& o)
      : o_(o),
        lineup_(o.plugins, o.params, o.window_s),
        first_runner_(lineup_.make_runner()),
        conn_(components::connect(o.transport, "plumb-estimator")),
        publication_(*conn_.participant),
        input_(*conn_.participant, {o.input_topic, o.tool_id, o.reliable}),
        status_(*conn_.participant, "plumb-estimator"),
        service_(*conn_.participant, o.name.empty() ? components::host_name() : o.name),
        parameters_(*conn_.participant, service_.name()) {
    status_.set_name(service_.name());  // plumb status shows it: two hosts on one computer are told apart
    for (const auto& e : lineup_.entries()) parameters_.publish(lineup_, e.name);
    for (const auto& slot : first_runner_.slots()) publication_.add(slot.name, slot.estimator->info().uses_gyro);
    if (o.compare_truth) truth_ = std::make_unique<TruthLookup>(*conn_.participant, o.truth_topic);
    open_resume_record();
  }

  int run();

 private:
  estimator::Runner& runner_for(const std::string& tool) {
    auto it = runners_.find(tool);
    if (it != runners_.end()) return it->second;
    if (runners_.empty()) return runners_.emplace(tool, std::move(first_runner_)).first->second;
    return runners_.emplace(tool, lineup_.make_runner()).first->second;
  }

  estimator::Runner::Sink publisher_for(const std::string& tool) {
    return [this, tool](const estimator::Runner::Slot&, Estimate& e) {
      publication_.publish(e, tool);
      if (!o_.quiet) print_estimate(e, truth_.get(), input_.tools() > 1 ? " tool '" + tool + "'" : std::string());
    };
  }

  void say_notices(estimator::Runner& runner, const std::string& tool) {
    for (std::string& text : runner.take_notices()) {
      std::cerr << "plumb-estimator: " << (input_.tools() > 1 ? "tool '" + tool + "': " : std::string()) << text << std::endl;
      last_notice_ = std::move(text);
    }
  }

  void open_resume_record();
  void save_resume_record();
  components::CounterList counters() const;
  bool enough() const;
  void announce() const;
  void check_gyro(const estimator::Runner& runner, const std::vector<Sample>& chunk);
  void push_chunk(const std::string& tool, std::vector<Sample>& chunk);
  void flush_idle();
  int summarise();
  // plumb component / plumb param: applied here, between two pushes, so at a window boundary.
  void serve_requests();
  topics::ComponentReply handle(const topics::ComponentRequest& request);
  template <class F> void for_each_runner(F&& f);

  const HostOptions& o_;
  Lineup lineup_;  // the plugins and their parameters now: a new tool's runner starts from it
  estimator::Runner first_runner_;
  std::map<std::string, estimator::Runner> runners_;  // tool id -> its runner
  components::Connection conn_;
  EstimatePublication publication_;
  SensorSubscription input_;
  components::StatusReporter status_;
  ComponentService service_;
  ParameterPublication parameters_;
  std::unique_ptr<TruthLookup> truth_;
  std::optional<ResumeFile> resume_;
  bool said_resume_failure_ = false;
  std::string last_notice_;  // the latest thing a plugin had to say, on plumb/status too
  std::map<std::string, std::optional<double>> last_t_;  // tool id -> time of its last sample
  std::uint64_t new_runs_ = 0;
  bool checked_gyro_ = false;
  std::optional<bool> stream_has_gyro_;  // known from the first samples: a plugin loaded later is told too
};

// The previous instance's record: where each tool stood when it last took samples.
void Host::open_resume_record() {
  if (o_.no_state) return;
  const std::string dir = o_.state_dir.empty() ? default_state_dir() : o_.state_dir;
  const std::string path = dir + "/" + resume_file_name(conn_.options.domain_id, o_.input_topic, o_.tool_id);
  std::string why;
  if (auto file = ResumeFile::open(path, why)) resume_.emplace(std::move(*file));
  if (!resume_) {
    std::cerr << "plumb-estimator: no record of the sequence for a restart (" << why
              << "): samples lost while this host is down will not be counted" << std::endl;
    return;
  }
  input_.resume_after(resume_->previous());
  std::cerr << "plumb-estimator: record of the last sequence taken: " << resume_->path()
            << (resume_->previous().empty() ? " (new)" : " (the previous instance's, read)") << std::endl;
}

void Host::save_resume_record() {
  if (!resume_ || resume_->save(input_.marks()) || said_resume_failure_) return;
  std::cerr << "plumb-estimator: cannot write " << resume_->path()
            << ": a restart of this host will not count what it lost while down" << std::endl;
  said_resume_failure_ = true;
}

components::CounterList Host::counters() const {
  components::CounterList all = input_.counters();
  all.emplace_back("new_runs", new_runs_);
  all.emplace_back("requests", service_.answered());
  all.emplace_back("requests_refused", service_.refused());
  // Summed over the tools, in the plugins' order: the per-plugin counters keep their names.
  const std::size_t own = all.size();
  if (runners_.empty())
    for (auto& c : first_runner_.counters()) all.push_back(std::move(c));
  for (const auto& [tool, runner] : runners_)
    for (auto& [name, value] : runner.counters()) {
      const std::string& key = name;  // clang 14 lets no lambda capture a structured binding (C++20 does)
      auto it = std::find_if(all.begin() + static_cast<std::ptrdiff_t>(own), all.end(),
                             [&](const auto& c) { return c.first == key; });
      if (it == all.end()) all.emplace_back(name, value);
      else it->second += value;
    }
  return all;
}

bool Host::enough() const {
  if (o_.max_estimates <= 0 || runners_.empty()) return false;
  for (const auto& [tool, runner] : runners_)
    for (const auto& slot : runner.slots())
      if (slot.estimates < static_cast<std::uint64_t>(o_.max_estimates)) return false;
  return true;
}

void Host::announce() const {
  std::cerr << "plumb-estimator: " << conn_.transport->name() << ", reading " << o_.input_topic
            << (o_.tool_id.empty() ? " (each tool separately)" : " (tool '" + o_.tool_id + "' only)") << ", plugins:";
  for (const auto& slot : first_runner_.slots())
    std::cerr << ' ' << slot.name << " -> " << transport::topic_names::attitude(slot.name);
  std::cerr << "; host '" << service_.name() << "' for plumb component and plumb param" << std::endl;
}

template <class F> void Host::for_each_runner(F&& f) {
  if (runners_.empty()) f(std::string(), first_runner_);  // no tool yet: the runner the first one gets
  for (auto& [tool, runner] : runners_) f(tool, runner);
}

namespace {

topics::ComponentParameter row_of(const Lineup::Value& v) { return {v.plugin, v.name, v.value, v.default_value}; }

}  // namespace

topics::ComponentReply Host::handle(const topics::ComponentRequest& r) {
  topics::ComponentReply reply;
  const std::string& plugin = r.plugin;
  try {
    if (r.verb == "list") {
      for (const auto& e : lineup_.entries()) reply.rows.push_back({e.name, "", e.info.version, e.info.description});
      reply.message = std::to_string(lineup_.entries().size()) + " plugin(s)";
    } else if (r.verb == "load") {
      const estimator::Parameters parameters = lineup_.load(plugin, split_assignments(r.value));
      publication_.add(plugin, lineup_.find(plugin)->info.uses_gyro);
      for_each_runner([&](const std::string& tool, estimator::Runner& runner) {
        runner.add(plugin, estimator::load_estimator(plugin));
        runner.reconfigure(plugin, parameters, publisher_for(tool));  // a new slot: nothing open to end
      });
      parameters_.publish(lineup_, plugin);
      reply.message = "loaded " + plugin + ", publishing on " + transport::topic_names::attitude(plugin);
      if (lineup_.find(plugin)->info.uses_gyro && stream_has_gyro_ == false)
        reply.message += "; it needs gyros, and " + o_.input_topic + " carries none";
    } else if (r.verb == "unload") {
      lineup_.unload(plugin);
      for_each_runner([&](const std::string& tool, estimator::Runner& runner) { runner.remove(plugin, publisher_for(tool)); });
      publication_.retire(plugin);
      parameters_.unloaded(plugin);
      reply.message = "unloaded " + plugin + " (its open window published)";
    } else if (r.verb == "set") {
      const estimator::Parameters parameters = lineup_.set(plugin, r.name, r.value);
      for_each_runner([&](const std::string& tool, estimator::Runner& runner) {
        runner.reconfigure(plugin, parameters, publisher_for(tool));
      });
      parameters_.publish(lineup_, plugin);
      reply.message = plugin + "." + r.name + " = " + r.value + " from the next window (the open one published)";
    } else if (r.verb == "get") {
      reply.rows.push_back(row_of(lineup_.get(plugin, r.name)));
    } else if (r.verb == "dump") {
      for (const auto& v : lineup_.dump(plugin)) reply.rows.push_back(row_of(v));
      if (reply.rows.size() > topics::ComponentReply::kRowsMax) reply.rows.resize(topics::ComponentReply::kRowsMax);
    } else {
      throw std::invalid_argument("unknown request '" + r.verb + "' (list, load, unload, get, set, dump)");
    }
    reply.result = topics::COMPONENT_DONE;
  } catch (const std::exception& e) {
    reply.result = topics::COMPONENT_REFUSED;
    reply.message = e.what();
  }
  return reply;
}

void Host::serve_requests() {
  for (const auto& request : service_.take()) {
    topics::ComponentReply reply = handle(request);
    std::string what = request.verb + (request.plugin.empty() ? "" : " " + request.plugin) +
                       (request.name.empty() ? "" : " " + request.name) + (request.verb == "set" ? " " + request.value : "");
    std::cerr << "plumb-estimator: " << what << " (from " << request.client << "): "
              << (reply.result == topics::COMPONENT_DONE ? reply.message.empty() ? std::string("done") : reply.message : "refused: " + reply.message)
              << std::endl;
    service_.answer(request, std::move(reply));
  }
  publication_.sweep();
}

// Said once, at the first samples: a plugin that needs gyros on a topic that carries none.
void Host::check_gyro(const estimator::Runner& runner, const std::vector<Sample>& chunk) {
  if (checked_gyro_) return;
  stream_has_gyro_ = (chunk.front().flags & flags::kHasGyro) != 0;
  for (const auto& name : runner.needing_gyro())
    if ((chunk.front().flags & flags::kHasGyro) == 0)
      std::cerr << "plumb-estimator: " << name << " needs gyros, and " << o_.input_topic << " carries none" << std::endl;
  checked_gyro_ = true;
}

// One tool's new samples through its runner. A source that started again (its clock back at the
// beginning) is a new run: what the old run's windows hold is published, and the plugins start afresh.
void Host::push_chunk(const std::string& tool, std::vector<Sample>& chunk) {
  estimator::Runner& runner = runner_for(tool);
  check_gyro(runner, chunk);
  std::span<const Sample> rest(chunk);
  for (std::size_t cut; (cut = new_run_start(rest, last_t_[tool])) < rest.size();) {
    const double before = cut > 0 ? rest[cut - 1].t : last_t_[tool].value_or(0.0);
    runner.push(rest.first(cut), publisher_for(tool));
    runner.flush(publisher_for(tool));
    runner.reset();
    ++new_runs_;
    std::cerr << "plumb-estimator: tool '" << tool << "': time went back from " << before << " s to " << rest[cut].t
              << " s: a new run, estimated afresh" << std::endl;
    last_t_[tool].reset();
    rest = rest.subspan(cut);
  }
  runner.push(rest, publisher_for(tool));
  say_notices(runner, tool);
  last_t_[tool] = rest.back().t;
  chunk.clear();
}

// The stream stopped: report what the open windows hold rather than keep it forever.
void Host::flush_idle() {
  for (auto& [tool, runner] : runners_) {
    runner.flush(publisher_for(tool));
    say_notices(runner, tool);
  }
  input_.restart_sequence();
}

int Host::summarise() {
  status_.publish("stopping", counters());
  std::cerr << "plumb-estimator: " << input_.batches() << " batches, " << input_.samples() << " samples ("
            << input_.lost_samples() << " lost in transit, " << input_.silent_lost_samples() << " lost while silent"
            << (input_.lost_while_down() > 0 ? ", " + std::to_string(input_.lost_while_down()) + " lost while this host was down"
                                             : std::string())
            << ")";
  for (const auto& [tool, runner] : runners_)
    for (const auto& slot : runner.slots())
      std::cerr << ", " << slot.name << (runners_.size() > 1 ? " (tool '" + tool + "')" : std::string()) << ": "
                << slot.estimates << " estimates";
  std::cerr << std::endl;
  if (input_.samples() == 0) {
    // Stopped having received nothing: not a success, and the silence notes above said why.
    components::print_error("plumb-estimator", "no sample received on " + o_.input_topic + " (" +
                                                   std::to_string(input_.matched_writers()) + " writer(s) matched)");
    return 1;
  }
  if (enough()) components::sleep_while_running(o_.linger_s);
  return 0;
}

int Host::run() {
  components::install_stop_handler();
  announce();
  const auto t0 = Clock::now();
  auto last_sample_time = t0;
  double next_silence_note_s = 5;
  bool pending = false;  // samples pushed since the last estimate or flush
  SensorSubscription::ToolChunks chunks;
  status_.publish("running", counters());
  while (!components::g_stop && !enough()) {
    if (o_.timeout_s > 0 && seconds_since(t0) > o_.timeout_s) {
      status_.publish("failed", counters(), "timed out");
      components::print_error("plumb-estimator", "timed out before " + std::to_string(o_.max_estimates) + " estimates per plugin");
      return 1;
    }
    input_.wait(std::chrono::milliseconds(100));
    if (input_.take(chunks)) {
      for (auto& [tool, chunk] : chunks)
        if (!chunk.empty()) push_chunk(tool, chunk);
      save_resume_record();
      pending = true;
      last_sample_time = Clock::now();
      next_silence_note_s = 5;
    }
    serve_requests();
    const double silent_s = seconds_since(last_sample_time);
    if (pending && o_.idle_flush_s > 0 && silent_s > o_.idle_flush_s) {
      flush_idle();
      pending = false;
    }
    if (silent_s > next_silence_note_s) {
      explain_silence(*conn_.participant, input_, o_.input_topic, silent_s);
      next_silence_note_s *= 2;  // 5, 10, 20, ... s: said, not shouted
    }
    if (status_.due()) status_.publish("running", counters(), last_notice_);
  }
  return summarise();
}

}  // namespace

int run_host(const HostOptions& o) {
  if (o.window_s < 0) throw std::invalid_argument("--window must be >= 0");
  Host host(o);
  return host.run();
}

}  // namespace plumb::estimator_component
