// The host's side of plumb/component/request and plumb/component/reply: the requests addressed to
// this host (by its --name; a list with no name is for every host), and the answers. A client sends
// a request again until it is answered, so a request seen before is answered again from here with
// its first reply and never applied twice.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "plumb/transport/transport.hpp"

namespace plumb::estimator_component {

class ComponentService {
 public:
  ComponentService(transport::Participant& participant, std::string host_name);
  const std::string& name() const { return name_; }
  // New requests for this host, oldest first. allocates: yes. blocks: no.
  std::vector<topics::ComponentRequest> take();
  // Sends the reply (host, client and request_id filled in from the request) and keeps it for a
  // repeat of the request.
  void answer(const topics::ComponentRequest& request, topics::ComponentReply reply);
  std::uint64_t answered() const { return answered_; }
  std::uint64_t refused() const { return refused_; }

 private:
  std::string name_;
  transport::Reader<topics::ComponentRequest> requests_;
  transport::Writer<topics::ComponentReply> replies_;
  // client -> its last request id and reply, for a repeat; the clients of the last kKeptClients
  // requests only (each `plumb` command is a client of its own: a host that runs for months must
  // not keep them all).
  static constexpr std::size_t kKeptClients = 64;
  std::map<std::string, std::pair<std::uint64_t, topics::ComponentReply>> last_;
  std::deque<std::string> order_;  // clients in last_, oldest first
  std::uint64_t answered_ = 0;
  std::uint64_t refused_ = 0;
};

}  // namespace plumb::estimator_component
