// plumb component list|load|unload and plumb param get|set|dump: a running estimator host's plugins
// loaded, unloaded and tuned over DDS, as `ros2 component` and `ros2 param` do with a ROS 2
// container. The host applies a change between two pushes of samples: docs/components.md.
#include <iomanip>
#include <iostream>
#include <memory>

#include "plumb/components/cli.hpp"
#include "plumb/components/component_client.hpp"
#include "plumb/transport/topic_names.hpp"
#include "verbs.hpp"

namespace plumb::cli {
namespace {

using components::ComponentClient;

// Runs a request against HOST and prints the refusal (one line on stderr, exit 1) or hands the
// accepted reply to `print` (exit 0). A host that did not answer: exit 1 with no_answer's line.
int run_component_request(const components::TransportOptions& transport, double wait_s, topics::ComponentRequest request,
                          void (*print)(const topics::ComponentReply&)) {
  components::install_stop_handler();
  ComponentClient client(transport, wait_s);
  const std::optional<topics::ComponentReply> reply = client.ask(request);
  if (!reply) {
    components::print_error("plumb", client.no_answer(request.host));
    return 1;
  }
  if (reply->result != topics::COMPONENT_DONE) {
    components::print_error("plumb", reply->message);
    return 1;
  }
  print(*reply);
  return 0;
}

struct ComponentOptions {
  components::TransportOptions transport;
  double wait_s = 5;
  std::string host, plugin, name, value;
  std::vector<std::string> params;
};

void print_message(const topics::ComponentReply& reply) { std::cout << reply.host << ": " << reply.message << std::endl; }

void print_plugins(const topics::ComponentReply& reply) {
  for (const auto& row : reply.rows)
    std::cout << std::left << std::setw(20) << reply.host << std::setw(14) << row.plugin << std::setw(30)
              << transport::topic_names::attitude(row.plugin) << row.value << '\n';
  std::cout << std::flush;
}

void print_value(const topics::ComponentReply& reply) {
  for (const auto& row : reply.rows) std::cout << row.value << std::endl;
}

// An empty value is one the plugin works out itself (strapdown's gravity from the data, ...).
std::string shown_value(const std::string& value) { return value.empty() ? "(none: the plugin's own)" : value; }

void print_parameters(const topics::ComponentReply& reply) {
  for (const auto& row : reply.rows)
    std::cout << row.name << " = " << shown_value(row.value)
              << (row.value == row.default_value ? "" : "  (default " + shown_value(row.default_value) + ")") << '\n';
  std::cout << std::flush;
}

// Every host's plugins (no HOST: each host that answers within --wait), or one host's.
int run_list(const ComponentOptions& o) {
  topics::ComponentRequest request;
  request.verb = "list";
  request.host = o.host;
  if (!o.host.empty()) return run_component_request(o.transport, o.wait_s, request, print_plugins);
  components::install_stop_handler();
  ComponentClient client(o.transport, o.wait_s);
  const auto replies = client.list_all(o.wait_s);
  if (replies.empty()) {
    components::print_error("plumb", "no estimator host answered within " + std::to_string(static_cast<int>(o.wait_s)) +
                                         " s (is plumb-estimator running, on this --domain?)");
    return 1;
  }
  for (const auto& r : replies) print_plugins(r);
  return 0;
}

topics::ComponentRequest request_of(const ComponentOptions& o, const std::string& verb) {
  topics::ComponentRequest r;
  r.verb = verb;
  r.host = o.host;
  r.plugin = o.plugin;
  r.name = o.name;
  r.value = o.value;
  if (verb == "load")
    for (const auto& p : o.params) r.value += (r.value.empty() ? "" : ";") + p;
  return r;
}

// The options every verb of both groups has.
std::shared_ptr<ComponentOptions> common_options(CLI::App& verb) {
  auto o = std::make_shared<ComponentOptions>();
  components::add_transport_options(verb, o->transport);
  verb.add_option("--wait", o->wait_s, "seconds to wait for the host's answer")->capture_default_str()->check(CLI::PositiveNumber);
  return o;
}

void add_host_plugin(CLI::App& verb, ComponentOptions& o) {
  verb.add_option("HOST", o.host, "the estimator host (plumb-estimator --name; default its computer's host name)")->required();
  verb.add_option("PLUGIN", o.plugin, "estimator plugin (see plumb plugins)")->required();
}

}  // namespace

void add_component_verbs(CLI::App& app, Verbs& verbs) {
  auto* group = app.add_subcommand("component", "A running estimator host's plugins: list, load, unload (over DDS)");
  group->require_subcommand(1);
  group->footer("A change applies between two pushes of samples: the plugin's open window is published first, the "
                "other plugins carry on untouched (docs/components.md).");

  auto* list = group->add_subcommand("list", "The plugins each estimator host runs (or HOST's)");
  auto lo = common_options(*list);
  list->add_option("HOST", lo->host, "only this host (plumb-estimator --name)");
  verbs.add(list, [lo] { return run_list(*lo); });

  auto* load = group->add_subcommand("load", "Load a plugin into a running host; it publishes plumb/attitude/PLUGIN");
  auto ld = common_options(*load);
  add_host_plugin(*load, *ld);
  load->add_option("--param", ld->params, "[PLUGIN.]KEY=VALUE for the new plugin (repeat); --window is the host's");
  verbs.add(load, [ld] { return run_component_request(ld->transport, ld->wait_s, request_of(*ld, "load"), print_message); });

  auto* unload = group->add_subcommand("unload", "Unload a plugin from a running host (its open window is published first)");
  auto ul = common_options(*unload);
  add_host_plugin(*unload, *ul);
  verbs.add(unload, [ul] { return run_component_request(ul->transport, ul->wait_s, request_of(*ul, "unload"), print_message); });

  auto* param = app.add_subcommand("param", "A running host's plugin parameters: get, set, dump (over DDS)");
  param->require_subcommand(1);
  param->footer("A value is refused with the message plumb-estimator --param gives for it; an accepted one applies "
                "from the plugin's next window (docs/components.md).");

  auto* get = param->add_subcommand("get", "Print a plugin parameter's value in use");
  auto go = common_options(*get);
  add_host_plugin(*get, *go);
  get->add_option("NAME", go->name, "parameter (see plumb plugins -v)")->required();
  verbs.add(get, [go] { return run_component_request(go->transport, go->wait_s, request_of(*go, "get"), print_value); });

  auto* set = param->add_subcommand("set", "Set a plugin parameter; it applies from the plugin's next window");
  auto so = common_options(*set);
  add_host_plugin(*set, *so);
  set->add_option("NAME", so->name, "parameter (see plumb plugins -v)")->required();
  set->add_option("VALUE", so->value, "new value")->required();
  verbs.add(set, [so] { return run_component_request(so->transport, so->wait_s, request_of(*so, "set"), print_message); });

  auto* dump = param->add_subcommand("dump", "Print every parameter of a plugin with its value in use");
  auto dm = common_options(*dump);
  add_host_plugin(*dump, *dm);
  verbs.add(dump, [dm] { return run_component_request(dm->transport, dm->wait_s, request_of(*dm, "dump"), print_parameters); });
}

}  // namespace plumb::cli
