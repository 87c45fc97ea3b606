// `plumb security`: a DDS Security keystore laid out as `ros2 security` lays it out, made with the
// openssl command. One CA signs both identities and the governance and permissions documents.
//   DIR/public/ca.cert.pem          the CA certificate (also as identity_ca / permissions_ca)
//   DIR/private/ca.key.pem          the CA key (0600; keep it on the computer that makes identities)
//   DIR/governance.xml, .p7s        the domain rules, and their signed form
//   DIR/enclaves/NAME/              one identity, the folder a component's --security names:
//       cert.pem key.pem identity_ca.cert.pem permissions_ca.cert.pem governance.p7s
//       permissions.xml permissions.p7s
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace plumb::cli {

struct DomainRange {
  int min = 0;
  int max = 230;  // Cyclone DDS 0.10 refuses a range whose max is above 230
};

struct Validity {
  int days = 3650;
  // Explicit dates (openssl's YYYYMMDDHHMMSSZ), for certificates that must be expired or not yet
  // valid (tests of the checks); empty: from now for `days`.
  std::string start, end;
};

struct Grant {
  std::vector<std::string> publish, subscribe;  // topic names, '*' wildcards allowed
};

std::string enclave_dir(const std::string& keystore, const std::string& name);

// Creates DIR with a CA and the signed governance. Refuses a DIR that already holds a CA key.
void create_keystore(const std::string& dir, const DomainRange& domains, int days);
// Creates DIR/enclaves/NAME with a key and a certificate signed by the CA, and copies of the CA
// certificate and the governance. Returns the default grant for NAME when it names a plumb component.
void create_identity(const std::string& dir, const std::string& name, const Validity& validity);
// Writes and signs DIR/enclaves/NAME/permissions.xml for the identity's certificate.
void create_permissions(const std::string& dir, const std::string& name, const Grant& grant, int days);
// The grant of a plumb component by its identity name (plumb-sim, plumb-bridge, plumb-estimator,
// plumb-calibrate, plumb-survey, plumb-monitor, plumb-operator); nullopt for other names.
std::optional<Grant> default_grant(const std::string& name);
// Names default_grant() knows, for messages.
std::string default_grant_names();

}  // namespace plumb::cli
