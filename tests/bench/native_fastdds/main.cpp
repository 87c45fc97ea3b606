// plumb-bench-native-fastdds: the Fast DDS baseline of plumb-bench-transport. One role of a latency
// (ping/pong) or throughput (source/sink) measurement of SensorBatch or Attitude, on loopback,
// written the way a plain Fast DDS application would be: fastddsgen's classes from idl/, loaned
// multi-sample takes in listeners, the same topics, QoS and loopback setup as plumb's Fast DDS
// plugin. No plumb code.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

#include "roles.hpp"

namespace {

void usage(std::FILE* out) {
  std::fputs(
      "usage: plumb-bench-native-fastdds --role ping|pong|source|sink --type sensor|attitude\n"
      "                                  [--domain ID] [--seconds S]\n"
      "One role of plumb-bench-transport's native Fast DDS baseline (normally started by it).\n"
      "  --role      ping/pong: latency (round trip / 2); source/sink: throughput\n"
      "  --type      sensor (SensorBatch, 32 samples) or attitude\n"
      "  --domain    DDS domain id (default 0)\n"
      "  --seconds   measuring time (default 1)\n"
      "Prints one line \"RESULT key=value ...\" on success.\n",
      out);
}

}  // namespace

int main(int argc, char** argv) {
  std::string role, type;
  int domain = 0;
  double seconds = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--help" || option == "-h") {
      usage(stdout);
      return 0;
    }
    if (i + 1 >= argc) {
      usage(stderr);
      return 1;
    }
    const char* value = argv[++i];
    if (option == "--role") role = value;
    else if (option == "--type") type = value;
    else if (option == "--domain") domain = std::atoi(value);
    else if (option == "--seconds") seconds = std::atof(value);
    else {
      std::cerr << "unknown option " << option << std::endl;
      usage(stderr);
      return 1;
    }
  }
  if (role.empty() || type.empty() || domain < 0 || domain > 232 || seconds <= 0) {
    usage(stderr);
    return 1;
  }
  try {
    const int rc = native_fastdds::run_role(role, type, domain, seconds);
    std::fflush(stdout);
    return rc;
  } catch (const std::exception& e) {
    std::cerr << "plumb-bench-native-fastdds: " << e.what() << std::endl;
    return 1;
  }
}
