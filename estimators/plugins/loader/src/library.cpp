#include "plumb/plugin/library.hpp"

#include "plumb/core/edit_distance.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>
#include <sstream>

namespace plumb::plugin {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSuffix = ".so";

std::string own_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&own_folder), &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code ec;
  const fs::path path = fs::canonical(info.dli_fname, ec);
  return (ec ? fs::path(info.dli_fname) : path).parent_path().string();
}

std::string name_of(const Kind& kind, const std::string& file) {
  const std::string prefix = kind.file_prefix;
  const std::string suffix = kSuffix;
  if (file.size() <= prefix.size() + suffix.size() || !file.starts_with(prefix) || !file.ends_with(suffix)) return {};
  std::string name = file.substr(prefix.size(), file.size() - prefix.size() - suffix.size());
  if (kind.not_a_plugin != nullptr && name == kind.not_a_plugin) return {};
  return name;
}

}  // namespace

Error::Error(std::string f, std::string r)
    : std::runtime_error(f.empty() ? r : f + ": " + r), file(std::move(f)), reason(std::move(r)) {}

std::vector<std::string> search_folders(const Kind& kind) {
  std::vector<std::string> folders;
  if (const char* env = std::getenv(kind.path_env); env != nullptr) {
    std::stringstream list(env);
    std::string item;
    while (std::getline(list, item, ':'))
      if (!item.empty()) folders.push_back(item);
  }
  if (std::string own = own_folder(); !own.empty()) folders.push_back(std::move(own));
  return folders;
}

std::vector<Found> find(const Kind& kind) {
  std::vector<Found> found;
  std::set<std::string> seen;
  for (const auto& folder : search_folders(kind)) {
    std::error_code ec;
    std::vector<Found> here;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
      std::string name = name_of(kind, entry.path().filename().string());
      if (!name.empty() && !seen.contains(name)) here.push_back({std::move(name), entry.path().string()});
    }
    std::sort(here.begin(), here.end(), [](const Found& a, const Found& b) { return a.name < b.name; });
    for (const auto& f : here) seen.insert(f.name);
    found.insert(found.end(), here.begin(), here.end());
  }
  return found;
}

std::string describe(const Kind& kind, const std::vector<Found>& found) {
  if (!found.empty()) {
    std::string names;
    for (const auto& f : found) names += (names.empty() ? "" : ", ") + f.name;
    return "found: " + names;
  }
  std::string folders;
  for (const auto& folder : search_folders(kind)) folders += (folders.empty() ? "" : ":") + folder;
  return "found: none, searched " + (folders.empty() ? std::string("nothing") : folders) + " (set " + kind.path_env +
         " to add folders)";
}

std::string unknown_name_message(const Kind& kind, const std::string& name, const std::vector<Found>& found) {
  std::string text = "unknown " + std::string(kind.label) + " '" + name + "'";
  std::vector<std::string> names;
  for (const auto& f : found) names.push_back(f.name);
  if (const std::string hint = did_you_mean(closest_names(name, names)); !hint.empty()) text += ": " + hint;
  return text + " (" + describe(kind, found) + ")";
}

Found locate(const Kind& kind, const std::string& name) {
  const auto found = find(kind);
  const auto it = std::find_if(found.begin(), found.end(), [&](const Found& f) { return f.name == name; });
  if (it == found.end()) throw UnknownName(unknown_name_message(kind, name, found));
  return *it;
}

void* open_entry_point(const Kind& kind, const Found& plugin) {
  // One lock: dlerror() is per thread, but concurrent loads of one library should not interleave
  // their checks either.
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  dlerror();
  void* handle = dlopen(plugin.path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw Error(plugin.path, std::string("could not be loaded: ") + (why != nullptr ? why : "dlopen failed"));
  }
  void* entry = dlsym(handle, kind.entry_point);
  if (entry == nullptr) throw Error(plugin.path, std::string("has no ") + kind.entry_point + " entry point");
  return entry;
}

void check_abi(const Kind& kind, const Found& plugin, const void* result) {
  if (result == nullptr) throw Error(plugin.path, std::string(kind.entry_point) + " returned nothing");
  // Every plugin struct starts with its ABI string (library.hpp).
  const char* abi = *static_cast<const char* const*>(result);
  if (abi == nullptr || std::strcmp(abi, kind.abi) != 0) {
    throw Error(plugin.path, "has ABI version " + std::string(abi ? abi : "none") + ", this program needs " + kind.abi +
                                 ": it was built against other interface headers; rebuild it");
  }
}

}  // namespace plumb::plugin
