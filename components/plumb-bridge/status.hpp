// The bridge's health on plumb/status: counters, state, last error, host.
#pragma once

#include <string>

#include "plumb/bridge/counters.hpp"
#include "plumb/transport/messages.hpp"

namespace plumb::bridge {

topics::ComponentStatus make_status(const Counters& counters, const std::string& state, const std::string& last_error,
                                    const std::string& component = "plumb-bridge");
std::string host_name();

}  // namespace plumb::bridge
