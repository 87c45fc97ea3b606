// plumb's topic names and what follows from a name: its type and QoS. The table is generated from
// the `// @topic` lines of idl/*.idl (plumb/topics/names.hpp); a new topic is declared there.
// Names use '/' as separator; both vendors accept it (ROS 2 topics are "rt/..." on both).
#pragma once

#include <string>

#include "plumb/topics/names.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::transport {

// kSensorRaw, kAttitudePrefix, attitude("<estimator>"), ... (generated).
namespace topic_names = topics::names;

// The type a topic carries by the table: an exact name, else the longest prefix followed by at
// least one character ("plumb/attitude/x" -> Attitude, "plumb/attitude/" -> none); nullptr for a
// name outside the table.
const TypeSupport* topic_type_for(const std::string& topic);

}  // namespace plumb::transport
