#include "dds_feed.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <type_traits>
#include <utility>

#include "json.hpp"
#include "plumb/transport/topic_names.hpp"

namespace plumb::display_component {
namespace {

// Messages per batched take.
constexpr std::size_t kTakeBatch = 64;
// A plugin that sent nothing for this long while another of its tool did is gone (docs/display.md).
constexpr double kSilentMs = 10000;

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

struct DdsFeed::Stream {
  virtual ~Stream() = default;
  virtual std::size_t drain(Hub& hub, PluginDifferences& differences) = 0;
  // The topic's last writer is gone: what the stream showed leaves the page (attitudes only).
  virtual void gone(Hub&, PluginDifferences&) {}
  // Attitudes only: the newest reception per tool (ms since the epoch), and the estimates silent
  // for `silent_ms` while their tool's newest is not, forgotten as gone() does.
  virtual void newest_by_tool(std::map<std::string, double>&) const {}
  virtual void forget_silent(Hub&, PluginDifferences&, const std::map<std::string, double>&, double) {}
};

namespace {

template <class M> class TypedStream final : public DdsFeed::Stream {
 public:
  explicit TypedStream(transport::Reader<M> reader) : reader_(std::move(reader)) {}

  std::size_t drain(Hub& hub, PluginDifferences& differences) override {
    std::size_t n = 0;
    while (reader_.take(taken_, kTakeBatch) > 0) {
      const double rx = wall_clock_ms();
      for (const M& m : taken_) {
        if constexpr (std::is_same_v<M, topics::Attitude>) {
          shown_[{m.tool_id, m.estimator}] = rx;
          deliver(hub, m, rx, differences.attitude(m, rx));
        } else {
          deliver(hub, m, rx);
        }
      }
      n += taken_.size();
    }
    return n;
  }

  void gone(Hub& hub, PluginDifferences& differences) override {
    drain(hub, differences);  // its last estimates first: they would bring the cards back after
    for (const auto& [shown, rx] : shown_) forget(hub, differences, shown.first, shown.second);
    shown_.clear();
  }

  void newest_by_tool(std::map<std::string, double>& newest) const override {
    for (const auto& [shown, rx] : shown_) newest[shown.first] = std::max(newest[shown.first], rx);
  }

  void forget_silent(Hub& hub, PluginDifferences& differences, const std::map<std::string, double>& newest,
                     double silent_ms) override {
    std::erase_if(shown_, [&](const auto& entry) {
      const auto& [shown, rx] = entry;
      if (newest.at(shown.first) - rx <= silent_ms) return false;
      forget(hub, differences, shown.first, shown.second);
      return true;
    });
  }

 private:
  static void forget(Hub& hub, PluginDifferences& differences, const std::string& tool, const std::string& estimator) {
    differences.gone(tool, estimator);
    hub.forget_attitude(tool + "/" + estimator);
  }
  static void deliver(Hub& hub, const topics::Attitude& a, double rx, const std::optional<AttitudeDifference>& difference) {
    const std::string key = a.tool_id + "/" + a.estimator;
    HistoryPoint p;
    p.rx_ms = rx;
    p.inclination = a.inclination_deg;
    p.azimuth = a.azimuth_deg;
    p.toolface = a.gravity_toolface_deg;
    p.rpm = a.rpm;
    p.flags = a.flags;
    hub.attitude(key, attitude_json(a, key, rx, difference), p);
  }
  static void deliver(Hub& hub, const topics::ComponentStatus& s, double rx) {
    const std::string key = s.component + "@" + s.host;
    hub.status(key, status_json(s, key, rx));
  }
  static void deliver(Hub& hub, const topics::Clearance& c, double) {
    hub.clearance(c.tool_id + "/" + c.offset_well, clearance_json(c, c.tool_id + "/" + c.offset_well));
  }
  static void deliver(Hub& hub, const topics::MeasuredDepth& d, double) { hub.depth(d.tool_id, depth_json(d)); }
  static void deliver(Hub& hub, const topics::SurveyStation& s, double) {
    const std::string key = s.tool_id + "#" + std::to_string(s.index);
    hub.station(key, station_json(s, key));
  }

  transport::Reader<M> reader_;
  std::vector<M> taken_;
  std::map<std::pair<std::string, std::string>, double> shown_;  // (tool, estimator) -> last received, ms
};

}  // namespace

DdsFeed::DdsFeed(transport::Participant& participant, Hub& hub, PluginDifferences& differences)
    : participant_(participant), hub_(hub), differences_(differences) {
  const std::string status = transport::topic_names::kStatus;
  streams_.push_back(std::make_unique<TypedStream<topics::ComponentStatus>>(transport::make_reader<topics::ComponentStatus>(
      participant_, status, transport::default_qos_for_topic(status), [this] { wake(); })));
  topics_.insert(status);
  const std::string clearance = transport::topic_names::kClearance, depth = transport::topic_names::kDepth;
  streams_.push_back(std::make_unique<TypedStream<topics::Clearance>>(transport::make_reader<topics::Clearance>(
      participant_, clearance, transport::default_qos_for_topic(clearance), [this] { wake(); })));
  streams_.push_back(std::make_unique<TypedStream<topics::MeasuredDepth>>(transport::make_reader<topics::MeasuredDepth>(
      participant_, depth, transport::default_qos_for_topic(depth), [this] { wake(); })));
  topics_.insert(clearance);
  topics_.insert(depth);
}

DdsFeed::~DdsFeed() = default;

void DdsFeed::wake() {
  {
    std::lock_guard lock(mutex_);
    pending_ = true;
  }
  cv_.notify_one();
}

void DdsFeed::discover() {
  const auto attitude_type = topics::type_support<topics::Attitude>().type_name;
  const auto survey_type = topics::type_support<topics::SurveyStation>().type_name;
  auto wake = [this] { this->wake(); };
  std::set<std::string> written;
  for (const auto& t : participant_.discovered_topics()) {
    if (t.writers > 0) written.insert(t.name);
    if (t.writers == 0 || topics_.count(t.name)) continue;
    const auto qos = transport::default_qos_for_topic(t.name);
    if (starts_with(t.name, transport::topic_names::kAttitudePrefix) && t.type_name == attitude_type) {
      streams_.push_back(std::make_unique<TypedStream<topics::Attitude>>(
          transport::make_reader<topics::Attitude>(participant_, t.name, qos, wake)));
    } else if (starts_with(t.name, transport::topic_names::kSurveyPrefix) && t.type_name == survey_type) {
      streams_.push_back(std::make_unique<TypedStream<topics::SurveyStation>>(
          transport::make_reader<topics::SurveyStation>(participant_, t.name, qos, wake)));
    } else {
      continue;
    }
    topics_.insert(t.name);
    discovered_streams_[t.name] = streams_.back().get();
  }
  // An estimator's topic without a writer (the plugin unloaded, its host gone): its cards and
  // differences go, as its Foxglove channel does (docs/display.md). The reader stays: a plugin
  // loaded again comes back.
  for (const auto& [name, stream] : discovered_streams_) {
    if (written.count(name)) {
      unwritten_.erase(name);
    } else if (unwritten_.insert(name).second) {
      stream->gone(hub_, differences_);
    }
  }
  // A plugin silent while another of its tool is not is gone too: a Fast DDS participant (2.9.1) is
  // never told that a Cyclone DDS writer was deleted while its participant lives on, so an unloaded
  // plugin's topic keeps its writer there.
  std::map<std::string, double> newest;
  for (const auto& [name, stream] : discovered_streams_) stream->newest_by_tool(newest);
  for (const auto& [name, stream] : discovered_streams_) stream->forget_silent(hub_, differences_, newest, kSilentMs);
}

std::size_t DdsFeed::poll(std::chrono::milliseconds timeout) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_discovery_ >= std::chrono::milliseconds(500)) {
    last_discovery_ = now;
    discover();
  }
  {
    std::unique_lock lock(mutex_);
    cv_.wait_for(lock, timeout, [this] { return pending_; });
    pending_ = false;
  }
  std::size_t n = 0;
  for (auto& s : streams_) n += s->drain(hub_, differences_);
  return n;
}

}  // namespace plumb::display_component
