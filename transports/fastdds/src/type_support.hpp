// What differs between topic types on Fast DDS, behind one interface so that the writer, reader and
// participant code is written once: the generated TypeSupport, and a codec that owns one generated
// sample and converts through it on write and take.
#pragma once

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <memory>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::fastdds {

class SampleCodec {
 public:
  virtual ~SampleCodec() = default;
  // Converts the topics:: message at `message` and writes it; throws Error if it cannot be sent.
  virtual void write(eprosima::fastdds::dds::DataWriter& writer, const void* message) = 0;
  // Takes the next valid sample (skipping disposal/unregistration notices) into `message`.
  virtual bool take(eprosima::fastdds::dds::DataReader& reader, void* message) = 0;
};

eprosima::fastdds::dds::TypeSupport make_type_support(TopicType type);
std::unique_ptr<SampleCodec> make_codec(TopicType type);

}  // namespace plumb::transport::fastdds
