// The sensor board's wire protocol (docs/protocol.md): a binary frame per sample and an ASCII line
// mode that speaks the sensor CSV of docs/conventions.md. Encoding only; the incremental parsers
// live in frame_parser.hpp and line_parser.hpp. No DDS here: the simulator links this too.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "plumb/core/sample.hpp"

namespace plumb::bridge {

// Binary frame, all fields little-endian (offsets in bytes):
//   0  u8[2] sync 0xA5 0x5A      2  u8 version (1)      3  u8 reserved (0)
//   4  u16 payload length (60 for version 1)
//   6  u64 seq                   14 i64 stamp_ns
//   22 f32 fx fy fz bx by bz wx wy wz temp_c (10 x 4 bytes)
//   62 u32 flags                 66 u32 CRC-32 (IEEE 802.3) of bytes 0..65
inline constexpr std::uint8_t kSync0 = 0xA5;
inline constexpr std::uint8_t kSync1 = 0x5A;
inline constexpr std::uint8_t kProtocolVersion = 1;
inline constexpr std::size_t kHeaderSize = 6;
inline constexpr std::size_t kPayloadSizeV1 = 60;
inline constexpr std::size_t kCrcSize = 4;
inline constexpr std::size_t kFrameSizeV1 = kHeaderSize + kPayloadSizeV1 + kCrcSize;  // 70
// Larger lengths are not a frame header: the parser resynchronises instead of waiting for them.
inline constexpr std::size_t kMaxPayloadSize = 1024;

// CRC-32/ISO-HDLC (the zlib/Ethernet CRC): reflected polynomial 0xEDB88320, init and final
// xor 0xFFFFFFFF. crc32("123456789") == 0xCBF43926.
std::uint32_t crc32(const std::uint8_t* data, std::size_t size);
inline std::uint32_t crc32(std::span<const std::uint8_t> bytes) { return crc32(bytes.data(), bytes.size()); }

// One sample as a version-1 frame (channels rounded to float32; stamp_ns = round(t * 1e9)).
std::vector<std::uint8_t> encode_frame(const Sample& s);
// Appends the frame to `out` (no allocation when `out` has room): for writers in a loop.
void append_frame(std::vector<std::uint8_t>& out, const Sample& s);
// A frame with any version/payload (tests and fuzzers: unknown versions, odd lengths).
std::vector<std::uint8_t> encode_raw_frame(std::uint8_t version, std::span<const std::uint8_t> payload);

// ASCII line mode: the header line, then one sensor CSV row per sample, '\n' terminated.
// Columns: seq,t,fx,fy,fz,bx,by,bz,wx,wy,wz,temp_c.
std::string ascii_header();
std::string encode_ascii_line(const Sample& s);

// Decodes the payload of a version-1 frame (no checks; `payload` must hold kPayloadSizeV1 bytes).
Sample decode_payload_v1(const std::uint8_t* payload);

}  // namespace plumb::bridge
