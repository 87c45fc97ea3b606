#include "security/security_verbs.hpp"

#include <iostream>
#include <vector>

namespace plumb::cli {

void print_grant(const std::string& name, const Grant& g) {
  auto list = [](const std::vector<std::string>& topics) {
    std::string s;
    for (const auto& t : topics) s += (s.empty() ? "" : " ") + t;
    return s.empty() ? std::string("(none)") : s;
  };
  std::cout << name << ": may publish " << list(g.publish) << "; may subscribe " << list(g.subscribe) << "\n";
}

void add_security_verbs(CLI::App& app, Verbs& verbs) {
  auto* security = app.add_subcommand("security", "Make and check DDS Security keystores (docs/security.md)");
  security->require_subcommand(1);
  add_security_create_keystore(*security, verbs);
  add_security_create_identity(*security, verbs);
  add_security_create_permissions(*security, verbs);
  add_security_check(*security, verbs);
}

}  // namespace plumb::cli
