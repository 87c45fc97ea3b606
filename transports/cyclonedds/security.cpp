#include "security.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::cyclonedds {

namespace {

// Debian's libddsc0debian puts the plugins in a folder of their own next to libddsc, outside the
// loader's search path, so Cyclone's default (a bare library name for dlopen) does not find them:
// they are given by absolute path, looked for beside the libddsc this process runs.
std::string plugin_path(const std::string& plugin) {
  Dl_info info{};
  std::vector<std::string> folders;
  if (dladdr(reinterpret_cast<void*>(&dds_create_participant), &info) != 0 && info.dli_fname != nullptr) {
    std::string dir = info.dli_fname;
    dir = dir.substr(0, dir.find_last_of('/'));
    folders = {dir + "/libddsc0debian", dir};
  }
  folders.emplace_back("/usr/lib/x86_64-linux-gnu/libddsc0debian");
  const std::string file = "libdds_security_" + plugin + ".so";
  for (const auto& folder : folders) {
    const std::string path = folder + "/" + file;
    if (::access(path.c_str(), R_OK) == 0) return path;
  }
  throw Error("security: Cyclone DDS's security plugin " + file + " is not installed (Debian package libddsc0debian)");
}

}  // namespace

void add_security(dds_qos_t* qos, const SecurityFiles& files) {
  // Cyclone reads "file:" followed by a path.
  const std::string uri = "file:";
  dds_qset_prop(qos, "dds.sec.auth.library.path", plugin_path("auth").c_str());
  dds_qset_prop(qos, "dds.sec.auth.library.init", "init_authentication");
  dds_qset_prop(qos, "dds.sec.auth.library.finalize", "finalize_authentication");
  dds_qset_prop(qos, "dds.sec.auth.identity_ca", (uri + files.identity_ca).c_str());
  dds_qset_prop(qos, "dds.sec.auth.identity_certificate", (uri + files.certificate).c_str());
  dds_qset_prop(qos, "dds.sec.auth.private_key", (uri + files.private_key).c_str());
  dds_qset_prop(qos, "dds.sec.access.library.path", plugin_path("ac").c_str());
  dds_qset_prop(qos, "dds.sec.access.library.init", "init_access_control");
  dds_qset_prop(qos, "dds.sec.access.library.finalize", "finalize_access_control");
  dds_qset_prop(qos, "dds.sec.access.permissions_ca", (uri + files.permissions_ca).c_str());
  dds_qset_prop(qos, "dds.sec.access.governance", (uri + files.governance).c_str());
  dds_qset_prop(qos, "dds.sec.access.permissions", (uri + files.permissions).c_str());
  dds_qset_prop(qos, "dds.sec.crypto.library.path", plugin_path("crypto").c_str());
  dds_qset_prop(qos, "dds.sec.crypto.library.init", "init_crypto");
  dds_qset_prop(qos, "dds.sec.crypto.library.finalize", "finalize_crypto");
}

}  // namespace plumb::transport::cyclonedds
