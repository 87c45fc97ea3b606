#include "navigator_parameters.hpp"

#include <chrono>
#include <sstream>
#include <utility>

#include "plumb/components/topic_safe.hpp"

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

survey::iscwsa::NavigatorParameters parameters_of(const topics::ComponentParameters& m) {
  survey::iscwsa::NavigatorParameters p;
  for (const auto& row : m.rows) p[row.name] = row.value;
  return p;
}

// "latitude_deg 35 -> 40, gravity_sd 0.002 -> 0.003" (the first three that differ).
std::string differences(const survey::iscwsa::NavigatorParameters& before, const survey::iscwsa::NavigatorParameters& now) {
  std::string out;
  int shown = 0, more = 0;
  for (const auto& [name, value] : now) {
    const auto it = before.find(name);
    const std::string was = it == before.end() ? "(none)" : it->second;
    if (was == value) continue;
    if (shown++ < 3) out += (out.empty() ? "" : ", ") + name + " " + (was.empty() ? "(default)" : was) + " -> " +
                            (value.empty() ? "(default)" : value);
    else ++more;
  }
  if (more > 0) out += " and " + std::to_string(more) + " more";
  return out;
}

}  // namespace

NavigatorParameterWatch::NavigatorParameterWatch(const components::Connection& conn, std::string host, std::string plugin)
    : where_("domain " + std::to_string(conn.options.domain_id) + " (" + conn.transport->name() + ")"),
      secured_(!conn.options.security.empty()),
      host_(std::move(host)),
      plugin_(std::move(plugin)),
      topic_(components::parameters_topic(host_, plugin_)) {
  try {
    reader_.emplace(transport::make_reader<topics::ComponentParameters>(*conn.participant, topic_,
                                                                        transport::default_qos_for_topic(topic_)));
  } catch (const std::exception& e) {
    if (!secured_) throw;
    refused_ = std::string(e.what()) + ": this identity may not read " + topic_ +
               " (the plumb-survey identity may: docs/security.md)";
  }
}

NavigatorAnswer NavigatorParameterWatch::first(double wait_s) {
  NavigatorAnswer answer;
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
  if (!reader_) {
    answer.why = refused_;
    answer.said = "error model: " + answer.why + "; " + fixes();
    answer.status = status_line(host_, "may not be read");
    return answer;
  }
  std::optional<topics::ComponentParameters> latest;
  for (topics::ComponentParameters m;;) {
    while (reader_->take(m)) latest = m;
    if (latest || std::chrono::steady_clock::now() >= until || components::g_stop) break;
    reader_->wait(std::chrono::milliseconds(100));
  }
  if (!latest) {
    std::ostringstream why;
    why << "no estimator host named '" << host_ << "' wrote its " << plugin_ << " parameters (" << topic_ << ") within "
        << wait_s << " s on " << where_ << ": is plumb-estimator --name " << host_ << " running the " << plugin_
        << " plugin on this domain?" << (secured_ ? "" : " (A secured host is read by secured readers only: --security)");
    answer.why = why.str();
    answer.said = "error model: " + answer.why + "; " + fixes();
    answer.status = status_line(host_, "wrote no parameters");
    return answer;
  }
  seen_revision_ = latest->revision;
  if (!latest->loaded) {
    answer.why = "estimator host '" + host_ + "' does not run the " + plugin_ + " plugin (unloaded)";
    answer.said = "error model: " + answer.why + "; " + fixes();
    answer.status = status_line(host_, "runs no " + plugin_);
    return answer;
  }
  answer.parameters = parameters_of(*latest);
  taken_ = answer.parameters;
  std::ostringstream said;
  said << "error model: the " << plugin_ << " navigator's parameters from estimator host '" << host_ << "' ("
       << latest->rows.size() << " parameters, " << topic_ << ")";
  answer.said = said.str();
  return answer;
}

std::optional<NavigatorParameterWatch::Change> NavigatorParameterWatch::change() {
  std::optional<topics::ComponentParameters> latest;
  for (topics::ComponentParameters m; reader_ && reader_->take(m);) latest = std::move(m);
  if (!latest || latest->revision == seen_revision_) return std::nullopt;
  seen_revision_ = latest->revision;
  if (!latest->loaded) {
    if (!taken_) return std::nullopt;
    taken_.reset();
    return Change{"estimator host '" + host_ + "' unloaded the " + plugin_ + " plugin", std::nullopt};
  }
  auto now = parameters_of(*latest);
  if (taken_ && now == *taken_) return std::nullopt;
  const std::string what = taken_ ? differences(*taken_, now) : std::string("now written");
  taken_ = now;
  return Change{"the " + plugin_ + " navigator's parameters on estimator host '" + host_ + "' changed (" + what + ")",
                std::move(now)};
}

}  // namespace plumb::survey_component
