#include "type_support.hpp"

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/topic/Topic.hpp>

#include "conversions.hpp"
#include "plumb_idl/attitudePubSubTypes.h"
#include "plumb_idl/calibrationPubSubTypes.h"
#include "plumb_idl/sensorPubSubTypes.h"
#include "plumb_idl/statusPubSubTypes.h"
#include "plumb_idl/truthPubSubTypes.h"

namespace plumb::transport::fastdds {
namespace {

namespace dds = eprosima::fastdds::dds;

template <class Plumb, class Fast> class Codec final : public SampleCodec {
 public:
  void write(dds::DataWriter& writer, const void* message) override {
    to_fast(*static_cast<const Plumb*>(message), sample_);
    if (!writer.write(&sample_)) {
      throw Error("Fast DDS refused to write on topic " + writer.get_topic()->get_name());
    }
  }

  bool take(dds::DataReader& reader, void* message) override {
    dds::SampleInfo info;
    while (reader.take_next_sample(&sample_, &info) == ReturnCode_t::RETCODE_OK) {
      if (info.valid_data) {
        from_fast(sample_, *static_cast<Plumb*>(message));
        return true;
      }
    }
    return false;
  }

 private:
  Fast sample_;  // reused: the generated classes allocate their sequences once
};

}  // namespace

dds::TypeSupport make_type_support(TopicType type) {
  switch (type) {
    case TopicType::SensorBatch: return dds::TypeSupport(new plumb::msg::SensorBatchPubSubType());
    case TopicType::Attitude: return dds::TypeSupport(new plumb::msg::AttitudePubSubType());
    case TopicType::CalibrationCoefficients: return dds::TypeSupport(new plumb::msg::CalibrationCoefficientsPubSubType());
    case TopicType::ComponentStatus: return dds::TypeSupport(new plumb::msg::ComponentStatusPubSubType());
    case TopicType::Truth: return dds::TypeSupport(new plumb::msg::TruthPubSubType());
  }
  throw Error("unknown topic type");
}

std::unique_ptr<SampleCodec> make_codec(TopicType type) {
  switch (type) {
    case TopicType::SensorBatch: return std::make_unique<Codec<topics::SensorBatch, plumb::msg::SensorBatch>>();
    case TopicType::Attitude: return std::make_unique<Codec<topics::Attitude, plumb::msg::Attitude>>();
    case TopicType::CalibrationCoefficients:
      return std::make_unique<Codec<topics::CalibrationCoefficients, plumb::msg::CalibrationCoefficients>>();
    case TopicType::ComponentStatus: return std::make_unique<Codec<topics::ComponentStatus, plumb::msg::ComponentStatus>>();
    case TopicType::Truth: return std::make_unique<Codec<topics::Truth, plumb::msg::Truth>>();
  }
  throw Error("unknown topic type");
}

}  // namespace plumb::transport::fastdds
