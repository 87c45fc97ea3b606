#include "truth_lookup.hpp"

#include <cmath>

#include "plumb/transport/topic_names.hpp"

namespace plumb::estimator_component {

TruthLookup::TruthLookup(transport::Participant& participant, const std::string& topic)
    : reader_(transport::make_reader<topics::Truth>(participant, topic, transport::default_qos_for_topic(topic))) {}

void TruthLookup::update() {
  topics::Truth t;
  while (reader_.take(t)) {
    recent_.push_back(t);
    if (recent_.size() > 4096) recent_.pop_front();
  }
}

std::optional<topics::Truth> TruthLookup::at(double t_s) const {
  const double t_ns = t_s * 1e9;
  const topics::Truth* best = nullptr;
  for (const auto& t : recent_)
    if (!best || std::abs(static_cast<double>(t.stamp_ns) - t_ns) < std::abs(static_cast<double>(best->stamp_ns) - t_ns))
      best = &t;
  if (!best || std::abs(static_cast<double>(best->stamp_ns) - t_ns) > 1e9) return std::nullopt;
  return *best;
}

}  // namespace plumb::estimator_component
