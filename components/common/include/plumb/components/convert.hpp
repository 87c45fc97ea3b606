// Conversions between the math libraries' types and the topic types.
#pragma once

#include <string>

#include "plumb/core/estimate.hpp"
#include "plumb/core/sample.hpp"
#include "plumb/topics/all.hpp"

namespace plumb::components {

topics::SensorSample to_topic(const Sample& s);
Sample from_topic(const topics::SensorSample& s);

// t_end / t_start (s) become window_end_ns / window_start_ns.
topics::Attitude to_topic(const Estimate& e, const std::string& tool_id);
// The inverse, for whoever reads attitude back (surveys, exports); the tool id stays on the message.
Estimate from_topic(const topics::Attitude& a);
// A navigator's estimate (Estimate::navigation) on plumb/navigation/<estimator>.
topics::Navigation to_navigation(const Estimate& e, const std::string& tool_id);
// The measured depth a sample carries (flags::kHasDepth), for plumb/depth.
topics::MeasuredDepth to_depth(const Sample& s, const std::string& tool_id);

topics::Truth to_topic(const TruthSample& t, const std::string& tool_id);

std::int64_t seconds_to_ns(double t);
double ns_to_seconds(std::int64_t ns);

// Cuts a string to an IDL bound (bounded strings reject longer values on write).
std::string bounded(const std::string& s, std::size_t max);

}  // namespace plumb::components
