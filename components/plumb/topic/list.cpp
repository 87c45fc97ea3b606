// plumb topic list: list the topics seen through DDS discovery.
#include <algorithm>
#include <iostream>
#include <memory>
#include <thread>

#include "topic/topic_verbs.hpp"

namespace plumb::cli {
namespace {

struct ListOptions {
  components::TransportOptions transport;
  double wait_s = 2;
};

int run_list(const ListOptions& o) {
  auto conn = components::connect(o.transport, "plumb-topic-list");
  std::this_thread::sleep_for(std::chrono::duration<double>(o.wait_s));
  auto topics = conn.participant->discovered_topics();
  std::sort(topics.begin(), topics.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  if (topics.empty()) std::cerr << "plumb topic list: no topics seen within " << o.wait_s << " s" << std::endl;
  for (const auto& t : topics) {
    std::cout << t.name << "  [" << t.type_name << "]  writers: " << t.writers << "  readers: " << t.readers << '\n';
  }
  return 0;
}

}  // namespace

void add_topic_list(CLI::App& topic, Verbs& verbs) {
  auto o = std::make_shared<ListOptions>();
  auto* list = topic.add_subcommand("list", "List the topics seen through DDS discovery");
  components::add_transport_options(*list, o->transport);
  list->add_option("--wait", o->wait_s, "seconds to listen for discovery")->capture_default_str();
  verbs.add(list, [o] { return run_list(*o); });
}

}  // namespace plumb::cli
