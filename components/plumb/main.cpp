// plumb: the command-line tool. `plumb --help` lists the verbs; each verb group is one folder here,
// and the verb the command line chose returns the exit status.
#include "plumb/components/cli.hpp"
#include "verbs.hpp"

int main(int argc, char** argv) {
  CLI::App app{"plumb: drilling-tool attitude over DDS (topics, transports, estimator plugins, offline estimation)"};
  app.name("plumb");
  app.require_subcommand(1);
  plumb::cli::Verbs verbs;
  plumb::cli::add_topic_verbs(app, verbs);
  plumb::cli::add_plugin_verbs(app, verbs);
  plumb::cli::add_estimate_verb(app, verbs);
  plumb::cli::add_compare_verb(app, verbs);
  plumb::cli::add_recording_verbs(app, verbs);
  plumb::cli::add_survey_verb(app, verbs);
  plumb::cli::add_clearance_verb(app, verbs);
  plumb::cli::add_status_verb(app, verbs);
  plumb::cli::add_component_verbs(app, verbs);
  plumb::cli::add_config_verbs(app, verbs);
  plumb::cli::add_security_verbs(app, verbs);
  plumb::cli::add_launch_verb(app, verbs);
  try {
    app.parse(argc, argv);
    return verbs.run_chosen(app);
  } catch (const CLI::ParseError& e) {
    return plumb::components::exit_on_parse_error(app, e);
  } catch (const std::exception& e) {
    return plumb::components::exit_on_error("plumb", e);
  }
}
