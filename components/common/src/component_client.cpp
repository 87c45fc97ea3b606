#include "plumb/components/component_client.hpp"

#include <unistd.h>

#include <chrono>
#include <functional>
#include <iostream>
#include <set>
#include <stdexcept>
#include <sstream>

#include "plumb/components/status_reporter.hpp"
#include "plumb/transport/topic_names.hpp"

namespace plumb::components {
namespace {

namespace names = transport::topic_names;
using RequestClock = std::chrono::steady_clock;

// A request not yet matched by the host's reader is dropped (volatile): it goes again this often.
constexpr std::chrono::milliseconds kResendEvery{500};

std::string make_client_id() {
  std::ostringstream id;
  id << host_name() << ':' << ::getpid() << ':' << std::hex
     << (RequestClock::now().time_since_epoch().count() & 0xffffff);
  return id.str();
}

// On a secured domain only an identity granted plumb/component/request may send requests: said so,
// rather than only the vendor's "not allowed".
transport::Writer<topics::ComponentRequest> make_request_writer(Connection& conn) {
  try {
    return transport::make_writer<topics::ComponentRequest>(*conn.participant, names::kComponentRequest,
                                                            transport::default_qos_for_topic(names::kComponentRequest));
  } catch (const std::exception& e) {
    if (conn.options.security.empty()) throw;
    throw std::runtime_error(std::string(e.what()) +
                             ": this identity may not send requests (the plumb-operator identity may: docs/security.md)");
  }
}

}  // namespace

ComponentClient::ComponentClient(const TransportOptions& transport, double wait_s)
    : conn_(connect(transport, "plumb-component")),
      replies_(transport::make_reader<topics::ComponentReply>(*conn_.participant, names::kComponentReply,
                                                              transport::default_qos_for_topic(names::kComponentReply))),
      requests_(make_request_writer(conn_)),
      wait_s_(wait_s),
      client_(make_client_id()) {}

// Sends the request as soon as a host's reader matched, then again every kResendEvery, and hands
// every reply to it to `take` until `take` has what it wants or `wait_s` is over.
void ComponentClient::exchange(topics::ComponentRequest& request, double wait_s, std::chrono::milliseconds poll,
                               const std::function<bool(const topics::ComponentReply&)>& take) {
  request.client = client_;
  request.request_id = next_id_++;
  const auto until = RequestClock::now() + std::chrono::duration<double>(wait_s);
  auto next_send = RequestClock::now();
  topics::ComponentReply reply;
  while (!g_stop && RequestClock::now() < until) {
    if (RequestClock::now() >= next_send && requests_.matched_readers() > 0) {
      requests_.write(request);
      next_send = RequestClock::now() + kResendEvery;
    }
    replies_.wait(poll);
    while (replies_.take(reply))
      if (reply.client == client_ && reply.request_id == request.request_id && take(reply)) return;
  }
}

std::optional<topics::ComponentReply> ComponentClient::ask(topics::ComponentRequest request) {
  std::optional<topics::ComponentReply> answer;
  exchange(request, wait_s_, std::chrono::milliseconds(20), [&](const topics::ComponentReply& reply) {
    if (reply.host != request.host) return false;
    answer = reply;
    return true;
  });
  return answer;
}

std::vector<topics::ComponentReply> ComponentClient::list_all(double listen_s) {
  topics::ComponentRequest request;
  request.verb = "list";
  std::vector<topics::ComponentReply> out;
  std::set<std::string> answered;
  exchange(request, listen_s, std::chrono::milliseconds(50), [&](const topics::ComponentReply& reply) {
    if (answered.insert(reply.host).second) out.push_back(reply);
    return false;  // every host that answers within listen_s
  });
  return out;
}

std::string ComponentClient::no_answer(const std::string& host) {
  std::string seen;
  for (const auto& r : list_all(1.5)) seen += (seen.empty() ? "" : ", ") + r.host;
  std::ostringstream out;
  out << "no estimator host named '" << host << "' answered within " << wait_s_ << " s on domain "
      << conn_.options.domain_id << " (" << conn_.transport->name() << "): "
      << (seen.empty() ? std::string("no estimator host answers (is plumb-estimator running, on this --domain?") +
                             (conn_.options.security.empty() ? " A secured host answers secured clients only: --security)" : ")")
                       : "hosts seen: " + seen + " (plumb-estimator --name)");
  return out.str();
}

}  // namespace plumb::components
