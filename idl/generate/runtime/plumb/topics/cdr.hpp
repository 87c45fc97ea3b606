// The CDR form of any plumb::topics type: XCDR1, little-endian, behind the 4-byte encapsulation
// header (00 01 00 00, CDR_LE), byte for byte what both DDS vendors put on the wire for plumb's
// @final types (docs/architecture.md: XCDR1 on both). Written once over visit_fields, so every struct
// that the generator makes from idl/ has it, with no vendor library: a recording (MCAP message
// encoding "cdr") and a tool reading one need nothing of DDS.
//
// XCDR1 rules used: a primitive is aligned to its size (8 at most) counted from the byte after
// the encapsulation header; a string is a uint32 length that counts the terminating NUL, the
// characters and the NUL; a sequence is a uint32 element count and the elements; an array is its
// elements; a struct is its members in order.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace plumb::topics::cdr {

static_assert(std::endian::native == std::endian::little, "plumb's CDR writes little-endian by copying");

// A message that does not decode: too short, a bound exceeded, not CDR_LE.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

namespace detail {
template <class T> struct is_vector : std::false_type {};
template <class T> struct is_vector<std::vector<T>> : std::true_type {};
template <class T> struct is_array : std::false_type {};
template <class T, std::size_t N> struct is_array<std::array<T, N>> : std::true_type {};

constexpr std::size_t kHeader = 4;

class Encoder {
 public:
  explicit Encoder(std::vector<std::uint8_t>& out) : out_(out) {}

  template <class T> void value(const T& v) {
    if constexpr (std::is_arithmetic_v<T>) {
      align(sizeof(T));
      const auto at = out_.size();
      out_.resize(at + sizeof(T));
      std::memcpy(out_.data() + at, &v, sizeof(T));
    } else if constexpr (std::is_same_v<T, std::string>) {
      value(static_cast<std::uint32_t>(v.size() + 1));
      out_.insert(out_.end(), v.begin(), v.end());
      out_.push_back(0);
    } else if constexpr (is_vector<T>::value) {
      value(static_cast<std::uint32_t>(v.size()));
      for (const auto& e : v) value(e);
    } else if constexpr (is_array<T>::value) {
      for (const auto& e : v) value(e);
    } else {
      visit_fields(v, [this](const char*, const auto& field) { this->value(field); });
    }
  }

 private:
  void align(std::size_t n) {
    while ((out_.size() - kHeader) % n != 0) out_.push_back(0);
  }
  std::vector<std::uint8_t>& out_;
};

class Decoder {
 public:
  Decoder(const std::uint8_t* data, std::size_t size) : data_(data), size_(size), at_(kHeader) {}

  template <class T> void value(T& v, std::size_t bound = 0, const char* name = "message") {
    if constexpr (std::is_arithmetic_v<T>) {
      align(sizeof(T));
      need(sizeof(T), name);
      std::memcpy(&v, data_ + at_, sizeof(T));
      at_ += sizeof(T);
    } else if constexpr (std::is_same_v<T, std::string>) {
      std::uint32_t n = 0;
      value(n, 0, name);
      if (n == 0) throw Error(std::string("string '") + name + "' has no terminating NUL");
      if (bound && n - 1 > bound) throw Error(std::string("string '") + name + "' exceeds its bound of " + std::to_string(bound));
      need(n, name);
      v.assign(reinterpret_cast<const char*>(data_ + at_), n - 1);
      at_ += n;
    } else if constexpr (is_vector<T>::value) {
      std::uint32_t n = 0;
      value(n, 0, name);
      if (bound && n > bound) throw Error(std::string("sequence '") + name + "' exceeds its bound of " + std::to_string(bound));
      if (n > size_ - at_) throw Error(std::string("sequence '") + name + "' claims more elements than bytes left");
      v.resize(n);
      for (auto& e : v) value(e, 0, name);
    } else if constexpr (is_array<T>::value) {
      for (auto& e : v) value(e, 0, name);
    } else {
      visit_fields(v, [this](const char* field_name, auto& field) { this->value(field, T::max_size(field_name), field_name); });
    }
  }
  std::size_t position() const { return at_; }

 private:
  void align(std::size_t n) { at_ += (n - (at_ - kHeader) % n) % n; }
  void need(std::size_t n, const char* name) const {
    if (at_ > size_ || n > size_ - at_)
      throw Error(std::string("message ends inside '") + name + "' (byte " + std::to_string(at_) + " of " + std::to_string(size_) + ")");
  }
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_;
};
}  // namespace detail

// Replaces `out` with the encapsulated CDR of `message`.
template <class M> void serialize(const M& message, std::vector<std::uint8_t>& out) {
  out.assign({0x00, 0x01, 0x00, 0x00});  // CDR_LE, no options
  detail::Encoder(out).value(message);
}

// Decodes `size` bytes of encapsulated CDR into `message`; Error when they are not a valid one.
template <class M> void deserialize(const std::uint8_t* data, std::size_t size, M& message) {
  if (size < detail::kHeader) throw Error("message of " + std::to_string(size) + " bytes has no CDR header");
  if (data[0] != 0x00 || data[1] != 0x01)
    throw Error("message is not little-endian XCDR1 (encapsulation " + std::to_string(data[0]) + " " + std::to_string(data[1]) + ")");
  detail::Decoder(data, size).value(message);
}

}  // namespace plumb::topics::cdr
