// The client side of plumb/component/request and plumb/component/reply, shared by the verbs of
// `plumb component` and `plumb param`: a request to one estimator host, sent again until that host
// answers or the wait is over (the host answers a repeat with its first reply and applies it once).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "plumb/components/cli.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::components {

class ComponentClient {
 public:
  ComponentClient(const TransportOptions& transport, double wait_s);
  // The host's answer, or nullopt when `request.host` did not answer within the wait.
  std::optional<topics::ComponentReply> ask(topics::ComponentRequest request);
  // Every host's answer to a list for all (a request with no host), collected for `listen_s`.
  std::vector<topics::ComponentReply> list_all(double listen_s);
  // One line for a host that did not answer: the hosts that do answer, and where we looked.
  std::string no_answer(const std::string& host);

 private:
  void exchange(topics::ComponentRequest& request, double wait_s, std::chrono::milliseconds poll,
                const std::function<bool(const topics::ComponentReply&)>& take);

  Connection conn_;
  transport::Reader<topics::ComponentReply> replies_;
  transport::Writer<topics::ComponentRequest> requests_;
  double wait_s_;
  std::string client_;
  std::uint64_t next_id_ = 1;
};

}  // namespace plumb::components
