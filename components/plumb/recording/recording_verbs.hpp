// The verbs on MCAP recordings, each in its own file: record (and --repair), play, info, export.
#pragma once

#include "verbs.hpp"

namespace plumb::cli {

void add_recording_record(CLI::App& app, Verbs& verbs);
void add_recording_play(CLI::App& app, Verbs& verbs);
void add_recording_info(CLI::App& app, Verbs& verbs);
void add_recording_export(CLI::App& app, Verbs& verbs);

}  // namespace plumb::cli
