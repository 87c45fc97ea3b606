// plumb security create-permissions DIR NAME: write and sign what identity NAME may publish and
// subscribe.
#include <memory>
#include <vector>

#include "security/security_verbs.hpp"

namespace plumb::cli {
namespace {

struct PermissionsOptions {
  std::string dir, name;
  std::vector<std::string> publish, subscribe;
  int days = 3650;
};

int run_create_permissions(const PermissionsOptions& o) {
  Grant grant{o.publish, o.subscribe};
  if (grant.publish.empty() && grant.subscribe.empty()) {
    if (const auto d = default_grant(o.name)) grant = *d;
  }
  create_permissions(o.dir, o.name, grant, o.days);
  print_grant(o.name, grant);
  return 0;
}

}  // namespace

void add_security_create_permissions(CLI::App& security, Verbs& verbs) {
  auto o = std::make_shared<PermissionsOptions>();
  auto* permissions = security.add_subcommand("create-permissions",
                                              "Write and sign what identity NAME may publish and subscribe");
  permissions->add_option("dir", o->dir, "keystore folder")->required();
  permissions->add_option("name", o->name, "identity name")->required();
  permissions->add_option("--publish", o->publish, "topics it may publish ('*' wildcards), repeatable or comma separated")
      ->delimiter(',');
  permissions->add_option("--subscribe", o->subscribe, "topics it may subscribe, repeatable or comma separated")->delimiter(',');
  permissions->add_option("--days", o->days, "days the grant is valid")->capture_default_str();
  permissions->footer("Without --publish and --subscribe, a plumb component's name gets its defaults: " + default_grant_names());
  verbs.add(permissions, [o] { return run_create_permissions(*o); });
}

}  // namespace plumb::cli
