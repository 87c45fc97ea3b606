// A Cyclone DDS domain participant behind plumb's Participant.
#pragma once

#include <memory>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::cyclonedds {

// Throws Error for a domain id outside 0..232, a bad interface or a vendor failure.
std::unique_ptr<Participant> make_participant(const ParticipantOptions& options);

}  // namespace plumb::transport::cyclonedds
