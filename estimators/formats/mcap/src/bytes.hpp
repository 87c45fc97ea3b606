// Little-endian encoding of MCAP's field types (fixed-width integers, String, Map) into a byte
// buffer, and a bounds-checked cursor that decodes them: a short read names the field, never
// reads past the record.
#pragma once

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace plumb::mcap::detail {

using Bytes = std::vector<std::uint8_t>;

template <class T> void put(Bytes& out, T value) {
  static_assert(std::is_integral_v<T>);
  for (std::size_t i = 0; i < sizeof(T); ++i) out.push_back(static_cast<std::uint8_t>(static_cast<std::uint64_t>(value) >> (8 * i)));
}

inline void put_raw(Bytes& out, const void* data, std::size_t size) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  out.insert(out.end(), p, p + size);
}

inline void put_string(Bytes& out, std::string_view s) {
  put<std::uint32_t>(out, static_cast<std::uint32_t>(s.size()));
  put_raw(out, s.data(), s.size());
}

inline void put_map(Bytes& out, const std::map<std::string, std::string>& m) {
  Bytes body;
  for (const auto& [k, v] : m) {
    put_string(body, k);
    put_string(body, v);
  }
  put<std::uint32_t>(out, static_cast<std::uint32_t>(body.size()));
  put_raw(out, body.data(), body.size());
}

// Starts a record: opcode and a length placeholder; end_record fills the length in.
inline std::size_t begin_record(Bytes& out, std::uint8_t opcode) {
  out.push_back(opcode);
  const std::size_t at = out.size();
  put<std::uint64_t>(out, 0);
  return at;
}

inline void end_record(Bytes& out, std::size_t length_at) {
  const std::uint64_t length = out.size() - length_at - 8;
  for (std::size_t i = 0; i < 8; ++i) out[length_at + i] = static_cast<std::uint8_t>(length >> (8 * i));
}

// Thrown by Cursor when a field runs past the end of its record; the reader adds the file offset.
struct ShortRead {
  const char* field;
};

class Cursor {
 public:
  Cursor(const std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}

  template <class T> T get(const char* field) {
    need(sizeof(T), field);
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) v |= static_cast<std::uint64_t>(p_[i]) << (8 * i);
    p_ += sizeof(T);
    return static_cast<T>(v);
  }
  std::string string(const char* field) {
    const auto n = get<std::uint32_t>(field);
    need(n, field);
    std::string s(reinterpret_cast<const char*>(p_), n);
    p_ += n;
    return s;
  }
  std::map<std::string, std::string> map(const char* field) {
    const auto n = get<std::uint32_t>(field);
    need(n, field);
    Cursor inner(p_, n);
    p_ += n;
    std::map<std::string, std::string> m;
    while (inner.left() > 0) {
      auto k = inner.string(field);
      m[std::move(k)] = inner.string(field);
    }
    return m;
  }
  const std::uint8_t* take(std::size_t n, const char* field) {
    need(n, field);
    const auto* at = p_;
    p_ += n;
    return at;
  }
  std::size_t left() const { return static_cast<std::size_t>(end_ - p_); }
  const std::uint8_t* position() const { return p_; }

 private:
  void need(std::size_t n, const char* field) const {
    if (n > left()) throw ShortRead{field};
  }
  const std::uint8_t* p_;
  const std::uint8_t* end_;
};

}  // namespace plumb::mcap::detail
