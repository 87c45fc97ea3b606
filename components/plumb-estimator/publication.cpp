#include "publication.hpp"

#include "plumb/components/convert.hpp"
#include "plumb/transport/topic_names.hpp"

namespace plumb::estimator_component {

void EstimatePublication::add(const std::string& plugin, bool navigator) {
  attitude_.emplace(plugin, transport::make_writer<topics::Attitude>(
                                participant_, transport::topic_names::attitude(plugin), transport::Qos::attitude()));
  if (navigator) {
    const std::string topic = transport::topic_names::navigation(plugin);
    navigation_.emplace(plugin, transport::make_writer<topics::Navigation>(participant_, topic,
                                                                           transport::default_qos_for_topic(topic)));
  }
}

void EstimatePublication::publish(const Estimate& e, const std::string& tool_id) {
  const std::string tool = tool_id.empty() ? "unknown" : tool_id;
  attitude_.at(e.estimator).write(components::to_topic(e, tool));
  if (const auto nav = navigation_.find(e.estimator); nav != navigation_.end()) nav->second.write(components::to_navigation(e, tool));
}

}  // namespace plumb::estimator_component
