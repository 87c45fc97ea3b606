// The Cyclone DDS configuration of one domain, built in code so that nothing depends on
// CYCLONEDDS_URI or a file on disk.
#pragma once

#include <string>

namespace plumb::transport::cyclonedds {

// XML configuration for dds_create_domain. An empty `interface` keeps all traffic on loopback
// (127.0.0.1, unicast discovery, since `lo` has no multicast); otherwise the named interface
// ("eth1") or the interface holding that IPv4 address is used, with multicast discovery.
// Throws Error naming the available interfaces when `interface` is not one of this host's.
std::string domain_config(const std::string& interface);

}  // namespace plumb::transport::cyclonedds
