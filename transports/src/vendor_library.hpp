// Names the Debian package behind a DDS vendor library that a transport plugin could not load, so
// that "could not be loaded: libfastrtps.so.2.9: cannot open shared object file" becomes one line a
// field engineer can act on (a tool computer installed with --force-depends, a library removed).
#pragma once

#include <optional>
#include <string>

namespace plumb::transport {

struct MissingVendorLibrary {
  std::string library;  // e.g. libfastrtps.so.2.9
  std::string package;  // e.g. libfastrtps2.9
};

// The vendor library named in a dlopen() message, with its Debian bookworm package; nothing when
// the message names no library plumb's transports link.
std::optional<MissingVendorLibrary> missing_vendor_library(const std::string& dlopen_message);

}  // namespace plumb::transport
