// One side (writer or reader process) of a measurement: plumb's transport plugin of a vendor (this
// program in a --role) or the native baseline program of that vendor (plumb-bench-native-cyclone,
// plumb-bench-native-fastdds: no plumb code). Both take the same role arguments and print the same
// RESULT line, and they talk to each other, so every writer -> reader vendor pair also has a native
// pair to compare with.
#pragma once

#include <string>
#include <vector>

namespace plumb::bench {

struct Side {
  bool native = false;
  std::string vendor;  // cyclonedds or fastdds
  std::string label() const { return native ? "native " + vendor : vendor; }
};

struct Programs {
  std::string self;        // plumb-bench-transport
  std::string native_dir;  // where the native programs are (next to this program)
  // Program and arguments that run `side` in `role` ("ping", "pong", "source", "sink").
  std::vector<std::string> command(const Side& side, const std::string& role, const std::string& type, int domain,
                                   double seconds) const;
  // The native program of `vendor`; empty when it was not built.
  std::string native_program(const std::string& vendor) const;
};

Programs find_programs();

}  // namespace plumb::bench
