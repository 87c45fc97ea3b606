// Command-line parameters for several estimators at once, one grammar for every tool: KEY=VALUE
// goes to every selected estimator that declares KEY, PLUGIN.KEY=VALUE to that plugin only, and
// `window` (when given) to every one that has a window.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "plumb/estimator/estimator.hpp"

namespace plumb::estimator {

bool declares_parameter(const Info& info, const std::string& name);

// An assignment may say where it was written, for the messages about it: ORIGIN, the separator,
// then [PLUGIN.]KEY=VALUE (a parameters file's entries carry "FILE:LINE"). A message about such an
// assignment starts with its origin instead of quoting a --param.
inline constexpr char kOriginSeparator = '\x1f';
std::string with_origin(const std::string& origin, const std::string& assignment);

// Where each of an estimator's parameters was written (KEY -> "FILE:LINE"), for assignments that
// carry an origin.
using ParameterOrigins = std::map<std::string, std::string>;

// One Parameters per estimator, in order; a later assignment of a key replaces an earlier one.
// Throws ParameterError for an assignment that is not [PLUGIN.]KEY=VALUE or whose KEY no (such)
// estimator declares (a typo must not pass silently; a close name is suggested). `origins`, if
// given, receives one ParameterOrigins per estimator.
std::vector<Parameters> assign_parameters(const std::vector<Info>& estimators, const std::vector<std::string>& assignments,
                                          std::optional<double> window_s,
                                          std::vector<ParameterOrigins>* origins = nullptr);

// A plugin's message about one of its parameters ("parameter 'KEY': ...") with where that
// parameter was written in front, when it came from a file; the message itself otherwise.
std::string located(const std::string& message, const ParameterOrigins& origins);

}  // namespace plumb::estimator
