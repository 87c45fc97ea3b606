// plumb's vendor-neutral Qos as a Cyclone DDS QoS object.
#pragma once

#include <dds/dds.h>

#include <memory>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::cyclonedds {

struct QosDeleter {
  void operator()(dds_qos_t* qos) const { dds_delete_qos(qos); }
};
using QosPtr = std::unique_ptr<dds_qos_t, QosDeleter>;

// Reader and writer QoS; always XCDR1, the data representation Fast DDS 2.9 speaks.
QosPtr make_endpoint_qos(const Qos& qos);

}  // namespace plumb::transport::cyclonedds
