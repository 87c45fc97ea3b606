#include "attitude_difference.hpp"

#include <cmath>
#include <memory>

#include "json.hpp"

namespace plumb::display_component {
namespace {

double wrap_180(double d) {
  const double w = std::fmod(std::fmod(d, 360.0) + 540.0, 360.0) - 180.0;
  return w == -180.0 ? 180.0 : w;
}

std::optional<AngleDifference> angle_difference(double own, double own_sd, double ref, double ref_sd, bool valid,
                                                bool circular) {
  if (!valid || !std::isfinite(own) || !std::isfinite(ref)) return std::nullopt;
  const auto sd = [](double s) { return std::isfinite(s) ? s : 0.0; };
  return AngleDifference{circular ? wrap_180(own - ref) : own - ref, std::hypot(sd(own_sd), sd(ref_sd))};
}

Json angle_json(const std::optional<AngleDifference>& d, int decimals) {
  if (!d) return nullptr;
  Json j;
  j["deg"] = json_number(d->degrees, decimals);
  j["sd_deg"] = json_number(d->sd_degrees, decimals);
  return j;
}

}  // namespace

std::optional<AttitudeDifference> AttitudeDifferences::update(const topics::Attitude& a, double rx_s) {
  auto& plugins = newest_[a.tool_id];
  plugins[a.estimator] = {a, rx_s};
  const Newest* reference = nullptr;  // the first fresh plugin by name (the map is ordered by name)
  for (const auto& [name, n] : plugins)
    if (rx_s - n.rx_s <= stale_s_) {
      reference = &n;
      break;
    }
  if (reference == nullptr || reference->attitude.estimator == a.estimator) return std::nullopt;
  const topics::Attitude& r = reference->attitude;
  const std::uint32_t both = a.flags & r.flags;
  AttitudeDifference d;
  d.tool = a.tool_id;
  d.estimator = a.estimator;
  d.reference = r.estimator;
  d.t = static_cast<double>(a.window_end_ns) * 1e-9;
  d.inclination = angle_difference(a.inclination_deg, a.inclination_sd_deg, r.inclination_deg, r.inclination_sd_deg,
                                   both & topics::ATTITUDE_VALID, false);
  d.azimuth = angle_difference(a.azimuth_deg, a.azimuth_sd_deg, r.azimuth_deg, r.azimuth_sd_deg,
                               both & topics::ATTITUDE_AZIMUTH_VALID, true);
  const double gap_s = static_cast<double>(r.window_end_ns - a.window_end_ns) * 1e-9;
  if (std::abs(gap_s) <= 1 && (gap_s == 0 || std::isfinite(a.rpm)))
    d.toolface = angle_difference(a.gravity_toolface_deg + (gap_s == 0 ? 0 : 6 * a.rpm * gap_s), a.toolface_sd_deg,
                                  r.gravity_toolface_deg, r.toolface_sd_deg, both & topics::ATTITUDE_TOOLFACE_VALID, true);
  return d;
}

void AttitudeDifferences::forget(const std::string& tool, const std::string& estimator) {
  const auto it = newest_.find(tool);
  if (it == newest_.end()) return;
  it->second.erase(estimator);
  if (it->second.empty()) newest_.erase(it);
}

std::string difference_topic(const std::string& tool, const std::string& estimator) {
  return "plumb-display/difference/" + (tool.empty() ? std::string("unknown") : tool) + "/" + estimator;
}

const char* const kDifferenceSchemaName = "plumb.display.AttitudeDifference";

std::string difference_schema() {
  const Json angle = {{"type", {"object", "null"}},
                      {"properties", {{"deg", {{"type", "number"}}}, {"sd_deg", {{"type", "number"}}}}}};
  Json j;
  j["title"] = kDifferenceSchemaName;
  j["description"] = "a plugin's estimate minus its tool's reference plugin's (plumb-display, docs/display.md)";
  j["type"] = "object";
  j["properties"] = {{"tool", {{"type", "string"}}},        {"estimator", {{"type", "string"}}},
                     {"reference", {{"type", "string"}}},   {"t", {{"type", "number"}}},
                     {"inclination", angle},                {"azimuth", angle},
                     {"toolface", angle}};
  return json_text(j);
}

std::string difference_json(const AttitudeDifference& d) {
  Json j;
  j["tool"] = d.tool;
  j["estimator"] = d.estimator;
  j["reference"] = d.reference;
  j["t"] = json_number(d.t, 6);
  j["inclination"] = angle_json(d.inclination, 4);
  j["azimuth"] = angle_json(d.azimuth, 3);
  j["toolface"] = angle_json(d.toolface, 2);
  return json_text(j);
}

std::optional<AttitudeDifference> PluginDifferences::attitude(const topics::Attitude& a, double rx_ms) {
  const std::optional<AttitudeDifference> d = differences_.update(a, rx_ms * 1e-3);
  if (!d) unadvertise(a.tool_id, a.estimator);
  if (!d || hub_ == nullptr) return d;
  const std::string topic = difference_topic(d->tool, d->estimator);
  auto channel = channels_.find(topic);
  if (channel == channels_.end())
    channel = channels_.emplace(topic, hub_->advertise(topic, kDifferenceSchemaName, difference_schema(), "json", "jsonschema"))
                  .first;
  const std::string text = difference_json(*d);
  hub_->publish(channel->second, static_cast<std::uint64_t>(rx_ms * 1e6),
                std::make_shared<const std::vector<std::uint8_t>>(text.begin(), text.end()));
  return d;
}

void PluginDifferences::gone(const std::string& tool, const std::string& estimator) {
  differences_.forget(tool, estimator);
  unadvertise(tool, estimator);
}

void PluginDifferences::unadvertise(const std::string& tool, const std::string& estimator) {
  if (hub_ == nullptr || channels_.erase(difference_topic(tool, estimator)) == 0) return;
  hub_->unadvertise(difference_topic(tool, estimator));
}

}  // namespace plumb::display_component
