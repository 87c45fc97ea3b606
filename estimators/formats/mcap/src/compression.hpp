// Chunk compression: zstd (Debian's libzstd), MCAP's well-known "zstd"; "" is stored as is.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace plumb::mcap::detail {

// Compresses `size` bytes at `data` into `out` (replaced) with zstd at `level`.
void zstd_compress(const std::uint8_t* data, std::size_t size, int level, std::vector<std::uint8_t>& out);

// Decompresses a chunk's records into `out` (replaced), which must come to `uncompressed_size`
// bytes. `compression` is the chunk's field: "" or "zstd"; anything else is an error (a text that
// says why, empty on success).
std::string decompress(const std::string& compression, const std::uint8_t* data, std::size_t size,
                       std::uint64_t uncompressed_size, std::vector<std::uint8_t>& out);

}  // namespace plumb::mcap::detail
