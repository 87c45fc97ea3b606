// DDS Security for Cyclone DDS: the participant QoS properties that load its security plugins.
#pragma once

#include <dds/dds.h>

#include "plumb/transport/security.hpp"

namespace plumb::transport::cyclonedds {

// Sets the dds.sec.* properties on `qos` for the checked `files`. Throws Error when Cyclone's
// security plugins (libdds_security_{auth,ac,crypto}.so) are not installed: never unsecured.
void add_security(dds_qos_t* qos, const SecurityFiles& files);

}  // namespace plumb::transport::cyclonedds
