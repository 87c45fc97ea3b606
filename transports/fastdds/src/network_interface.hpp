// Resolves ParticipantOptions::interface ("eth1" or "192.168.1.5") to an IPv4 address of this host.
#pragma once

#include <string>

namespace plumb::transport::fastdds {

inline constexpr const char* kLoopbackAddress = "127.0.0.1";

// The IPv4 address of the named interface, or the address itself if this host has it; "" resolves
// to the loopback address. Throws Error naming the available interfaces otherwise.
std::string resolve_ipv4_interface(const std::string& name_or_address);

bool is_loopback_address(const std::string& ipv4);

}  // namespace plumb::transport::fastdds
