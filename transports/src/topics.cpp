// Looks topic names up in the table generated from idl/ (plumb/topics/names.hpp).
#include <string_view>

#include "plumb/transport/topic_names.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::transport {

namespace {

const topics::TopicEntry* entry_for(std::string_view topic) {
  const topics::TopicEntry* best = nullptr;
  std::size_t best_length = 0;
  for (const auto& e : topics::kTopicTable) {
    const std::string_view name = e.name;
    if (!e.prefix) {
      if (topic == name) return &e;
      continue;
    }
    if (topic.size() > name.size() && topic.starts_with(name) && name.size() > best_length) {
      best = &e;
      best_length = name.size();
    }
  }
  return best;
}

}  // namespace

const TypeSupport* topic_type_for(const std::string& topic) {
  const auto* e = entry_for(topic);
  return e ? e->type : nullptr;
}

Qos default_qos_for_topic(const std::string& topic) {
  const auto* e = entry_for(topic);
  if (e == nullptr) return Qos::attitude();  // reliable, volatile: the safe guess for a name we do not know
  return {e->qos.reliable ? Reliability::Reliable : Reliability::BestEffort,
          e->qos.transient_local ? Durability::TransientLocal : Durability::Volatile,
          e->qos.keep_all ? History::KeepAll : History::KeepLast, e->qos.depth};
}

}  // namespace plumb::transport
