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
  if (names.count(topic)) return {};
  // A typo is a few characters; a third of the name would be another name altogether.
  const std::size_t limit = std::max<std::size_t>(2, std::min<std::size_t>(4, topic.size() / 3));
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const auto& n : names) {
    const std::size_t d = edit_distance(topic, n);
    if (d <= limit) scored.emplace_back(d, n);
  }
  std::sort(scored.begin(), scored.end());
  std::vector<std::string> out;
  for (const auto& [d, n] : scored) {
    if (out.size() == 3 || d > scored.front().first) break;
    out.push_back(n);
  }
  return out;
}

std::string did_you_mean(const std::vector<std::string>& names) {
  if (names.empty()) return "";
  std::string text = "did you mean ";
  for (std::size_t i = 0; i < names.size(); ++i) text += (i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ")) + names[i];
  return text + "?";
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
