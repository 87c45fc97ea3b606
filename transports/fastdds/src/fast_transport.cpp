#include "fast_transport.hpp"

#include <fastrtps/config.h>

#include "fast_participant.hpp"

namespace plumb::transport::fastdds {

std::string FastTransport::vendor_version() const { return "Fast DDS " FASTRTPS_VERSION_STR; }

std::unique_ptr<Participant> FastTransport::create_participant(const ParticipantOptions& options) {
  return std::make_unique<FastParticipant>(options);
}

}  // namespace plumb::transport::fastdds
