#include "fast_reader.hpp"

#include "qos.hpp"

namespace plumb::transport::fastdds {

namespace dds = eprosima::fastdds::dds;

FastReader::FastReader(std::shared_ptr<ParticipantState> state, const TypeSupport& type, const std::string& topic, const Qos& qos,
                       std::function<void()> on_data)
    : state_(std::move(state)), codec_(find_type(type).make_codec()) {
  const dds::DataReaderQos reader_qos_value = reader_qos(qos);
  dds::StatusMask mask = dds::StatusMask::none();
  if (on_data) {
    listener_ = std::make_unique<Listener>(std::move(on_data));
    mask = dds::StatusMask::data_available();
  }
  std::lock_guard lock(state_->entity_mutex());
  dds::Topic* dds_topic = state_->topic(type, topic);
  reader_ = state_->subscriber().create_datareader(dds_topic, reader_qos_value, listener_.get(), mask);
  if (reader_ == nullptr) throw Error("Fast DDS could not create a reader on topic " + topic);
  state_->discovery().add(reader_->guid(), topic, dds_topic->get_type_name(), false);
}

FastReader::~FastReader() {
  std::lock_guard lock(state_->entity_mutex());
  state_->discovery().remove(reader_->guid());
  // Stop callbacks first, so none runs into a half-deleted reader.
  reader_->set_listener(nullptr);
  state_->subscriber().delete_datareader(reader_);
}

bool FastReader::take(void* message) {
  std::lock_guard lock(take_mutex_);
  return codec_->take(*reader_, message);
}

std::size_t FastReader::take(std::size_t max, TakeTarget target) {
  std::lock_guard lock(take_mutex_);
  return codec_->take(*reader_, max, target);
}

bool FastReader::wait(std::chrono::nanoseconds timeout) {
  if (timeout.count() < 0) timeout = std::chrono::nanoseconds(0);
  const auto seconds = std::chrono::duration_cast<std::chrono::seconds>(timeout);
  const eprosima::fastrtps::Duration_t duration(static_cast<std::int32_t>(std::min<std::int64_t>(seconds.count(), INT32_MAX)),
                                                static_cast<std::uint32_t>((timeout - seconds).count()));
  return reader_->wait_for_unread_message(duration);
}

std::size_t FastReader::matched_writers() const {
  dds::SubscriptionMatchedStatus status;
  reader_->get_subscription_matched_status(status);
  return static_cast<std::size_t>(status.current_count);
}

}  // namespace plumb::transport::fastdds
