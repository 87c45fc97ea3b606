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

#include "plumb/topics/all.hpp"

namespace plumb::transport {

// Every failure of a transport (bad argument, vendor refused to start, ...) is reported as this.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Names a topic type to a transport: generated from idl/ for every struct (plumb/topics/*.hpp);
// topics::type_support<T>() gives the one of plumb::topics::T. Its type_name is the scoped IDL name
// ("plumb::msg::Attitude"), identical on both vendors.
using TypeSupport = topics::TypeSupport;

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

// The QoS idl/ declares for a topic name (its `// @topic` line); reliable for other names.
Qos default_qos_for_topic(const std::string& topic);

struct ParticipantOptions {
  int domain_id = 0;  // 0..232
  // Network interface to use: a name ("eth1") or an IPv4 address of this host. Empty means
  // loopback only, the safe default for one computer; set it to run across computers.
  std::string interface;
  std::string name = "plumb";  // participant name, shows up in discovery
  // DDS Security: an identity folder (security.hpp; made by `plumb security create-identity`).
  // Empty means an unsecured participant. When set, the plugin checks the folder with
  // check_security_files() and throws Error rather than ever fall back to an unsecured participant.
  std::string security;
};

class RawWriter {
 public:
  virtual ~RawWriter() = default;
  // `message` points to the topics:: type the writer was created with.
  virtual void write(const void* message) = 0;
  virtual std::size_t matched_readers() const = 0;
};

// Where a batched take puts its messages: slot(context, i) returns the i-th message to fill (the
// reader's topics:: type). A function pointer and a context, not std::function: no allocation per call.
struct TakeTarget {
  void* context = nullptr;
  void* (*slot)(void* context, std::size_t index) = nullptr;
};

class RawReader {
 public:
  virtual ~RawReader() = default;
  // Takes the oldest unread message into `message` (the matching topics:: type); false when none.
  virtual bool take(void* message) = 0;
  // Takes up to `max` unread messages, oldest first, in as few vendor calls as possible (one multi-
  // sample take per call where the vendor allows it); message i goes to target.slot(target.context, i).
  // Returns how many it filled.
  virtual std::size_t take(std::size_t max, TakeTarget target) = 0;
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
  // Error when the plugin was built from an idl/ without `type` or with another layout of it.
  virtual std::unique_ptr<RawWriter> create_writer(const TypeSupport& type, const std::string& topic, const Qos& qos) = 0;
  virtual std::unique_ptr<RawReader> create_reader(const TypeSupport& type, const std::string& topic, const Qos& qos,
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
  // Replaces the contents of `out` with up to `max` unread messages, oldest first; returns how many.
  // Elements already in `out` are reused as messages arrive (their strings and sequences keep their
  // capacity), so a reader that calls this in a loop with the same vector allocates little.
  std::size_t take(std::vector<T>& out, std::size_t max) {
    Slots slots{&out};
    const std::size_t n = raw_->take(max, TakeTarget{&slots, &Slots::slot});
    out.resize(n);
    return n;
  }
  bool wait(std::chrono::nanoseconds timeout) { return raw_->wait(timeout); }
  std::size_t matched_writers() const { return raw_->matched_writers(); }

 private:
  struct Slots {
    std::vector<T>* out;
    static void* slot(void* context, std::size_t index) {
      auto& out = *static_cast<Slots*>(context)->out;
      if (index >= out.size()) out.resize(index + 1);
      return &out[index];
    }
  };
  std::unique_ptr<RawReader> raw_;
};

template <class T> Writer<T> make_writer(Participant& p, const std::string& topic, const Qos& qos) {
  return Writer<T>(p.create_writer(topics::type_support<T>(), topic, qos));
}
template <class T> Reader<T> make_reader(Participant& p, const std::string& topic, const Qos& qos,
                                         std::function<void()> on_data = {}) {
  return Reader<T>(p.create_reader(topics::type_support<T>(), topic, qos, std::move(on_data)));
}

}  // namespace plumb::transport
