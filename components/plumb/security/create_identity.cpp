// plumb security create-identity DIR NAME: a key and certificate in DIR/enclaves/NAME, and its
// default permissions when NAME is a plumb component.
#include <iostream>
#include <memory>

#include "security/security_verbs.hpp"

namespace plumb::cli {
namespace {

struct IdentityOptions {
  std::string dir, name, valid_from, valid_until;
  int days = 3650;
  bool no_permissions = false;
};

int run_create_identity(const IdentityOptions& o) {
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

}  // namespace

void add_security_create_identity(CLI::App& security, Verbs& verbs) {
  auto o = std::make_shared<IdentityOptions>();
  auto* identity = security.add_subcommand("create-identity",
                                           "Create an identity (key, certificate) in DIR/enclaves/NAME, and its default "
                                           "permissions when NAME is a plumb component");
  identity->add_option("dir", o->dir, "keystore folder")->required();
  identity->add_option("name", o->name, "identity name, e.g. plumb-sim (becomes CN=NAME,O=plumb)")->required();
  identity->add_option("--days", o->days, "days the certificate and permissions are valid")->capture_default_str();
  identity->add_option("--valid-from", o->valid_from, "certificate start date, YYYYMMDDHHMMSSZ (with --valid-until)");
  identity->add_option("--valid-until", o->valid_until, "certificate end date, YYYYMMDDHHMMSSZ (with --valid-from)");
  identity->add_flag("--no-permissions", o->no_permissions, "do not write the default permissions");
  verbs.add(identity, [o] { return run_create_identity(*o); });
}

}  // namespace plumb::cli
