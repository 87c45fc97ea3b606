#include "plumb/components/topic_wait.hpp"

#include <algorithm>
#include <iostream>
#include <set>

#include "plumb/core/edit_distance.hpp"
#include "plumb/estimator/loader.hpp"
#include "plumb/transport/topic_names.hpp"

namespace plumb::components {

namespace {

std::set<std::string> known_topic_names(transport::Participant& participant) {
  std::set<std::string> names;
  for (const auto& e : topics::kTopicTable)
    if (!e.prefix) names.insert(e.name);
  for (const auto& p : estimator::list_plugins()) {  // by file name: nothing is opened
    names.insert(transport::topic_names::attitude(p.name));
    names.insert(transport::topic_names::navigation(p.name));
  }
  // Only topics someone writes: our own reader makes the mistyped name "discovered" too.
  for (const auto& d : participant.discovered_topics())
    if (d.writers > 0) names.insert(d.name);
  return names;
}

}  // namespace

std::vector<std::string> closest_topic_names(transport::Participant& participant, const std::string& topic) {
  const auto names = known_topic_names(participant);
  return closest_names(topic, std::vector<std::string>(names.begin(), names.end()));
}

SilenceNotes::SilenceNotes(std::string program, std::string topic, bool unsecured)
    : program_(std::move(program)), topic_(std::move(topic)), unsecured_(unsecured) {}

void SilenceNotes::received() {
  since_ = Clock::now();
  next_note_s_ = 3;
}

void SilenceNotes::check(transport::Participant& participant, std::size_t matched_writers) {
  const double silent_s = std::chrono::duration<double>(Clock::now() - since_).count();
  if (silent_s < next_note_s_) return;
  next_note_s_ *= 2;
  std::string line = program_ + ": nothing on " + topic_ + " for " + std::to_string(static_cast<int>(silent_s)) +
                     " s (" + std::to_string(matched_writers) + " writer(s) matched); ";
  std::string with_writers;
  std::size_t topic_writers = 0;  // writers seen on the topic itself, matched or not
  for (const auto& t : participant.discovered_topics()) {
    if (t.writers > 0 && t.name != topic_) with_writers += (with_writers.empty() ? "" : ", ") + t.name;
    if (t.name == topic_) topic_writers += t.writers;
  }
  line += with_writers.empty() ? "no topic has a writer on this domain" : "topics with writers: " + with_writers;
  if (matched_writers == 0) {
    const std::string hint = did_you_mean(closest_topic_names(participant, topic_));
    if (!hint.empty()) line += "; " + hint;
  }
  if (unsecured_ && matched_writers == 0 && (with_writers.empty() || topic_writers > 0))
    line += "; if the system is secured, its participants ignore an unsecured one: give --security DIR (an identity "
            "folder, docs/security.md)";
  std::cerr << line << std::endl;
}

}  // namespace plumb::components
