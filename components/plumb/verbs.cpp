#include "verbs.hpp"

#include <stdexcept>
#include <string>

namespace plumb::cli {

int Verbs::run_chosen(const CLI::App& app) const {
  const CLI::App* chosen = &app;
  for (auto subcommands = chosen->get_subcommands(); !subcommands.empty(); subcommands = chosen->get_subcommands())
    chosen = subcommands.front();
  for (const auto& [command, run] : verbs_)
    if (command == chosen) return run();
  // Every subcommand without subcommands of its own is a verb: a missing one is a bug here.
  throw std::logic_error("'" + chosen->get_name() + "' has nothing to run");
}

}  // namespace plumb::cli
