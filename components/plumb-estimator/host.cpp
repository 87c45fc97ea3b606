#include "host.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>

#include "plumb/components/convert.hpp"
#include "plumb/estimator/assignments.hpp"
#include "plumb/estimator/loader.hpp"

namespace plumb::components {
namespace {

using Clock = std::chrono::steady_clock;

struct Plugin {
  std::string name;
  estimator::EstimatorPtr estimator;
  std::unique_ptr<transport::Writer<topics::Attitude>> writer;
  std::uint64_t published = 0;
  std::uint64_t invalid = 0;
};

void print_estimate(const Estimate& e) {
  std::printf("%-12s t=%8.2f s  inc %8.4f deg  azi %8.3f deg  tf %7.2f deg  rpm %6.1f  %s%s%s\n", e.estimator.c_str(),
              e.t_end, e.inclination_deg, e.azimuth_deg, e.gravity_toolface_deg, e.rpm, e.valid ? "valid" : "INVALID",
              e.reason.empty() ? "" : ": ", e.reason.c_str());
  std::fflush(stdout);
}

std::string host_name() {
  char buf[256] = {};
  return gethostname(buf, sizeof buf - 1) == 0 ? buf : "unknown";
}

}  // namespace

int run_host(const HostOptions& o) {
  if (o.window_s < 0) throw std::invalid_argument("--window must be >= 0");
  std::vector<Plugin> plugins;
  std::vector<estimator::Info> infos;
  for (const auto& name : o.plugins) {
    plugins.push_back({name, estimator::load_estimator(name), nullptr});
    infos.push_back(plugins.back().estimator->info());
  }
  const auto params = estimator::assign_parameters(infos, o.params, o.window_s);
  for (std::size_t i = 0; i < plugins.size(); ++i) plugins[i].estimator->configure(params[i]);
  auto conn = connect(o.transport, "plumb-estimator");
  for (auto& p : plugins) {
    p.writer = std::make_unique<transport::Writer<topics::Attitude>>(transport::make_writer<topics::Attitude>(
        *conn.participant, transport::topic_names::attitude(p.name), transport::Qos::attitude()));
  }
  auto reader = transport::make_reader<topics::SensorBatch>(
      *conn.participant, o.input_topic, o.reliable ? transport::Qos::reliable_stream() : transport::Qos::sensor_stream());
  auto status_writer =
      transport::make_writer<topics::ComponentStatus>(*conn.participant, transport::topic_names::kStatus, transport::Qos::status());
  install_stop_handler();

  std::cerr << "plumb-estimator: " << conn.transport->name() << ", reading " << o.input_topic << ", plugins:";
  for (const auto& p : plugins) std::cerr << ' ' << p.name << " -> " << transport::topic_names::attitude(p.name);
  std::cerr << std::endl;

  std::uint64_t batches = 0, samples = 0, seq_gaps = 0, lost_samples = 0, seq_backwards = 0;
  bool have_seq = false;
  std::uint64_t next_seq = 0;
  std::string tool_id = o.tool_id;
  std::string last_error;
  const auto t0 = Clock::now();
  auto last_sample_time = t0, last_status = t0;
  bool pending = false;  // samples pushed since the last estimate or flush
  std::vector<Sample> chunk;
  std::vector<Estimate> estimates;

  // Publishes what one plugin just produced.
  auto publish = [&](Plugin& p) {
    for (auto& e : estimates) {
      if (e.estimator.empty()) e.estimator = p.name;
      p.writer->write(to_topic(e, tool_id.empty() ? "unknown" : tool_id));
      ++p.published;
      if (!e.valid) ++p.invalid;
      if (!o.quiet) print_estimate(e);
    }
    estimates.clear();
  };
  auto enough = [&] {
    if (o.max_estimates <= 0) return false;
    for (const auto& p : plugins)
      if (p.published < static_cast<std::uint64_t>(o.max_estimates)) return false;
    return true;
  };
  auto send_status = [&](const std::string& state) {
    topics::ComponentStatus s;
    s.component = "plumb-estimator";
    s.host = bounded(host_name(), topics::kHostMax);
    s.state = state;
    s.stamp_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
    auto add = [&](const std::string& name, std::uint64_t v) {
      if (s.counters.size() < 32) s.counters.push_back({bounded(name, topics::kNameMax), v});
    };
    add("batches", batches);
    add("samples", samples);
    add("seq_gaps", seq_gaps);
    add("lost_samples", lost_samples);
    add("seq_backwards", seq_backwards);
    for (const auto& p : plugins) {
      add(p.name + ".estimates", p.published);
      add(p.name + ".invalid", p.invalid);
      for (const auto& [reason, n] : p.estimator->counters()) add(p.name + "." + reason, n);
    }
    s.last_error = bounded(last_error, topics::kErrorMax);
    status_writer.write(s);
  };

  send_status("running");
  topics::SensorBatch batch;
  while (!components::g_stop && !enough()) {
    if (o.timeout_s > 0 && std::chrono::duration<double>(Clock::now() - t0).count() > o.timeout_s) {
      send_status("failed");
      print_error("plumb-estimator", "timed out before " + std::to_string(o.max_estimates) + " estimates per plugin");
      return 1;
    }
    reader.wait(std::chrono::milliseconds(100));
    while (reader.take(batch)) {
      ++batches;
      if (tool_id.empty()) tool_id = batch.tool_id;
      for (const auto& m : batch.samples) {
        // The sensor stream is best-effort by default: count what the network lost.
        if (have_seq && m.seq != next_seq) {
          if (m.seq > next_seq) {
            ++seq_gaps;
            lost_samples += m.seq - next_seq;
          } else {
            ++seq_backwards;
          }
        }
        have_seq = true;
        next_seq = m.seq + 1;
        chunk.push_back(from_topic(m));
      }
      samples += batch.samples.size();
      for (auto& p : plugins) {
        p.estimator->push(chunk, estimates);
        publish(p);
      }
      chunk.clear();
      pending = true;
      last_sample_time = Clock::now();
    }
    const auto now = Clock::now();
    if (pending && o.idle_flush_s > 0 && std::chrono::duration<double>(now - last_sample_time).count() > o.idle_flush_s) {
      // The stream stopped: report what the open windows hold rather than keep it forever.
      for (auto& p : plugins) {
        p.estimator->flush(estimates);
        publish(p);
      }
      pending = false;
      have_seq = false;
    }
    if (std::chrono::duration<double>(now - last_status).count() >= 1.0) {
      send_status("running");
      last_status = now;
    }
  }
  send_status("stopping");
  std::cerr << "plumb-estimator: " << batches << " batches, " << samples << " samples (" << lost_samples
            << " lost in transit)";
  for (const auto& p : plugins) std::cerr << ", " << p.name << ": " << p.published << " estimates";
  std::cerr << std::endl;
  return 0;
}

}  // namespace plumb::components
