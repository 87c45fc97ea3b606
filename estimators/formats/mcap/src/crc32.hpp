// CRC-32 (IEEE 802.3, the zlib one) that MCAP puts on chunks, the data section and the summary:
// zlib's, which Debian's zlib1g computes with its braided tables.
#pragma once

#include <zlib.h>

#include <cstddef>
#include <cstdint>

namespace plumb::mcap::detail {

// Continues `crc` (0 to start) over `size` bytes; crc32(crc32(0, a), b) == crc32 of a then b.
inline std::uint32_t crc32(std::uint32_t crc, const void* data, std::size_t size) {
  return static_cast<std::uint32_t>(::crc32_z(crc, static_cast<const Bytef*>(data), size));
}

}  // namespace plumb::mcap::detail
