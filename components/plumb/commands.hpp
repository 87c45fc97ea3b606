// The subcommands of the `plumb` tool; each registers itself on the CLI11 app and runs when chosen.
#pragma once

#include <CLI/CLI.hpp>

namespace plumb::cli {

void add_topic_commands(CLI::App& app);      // topic list | echo | hz | pub
void add_listing_commands(CLI::App& app);    // transports, plugins
void add_estimate_command(CLI::App& app);    // estimate (offline, CSV in, CSV out)
void add_compare_command(CLI::App& app);     // compare (scenario grid, CRB, plots)
void add_record_command(CLI::App& app);      // record (topics into an MCAP file), record --repair
void add_play_command(CLI::App& app);        // play (an MCAP recording back onto the topics)
void add_info_command(CLI::App& app);        // info (what a recording holds)
void add_export_command(CLI::App& app);      // export (a recorded topic as CSV)
void add_survey_command(CLI::App& app);      // survey (offline: stations, QC, minimum curvature, uncertainty)
void add_status_command(CLI::App& app);      // status (components seen on the network)
void add_config_command(CLI::App& app);      // config check (DDS XML files for other applications)
void add_security_command(CLI::App& app);    // security create-keystore | create-identity | create-permissions | check

// Set by a subcommand's callback: the process exit code.
extern int g_exit_code;

}  // namespace plumb::cli
