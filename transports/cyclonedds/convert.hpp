// The pieces the generated conversions (idl/generate/emit_cyclonedds.py) are made of: bounded
// strings as char[N + 1], sequences pointing into a per-write arena. Going out, a value that does
// not fit its IDL bound is an Error: silently cutting it would change the message.
#pragma once

#include <dds/dds.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <memory_resource>
#include <string>
#include <type_traits>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::cyclonedds {

// Storage for the sequences of one outgoing message: on the stack for every plumb type today
// (a full SensorBatch needs about 3.5 KB), on the heap beyond.
class Arena {
 public:
  Arena() = default;
  Arena(const Arena&) = delete;
  Arena& operator=(const Arena&) = delete;

  template <class T> T* alloc(std::size_t n) {
    static_assert(std::is_trivially_destructible_v<T>, "idlc's C structs need no destructor");
    if (n == 0) return nullptr;
    T* p = static_cast<T*>(resource_.allocate(n * sizeof(T), alignof(T)));
    std::uninitialized_value_construct_n(p, n);
    return p;
  }

 private:
  alignas(std::max_align_t) std::byte buffer_[16384];
  std::pmr::monotonic_buffer_resource resource_{buffer_, sizeof buffer_};
};

// string<N> is char[N + 1] in idlc's C.
template <std::size_t Size> void put_string(const std::string& value, char (&out)[Size], const char* field) {
  constexpr std::size_t bound = Size - 1;
  if (value.size() > bound) {
    throw Error(std::string(field) + " is " + std::to_string(value.size()) + " characters long, its IDL bound is " +
                std::to_string(bound));
  }
  if (value.find('\0') != std::string::npos) throw Error(std::string(field) + " contains a NUL character");
  std::memcpy(out, value.data(), value.size());
  out[value.size()] = '\0';
}

// Assigned in place: a message taken again and again keeps its strings' capacity (no allocation
// per message for strings longer than the small-string buffer).
template <std::size_t Size> void get_string(const char (&in)[Size], std::string& out) { out.assign(in, strnlen(in, Size)); }

inline void check_length(std::size_t length, std::size_t bound, const char* field) {
  if (length > bound) {
    throw Error(std::string(field) + " has " + std::to_string(length) + " elements, its IDL bound is " +
                std::to_string(bound));
  }
}

// The buffer belongs to the arena: Cyclone must not free it (_release = false).
template <class Sequence, class Element> void set_sequence(Sequence& sequence, Element* buffer, std::size_t length) {
  sequence._maximum = static_cast<std::uint32_t>(length);
  sequence._length = static_cast<std::uint32_t>(length);
  sequence._buffer = buffer;
  sequence._release = false;
}

}  // namespace plumb::transport::cyclonedds
