#include "sides.hpp"

#include <unistd.h>

#include <stdexcept>

namespace plumb::bench {

namespace {

std::string self_path() {
  char path[4096];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) throw std::runtime_error("cannot find this program's path in /proc/self/exe");
  return std::string(path, static_cast<std::size_t>(n));
}

}  // namespace

Programs find_programs() {
  Programs programs;
  programs.self = self_path();
  programs.native_dir = programs.self.substr(0, programs.self.rfind('/'));
  return programs;
}

std::string Programs::native_program(const std::string& vendor) const {
  const std::string path = native_dir + "/plumb-bench-native-" + (vendor == "cyclonedds" ? "cyclone" : vendor);
  return access(path.c_str(), X_OK) == 0 ? path : std::string();
}

std::vector<std::string> Programs::command(const Side& side, const std::string& role, const std::string& type, int domain,
                                           double seconds) const {
  std::vector<std::string> command{side.native ? native_program(side.vendor) : self, "--role", role, "--type", type,
                                   "--domain", std::to_string(domain), "--seconds", std::to_string(seconds)};
  if (command.front().empty()) throw std::runtime_error("the native " + side.vendor + " program was not built");
  if (!side.native) command.insert(command.end(), {"--transport", side.vendor});
  return command;
}

}  // namespace plumb::bench
