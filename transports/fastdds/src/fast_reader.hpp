// A RawReader on one Fast DDS DataReader. Its listener forwards "data available" to the user's
// on_data callback.
#pragma once

#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>

#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "participant_state.hpp"
#include "type_support.hpp"

namespace plumb::transport::fastdds {

class FastReader final : public RawReader {
 public:
  FastReader(std::shared_ptr<ParticipantState> state, const TypeSupport& type, const std::string& topic, const Qos& qos,
             std::function<void()> on_data);
  ~FastReader() override;

  bool take(void* message) override;
  std::size_t take(std::size_t max, TakeTarget target) override;
  bool wait(std::chrono::nanoseconds timeout) override;
  std::size_t matched_writers() const override;

 private:
  class Listener final : public eprosima::fastdds::dds::DataReaderListener {
   public:
    explicit Listener(std::function<void()> on_data) : on_data_(std::move(on_data)) {}
    void on_data_available(eprosima::fastdds::dds::DataReader*) override { on_data_(); }

   private:
    std::function<void()> on_data_;
  };

  std::shared_ptr<ParticipantState> state_;
  std::unique_ptr<SampleCodec> codec_;
  std::unique_ptr<Listener> listener_;  // outlives reader_, which is deleted in the destructor body
  std::mutex take_mutex_;               // the codec's samples are shared by concurrent take() calls
  eprosima::fastdds::dds::DataReader* reader_ = nullptr;
};

}  // namespace plumb::transport::fastdds
