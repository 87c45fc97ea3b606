// The vendor-neutral transport interface: everything above transports/ talks DDS through this
// file only. A transport plugin (libplumb_transport_<name>.so) implements Transport; the loader
// (loader.hpp) picks one at run time by name, the way ROS 2 picks its rmw implementation.
//
// Each call below states its contract, as both plugins (transports/cyclonedds, transports/fastdds)
// implement it:
//   blocks     whether the call can wait (for the network, for readers, for another thread);
//   allocates  whether it takes memory from the heap (plumb's own code or the vendor's);
//   threads    from which threads it may be called. "Any" includes the on_data callback of a
//              reader, unless the call says otherwise.
// Every call reports failure by throwing Error; none returns a half-made object.
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
  // Status: a state, not a stream. Each writer keeps its last report for readers that join later
  // (ComponentStatus has no key: one instance per writer, so keep_last 1 is "the last per writer").
  // Readers use the topic's table entry (idl/status.idl), whose deeper history holds one report
  // of every writer when many answer a late joiner at once.
  static Qos status() { return {Reliability::Reliable, Durability::TransientLocal, History::KeepLast, 1}; }
  // Calibration: kept by the writer for late joiners.
  static Qos calibration() { return {Reliability::Reliable, Durability::TransientLocal, History::KeepLast, 1}; }
};

// The QoS idl/ declares for a topic name (its `// @topic` line); reliable for other names.
//   blocks: no. allocates: no (a table lookup). threads: any.
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
  //   blocks: a best-effort writer never waits for readers. A reliable one waits when its
  //     unacknowledged samples reach the vendor's limit, for at most the max blocking time
  //     (Cyclone DDS 1 s, set in cyclonedds/qos.cpp; Fast DDS its default 100 ms), then throws
  //     Error. Both vendors send on the calling thread (socket writes, no hand-off).
  //   allocates: yes, in the vendor (serialized payload, history). plumb's conversion does not:
  //     Cyclone's uses an arena on the stack, Fast DDS's one sample kept by the writer.
  //   threads: any; concurrent calls on one writer are safe (Fast DDS serializes them with a
  //     mutex; Cyclone's dds_write is thread-safe).
  virtual void write(const void* message) = 0;
  //   blocks: no (reads the vendor's status). allocates: no. threads: any.
  virtual std::size_t matched_readers() const = 0;
  // Waits until every matched reliable reader has acknowledged every sample written so far, or the
  // timeout passes; true when all did. A component's last words (its "stopping" status) are
  // written, waited for, and only then is the participant deleted: deleting it at once can take
  // the sample with it before a matched reader got it. Best-effort readers never acknowledge and
  // are not waited for.
  //   blocks: yes, up to `timeout` (negative counts as 0). allocates: no. threads: any but on_data.
  virtual bool wait_for_acknowledgments(std::chrono::nanoseconds timeout) = 0;
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
  //   blocks: never waits for data (a short lock on the reader's cache).
  //   allocates: only when a string or sequence of `message` must grow; vendor buffers are reused
  //     (Cyclone lends its samples, Fast DDS deserializes into one sample kept by the reader).
  //   threads: any, including on_data; concurrent calls on one reader are safe (Fast DDS
  //     serializes them with a mutex) but share its messages between them.
  virtual bool take(void* message) = 0;
  // Takes up to `max` unread messages, oldest first, in as few vendor calls as possible (one multi-
  // sample take per call where the vendor allows it); message i goes to target.slot(target.context, i).
  // Returns how many it filled.
  //   blocks: never waits for data. allocates: as take(message), plus what slot() allocates; Fast
  //     DDS sizes its sample sequence once, on the first call. threads: as take(message).
  virtual std::size_t take(std::size_t max, TakeTarget target) = 0;
  // Blocks until data may be available or the timeout passes; true if data arrived.
  //   blocks: yes, up to `timeout` (negative counts as 0). allocates: no.
  //   threads: one thread at a time per reader (Cyclone waits on one waitset per reader); never
  //     from on_data.
  virtual bool wait(std::chrono::nanoseconds timeout) = 0;
  //   blocks: no (reads the vendor's status). allocates: no. threads: any.
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
  // quick and must not destroy the reader. A writer in the same process may deliver on its own
  // thread, so on_data can also run inside that writer's write().
  // Error when the plugin was built from an idl/ without `type` or with another layout of it.
  //   blocks: briefly (the vendor creates the topic and endpoint; matching with remote endpoints
  //     happens later, in the background: matched_readers() / matched_writers() tell when).
  //   allocates: yes. threads: any (Fast DDS serializes entity creation per participant with a
  //     mutex; Cyclone's calls are thread-safe); not from on_data.
  // Writers and readers may be destroyed before or after their participant (one left over can
  // only be destroyed: with Cyclone DDS its entity went with the participant's), from any thread
  // but a reader's own on_data.
  virtual std::unique_ptr<RawWriter> create_writer(const TypeSupport& type, const std::string& topic, const Qos& qos) = 0;
  virtual std::unique_ptr<RawReader> create_reader(const TypeSupport& type, const std::string& topic, const Qos& qos,
                                                   std::function<void()> on_data = {}) = 0;
  // Topics seen through discovery so far (other participants' and our own).
  //   blocks: no (a snapshot of what discovery has found; it does not wait for more).
  //   allocates: yes (the list; Cyclone also reads up to 4096 endpoints into a buffer). threads: any.
  virtual std::vector<DiscoveredTopic> discovered_topics() = 0;
};

class Transport {
 public:
  virtual ~Transport() = default;
  // name() and vendor_version(): blocks: no. allocates: the string. threads: any.
  virtual std::string name() const = 0;            // "fastdds" or "cyclonedds"
  virtual std::string vendor_version() const = 0;  // e.g. "Fast DDS 2.9.1"
  // Error for a domain id outside 0..232, an unknown interface, bad security files, or a vendor
  // that refuses to start.
  //   blocks: briefly (opens sockets, starts the vendor's threads; the first participant of a
  //     domain id in a Cyclone process starts that domain). It does not wait for discovery.
  //   allocates: yes. threads: any. A Cyclone process runs each domain id on one interface: a
  //     second participant on the same id with another interface is refused.
  virtual std::unique_ptr<Participant> create_participant(const ParticipantOptions& options) = 0;
};

// Typed wrappers over the raw interface: each call has the contract of the raw call it forwards to.
template <class T> class Writer {
 public:
  explicit Writer(std::unique_ptr<RawWriter> raw) : raw_(std::move(raw)) {}
  void write(const T& message) { raw_->write(&message); }
  std::size_t matched_readers() const { return raw_->matched_readers(); }
  bool wait_for_acknowledgments(std::chrono::nanoseconds timeout) { return raw_->wait_for_acknowledgments(timeout); }

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
