// The strapdown navigator's parameters for the survey's error model (`--error-model auto` on the
// navigator's stations), read from the topic on which the estimator host that runs it writes them
// (plumb/component/parameters/HOST/PLUGIN, idl/component.idl): read, not asked, so that an identity
// that may not send requests (a secured domain) gets them too, and a later change (plumb param
// set) is seen.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "plumb/components/cli.hpp"
#include "plumb/survey/navigator_tool_code.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::survey_component {

struct NavigatorAnswer {
  std::optional<survey::iscwsa::NavigatorParameters> parameters;  // none: not written, or unloaded
  std::string said;    // one line: where they came from, or why there are none and what fixes it
  std::string why;     // without them: why there are none, alone
  std::string status;  // without them: the same within plumb/status's 127 characters, the options first
};

// Its reader is the connection's participant's: it must go before the participant does.
class NavigatorParameterWatch {
 public:
  NavigatorParameterWatch(const components::Connection& conn, std::string host, std::string plugin);
  // The host's parameters as written now, waiting up to `wait_s` for them. Never throws for the
  // network's sake: a host that is not there or does not run the plugin, an identity that may not
  // read the topic, come back as no parameters with the reason.
  NavigatorAnswer first(double wait_s);
  // What the host wrote since the parameters last taken (once per change), or nothing: what
  // changed, and the parameters now (none: the plugin was unloaded). The new ones are taken.
  struct Change {
    std::string said;  // "the strapdown navigator's parameters on estimator host 'H' changed (a 1 -> 2)"
    std::optional<survey::iscwsa::NavigatorParameters> now;
  };
  std::optional<Change> change();

 private:
  std::string where_;  // "domain 7 (cyclonedds)", for messages
  bool secured_;
  std::string host_, plugin_, topic_;
  std::optional<transport::Reader<topics::ComponentParameters>> reader_;
  std::string refused_;  // why there is no reader (an identity not granted the topic)
  std::optional<survey::iscwsa::NavigatorParameters> taken_;  // what first() or the last change() returned
  std::uint64_t seen_revision_ = 0;
};

}  // namespace plumb::survey_component
