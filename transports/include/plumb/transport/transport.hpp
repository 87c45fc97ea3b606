// The vendor-neutral transport interface: everything above transports/ talks DDS through this
// file only. A transport plugin (libplumb_transport_<name>.so) implements Transport; the loader
// (loader.hpp) picks one at run time by name, the way ROS 2 picks its rmw implementation.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "plumb/transport/messages.hpp"

namespace plumb::transport {

// Every failure of a transport (bad argument, vendor refused to start, ...) is reported as this.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class TopicType { SensorBatch, Attitude, CalibrationCoefficients, ComponentStatus, Truth };

// The IDL scoped name of a topic type ("plumb::msg::Attitude"), identical on both vendors.
const char* type_name(TopicType type);

template <class T> struct TopicTraits;
template <> struct TopicTraits<topics::SensorBatch> { static constexpr TopicType type = TopicType::SensorBatch; };
template <> struct TopicTraits<topics::Attitude> { static constexpr TopicType type = TopicType::Attitude; };
template <> struct TopicTraits<topics::CalibrationCoefficients> { static constexpr TopicType type = TopicType::CalibrationCoefficients; };
template <> struct TopicTraits<topics::ComponentStatus> { static constexpr TopicType type = TopicType::ComponentStatus; };
template <> struct TopicTraits<topics::Truth> { static constexpr TopicType type = TopicType::Truth; };

enum class Reliability { BestEffort, Reliable };
enum class Durability { Volatile, TransientLocal };
enum class History { KeepLast, KeepAll };

struct Qos {
  Reliability reliability = Reliability::Reliable;
  Durability durability = Durability::Volatile;
  History history = History::KeepLast;
  std::int32_t depth = 64;  // KeepLast depth

  // The profiles every plumb component uses (see README "Topics").
  static Qos sensor_stream() { return {Reliability::BestEffort, Durability::Volatile, History::KeepLast, 64}; }
  // Sensor stream for runs where nothing may be lost (bridge --reliable, tests that count sequence numbers).
  static Qos reliable_stream() { return {Reliability::Reliable, Durability::Volatile, History::KeepLast, 4096}; }
  static Qos attitude() { return {Reliability::Reliable, Durability::Volatile, History::KeepLast, 64}; }
  static Qos status() { return {Reliability::Reliable, Durability::Volatile, History::KeepLast, 16}; }
  // Calibration: kept by the writer for late joiners.
  static Qos calibration() { return {Reliability::Reliable, Durability::TransientLocal, History::KeepLast, 1}; }
};

// The standard QoS of a well-known plumb topic name (falls back to reliable).
Qos default_qos_for_topic(const std::string& topic);

struct ParticipantOptions {
  int domain_id = 0;  // 0..232
  // Network interface to use: a name ("eth1") or an IPv4 address of this host. Empty means
  // loopback only, the safe default for one computer; set it to run across computers.
  std::string interface;
  std::string name = "plumb";  // participant name, shows up in discovery
};

class RawWriter {
 public:
  virtual ~RawWriter() = default;
  // `message` points to the topics:: type matching the writer's TopicType.
  virtual void write(const void* message) = 0;
  virtual std::size_t matched_readers() const = 0;
};

class RawReader {
 public:
  virtual ~RawReader() = default;
  // Takes the oldest unread message into `message` (the matching topics:: type); false when none.
  virtual bool take(void* message) = 0;
  // Blocks until data may be available or the timeout passes; true if data arrived.
  virtual bool wait(std::chrono::nanoseconds timeout) = 0;
  virtual std::size_t matched_writers() const = 0;
};

struct DiscoveredTopic {
  std::string name;
  std::string type_name;
  std::size_t writers = 0;
  std::size_t readers = 0;
};

class Participant {
 public:
  virtual ~Participant() = default;
  // `on_data` (optional) is called from a vendor thread when data may be available; it must be
  // quick and must not destroy the reader.
  virtual std::unique_ptr<RawWriter> create_writer(TopicType type, const std::string& topic, const Qos& qos) = 0;
  virtual std::unique_ptr<RawReader> create_reader(TopicType type, const std::string& topic, const Qos& qos,
                                                   std::function<void()> on_data = {}) = 0;
  // Topics seen through discovery so far (other participants' and our own).
  virtual std::vector<DiscoveredTopic> discovered_topics() = 0;
};

class Transport {
 public:
  virtual ~Transport() = default;
  virtual std::string name() const = 0;            // "fastdds" or "cyclonedds"
  virtual std::string vendor_version() const = 0;  // e.g. "Fast DDS 2.9.1"
  virtual std::unique_ptr<Participant> create_participant(const ParticipantOptions& options) = 0;
};

// Typed wrappers over the raw interface.
template <class T> class Writer {
 public:
  explicit Writer(std::unique_ptr<RawWriter> raw) : raw_(std::move(raw)) {}
  void write(const T& message) { raw_->write(&message); }
  std::size_t matched_readers() const { return raw_->matched_readers(); }

 private:
  std::unique_ptr<RawWriter> raw_;
};

template <class T> class Reader {
 public:
  explicit Reader(std::unique_ptr<RawReader> raw) : raw_(std::move(raw)) {}
  bool take(T& message) { return raw_->take(&message); }
  bool wait(std::chrono::nanoseconds timeout) { return raw_->wait(timeout); }
  std::size_t matched_writers() const { return raw_->matched_writers(); }

 private:
  std::unique_ptr<RawReader> raw_;
};

template <class T> Writer<T> make_writer(Participant& p, const std::string& topic, const Qos& qos) {
  return Writer<T>(p.create_writer(TopicTraits<T>::type, topic, qos));
}
template <class T> Reader<T> make_reader(Participant& p, const std::string& topic, const Qos& qos,
                                         std::function<void()> on_data = {}) {
  return Reader<T>(p.create_reader(TopicTraits<T>::type, topic, qos, std::move(on_data)));
}

}  // namespace plumb::transport
