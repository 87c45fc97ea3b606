// Finds estimator plugins on disk and loads them by name (see loader.hpp). The library handle is
// shared by every instance it created, so a plugin is unloaded only after its last estimator dies:
// the deleter runs the plugin's own destroy (the object was allocated by the plugin's allocator).
#include "plumb/estimator/loader.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>

namespace plumb::estimator {
namespace {

namespace fs = std::filesystem;

constexpr const char* kPrefix = "libplumb_estimator_";
constexpr const char* kSuffix = ".so";

// Folders to search, in order: $PLUMB_ESTIMATOR_PATH, then the folder holding this library.
std::vector<fs::path> search_folders() {
  std::vector<fs::path> folders;
  if (const char* env = std::getenv("PLUMB_ESTIMATOR_PATH"); env != nullptr) {
    std::stringstream list(env);
    std::string item;
    while (std::getline(list, item, ':')) {
      if (!item.empty()) folders.emplace_back(item);
    }
  }
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&search_folders), &info) != 0 && info.dli_fname != nullptr) {
    folders.push_back(fs::path(info.dli_fname).parent_path());
  }
  return folders;
}

// Plugin name from a file name, or empty when the file is not an estimator plugin. The API library
// itself (libplumb_estimator_api.so) shares the prefix and is skipped.
std::string plugin_name(const std::string& filename) {
  const std::string prefix = kPrefix, suffix = kSuffix;
  if (filename.size() <= prefix.size() + suffix.size()) return {};
  if (filename.compare(0, prefix.size(), prefix) != 0) return {};
  if (filename.compare(filename.size() - suffix.size(), suffix.size(), suffix) != 0) return {};
  std::string name = filename.substr(prefix.size(), filename.size() - prefix.size() - suffix.size());
  return name == "api" ? std::string{} : name;
}

struct Library {
  std::shared_ptr<void> handle;
  const plumb_estimator_plugin_v1* plugin = nullptr;
  std::string error;
};

Library open_library(const std::string& path) {
  Library lib;
  dlerror();
  // RTLD_NODELETE: an exception thrown by plugin code (ParameterError from configure, say) carries
  // a vtable and type_info from the plugin; if the last instance died while it propagates, an
  // unmapped library would crash the catch. So a library, once loaded, stays mapped.
  void* raw = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (raw == nullptr) {
    const char* why = dlerror();
    lib.error = why != nullptr ? why : "dlopen failed";
    return lib;
  }
  lib.handle = std::shared_ptr<void>(raw, [](void* h) { dlclose(h); });
  using EntryPoint = const plumb_estimator_plugin_v1* (*)();
  auto entry = reinterpret_cast<EntryPoint>(dlsym(raw, "plumb_estimator_plugin"));
  if (entry == nullptr) {
    lib.error = "no plumb_estimator_plugin entry point";
    return lib;
  }
  const plumb_estimator_plugin_v1* plugin = entry();
  if (plugin == nullptr) {
    lib.error = "entry point returned no plugin";
  } else if (plugin->abi_version != PLUMB_ESTIMATOR_ABI_VERSION) {
    lib.error = "ABI version " + std::to_string(plugin->abi_version) + ", expected " +
                std::to_string(PLUMB_ESTIMATOR_ABI_VERSION);
  } else if (plugin->create == nullptr || plugin->destroy == nullptr) {
    lib.error = "plugin has no create/destroy";
  } else {
    lib.plugin = plugin;
  }
  return lib;
}

std::string describe_found(const std::vector<FoundPlugin>& found) {
  if (found.empty()) return "no estimator plugins found";
  std::string text = "plugins found:";
  for (const auto& p : found) {
    text += " " + p.name;
    if (!p.error.empty()) text += " (broken: " + p.error + ")";
  }
  return text;
}

std::string describe_folders() {
  std::string text;
  for (const auto& folder : search_folders()) text += (text.empty() ? "" : ":") + folder.string();
  return text;
}

}  // namespace

std::vector<FoundPlugin> find_plugins() {
  std::vector<FoundPlugin> found;
  std::set<std::string> seen;  // an earlier folder shadows a later one, as PATH does
  for (const auto& folder : search_folders()) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) continue;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder, ec)) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      const std::string name = plugin_name(file.filename().string());
      if (name.empty() || !seen.insert(name).second) continue;
      FoundPlugin plugin{name, file.string(), {}, {}};
      Library lib = open_library(plugin.path);
      if (lib.plugin != nullptr) {
        plugin.description = lib.plugin->description != nullptr ? lib.plugin->description : "";
      } else {
        plugin.error = lib.error;
      }
      found.push_back(std::move(plugin));
    }
  }
  return found;
}

EstimatorPtr load_estimator(const std::string& name) {
  const auto found = find_plugins();
  for (const auto& candidate : found) {
    if (candidate.name != name) continue;
    Library lib = open_library(candidate.path);
    if (lib.plugin == nullptr) {
      throw std::runtime_error("estimator plugin '" + name + "' at " + candidate.path + " cannot be used: " + lib.error);
    }
    Estimator* raw = lib.plugin->create();
    if (raw == nullptr) throw std::runtime_error("estimator plugin '" + name + "' failed to create an estimator");
    auto destroy = lib.plugin->destroy;
    std::shared_ptr<void> handle = lib.handle;
    return EstimatorPtr(raw, [destroy, handle](Estimator* e) { destroy(e); });
  }
  throw std::runtime_error("unknown estimator '" + name + "'; " + describe_found(found) + " (searched " +
                           describe_folders() + ", set PLUMB_ESTIMATOR_PATH to add folders)");
}

}  // namespace plumb::estimator
