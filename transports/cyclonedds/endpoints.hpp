// Cyclone DDS readers and writers behind plumb's RawReader/RawWriter.
#pragma once

#include <dds/dds.h>

#include <functional>
#include <memory>
#include <string>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::cyclonedds {

std::unique_ptr<RawWriter> make_writer(dds_entity_t participant, const TypeSupport& type, const std::string& topic,
                                       const Qos& qos);
std::unique_ptr<RawReader> make_reader(dds_entity_t participant, const TypeSupport& type, const std::string& topic,
                                       const Qos& qos, std::function<void()> on_data);

}  // namespace plumb::transport::cyclonedds
