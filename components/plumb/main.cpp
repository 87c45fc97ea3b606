// plumb: the command-line tool. `plumb --help` lists the subcommands.
#include <iostream>

#include "commands.hpp"
#include "launch/launch_command.hpp"
#include "plumb/components/cli.hpp"

namespace plumb::cli {
int g_exit_code = 0;
}

int main(int argc, char** argv) {
  CLI::App app{"plumb: drilling-tool attitude over DDS (topics, transports, estimator plugins, offline estimation)"};
  app.name("plumb");
  app.require_subcommand(1);
  plumb::cli::add_topic_commands(app);
  plumb::cli::add_listing_commands(app);
  plumb::cli::add_estimate_command(app);
  plumb::cli::add_compare_command(app);
  plumb::cli::add_record_command(app);
  plumb::cli::add_play_command(app);
  plumb::cli::add_info_command(app);
  plumb::cli::add_export_command(app);
  plumb::cli::add_survey_command(app);
  plumb::cli::add_status_command(app);
  plumb::cli::add_config_command(app);
  plumb::cli::add_security_command(app);
  plumb::cli::add_launch_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return plumb::components::exit_on_parse_error(app, e);
  } catch (const std::exception& e) {
    return plumb::components::exit_on_error("plumb", e);
  }
  return plumb::cli::g_exit_code;
}
