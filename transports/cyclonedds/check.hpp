// Turns Cyclone DDS return codes into transport::Error with a readable message.
#pragma once

#include <dds/dds.h>

#include <string>
#include <type_traits>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::cyclonedds {

// Throws Error("<what>: <Cyclone's reason>") when rc is negative (an error or an invalid entity).
inline dds_return_t check(dds_return_t rc, const std::string& what) {
  if (rc < 0) throw Error(what + ": " + dds_strretcode(rc));
  return rc;
}

// For hot paths (write, take, wait): the message is only built when there is an error.
template <class Describe>
  requires std::is_invocable_r_v<std::string, Describe>
inline dds_return_t check(dds_return_t rc, Describe&& describe) {
  if (rc < 0) throw Error(describe() + ": " + dds_strretcode(rc));
  return rc;
}

}  // namespace plumb::transport::cyclonedds
