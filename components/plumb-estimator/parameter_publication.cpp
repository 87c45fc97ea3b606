#include "parameter_publication.hpp"

#include <utility>

#include "plumb/components/topic_safe.hpp"

namespace plumb::estimator_component {

ParameterPublication::ParameterPublication(transport::Participant& participant, std::string host)
    : participant_(participant), host_(std::move(host)) {}

transport::Writer<topics::ComponentParameters>& ParameterPublication::writer(const std::string& plugin) {
  auto it = writers_.find(plugin);
  if (it == writers_.end()) {
    const std::string topic = components::parameters_topic(host_, plugin);
    it = writers_
             .emplace(plugin, transport::make_writer<topics::ComponentParameters>(
                                  participant_, topic, transport::default_qos_for_topic(topic)))
             .first;
  }
  return it->second;
}

void ParameterPublication::write(topics::ComponentParameters message) {
  message.host = host_;
  message.revision = ++revision_;
  writer(message.plugin).write(message);
}

void ParameterPublication::publish(const Lineup& lineup, const std::string& plugin) {
  topics::ComponentParameters message;
  message.plugin = plugin;
  message.loaded = true;
  for (const auto& v : lineup.dump(plugin)) {
    if (message.rows.size() == topics::ComponentParameters::kRowsMax) break;
    message.rows.push_back({v.plugin, v.name, v.value, v.default_value});
  }
  write(std::move(message));
}

void ParameterPublication::unloaded(const std::string& plugin) {
  topics::ComponentParameters message;
  message.plugin = plugin;
  message.loaded = false;
  write(std::move(message));
}

}  // namespace plumb::estimator_component
