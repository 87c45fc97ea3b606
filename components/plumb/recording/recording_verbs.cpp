#include "recording/recording_verbs.hpp"

namespace plumb::cli {

void add_recording_verbs(CLI::App& app, Verbs& verbs) {
  add_recording_record(app, verbs);
  add_recording_play(app, verbs);
  add_recording_info(app, verbs);
  add_recording_export(app, verbs);
}

}  // namespace plumb::cli
