#include "publication.hpp"

#include "plumb/components/convert.hpp"
#include "plumb/transport/topic_names.hpp"

namespace plumb::estimator_component {
namespace {

// Long enough for a reliable reader to acknowledge (a few heartbeats), short enough not to linger.
constexpr std::chrono::seconds kRetiredWritersKept{3};

}  // namespace

void EstimatePublication::add(const std::string& plugin, bool navigator) {
  if (const auto it = retired_.find(plugin); it != retired_.end()) {
    writers_[plugin] = std::move(it->second.second);
    retired_.erase(it);
  }
  Writers& w = writers_[plugin];
  if (!w.attitude)
    w.attitude.emplace(transport::make_writer<topics::Attitude>(participant_, transport::topic_names::attitude(plugin),
                                                                transport::Qos::attitude()));
  if (navigator && !w.navigation) {
    const std::string topic = transport::topic_names::navigation(plugin);
    w.navigation.emplace(
        transport::make_writer<topics::Navigation>(participant_, topic, transport::default_qos_for_topic(topic)));
  }
}

void EstimatePublication::publish(const Estimate& e, const std::string& tool_id) {
  const std::string tool = tool_id.empty() ? "unknown" : tool_id;
  Writers& w = writers_.at(e.estimator);
  w.attitude->write(components::to_topic(e, tool));
  if (w.navigation) w.navigation->write(components::to_navigation(e, tool));
}

void EstimatePublication::retire(const std::string& plugin) {
  const auto it = writers_.find(plugin);
  if (it == writers_.end()) return;
  retired_[plugin] = {std::chrono::steady_clock::now() + kRetiredWritersKept, std::move(it->second)};
  writers_.erase(it);
}

void EstimatePublication::sweep() {
  const auto now = std::chrono::steady_clock::now();
  std::erase_if(retired_, [&](const auto& entry) { return entry.second.first < now; });
}

}  // namespace plumb::estimator_component
