#include "plumb/components/topic_safe.hpp"

#include <cctype>

#include "plumb/transport/topic_names.hpp"

namespace plumb::components {

std::string topic_safe(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  return name;
}

std::string parameters_topic(const std::string& host, const std::string& plugin) {
  return transport::topic_names::parameters(topic_safe(host) + "/" + topic_safe(plugin));
}

}  // namespace plumb::components
