// plumb: the command-line tool. `plumb --help` lists the subcommands.
#include <iostream>

#include "commands.hpp"
#include "plumb/components/cli.hpp"

namespace plumb::cli {
int g_exit_code = 0;
}

int main(int argc, char** argv) {
  CLI::App app{"plumb: drilling-tool attitude over DDS (topics, transports, estimator plugins, offline estimation)"};
  app.require_subcommand(1);
  plumb::cli::add_topic_commands(app);
  plumb::cli::add_listing_commands(app);
  plumb::cli::add_estimate_command(app);
#ifdef PLUMB_HAVE_COMPARE
  plumb::cli::add_compare_command(app);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    plumb::components::print_error("plumb", e.what());
    return 1;
  }
  return plumb::cli::g_exit_code;
}
