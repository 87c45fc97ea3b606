#include "component_service.hpp"

#include "plumb/transport/topic_names.hpp"

namespace plumb::estimator_component {

namespace names = transport::topic_names;

ComponentService::ComponentService(transport::Participant& participant, std::string host_name)
    : name_(std::move(host_name)),
      requests_(transport::make_reader<topics::ComponentRequest>(participant, names::kComponentRequest,
                                                                 transport::default_qos_for_topic(names::kComponentRequest))),
      replies_(transport::make_writer<topics::ComponentReply>(participant, names::kComponentReply,
                                                               transport::default_qos_for_topic(names::kComponentReply))) {}

std::vector<topics::ComponentRequest> ComponentService::take() {
  std::vector<topics::ComponentRequest> out;
  topics::ComponentRequest r;
  while (requests_.take(r)) {
    const bool mine = r.host == name_ || (r.host.empty() && r.verb == "list");
    if (!mine) continue;
    if (const auto seen = last_.find(r.client); seen != last_.end() && r.request_id <= seen->second.first) {
      if (r.request_id == seen->second.first) replies_.write(seen->second.second);  // its answer was missed
      continue;
    }
    out.push_back(r);
  }
  return out;
}

void ComponentService::answer(const topics::ComponentRequest& request, topics::ComponentReply reply) {
  reply.host = name_;
  reply.client = request.client;
  reply.request_id = request.request_id;
  if (reply.message.size() > topics::ComponentReply::kMessageMax)
    reply.message.resize(topics::ComponentReply::kMessageMax);
  replies_.write(reply);
  ++answered_;
  if (reply.result != topics::COMPONENT_DONE) ++refused_;
  if (last_.insert_or_assign(request.client, std::pair{request.request_id, std::move(reply)}).second)
    order_.push_back(request.client);
  if (order_.size() > kKeptClients) {
    last_.erase(order_.front());
    order_.pop_front();
  }
}

}  // namespace plumb::estimator_component
