// One started program: its own process group (so that a terminal's Ctrl-C reaches plumb launch
// alone, which then stops every program itself), its stdout and stderr on pipes, read line by line.
#pragma once

#include <sys/types.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace plumb::launch {

// Where a program named in a launch file is run from: a word with a slash as written; a plain
// name next to this plumb executable first (an installed tree need not be on PATH), then on PATH.
// Empty when not found.
std::string find_program(const std::string& word);

class Child {
 public:
  // Starts `path` with `argv`, the environment plus `env`, in `cwd` (empty: this one). Throws
  // std::runtime_error when it cannot be started.
  Child(const std::string& path, const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
        const std::string& cwd);
  ~Child();
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  pid_t pid() const { return pid_; }
  // The pipes still open (stdout, stderr), for poll.
  std::vector<int> fds() const;
  // Reads what `fd` holds; each complete line goes to `line(text, is_stderr)`. At the end of the
  // pipe a last unterminated line goes too, and the pipe is closed.
  void read(int fd, const std::function<void(const std::string&, bool)>& line);
  // Sends `signal` to the program's process group (the program and what it started).
  void signal(int sig) const;

 private:
  pid_t pid_ = -1;
  int out_ = -1, err_ = -1;
  std::string out_partial_, err_partial_;
};

}  // namespace plumb::launch
