// DDS Security, vendor-neutral part: the files of one identity (an "enclave" folder, laid out as
// `ros2 security` lays it out) and the checks plumb makes before it hands them to a vendor.
// The vendors' own refusals are many log lines, and some mistakes (a key readable by everyone) they
// do not refuse at all; plumb refuses each with one line naming the file and the problem.
#pragma once

#include <string>

namespace plumb::transport {

// Environment variable that --security falls back to.
inline constexpr const char* kSecurityEnv = "PLUMB_SECURITY";

// The files of one identity folder, as absolute paths.
struct SecurityFiles {
  std::string identity_ca;     // identity_ca.cert.pem: the CA that signs identities
  std::string certificate;     // cert.pem: this participant's identity certificate
  std::string private_key;     // key.pem: its private key (mode 0600 or stricter)
  std::string permissions_ca;  // permissions_ca.cert.pem: the CA that signs governance and permissions
  std::string governance;      // governance.p7s: the domain rules, S/MIME signed by permissions_ca
  std::string permissions;     // permissions.p7s: what this identity may publish and subscribe, signed
};

// Checks the identity folder `dir` and returns its files. Throws transport::Error with one line
// "security: FILE: problem" for: a missing folder or file (the private key among them), a private
// key readable or any file writable by group or others, a certificate that is expired, not yet
// valid, or not signed by identity_ca.cert.pem, a key that does not belong to the certificate, a
// governance or permissions document whose S/MIME signature does not verify against
// permissions_ca.cert.pem (tampered, or signed by another CA), and a permissions document that
// grants another subject than the certificate's or whose validity has passed.
SecurityFiles check_security_files(const std::string& dir);

}  // namespace plumb::transport
