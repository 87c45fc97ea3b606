// The Transport of the Fast DDS plugin.
#pragma once

#include "plumb/transport/transport.hpp"

namespace plumb::transport::fastdds {

class FastTransport final : public Transport {
 public:
  std::string name() const override { return "fastdds"; }
  std::string vendor_version() const override;
  std::unique_ptr<Participant> create_participant(const ParticipantOptions& options) override;
};

}  // namespace plumb::transport::fastdds
