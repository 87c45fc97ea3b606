// plumb topic: list, print, measure and publish topics, one verb per file.
#include "topic/topic_verbs.hpp"

#include "messages/fields.hpp"

namespace plumb::cli {

std::string end_reason(double timeout_s, double elapsed_s) {
  if (components::g_stop) return "interrupted after " + format_measured(elapsed_s) + " s";
  if (timeout_s > 0 && elapsed_s >= timeout_s) return "timed out after " + format_measured(elapsed_s) + " s";
  return "in " + format_measured(elapsed_s) + " s";
}

void add_topic_verbs(CLI::App& app, Verbs& verbs) {
  auto* topic = app.add_subcommand("topic", "List, print, measure and publish topics");
  topic->require_subcommand(1);
  add_topic_list(*topic, verbs);
  add_topic_echo(*topic, verbs);
  add_topic_hz(*topic, verbs);
  add_topic_pub(*topic, verbs);
}

}  // namespace plumb::cli
