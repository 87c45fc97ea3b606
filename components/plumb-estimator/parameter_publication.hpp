// The host's plugins' parameters as they are now, one topic per plugin
// (plumb/component/parameters/HOST/PLUGIN, transient-local): written at start and after every load,
// unload and set, for readers that may not ask (plumb-survey on a secured domain) and for those
// that follow changes (plumb-survey says when the navigator it surveys with was re-tuned).
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "lineup.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::estimator_component {

class ParameterPublication {
 public:
  ParameterPublication(transport::Participant& participant, std::string host);
  // The plugin's parameters as the lineup has them now (a plugin loaded or re-tuned).
  void publish(const Lineup& lineup, const std::string& plugin);
  // The plugin is no longer loaded: said on its topic, with no rows.
  void unloaded(const std::string& plugin);

 private:
  transport::Writer<topics::ComponentParameters>& writer(const std::string& plugin);
  void write(topics::ComponentParameters message);
  transport::Participant& participant_;
  std::string host_;
  std::map<std::string, transport::Writer<topics::ComponentParameters>> writers_;
  std::uint64_t revision_ = 0;
};

}  // namespace plumb::estimator_component
