#include "endpoints.hpp"

#include <algorithm>
#include <limits>

#include "check.hpp"
#include "conversions.hpp"
#include "entity.hpp"
#include "qos.hpp"

namespace plumb::transport::cyclonedds {

namespace {

template <class T> Entity create_topic(dds_entity_t participant, const std::string& topic) {
  // The descriptor's type name is the scoped IDL name ("plumb::msg::Attitude"), the same string
  // Fast DDS registers, so the two vendors match on it.
  const dds_entity_t handle = dds_create_topic(participant, CType<T>::descriptor(), topic.c_str(), nullptr, nullptr);
  check(handle, "cannot create topic '" + topic + "' of type " + type_name(TopicTraits<T>::type));
  return Entity(handle);
}

template <class T> class Writer final : public RawWriter {
 public:
  Writer(dds_entity_t participant, const std::string& topic, const Qos& qos)
      : topic_name_(topic), topic_(create_topic<T>(participant, topic)) {
    const QosPtr q = make_endpoint_qos(qos);
    const dds_entity_t handle = dds_create_writer(participant, topic_.get(), q.get(), nullptr);
    check(handle, "cannot create a writer on '" + topic + "'");
    writer_ = Entity(handle);
  }

  void write(const void* message) override {
    typename CType<T>::type c{};
    OutgoingBuffers buffers;
    to_c(*static_cast<const T*>(message), c, buffers);
    check(dds_write(writer_.get(), &c), [&] { return "write on '" + topic_name_ + "' failed"; });
  }

  std::size_t matched_readers() const override {
    dds_publication_matched_status_t status{};
    check(dds_get_publication_matched_status(writer_.get(), &status), [&] { return "matched readers of '" + topic_name_ + "'"; });
    return status.current_count;
  }

 private:
  std::string topic_name_;
  Entity topic_;
  Entity writer_;  // declared after topic_: deleted first
};

template <class T> class Reader final : public RawReader {
 public:
  Reader(dds_entity_t participant, const std::string& topic, const Qos& qos, std::function<void()> on_data)
      : topic_name_(topic), topic_(create_topic<T>(participant, topic)) {
    const QosPtr q = make_endpoint_qos(qos);
    dds_listener_t* listener = nullptr;
    if (on_data) {
      on_data_ = std::make_unique<std::function<void()>>(std::move(on_data));
      listener = dds_create_listener(on_data_.get());
      dds_lset_data_available(listener, &Reader::data_available);
    }
    const dds_entity_t handle = dds_create_reader(participant, topic_.get(), q.get(), listener);
    if (listener != nullptr) dds_delete_listener(listener);  // the reader keeps its own copy
    check(handle, "cannot create a reader on '" + topic + "'");
    reader_ = Entity(handle);

    // Any sample in the cache wakes wait(): take() removes what it returns, so this is "unread data".
    const dds_entity_t condition = dds_create_readcondition(reader_.get(), DDS_ANY_STATE);
    check(condition, "cannot create a read condition on '" + topic + "'");
    condition_ = Entity(condition);
    const dds_entity_t waitset = dds_create_waitset(participant);
    check(waitset, "cannot create a waitset for '" + topic + "'");
    waitset_ = Entity(waitset);
    check(dds_waitset_attach(waitset_.get(), condition_.get(), 0), "cannot attach to the waitset of '" + topic + "'");
  }

  bool take(void* message) override {
    // One sample at a time, loaned from Cyclone and returned before the next; samples without
    // data (a writer went away) are dropped on the way.
    for (;;) {
      void* loaned[1] = {nullptr};
      dds_sample_info_t info{};
      const dds_return_t n = dds_take(reader_.get(), loaned, &info, 1, 1);
      check(n, [&] { return "take on '" + topic_name_ + "' failed"; });
      if (n == 0) return false;
      const bool valid = info.valid_data;
      if (valid) {
        try {
          from_c(*static_cast<const typename CType<T>::type*>(loaned[0]), *static_cast<T*>(message));
        } catch (...) {
          dds_return_loan(reader_.get(), loaned, n);
          throw;
        }
      }
      dds_return_loan(reader_.get(), loaned, n);
      if (valid) return true;
    }
  }

  bool wait(std::chrono::nanoseconds timeout) override {
    const auto ns = std::clamp<std::chrono::nanoseconds::rep>(timeout.count(), 0, std::numeric_limits<dds_duration_t>::max());
    const dds_return_t rc = dds_waitset_wait(waitset_.get(), nullptr, 0, ns);
    check(rc, [&] { return "wait on '" + topic_name_ + "' failed"; });
    return rc > 0;
  }

  std::size_t matched_writers() const override {
    dds_subscription_matched_status_t status{};
    check(dds_get_subscription_matched_status(reader_.get(), &status), [&] { return "matched writers of '" + topic_name_ + "'"; });
    return status.current_count;
  }

 private:
  static void data_available(dds_entity_t, void* arg) { (*static_cast<std::function<void()>*>(arg))(); }

  std::string topic_name_;
  std::unique_ptr<std::function<void()>> on_data_;  // outlives reader_, whose listener calls it
  Entity topic_;
  Entity reader_;
  Entity condition_;
  Entity waitset_;
};

template <template <class> class Endpoint, class... Args> auto make_endpoint(TopicType type, Args&&... args) {
  using Base = std::conditional_t<std::is_same_v<Endpoint<topics::Truth>, Writer<topics::Truth>>, RawWriter, RawReader>;
  switch (type) {
    case TopicType::SensorBatch:
      return std::unique_ptr<Base>(new Endpoint<topics::SensorBatch>(std::forward<Args>(args)...));
    case TopicType::Attitude:
      return std::unique_ptr<Base>(new Endpoint<topics::Attitude>(std::forward<Args>(args)...));
    case TopicType::CalibrationCoefficients:
      return std::unique_ptr<Base>(new Endpoint<topics::CalibrationCoefficients>(std::forward<Args>(args)...));
    case TopicType::ComponentStatus:
      return std::unique_ptr<Base>(new Endpoint<topics::ComponentStatus>(std::forward<Args>(args)...));
    case TopicType::Truth:
      return std::unique_ptr<Base>(new Endpoint<topics::Truth>(std::forward<Args>(args)...));
  }
  throw Error("unknown topic type");
}

}  // namespace

std::unique_ptr<RawWriter> make_writer(dds_entity_t participant, TopicType type, const std::string& topic,
                                       const Qos& qos) {
  return make_endpoint<Writer>(type, participant, topic, qos);
}

std::unique_ptr<RawReader> make_reader(dds_entity_t participant, TopicType type, const std::string& topic,
                                       const Qos& qos, std::function<void()> on_data) {
  return make_endpoint<Reader>(type, participant, topic, qos, std::move(on_data));
}

}  // namespace plumb::transport::cyclonedds
