#include "vendor_library.hpp"

#include <array>
#include <utility>

namespace plumb::transport {

std::optional<MissingVendorLibrary> missing_vendor_library(const std::string& message) {
  // The libraries the two plugins link (ldd), by soname, and the Debian bookworm packages that
  // hold them (dpkg -S). Debian pins these names with the ABI: a new soname is a new package.
  static constexpr std::array<std::pair<const char*, const char*>, 5> kLibraries{{
      {"libddsc.so.0debian", "libddsc0debian"},
      {"libfastrtps.so.2.9", "libfastrtps2.9"},
      {"libfastcdr.so.1", "libfastcdr1"},
      {"libfoonathan_memory.so.0.7.2", "libfoonathan-memory0.7.2"},
      {"libtinyxml2.so.9", "libtinyxml2-9"},
  }};
  // dlopen() names the library that failed first, as "<soname>: <reason>".
  for (const auto& [library, package] : kLibraries) {
    if (message.find(std::string(library) + ":") != std::string::npos) return MissingVendorLibrary{library, package};
  }
  return std::nullopt;
}

}  // namespace plumb::transport
