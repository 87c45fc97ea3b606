// The verbs of `plumb security`, each in its own file: DDS Security keystores for plumb's components
// (keystore.hpp), and the checks every component makes on --security before a vendor sees it
// (plumb/transport/security.hpp), runnable by hand.
#pragma once

#include <string>

#include "security/keystore.hpp"
#include "verbs.hpp"

namespace plumb::cli {

void add_security_create_keystore(CLI::App& security, Verbs& verbs);
void add_security_create_identity(CLI::App& security, Verbs& verbs);
void add_security_create_permissions(CLI::App& security, Verbs& verbs);
void add_security_check(CLI::App& security, Verbs& verbs);

// "NAME: may publish ...; may subscribe ...", what create-identity and create-permissions granted.
void print_grant(const std::string& name, const Grant& grant);

}  // namespace plumb::cli
