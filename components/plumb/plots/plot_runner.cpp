#include "plots/plot_runner.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace plumb::cli {

void run_plot(const std::string& kind, const std::string& input, const std::string& output) {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::string script = (ec ? std::filesystem::path(".") : self.parent_path()) / "plumb-plot";
  if (!std::filesystem::exists(script)) throw std::runtime_error("no plumb-plot beside plumb (" + script + ")");
  // What was printed so far shows before the drawing starts: a piped stdout is block-buffered.
  std::cout.flush();
  std::cerr << "plumb: drawing " << output << " (plumb-plot " << kind << ")" << std::endl;
  std::vector<std::string> args = {script, kind, input, "-o", output};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, script.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot run " + script);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("lost plumb-plot (waitpid failed)");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("plumb-plot could not draw " + output + " (its message is above)");
}

}  // namespace plumb::cli
