// The strapdown navigator's parameters for the survey's error model (`--error-model auto` on the
// navigator's stations), asked of the estimator host that runs it with the component protocol, as
// `plumb param dump HOST strapdown` does (idl/component.idl).
#pragma once

#include <optional>
#include <string>

#include "plumb/components/cli.hpp"
#include "plumb/survey/navigator_tool_code.hpp"

namespace plumb::survey_component {

struct NavigatorAnswer {
  std::optional<survey::iscwsa::NavigatorParameters> parameters;  // none: no answer, or refused
  std::string said;    // one line: where they came from, or why there are none and what fixes it
  std::string why;     // without them: why there are none, alone
  std::string status;  // without them: the same within plumb/status's 127 characters, the options first
};

// Waits up to `wait_s` for `host`'s answer. Never throws for the network's sake: a secured domain
// that does not let this identity ask, a host that is not there or does not run the plugin, all
// come back as no parameters with the reason.
NavigatorAnswer ask_navigator_parameters(const components::TransportOptions& transport, const std::string& host,
                                         const std::string& plugin, double wait_s);

}  // namespace plumb::survey_component
