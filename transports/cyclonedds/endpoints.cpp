#include "endpoints.hpp"

#include <algorithm>
#include <limits>

#include "check.hpp"
#include "entity.hpp"
#include "qos.hpp"
#include "type_support.hpp"

namespace plumb::transport::cyclonedds {

namespace {

Entity create_topic(dds_entity_t participant, const CycloneTypeSupport& type, const std::string& topic) {
  // The descriptor's type name is the scoped IDL name ("plumb::msg::Attitude"), the same string
  // Fast DDS registers, so the two vendors match on it.
  const dds_entity_t handle = dds_create_topic(participant, type.descriptor, topic.c_str(), nullptr, nullptr);
  check(handle, "cannot create topic '" + topic + "' of type " + type.type->type_name);
  return Entity(handle);
}

class Writer final : public RawWriter {
 public:
  Writer(dds_entity_t participant, const CycloneTypeSupport& type, const std::string& topic, const Qos& qos)
      : type_(type), topic_name_(topic), topic_(create_topic(participant, type, topic)) {
    const QosPtr q = make_endpoint_qos(qos);
    const dds_entity_t handle = dds_create_writer(participant, topic_.get(), q.get(), nullptr);
    check(handle, "cannot create a writer on '" + topic + "'");
    writer_ = Entity(handle);
  }

  void write(const void* message) override {
    check(type_.write(writer_.get(), message), [&] { return "write on '" + topic_name_ + "' failed"; });
  }

  std::size_t matched_readers() const override {
    dds_publication_matched_status_t status{};
    check(dds_get_publication_matched_status(writer_.get(), &status), [&] { return "matched readers of '" + topic_name_ + "'"; });
    return status.current_count;
  }

  bool wait_for_acknowledgments(std::chrono::nanoseconds timeout) override {
    const auto ns = std::clamp<std::chrono::nanoseconds::rep>(timeout.count(), 0, std::numeric_limits<dds_duration_t>::max());
    return dds_wait_for_acks(writer_.get(), static_cast<dds_duration_t>(ns)) == DDS_RETCODE_OK;
  }

 private:
  const CycloneTypeSupport& type_;
  std::string topic_name_;
  Entity topic_;
  Entity writer_;  // declared after topic_: deleted first
};

class Reader final : public RawReader {
 public:
  Reader(dds_entity_t participant, const CycloneTypeSupport& type, const std::string& topic, const Qos& qos,
         std::function<void()> on_data)
      : type_(type), topic_name_(topic), topic_(create_topic(participant, type, topic)) {
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

  bool take(void* message) override { return take_loaned(1, [&](std::size_t) { return message; }) == 1; }

  std::size_t take(std::size_t max, TakeTarget target) override {
    return take_loaned(max, [&](std::size_t i) { return target.slot(target.context, i); });
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
  // Samples per dds_take: the loans of one call are arrays on the stack.
  static constexpr std::size_t kLoansPerTake = 64;

  // Takes up to `max` valid samples with Cyclone's multi-sample take, loaned (no copy into a
  // sample of ours: each is converted straight from Cyclone's buffer into slot(i)) and returned
  // after each call. Samples without data (a writer went away) are dropped on the way.
  template <class Slot> std::size_t take_loaned(std::size_t max, Slot&& slot) {
    std::size_t filled = 0;
    while (filled < max) {
      void* loaned[kLoansPerTake] = {};
      dds_sample_info_t infos[kLoansPerTake];
      const std::size_t wanted = std::min(max - filled, kLoansPerTake);
      const dds_return_t n = dds_take(reader_.get(), loaned, infos, wanted, static_cast<uint32_t>(wanted));
      check(n, [&] { return "take on '" + topic_name_ + "' failed"; });
      if (n == 0) break;
      try {
        for (dds_return_t i = 0; i < n; ++i) {
          if (infos[i].valid_data) type_.read(loaned[i], slot(filled++));
        }
      } catch (...) {
        dds_return_loan(reader_.get(), loaned, n);
        throw;
      }
      dds_return_loan(reader_.get(), loaned, n);
      if (static_cast<std::size_t>(n) < wanted) break;  // the cache is empty
    }
    return filled;
  }

  static void data_available(dds_entity_t, void* arg) { (*static_cast<std::function<void()>*>(arg))(); }

  const CycloneTypeSupport& type_;
  std::string topic_name_;
  std::unique_ptr<std::function<void()>> on_data_;  // outlives reader_, whose listener calls it
  Entity topic_;
  Entity reader_;
  Entity condition_;
  Entity waitset_;
};

}  // namespace

std::unique_ptr<RawWriter> make_writer(dds_entity_t participant, const TypeSupport& type, const std::string& topic,
                                       const Qos& qos) {
  return std::make_unique<Writer>(participant, find_type(type), topic, qos);
}

std::unique_ptr<RawReader> make_reader(dds_entity_t participant, const TypeSupport& type, const std::string& topic,
                                       const Qos& qos, std::function<void()> on_data) {
  return std::make_unique<Reader>(participant, find_type(type), topic, qos, std::move(on_data));
}

}  // namespace plumb::transport::cyclonedds
