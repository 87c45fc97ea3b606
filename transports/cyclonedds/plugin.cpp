// Entry point of libplumb_transport_cyclonedds.so: the Transport the loader asks for by name.
#include <dds/version.h>

#include "participant.hpp"
#include "plumb/transport/loader.hpp"

namespace plumb::transport::cyclonedds {

namespace {

class CycloneTransport final : public Transport {
 public:
  std::string name() const override { return "cyclonedds"; }
  std::string vendor_version() const override { return std::string("Cyclone DDS ") + DDS_VERSION; }
  std::unique_ptr<Participant> create_participant(const ParticipantOptions& options) override {
    return make_participant(options);
  }
};

}  // namespace

}  // namespace plumb::transport::cyclonedds

PLUMB_TRANSPORT_PLUGIN(plumb::transport::cyclonedds::CycloneTransport)
