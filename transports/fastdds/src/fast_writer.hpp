// A RawWriter on one Fast DDS DataWriter.
#pragma once

#include <fastdds/dds/publisher/DataWriter.hpp>

#include <chrono>
#include <memory>
#include <mutex>
#include <string>

#include "participant_state.hpp"
#include "type_support.hpp"

namespace plumb::transport::fastdds {

class FastWriter final : public RawWriter {
 public:
  FastWriter(std::shared_ptr<ParticipantState> state, const TypeSupport& type, const std::string& topic, const Qos& qos);
  ~FastWriter() override;

  void write(const void* message) override;
  std::size_t matched_readers() const override;
  bool wait_for_acknowledgments(std::chrono::nanoseconds timeout) override;

 private:
  std::shared_ptr<ParticipantState> state_;
  std::unique_ptr<SampleCodec> codec_;
  std::mutex write_mutex_;  // the codec's sample is shared by concurrent write() calls
  eprosima::fastdds::dds::DataWriter* writer_ = nullptr;
};

}  // namespace plumb::transport::fastdds
