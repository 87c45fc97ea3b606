// Starts a program with its stdout captured and collects that output within a deadline, killing
// the child if it overstays, so that the benchmark can never hang on a stuck peer.
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <sys/types.h>
#include <vector>

namespace plumb::bench {

class ChildProcess {
 public:
  // `environment` entries are added to (or replace those of) this process's environment.
  ChildProcess(const std::string& program, const std::vector<std::string>& arguments,
               const std::map<std::string, std::string>& environment = {});
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  struct Outcome {
    bool exited_normally = false;  // false: killed at the deadline or by a signal
    int exit_code = -1;
    std::string output;            // everything it wrote to stdout
  };
  // Reads stdout until the child closes it and exits, or until `timeout`; then kills it if needed.
  Outcome finish(std::chrono::steady_clock::duration timeout);

 private:
  pid_t pid_ = -1;
  int stdout_fd_ = -1;
};

// The value of `key` in the last line of `output` starting with "RESULT " ("RESULT a=1 b=2").
bool result_value(const std::string& output, const std::string& key, double& value);

}  // namespace plumb::bench
