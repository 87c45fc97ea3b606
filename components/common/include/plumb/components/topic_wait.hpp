// What a listening program (`plumb topic echo|hz`, `plumb-calibrate --live`) says while nothing
// arrives, and the names it suggests for a typo: a program that waits says what it waits for and what
// it does see, instead of waiting in silence.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "plumb/transport/transport.hpp"

namespace plumb::components {

// Up to three known topic names closest to `topic` (edit distance): the exact names of idl/, the
// attitude and navigation topics of the installed estimator plugins, and the topics discovered
// (plumb::closest_names; plumb::did_you_mean words them). Empty when nothing is close or `topic`
// itself is known.
std::vector<std::string> closest_topic_names(transport::Participant& participant, const std::string& topic);

// Notes on stderr after 3, 6, 12, 24... s without a message on the topic (growing, so a long wait is
// said, not shouted): matched writers, the topics that do have writers, and close names. An
// unsecured program (`unsecured`) that sees no writer at all adds that a secured system needs
// --security: secured participants do not show their topics to an unsecured one, and the vendors
// do not tell a participant that another refused it.
class SilenceNotes {
 public:
  SilenceNotes(std::string program, std::string topic, bool unsecured = false);
  void received();  // a message came: the next note waits for a new silence
  void check(transport::Participant& participant, std::size_t matched_writers);

 private:
  using Clock = std::chrono::steady_clock;
  std::string program_;
  std::string topic_;
  bool unsecured_ = false;
  Clock::time_point since_ = Clock::now();
  double next_note_s_ = 3;
};

}  // namespace plumb::components
