#include "plumb/components/parameters_topic.hpp"

#include <cctype>

#include "plumb/transport/topic_names.hpp"

namespace plumb::components {
namespace {

std::string topic_safe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  return s;
}

}  // namespace

std::string parameters_topic(const std::string& host, const std::string& plugin) {
  return transport::topic_names::parameters(topic_safe(host) + "/" + topic_safe(plugin));
}

}  // namespace plumb::components
