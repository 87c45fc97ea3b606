// Two or more plugins of one tool side by side: each one's newest estimate against the tool's
// reference plugin (the first by name among those heard from in the last few seconds), computed
// here once for both readers: the page (the "diff" of each estimate's JSON, json.hpp; the page only
// draws it) and Foxglove (one JSON channel per tool and plugin,
// "plumb-display/difference/<tool>/<plugin>"). No DDS, no sockets.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "foxglove_hub.hpp"
#include "plumb/topics/all.hpp"

namespace plumb::display_component {

// One angle: the plugin's minus the reference's (wrapped to (-180, 180] for azimuth and toolface)
// and the two sigmas combined; nullopt when either estimate does not give the angle.
struct AngleDifference {
  double degrees = 0;
  double sd_degrees = 0;
};

struct AttitudeDifference {
  std::string tool, estimator, reference;
  double t = 0;  // the plugin's window end, s
  std::optional<AngleDifference> inclination, azimuth, toolface;
};

class AttitudeDifferences {
 public:
  explicit AttitudeDifferences(double stale_s = 5) : stale_s_(stale_s) {}
  // Keeps `a` as its plugin's newest; returns its difference from the reference, or nullopt when it
  // is the reference (or its tool has one plugin). `rx_s`: when it was received (any clock, seconds).
  // The toolface (at the window's end, turning with the tool) is carried to the reference's window
  // end with the plugin's rpm, and only when the two ends are within 1 s.
  std::optional<AttitudeDifference> update(const topics::Attitude& a, double rx_s);
  // The plugin's estimates of that tool are no more (its topic has no writer): it is nobody's
  // reference from now on.
  void forget(const std::string& tool, const std::string& estimator);

 private:
  struct Newest {
    topics::Attitude attitude;
    double rx_s = 0;
  };
  double stale_s_;
  std::map<std::string, std::map<std::string, Newest>> newest_;  // tool -> plugin -> its newest estimate
};

// The channel's name, its JSON message and its JSON schema.
std::string difference_topic(const std::string& tool, const std::string& estimator);
std::string difference_json(const AttitudeDifference& d);
extern const char* const kDifferenceSchemaName;
std::string difference_schema();

// Each estimate's difference, computed once: returned for the page's JSON and, with a Foxglove hub,
// published on its channel there: advertised at its first difference, unadvertised when the plugin
// has none any more (docs/display.md).
class PluginDifferences {
 public:
  explicit PluginDifferences(FoxgloveHub* hub = nullptr) : hub_(hub) {}
  // `rx_ms`: when the display took it, ms since the epoch (wall_clock_ms()).
  // A plugin that has no difference (it is its tool's reference now: the one it was compared with is
  // gone) loses its channel.
  std::optional<AttitudeDifference> attitude(const topics::Attitude& a, double rx_ms);
  // Its attitude topic has no writer any more (unloaded, its host gone): forgotten, and its channel
  // unadvertised, as every channel of a topic whose last writer is gone.
  void gone(const std::string& tool, const std::string& estimator);

 private:
  FoxgloveHub* hub_;
  AttitudeDifferences differences_;
  void unadvertise(const std::string& tool, const std::string& estimator);
  std::map<std::string, std::uint32_t> channels_;  // topic -> channel id
};

}  // namespace plumb::display_component
