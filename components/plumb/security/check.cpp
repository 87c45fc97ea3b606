// plumb security check DIR [NAME]: an identity checked as the components check it before they
// start secured.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>

#include "plumb/transport/security.hpp"
#include "plumb/transport/transport.hpp"
#include "security/security_verbs.hpp"

namespace plumb::cli {
namespace {

struct CheckOptions {
  std::string dir, name;
};

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// check DIR NAME: the identity folder's own checks, and that its CA is this keystore's CA.
// check FOLDER: an identity folder alone (as copied to another computer).
int run_check(const CheckOptions& o) {
  const std::string folder = o.name.empty() ? o.dir : enclave_dir(o.dir, o.name);
  const auto files = transport::check_security_files(folder);
  if (!o.name.empty()) {
    const std::string keystore_ca = (std::filesystem::path(o.dir) / "public/ca.cert.pem").string();
    const std::string ca = file_text(keystore_ca);
    if (ca.empty()) throw transport::Error("security: " + keystore_ca + ": file is missing");
    for (const auto& f : {files.identity_ca, files.permissions_ca}) {
      if (file_text(f) != ca) throw transport::Error("security: " + f + ": is not this keystore's CA (" + keystore_ca + ")");
    }
  }
  std::cout << folder << ": ok (key private, certificate valid and signed by the CA, governance and permissions verified)\n";
  return 0;
}

}  // namespace

void add_security_check(CLI::App& security, Verbs& verbs) {
  auto o = std::make_shared<CheckOptions>();
  auto* check = security.add_subcommand("check", "Check an identity as the components do before they start secured");
  check->add_option("dir", o->dir, "keystore folder (with NAME), or an identity folder alone")->required();
  check->add_option("name", o->name, "identity name in the keystore");
  verbs.add(check, [o] { return run_check(*o); });
}

}  // namespace plumb::cli
