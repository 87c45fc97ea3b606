// Finds and loads transport plugins (libplumb_transport_<name>.so) at run time.
#include "plumb/transport/loader.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string_view>

namespace plumb::transport {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kPrefix = "libplumb_transport_";
constexpr std::string_view kSuffix = ".so";
constexpr const char* kPathEnv = "PLUMB_TRANSPORT_PATH";

// The folder holding this library (libplumb_transport.so): plugins are installed next to it.
std::string own_directory() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&find_transports), &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code ec;
  const fs::path path = fs::canonical(info.dli_fname, ec);
  return ec ? fs::path(info.dli_fname).parent_path().string() : path.parent_path().string();
}

std::vector<std::string> search_directories() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv(kPathEnv); env != nullptr) {
    std::string_view rest(env);
    while (!rest.empty()) {
      const auto colon = rest.find(':');
      const std::string_view dir = rest.substr(0, colon);
      if (!dir.empty()) dirs.emplace_back(dir);
      rest = colon == std::string_view::npos ? std::string_view{} : rest.substr(colon + 1);
    }
  }
  if (std::string own = own_directory(); !own.empty()) dirs.push_back(std::move(own));
  return dirs;
}

std::string found_list(const std::vector<FoundTransport>& found) {
  if (found.empty()) {
    std::string dirs;
    for (const auto& dir : search_directories()) dirs += (dirs.empty() ? "" : ":") + dir;
    return "(found: none, searched " + (dirs.empty() ? std::string("nothing") : dirs) + ")";
  }
  std::vector<std::string> sorted;
  for (const auto& t : found) sorted.push_back(t.name);
  std::sort(sorted.begin(), sorted.end());
  std::string names;
  for (const auto& name : sorted) names += (names.empty() ? "" : ", ") + name;
  return "(found: " + names + ")";
}

const plumb_transport_plugin_v1* open_plugin(const FoundTransport& found, const std::vector<FoundTransport>& all) {
  // RTLD_NODELETE: a plugin is never unloaded. Vendor DDS libraries start threads and register
  // static destructors and atexit handlers; unmapping their code while any of that is alive
  // crashes at exit (the class_loader/pluginlib lesson). dlclose is therefore never called.
  void* handle = dlopen(found.path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw Error("transport '" + found.name + "' could not be loaded from " + found.path + ": " +
                (why ? why : "unknown dlopen error") + " " + found_list(all));
  }
  using Entry = const plumb_transport_plugin_v1* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(handle, "plumb_transport_plugin"));
  if (entry == nullptr) {
    throw Error("transport '" + found.name + "' in " + found.path + " has no plumb_transport_plugin entry point " +
                found_list(all));
  }
  const plumb_transport_plugin_v1* plugin = entry();
  if (plugin == nullptr) {
    throw Error("transport '" + found.name + "' in " + found.path + " returned no plugin " + found_list(all));
  }
  if (plugin->abi_version != PLUMB_TRANSPORT_ABI_VERSION) {
    throw Error("transport '" + found.name + "' in " + found.path + " has ABI version " +
                std::to_string(plugin->abi_version) + ", this program needs " +
                std::to_string(PLUMB_TRANSPORT_ABI_VERSION) + " " + found_list(all));
  }
  if (plugin->create == nullptr) {
    throw Error("transport '" + found.name + "' in " + found.path + " has no create function " + found_list(all));
  }
  return plugin;
}

}  // namespace

std::vector<FoundTransport> find_transports() {
  std::vector<FoundTransport> found;
  for (const auto& dir : search_directories()) {
    std::error_code ec;
    std::vector<FoundTransport> here;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      const std::string file = entry.path().filename().string();
      if (file.size() <= kPrefix.size() + kSuffix.size() || !file.starts_with(kPrefix) || !file.ends_with(kSuffix)) {
        continue;
      }
      const std::string name = file.substr(kPrefix.size(), file.size() - kPrefix.size() - kSuffix.size());
      // Earlier directories win: $PLUMB_TRANSPORT_PATH overrides the installed plugins.
      const bool known = std::any_of(found.begin(), found.end(), [&](const auto& t) { return t.name == name; });
      if (!known) here.push_back({name, entry.path().string()});
    }
    std::sort(here.begin(), here.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    found.insert(found.end(), here.begin(), here.end());
  }
  return found;
}

std::string resolve_transport_name(const std::string& name) {
  if (!name.empty()) return name;
  if (const char* env = std::getenv(kTransportEnv); env != nullptr && *env != '\0') return env;
  return kDefaultTransport;
}

std::shared_ptr<Transport> load_transport(const std::string& requested) {
  const std::string name = resolve_transport_name(requested);
  const std::vector<FoundTransport> found = find_transports();
  const auto it = std::find_if(found.begin(), found.end(), [&](const auto& t) { return t.name == name; });
  if (it == found.end()) throw Error("unknown transport '" + name + "' " + found_list(found));

  // dlopen is thread-safe, but one lock keeps the error messages of concurrent loads apart.
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  const plumb_transport_plugin_v1* plugin = open_plugin(*it, found);
  Transport* transport = plugin->create();
  if (transport == nullptr) throw Error("transport '" + name + "' failed to start " + found_list(found));
  return std::shared_ptr<Transport>(transport);
}

}  // namespace plumb::transport
