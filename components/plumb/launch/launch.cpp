// plumb launch FILE.yaml: start the plumb programs of a launch file on this computer
// (launch_file.hpp), supervise them (supervisor.hpp).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "launch_file.hpp"
#include "plumb/components/cli.hpp"
#include "supervisor.hpp"
#include "verbs.hpp"

namespace plumb::cli {
namespace {

struct LaunchOptions {
  std::string file;
  std::vector<std::string> arguments;  // NAME:=VALUE
  launch::SupervisorOptions supervisor;
};

int run_launch(const LaunchOptions& o) {
  try {
    const auto programs = launch::read_launch_file(o.file, launch::parse_arguments(o.arguments));
    components::install_stop_handler();
    return launch::supervise(programs, o.supervisor, std::cout, std::cerr);
  } catch (const std::exception& e) {
    return components::exit_on_error("plumb launch", e);
  }
}

}  // namespace

void add_launch_verb(CLI::App& app, Verbs& verbs) {
  auto o = std::make_shared<LaunchOptions>();
  auto* cmd = app.add_subcommand(
      "launch",
      "Start the plumb programs of a launch file on this computer, each output line prefixed with its name; "
      "restart them per their policy; Ctrl-C stops them all (docs/deployment.md)");
  cmd->add_option("file", o->file, "launch file (YAML: 'launch:', then '- cmd: PROGRAM OPTIONS' entries)")
      ->required()
      ->type_name("FILE.yaml");
  cmd->add_option("arguments", o->arguments, "launch arguments the file declares, NAME:=VALUE (e.g. port:=8081)")
      ->type_name("NAME:=VALUE");
  cmd->add_option("--stop-timeout", o->supervisor.stop_timeout_s,
                  "seconds a program has to stop after SIGINT before it is killed")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  verbs.add(cmd, [o] { return run_launch(*o); });
}

}  // namespace plumb::cli
