// plumb plugins: the estimator plugins found, whether each loads, and with -v their parameters.
#include <iostream>
#include <memory>

#include "plugins/plugin_verbs.hpp"
#include "plumb/estimator/loader.hpp"

namespace plumb::cli {
namespace {

int run_plugins(bool verbose) {
  int status = 0;
  const auto found = estimator::find_plugins();
  if (found.empty()) {
    std::cerr << "plumb plugins: no estimator plugin found (set PLUMB_ESTIMATOR_PATH?)" << std::endl;
    status = 1;
  }
  for (const auto& p : found) {
    if (!p.error.empty()) {
      std::cout << p.name << "  BROKEN: " << p.error << "  " << p.path << '\n';
      status = 1;
      continue;
    }
    std::cout << p.name << "  " << p.description << "  " << p.path << '\n';
    if (!verbose) continue;
    const auto est = estimator::load_estimator(p.name);
    for (const auto& spec : est->info().parameters) {
      std::cout << "    " << spec.name << " (default " << spec.default_value << "): " << spec.description << '\n';
    }
  }
  return status;
}

}  // namespace

void add_plugins_verb(CLI::App& app, Verbs& verbs) {
  auto* plugins = app.add_subcommand("plugins", "List the estimator plugins found, with their parameters");
  auto verbose = std::make_shared<bool>(false);
  plugins->add_flag("-v,--verbose", *verbose, "also list each plugin's parameters");
  verbs.add(plugins, [verbose] { return run_plugins(*verbose); });
}

}  // namespace plumb::cli
