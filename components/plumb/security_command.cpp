// plumb security create-keystore | create-identity | create-permissions | check: DDS Security
// keystores for plumb's components (keystore.hpp), and the checks every component makes on
// --security before a vendor sees it (plumb/transport/security.hpp), runnable by hand.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <stdexcept>

#include "commands.hpp"
#include "keystore.hpp"
#include "plumb/transport/security.hpp"
#include "plumb/transport/transport.hpp"

namespace plumb::cli {
namespace {

struct SecurityOptions {
  std::string dir, name, domains = "0-230", valid_from, valid_until;
  int days = 3650;
  std::vector<std::string> publish, subscribe;
  bool no_permissions = false;
};

DomainRange parse_domains(const std::string& text) {
  const auto dash = text.find('-');
  try {
    if (dash == std::string::npos) throw std::invalid_argument(text);
    std::size_t a = 0, b = 0;
    const int min = std::stoi(text.substr(0, dash), &a), max = std::stoi(text.substr(dash + 1), &b);
    if (a != dash || b != text.size() - dash - 1) throw std::invalid_argument(text);
    return {min, max};
  } catch (const std::logic_error&) {
    throw std::invalid_argument("--domains: expected MIN-MAX (e.g. 0-230), got '" + text + "'");
  }
}

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void print_grant(const std::string& name, const Grant& g) {
  auto list = [](const std::vector<std::string>& topics) {
    std::string s;
    for (const auto& t : topics) s += (s.empty() ? "" : " ") + t;
    return s.empty() ? std::string("(none)") : s;
  };
  std::cout << name << ": may publish " << list(g.publish) << "; may subscribe " << list(g.subscribe) << "\n";
}

int run_create_identity(const SecurityOptions& o) {
  create_identity(o.dir, o.name, Validity{o.days, o.valid_from, o.valid_until});
  std::cout << "identity " << enclave_dir(o.dir, o.name) << " created\n";
  if (o.no_permissions) return 0;
  if (const auto grant = default_grant(o.name)) {
    create_permissions(o.dir, o.name, *grant, o.days);
    print_grant(o.name, *grant);
  } else {
    std::cout << "no default permissions for '" << o.name << "' (defaults exist for " << default_grant_names()
              << "): run plumb security create-permissions " << o.dir << " " << o.name << " --publish ... --subscribe ...\n";
  }
  return 0;
}

int run_create_permissions(const SecurityOptions& o) {
  Grant grant{o.publish, o.subscribe};
  if (grant.publish.empty() && grant.subscribe.empty()) {
    if (const auto d = default_grant(o.name)) grant = *d;
  }
  create_permissions(o.dir, o.name, grant, o.days);
  print_grant(o.name, grant);
  return 0;
}

// check DIR NAME: the identity folder's own checks, and that its CA is this keystore's CA.
// check FOLDER: an identity folder alone (as copied to another computer).
int run_check(const SecurityOptions& o) {
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

void add_security_command(CLI::App& app) {
  auto* security = app.add_subcommand("security", "Make and check DDS Security keystores (docs/security.md)");
  security->require_subcommand(1);
  auto o = std::make_shared<SecurityOptions>();

  auto* keystore = security->add_subcommand("create-keystore", "Create a keystore: a CA and the signed governance");
  keystore->add_option("dir", o->dir, "keystore folder (created)")->required();
  keystore->add_option("--domains", o->domains, "DDS domain ids the governance and permissions cover, MIN-MAX (max <= 230)")
      ->capture_default_str();
  keystore->add_option("--days", o->days, "days the CA certificate is valid")->capture_default_str();
  keystore->callback([o] {
    create_keystore(o->dir, parse_domains(o->domains), o->days);
    std::cout << "keystore " << o->dir << " created (CA key in " << o->dir << "/private: keep it off the components' computers)\n";
    g_exit_code = 0;
  });

  auto* identity = security->add_subcommand("create-identity",
                                            "Create an identity (key, certificate) in DIR/enclaves/NAME, and its default "
                                            "permissions when NAME is a plumb component");
  identity->add_option("dir", o->dir, "keystore folder")->required();
  identity->add_option("name", o->name, "identity name, e.g. plumb-sim (becomes CN=NAME,O=plumb)")->required();
  identity->add_option("--days", o->days, "days the certificate and permissions are valid")->capture_default_str();
  identity->add_option("--valid-from", o->valid_from, "certificate start date, YYYYMMDDHHMMSSZ (with --valid-until)");
  identity->add_option("--valid-until", o->valid_until, "certificate end date, YYYYMMDDHHMMSSZ (with --valid-from)");
  identity->add_flag("--no-permissions", o->no_permissions, "do not write the default permissions");
  identity->callback([o] { g_exit_code = run_create_identity(*o); });

  auto* permissions = security->add_subcommand("create-permissions",
                                               "Write and sign what identity NAME may publish and subscribe");
  permissions->add_option("dir", o->dir, "keystore folder")->required();
  permissions->add_option("name", o->name, "identity name")->required();
  permissions->add_option("--publish", o->publish, "topics it may publish ('*' wildcards), repeatable or comma separated")
      ->delimiter(',');
  permissions->add_option("--subscribe", o->subscribe, "topics it may subscribe, repeatable or comma separated")->delimiter(',');
  permissions->add_option("--days", o->days, "days the grant is valid")->capture_default_str();
  permissions->footer("Without --publish and --subscribe, a plumb component's name gets its defaults: " + default_grant_names());
  permissions->callback([o] { g_exit_code = run_create_permissions(*o); });

  auto* check = security->add_subcommand("check", "Check an identity as the components do before they start secured");
  check->add_option("dir", o->dir, "keystore folder (with NAME), or an identity folder alone")->required();
  check->add_option("name", o->name, "identity name in the keystore");
  check->callback([o] { g_exit_code = run_check(*o); });
}

}  // namespace plumb::cli
