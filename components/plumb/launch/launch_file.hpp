// A launch file: the plumb programs to start on this computer, each with its options and its
// restart policy, in the habit of ROS 2's YAML launch files:
//
//   arguments:                           # launch arguments: NAME: default, `plumb launch FILE NAME:=VALUE`
//     port: "8080"
//   launch:
//     - name: estimator                  # the prefix of its output lines (default: the program)
//       cmd: plumb-estimator --plugin compensated --input plumb/sensor/raw
//       restart: on-failure              # never (default) or on-failure
//       restart_limit: 3                 # restarts before it has failed for good
//       restart_delay: 1                 # seconds before each restart
//       required: true                   # failed for good, it stops the others (default: it fails alone)
//       on_exit: shutdown                # when it ends, stop the others (default: keep them)
//       env: {PLUMB_DOMAIN_ID: "7"}
//       cwd: some/folder                 # relative to the folder launch was started in
//     - cmd: plumb-display --port $(var port)
//
// `cmd` is one line split as a shell splits words (quotes, backslashes; no variables, no globs)
// or a YAML list of words. `$(var NAME)` in cmd, env and cwd is a launch argument's value, as in
// ROS 2 launch files.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace plumb::launch {

enum class Restart { Never, OnFailure };

struct ProgramSpec {
  std::string name;
  std::vector<std::string> argv;  // argv[0]: the program as written
  Restart restart = Restart::Never;
  int restart_limit = 3;
  double restart_delay_s = 1;
  bool shutdown_on_exit = false;
  bool required = false;
  std::map<std::string, std::string> env;
  std::string cwd;
  std::string where;      // FILE:LINE of its entry, for messages
  std::string cmd_where;  // FILE:LINE of its cmd
};

using Arguments = std::map<std::string, std::string>;

// Throws std::invalid_argument "FILE:LINE: what" for a file that cannot be read, is not YAML, or
// is not in the layout above (an unknown key, a value of the wrong kind, a name given twice, no
// program at all, a `$(var NAME)` not declared), and for a given argument the file does not declare.
std::vector<ProgramSpec> read_launch_file(const std::string& path, const Arguments& given = {});

// "NAME:=VALUE" words from the command line. Throws std::invalid_argument for any other word.
Arguments parse_arguments(const std::vector<std::string>& words);

// "a 'b c' \"d\"" -> {a, b c, d}. Throws std::invalid_argument for an unterminated quote.
std::vector<std::string> split_words(const std::string& line);

}  // namespace plumb::launch
