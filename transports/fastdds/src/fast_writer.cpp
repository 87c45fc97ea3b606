#include "fast_writer.hpp"

#include "qos.hpp"

#include <algorithm>
#include <cstdint>

namespace plumb::transport::fastdds {

namespace dds = eprosima::fastdds::dds;

FastWriter::FastWriter(std::shared_ptr<ParticipantState> state, const TypeSupport& type, const std::string& topic, const Qos& qos)
    : state_(std::move(state)), codec_(find_type(type).make_codec()) {
  const dds::DataWriterQos writer_qos_value = writer_qos(qos);
  std::lock_guard lock(state_->entity_mutex());
  dds::Topic* dds_topic = state_->topic(type, topic);
  writer_ = state_->publisher().create_datawriter(dds_topic, writer_qos_value, nullptr, dds::StatusMask::none());
  if (writer_ == nullptr) throw Error("Fast DDS could not create a writer on topic " + topic);
  state_->discovery().add(writer_->guid(), topic, dds_topic->get_type_name(), true);
}

FastWriter::~FastWriter() {
  std::lock_guard lock(state_->entity_mutex());
  state_->discovery().remove(writer_->guid());
  state_->publisher().delete_datawriter(writer_);
}

void FastWriter::write(const void* message) {
  std::lock_guard lock(write_mutex_);
  codec_->write(*writer_, message);
}

std::size_t FastWriter::matched_readers() const {
  dds::PublicationMatchedStatus status;
  writer_->get_publication_matched_status(status);
  return static_cast<std::size_t>(status.current_count);
}

bool FastWriter::wait_for_acknowledgments(std::chrono::nanoseconds timeout) {
  const auto ns = std::max<std::chrono::nanoseconds::rep>(timeout.count(), 0);
  const eprosima::fastrtps::Duration_t wait(static_cast<std::int32_t>(ns / 1000000000),
                                            static_cast<std::uint32_t>(ns % 1000000000));
  return writer_->wait_for_acknowledgments(wait) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK;
}

}  // namespace plumb::transport::fastdds
