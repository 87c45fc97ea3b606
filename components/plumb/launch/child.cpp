#include "child.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace plumb::launch {
namespace {

bool executable(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

std::string own_folder() {
  char buffer[4096];
  const ssize_t n = ::readlink("/proc/self/exe", buffer, sizeof buffer - 1);
  if (n <= 0) return "";
  const std::string self(buffer, static_cast<std::size_t>(n));
  return self.substr(0, self.rfind('/'));
}

}  // namespace

std::string find_program(const std::string& word) {
  if (word.find('/') != std::string::npos) return executable(word) ? word : "";
  if (const std::string here = own_folder(); !here.empty() && executable(here + "/" + word)) return here + "/" + word;
  const char* path = std::getenv("PATH");
  std::string folders = path ? path : "/usr/bin:/bin";
  for (std::size_t start = 0; start <= folders.size();) {
    const std::size_t end = std::min(folders.find(':', start), folders.size());
    const std::string folder = folders.substr(start, end - start);
    if (!folder.empty() && executable(folder + "/" + word)) return folder + "/" + word;
    start = end + 1;
  }
  return "";
}

Child::Child(const std::string& path, const std::vector<std::string>& argv,
             const std::map<std::string, std::string>& env, const std::string& cwd) {
  int out[2], err[2];
  if (::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(err, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot make pipes: ") + std::strerror(errno));
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error(std::string("cannot start ") + path + ": " + std::strerror(errno));
  if (pid_ == 0) {
    ::setpgid(0, 0);
    ::dup2(out[1], STDOUT_FILENO);
    ::dup2(err[1], STDERR_FILENO);
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    for (const auto& [name, value] : env) ::setenv(name.c_str(), value.c_str(), 1);
    if (!cwd.empty() && ::chdir(cwd.c_str()) != 0) {
      const std::string why = "cannot enter " + cwd + ": " + std::strerror(errno) + "\n";
      (void)!::write(STDERR_FILENO, why.data(), why.size());
      ::_exit(127);
    }
    ::execv(path.c_str(), args.data());
    const std::string why = "cannot run " + path + ": " + std::strerror(errno) + "\n";
    (void)!::write(STDERR_FILENO, why.data(), why.size());
    ::_exit(127);
  }
  ::setpgid(pid_, pid_);  // also here: no race with a signal sent right after the start
  ::close(out[1]);
  ::close(err[1]);
  out_ = out[0];
  err_ = err[0];
}

Child::~Child() {
  if (out_ >= 0) ::close(out_);
  if (err_ >= 0) ::close(err_);
}

std::vector<int> Child::fds() const {
  std::vector<int> v;
  if (out_ >= 0) v.push_back(out_);
  if (err_ >= 0) v.push_back(err_);
  return v;
}

void Child::read(int fd, const std::function<void(const std::string&, bool)>& line) {
  const bool is_err = fd == err_;
  std::string& partial = is_err ? err_partial_ : out_partial_;
  char buffer[4096];
  const ssize_t n = ::read(fd, buffer, sizeof buffer);
  if (n < 0 && (errno == EINTR || errno == EAGAIN)) return;
  if (n > 0) {
    partial.append(buffer, static_cast<std::size_t>(n));
    for (std::size_t nl; (nl = partial.find('\n')) != std::string::npos; partial.erase(0, nl + 1))
      line(partial.substr(0, nl), is_err);
    return;
  }
  if (!partial.empty()) line(partial, is_err);
  partial.clear();
  ::close(fd);
  (is_err ? err_ : out_) = -1;
}

void Child::signal(int sig) const {
  if (pid_ > 0) ::kill(-pid_, sig);
}

}  // namespace plumb::launch
