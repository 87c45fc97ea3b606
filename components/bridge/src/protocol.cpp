#include "plumb/bridge/protocol.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <sstream>

#include "little_endian.hpp"
#include "plumb/csv/files.hpp"

namespace plumb::bridge {
namespace {

// Slicing-by-8 tables: the parser runs the CRC over every frame, so this is its hot loop.
struct CrcTables {
  std::array<std::array<std::uint32_t, 256>, 8> t{};
  constexpr CrcTables() {
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? (c >> 1) ^ 0xEDB88320u : c >> 1;
      t[0][i] = c;
    }
    for (std::uint32_t i = 0; i < 256; ++i) {
      for (std::size_t s = 1; s < 8; ++s) t[s][i] = (t[s - 1][i] >> 8) ^ t[0][t[s - 1][i] & 0xFF];
    }
  }
};
constexpr CrcTables kCrc;

void put_u16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
void put_u32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void put_u64(std::uint8_t* p, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void put_f32(std::uint8_t* p, double v) { put_u32(p, std::bit_cast<std::uint32_t>(static_cast<float>(v))); }
double get_f32(const std::uint8_t* p) { return static_cast<double>(std::bit_cast<float>(get_u32(p))); }

std::int64_t to_ns(double t) {
  // Out-of-range times saturate instead of invoking undefined behaviour in the conversion.
  if (!std::isfinite(t)) return 0;
  const double ns = std::round(t * 1e9);
  if (ns >= 9.2e18) return INT64_MAX;
  if (ns <= -9.2e18) return INT64_MIN;
  return static_cast<std::int64_t>(ns);
}

void write_header(std::uint8_t* p, std::uint8_t version, std::size_t payload_size) {
  p[0] = kSync0;
  p[1] = kSync1;
  p[2] = version;
  p[3] = 0;
  put_u16(p + 4, static_cast<std::uint16_t>(payload_size));
}

}  // namespace

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
  std::uint32_t c = 0xFFFFFFFFu;
  const auto& t = kCrc.t;
  while (size >= 8) {
    const std::uint32_t lo = get_u32(data) ^ c;
    const std::uint32_t hi = get_u32(data + 4);
    c = t[7][lo & 0xFF] ^ t[6][(lo >> 8) & 0xFF] ^ t[5][(lo >> 16) & 0xFF] ^ t[4][lo >> 24] ^ t[3][hi & 0xFF] ^
        t[2][(hi >> 8) & 0xFF] ^ t[1][(hi >> 16) & 0xFF] ^ t[0][hi >> 24];
    data += 8;
    size -= 8;
  }
  while (size--) c = (c >> 8) ^ t[0][(c ^ *data++) & 0xFF];
  return c ^ 0xFFFFFFFFu;
}

void append_frame(std::vector<std::uint8_t>& out, const Sample& s) {
  const std::size_t at = out.size();
  out.resize(at + kFrameSizeV1);
  std::uint8_t* p = out.data() + at;
  write_header(p, kProtocolVersion, kPayloadSizeV1);
  put_u64(p + 6, s.seq);
  put_u64(p + 14, static_cast<std::uint64_t>(to_ns(s.t)));
  const double channels[10] = {s.f.x(), s.f.y(), s.f.z(), s.b.x(), s.b.y(), s.b.z(), s.w.x(), s.w.y(), s.w.z(), s.temp_c};
  for (int i = 0; i < 10; ++i) put_f32(p + 22 + 4 * i, channels[i]);
  put_u32(p + 62, s.flags);
  put_u32(p + 66, crc32(p, 66));
}

std::vector<std::uint8_t> encode_frame(const Sample& s) {
  std::vector<std::uint8_t> out;
  out.reserve(kFrameSizeV1);
  append_frame(out, s);
  return out;
}

std::vector<std::uint8_t> encode_raw_frame(std::uint8_t version, std::span<const std::uint8_t> payload) {
  std::vector<std::uint8_t> out(kHeaderSize + payload.size() + kCrcSize);
  write_header(out.data(), version, payload.size());
  std::copy(payload.begin(), payload.end(), out.begin() + kHeaderSize);
  put_u32(out.data() + kHeaderSize + payload.size(), crc32(out.data(), kHeaderSize + payload.size()));
  return out;
}

Sample decode_payload_v1(const std::uint8_t* p) {
  Sample s;
  s.seq = get_u64(p);
  s.t = static_cast<double>(static_cast<std::int64_t>(get_u64(p + 8))) * 1e-9;
  s.f = {get_f32(p + 16), get_f32(p + 20), get_f32(p + 24)};
  s.b = {get_f32(p + 28), get_f32(p + 32), get_f32(p + 36)};
  s.w = {get_f32(p + 40), get_f32(p + 44), get_f32(p + 48)};
  s.temp_c = get_f32(p + 52);
  s.flags = get_u32(p + 56);
  return s;
}

std::string ascii_header() {
  std::ostringstream out;
  csv::write_sensor_header(out, true, true);
  return out.str();
}

std::string encode_ascii_line(const Sample& s) {
  std::ostringstream out;
  csv::write_sensor_row(out, s, true, true);
  return out.str();
}

}  // namespace plumb::bridge
