#include "child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace plumb::bench {

ChildProcess::ChildProcess(const std::string& program, const std::vector<std::string>& arguments,
                           const std::map<std::string, std::string>& environment) {
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));

  std::vector<std::string> env_strings;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string text = *entry;
    const auto key = text.substr(0, text.find('='));
    if (environment.count(key) == 0) env_strings.push_back(text);
  }
  for (const auto& [key, value] : environment) env_strings.push_back(key + "=" + value);
  std::vector<char*> envp;
  for (auto& text : env_strings) envp.push_back(text.data());
  envp.push_back(nullptr);

  std::vector<std::string> argv_strings{program};
  argv_strings.insert(argv_strings.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& text : argv_strings) argv.push_back(text.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
  const int rc = posix_spawnp(&pid_, program.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fds[1]);
  if (rc != 0) {
    close(pipe_fds[0]);
    throw std::runtime_error("cannot start " + program + ": " + std::strerror(rc));
  }
  stdout_fd_ = pipe_fds[0];
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  if (stdout_fd_ >= 0) close(stdout_fd_);
}

ChildProcess::Outcome ChildProcess::finish(std::chrono::steady_clock::duration timeout) {
  Outcome outcome;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  bool open = true;
  while (open) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd fd{stdout_fd_, POLLIN, 0};
    const int ready = poll(&fd, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) break;
    char buffer[4096];
    const ssize_t n = read(stdout_fd_, buffer, sizeof buffer);
    if (n > 0) {
      outcome.output.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      open = false;
    }
  }
  // Output closed (or the deadline passed): give the child a moment to exit on its own.
  int status = 0;
  pid_t waited = 0;
  const auto exit_deadline = std::max(deadline, std::chrono::steady_clock::now() + std::chrono::seconds(2));
  while ((waited = waitpid(pid_, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < exit_deadline) {
    usleep(10'000);
  }
  if (waited == 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, &status, 0);
  } else if (waited > 0 && WIFEXITED(status)) {
    outcome.exited_normally = true;
    outcome.exit_code = WEXITSTATUS(status);
  }
  pid_ = -1;
  return outcome;
}

bool result_value(const std::string& output, const std::string& key, double& value) {
  std::istringstream lines(output);
  std::string line, result_line;
  while (std::getline(lines, line)) {
    if (line.rfind("RESULT ", 0) == 0) result_line = line;
  }
  std::istringstream fields(result_line);
  std::string field;
  while (fields >> field) {
    if (field.rfind(key + "=", 0) == 0) {
      try {
        value = std::stod(field.substr(key.size() + 1));
        return true;
      } catch (const std::exception&) {
        return false;
      }
    }
  }
  return false;
}

}  // namespace plumb::bench
