// plumb security create-keystore DIR: a CA and the signed governance.
#include <iostream>
#include <memory>
#include <stdexcept>

#include "security/security_verbs.hpp"

namespace plumb::cli {
namespace {

struct KeystoreOptions {
  std::string dir, domains = "0-230";
  int days = 3650;
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

int run_create_keystore(const KeystoreOptions& o) {
  create_keystore(o.dir, parse_domains(o.domains), o.days);
  std::cout << "keystore " << o.dir << " created (CA key in " << o.dir << "/private: keep it off the components' computers)\n";
  return 0;
}

}  // namespace

void add_security_create_keystore(CLI::App& security, Verbs& verbs) {
  auto o = std::make_shared<KeystoreOptions>();
  auto* keystore = security.add_subcommand("create-keystore", "Create a keystore: a CA and the signed governance");
  keystore->add_option("dir", o->dir, "keystore folder (created)")->required();
  keystore->add_option("--domains", o->domains, "DDS domain ids the governance and permissions cover, MIN-MAX (max <= 230)")
      ->capture_default_str();
  keystore->add_option("--days", o->days, "days the CA certificate is valid")->capture_default_str();
  verbs.add(keystore, [o] { return run_create_keystore(*o); });
}

}  // namespace plumb::cli
