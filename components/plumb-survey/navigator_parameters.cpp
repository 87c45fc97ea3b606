#include "navigator_parameters.hpp"

#include <sstream>

#include "plumb/components/component_client.hpp"

namespace plumb::survey_component {
namespace {

// What the operator can do about a survey that fell back to plumb's own terms.
std::string fixes() {
  return "plumb's own terms instead (--error-model GYRO:tactical, GYRO:mems or a tool code file names the model; "
         "--estimator-host names the host that runs the navigator)";
}

// plumb/status's line (127 characters): the options that fix it before the host's name.
std::string status_line(const std::string& host, const std::string& what) {
  return "error model plumb (--estimator-host NAME or --error-model GYRO:tactical): estimator host '" + host + "' " + what;
}

}  // namespace

NavigatorAnswer ask_navigator_parameters(const components::TransportOptions& transport, const std::string& host,
                                         const std::string& plugin, double wait_s) {
  NavigatorAnswer answer;
  try {
    components::ComponentClient client(transport, wait_s);
    topics::ComponentRequest request;
    request.verb = "dump";
    request.host = host;
    request.plugin = plugin;
    const std::optional<topics::ComponentReply> reply = client.ask(request);
    if (!reply) {
      answer.why = client.no_answer(host);
      answer.said = "error model: " + answer.why + "; " + fixes();
      answer.status = status_line(host, "did not answer");
      return answer;
    }
    if (reply->result != topics::COMPONENT_DONE) {
      answer.why = "estimator host '" + host + "' refused its " + plugin + " parameters (" + reply->message + ")";
      answer.said = "error model: " + answer.why + "; " + fixes();
      answer.status = status_line(host, "refused");
      return answer;
    }
    survey::iscwsa::NavigatorParameters p;
    for (const auto& row : reply->rows) p[row.name] = row.value;
    answer.parameters = std::move(p);
    std::ostringstream said;
    said << "error model: the " << plugin << " navigator's parameters from estimator host '" << host << "' ("
         << reply->rows.size() << " parameters)";
    answer.said = said.str();
  } catch (const std::exception& e) {
    answer.why = "cannot ask estimator host '" + host + "': " + e.what();
    answer.said = "error model: " + answer.why + "; " + fixes();
    answer.status = status_line(host, "cannot be asked");
  }
  return answer;
}

}  // namespace plumb::survey_component
