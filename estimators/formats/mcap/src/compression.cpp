#include "compression.hpp"

#include <zstd.h>

#include <stdexcept>

namespace plumb::mcap::detail {

void zstd_compress(const std::uint8_t* data, std::size_t size, int level, std::vector<std::uint8_t>& out) {
  out.resize(ZSTD_compressBound(size));
  const std::size_t n = ZSTD_compress(out.data(), out.size(), data, size, level);
  if (ZSTD_isError(n)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(n));
  out.resize(n);
}

std::string decompress(const std::string& compression, const std::uint8_t* data, std::size_t size,
                       std::uint64_t uncompressed_size, std::vector<std::uint8_t>& out) {
  if (compression.empty()) {
    if (size != uncompressed_size) return "uncompressed chunk of " + std::to_string(size) + " bytes says " +
                                          std::to_string(uncompressed_size);
    out.assign(data, data + size);
    return {};
  }
  if (compression != "zstd") return "chunk compression '" + compression + "' is not supported (only zstd and none)";
  // A corrupt size field must not make us allocate terabytes: zstd expands at most ~1000x.
  if (uncompressed_size > 1024 * static_cast<std::uint64_t>(size) + 1024)
    return "chunk claims " + std::to_string(uncompressed_size) + " bytes uncompressed from " + std::to_string(size);
  out.resize(uncompressed_size);
  const std::size_t n = ZSTD_decompress(out.data(), out.size(), data, size);
  if (ZSTD_isError(n)) return std::string("zstd: ") + ZSTD_getErrorName(n);
  if (n != uncompressed_size) return "chunk decompressed to " + std::to_string(n) + " bytes, not " + std::to_string(uncompressed_size);
  return {};
}

}  // namespace plumb::mcap::detail
