// The pieces the generated conversions (idl/generate/emit_fastdds.py) are made of. fixed_string
// truncates at its bound and at the first NUL without telling anyone; a message that arrives
// different from what was written is worse than an error, so both are refused here.
#pragma once

#include <fastrtps/utils/fixed_size_string.hpp>

#include <cstddef>
#include <cstring>
#include <string>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::fastdds {

template <std::size_t N>
void put_string(const std::string& in, eprosima::fastrtps::fixed_string<N>& out, const char* field) {
  if (in.size() > N) {
    throw Error(std::string(field) + " is " + std::to_string(in.size()) + " characters long, its IDL bound is " +
                std::to_string(N));
  }
  if (std::memchr(in.data(), '\0', in.size()) != nullptr) {
    throw Error(std::string(field) + " contains a NUL character, which an IDL string cannot carry");
  }
  out = in.c_str();
}

// Assigned in place: a message taken again and again keeps its strings' capacity (no allocation
// per message for strings longer than the small-string buffer).
template <std::size_t N> void get_string(const eprosima::fastrtps::fixed_string<N>& in, std::string& out) {
  out.assign(in.c_str(), in.size());
}

inline void check_length(std::size_t length, std::size_t bound, const char* field) {
  if (length > bound) {
    throw Error(std::string(field) + " has " + std::to_string(length) + " elements, its IDL bound is " +
                std::to_string(bound));
  }
}

}  // namespace plumb::transport::fastdds
