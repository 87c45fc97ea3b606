// The one plugin facility of plumb: transports (libplumb_transport_<name>.so) and estimators
// (libplumb_estimator_<name>.so) are found, identified, checked and loaded by these rules.
//
// - Search path: the folders in $PLUMB_<KIND>_PATH (':'-separated), then the folder that holds
//   libplumb_plugin.so (build/lib in a build tree, <prefix>/lib when installed). An earlier folder
//   shadows a later one, as PATH does.
// - Identity: the name between the prefix and ".so" is the plugin's one name.
// - Listing reads file names only: no plugin code runs until a plugin is opened.
// - ABI: each plugin's entry point returns a struct whose first member is a `const char*` ABI
//   string, a hash of the interface headers it was built against (cmake/PlumbAbi.cmake); any
//   change to those headers changes it, and a plugin built against other headers is refused.
// - Lifetime: a library, once opened, is never unloaded (RTLD_NODELETE, no dlclose). Vendor DDS
//   libraries leave threads, atexit handlers and static destructors behind, and an exception
//   thrown by plugin code carries type information from the plugin: unmapping either crashes
//   (the class_loader/pluginlib lesson). Objects a plugin creates are destroyed by the plugin.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace plumb::plugin {

// What is wrong with one plugin file, or that a name matches none.
struct Error : std::runtime_error {
  Error(std::string file, std::string reason);
  std::string file;    // the library's path; empty when no file matched
  std::string reason;
};

// A name that matches no plugin: a usage error (the command line must change), hence
// std::invalid_argument, which every plumb program reports with exit status 2. One line naming the
// close matches and the plugins found.
struct UnknownName : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// One family of plugins.
struct Kind {
  const char* label;         // "transport": used in messages
  const char* file_prefix;   // "libplumb_transport_"
  const char* path_env;      // "PLUMB_TRANSPORT_PATH"
  const char* entry_point;   // "plumb_transport_plugin"
  const char* abi;           // the ABI string this program was built with
  const char* not_a_plugin = nullptr;  // a name with the prefix that is a library, not a plugin
};

struct Found {
  std::string name;
  std::string path;
};

std::vector<std::string> search_folders(const Kind& kind);

// Every plugin file on the search path, shadowed ones left out, sorted by name within a folder.
std::vector<Found> find(const Kind& kind);

// "found: a, b" or "found: none, searched X:Y (set PLUMB_..._PATH to add folders)".
std::string describe(const Kind& kind, const std::vector<Found>& found);

// The names of `found` a few edits away from `name` (a typo), closest first, at most three.
std::vector<std::string> close_names(const std::string& name, const std::vector<Found>& found);

// "unknown transport 'fastds': did you mean fastdds? (found: cyclonedds, fastdds)"
std::string unknown_name_message(const Kind& kind, const std::string& name, const std::vector<Found>& found);

// The plugin named `name`: throws UnknownName naming the close matches and the plugins found when
// there is none.
Found locate(const Kind& kind, const std::string& name);

// Opens the library and returns its entry point, a function of no arguments that returns
// `const Plugin*`. Throws Error naming the file and the reason.
void* open_entry_point(const Kind& kind, const Found& plugin);
// Throws Error unless `result`, what the entry point returned, starts with kind.abi.
void check_abi(const Kind& kind, const Found& plugin, const void* result);

// Opens the library and returns what its entry point returns, once the ABI string matched.
// Called through its own type (a call through another function type is undefined behaviour,
// which clang's -fsanitize=function reports). Throws Error naming the file and the reason.
template <class Plugin>
const Plugin* open(const Kind& kind, const Found& plugin) {
  using Entry = const Plugin* (*)();
  const Plugin* result = reinterpret_cast<Entry>(open_entry_point(kind, plugin))();
  check_abi(kind, plugin, result);
  return result;
}

}  // namespace plumb::plugin
