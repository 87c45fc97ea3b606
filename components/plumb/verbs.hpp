// The verbs of the `plumb` command. Each verb group (one folder: topic/, recording/, survey/, ...)
// adds its subcommands and, for each verb, what runs it; `main` runs the verb the command line
// chose and returns that verb's exit status, so no verb sets the process's status anywhere else.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace plumb::cli {

class Verbs {
 public:
  // What a verb does once its command line is parsed: returns the exit status.
  using Run = std::function<int()>;

  void add(const CLI::App* command, Run run) { verbs_.emplace_back(command, std::move(run)); }

  // Runs the verb the parsed command line chose (its deepest subcommand) and returns its status.
  int run_chosen(const CLI::App& app) const;

 private:
  std::vector<std::pair<const CLI::App*, Run>> verbs_;
};

// The verb groups, one folder each, in the order `plumb --help` lists them.
void add_topic_verbs(CLI::App& app, Verbs& verbs);     // topic list | echo | hz | pub
void add_plugin_verbs(CLI::App& app, Verbs& verbs);    // transports, plugins
void add_estimate_verb(CLI::App& app, Verbs& verbs);   // estimate (offline, CSV or recording in, CSV out)
void add_compare_verb(CLI::App& app, Verbs& verbs);    // compare (scenario grid, CRB, plots; or a recorded run)
void add_recording_verbs(CLI::App& app, Verbs& verbs); // record (and --repair), play, info, export
void add_survey_verb(CLI::App& app, Verbs& verbs);     // survey (offline: stations, QC, minimum curvature, uncertainty)
void add_clearance_verb(CLI::App& app, Verbs& verbs);  // clearance (offline anti-collision: ISCWSA separation factor)
void add_status_verb(CLI::App& app, Verbs& verbs);     // status (components seen on the network)
void add_component_verbs(CLI::App& app, Verbs& verbs); // component list | load | unload, param get | set | dump (a running estimator host)
void add_config_verbs(CLI::App& app, Verbs& verbs);    // config check (DDS XML files for other applications)
void add_security_verbs(CLI::App& app, Verbs& verbs);  // security create-keystore | create-identity | create-permissions | check
void add_launch_verb(CLI::App& app, Verbs& verbs);     // launch (a set of plumb programs from a launch file)

}  // namespace plumb::cli
