#include "security/keystore.hpp"

#include <sys/stat.h>

#include <cctype>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "security/openssl_command.hpp"

namespace plumb::cli {

namespace fs = std::filesystem;

namespace {

// Subjects without blanks after the separators: Cyclone DDS 0.10 does not match "O=plumb, CN=x".
std::string subject_of(const std::string& name) { return "/O=plumb/CN=" + name; }

void write_file(const fs::path& path, const std::string& text, fs::perms mode = fs::perms(0644)) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out.close();
  fs::permissions(path, mode);
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void require(const fs::path& path, const std::string& what) {
  if (!fs::exists(path)) throw std::runtime_error(path.string() + ": missing (" + what + ")");
}

// A new EC P-256 key, created readable by its owner only.
// The umask makes openssl create the file 0600: never readable by others, not even for a moment.
void make_key(const fs::path& path) {
  fs::remove(path);
  const mode_t old_mask = ::umask(077);
  try {
    run_openssl({"genpkey", "-algorithm", "EC", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-out", path.string()});
  } catch (...) {
    ::umask(old_mask);
    throw;
  }
  ::umask(old_mask);
  fs::permissions(path, fs::perms(0600));
}

// S/MIME signature of `in` by the keystore CA, as both vendors and ros2 security expect it.
void sign(const fs::path& keystore, const fs::path& in, const fs::path& out) {
  run_openssl({"smime", "-sign", "-text", "-in", in.string(), "-out", out.string(), "-signer",
               (keystore / "public/ca.cert.pem").string(), "-inkey", (keystore / "private/ca.key.pem").string()});
  fs::permissions(out, fs::perms(0644));
}

std::string utc_text(std::chrono::system_clock::time_point t) {
  const std::time_t s = std::chrono::system_clock::to_time_t(t);
  std::tm tm{};
  gmtime_r(&s, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &tm);
  return text;
}

std::string governance_xml(const DomainRange& d) {
  const std::string range = "<id_range><min>" + std::to_string(d.min) + "</min><max>" + std::to_string(d.max) + "</max></id_range>";
  // Every topic ("*"): authenticated, access-controlled, discovery and data encrypted.
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains>)" + range + R"(</domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>NONE</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
)";
}

std::string topics_xml(const std::string& kind, const std::vector<std::string>& topics) {
  if (topics.empty()) return "";
  std::string xml = "        <" + kind + "><topics>";
  for (const auto& t : topics) xml += "<topic>" + t + "</topic>";
  return xml + "</topics></" + kind + ">\n";
}

std::string permissions_xml(const std::string& name, const std::string& subject, const DomainRange& d,
                            const Grant& grant, int days) {
  const auto now = std::chrono::system_clock::now();
  const std::string range = "<id_range><min>" + std::to_string(d.min) + "</min><max>" + std::to_string(d.max) + "</max></id_range>";
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
    <grant name=")" + name + R"(">
      <subject_name>)" + subject + R"(</subject_name>
      <validity><not_before>)" + utc_text(now - std::chrono::hours(1)) + "</not_before><not_after>" +
         utc_text(now + std::chrono::hours(24) * days) + R"(</not_after></validity>
      <allow_rule>
        <domains>)" + range + "</domains>\n" +
         topics_xml("publish", grant.publish) + topics_xml("subscribe", grant.subscribe) + R"(      </allow_rule>
      <default>DENY</default>
    </grant>
  </permissions>
</dds>
)";
}

// The range the keystore's governance names (create-keystore wrote it).
DomainRange keystore_domains(const fs::path& keystore) {
  const std::string xml = read_file(keystore / "governance.xml");
  auto number = [&](const std::string& tag) {
    const auto at = xml.find("<" + tag + ">");
    if (at == std::string::npos) throw std::runtime_error((keystore / "governance.xml").string() + ": no <" + tag + ">");
    return std::stoi(xml.substr(at + tag.size() + 2));
  };
  return {number("min"), number("max")};
}

void check_name(const std::string& name) {
  if (name.empty() || name.size() > 64) throw std::invalid_argument("identity name must be 1..64 characters");
  for (unsigned char c : name) {
    if (!std::isalnum(c) && c != '-' && c != '_' && c != '.') {
      throw std::invalid_argument("identity name '" + name + "' may only hold letters, digits, '-', '_' and '.'");
    }
  }
}

}  // namespace

std::string enclave_dir(const std::string& keystore, const std::string& name) {
  return (fs::path(keystore) / "enclaves" / name).string();
}

void create_keystore(const std::string& dir_text, const DomainRange& domains, int days) {
  if (domains.min < 0 || domains.max > 230 || domains.min > domains.max) {
    throw std::invalid_argument("--domains: expected MIN-MAX within 0-230 (Cyclone DDS 0.10 refuses a max above 230)");
  }
  if (days < 1) throw std::invalid_argument("--days must be at least 1");
  const fs::path dir(dir_text);
  if (fs::exists(dir / "private/ca.key.pem")) {
    throw std::runtime_error(dir_text + " already holds a keystore (private/ca.key.pem): not overwritten");
  }
  fs::create_directories(dir / "public");
  fs::create_directories(dir / "private");
  fs::create_directories(dir / "enclaves");
  fs::permissions(dir / "private", fs::perms(0700));
  const fs::path key = dir / "private/ca.key.pem", cert = dir / "public/ca.cert.pem";
  make_key(key);
  run_openssl({"req", "-new", "-x509", "-sha256", "-key", key.string(), "-out", cert.string(), "-days",
               std::to_string(days), "-subj", "/O=plumb/CN=plumb-ca"});
  fs::permissions(cert, fs::perms(0644));
  for (const char* copy : {"public/identity_ca.cert.pem", "public/permissions_ca.cert.pem"}) {
    fs::copy_file(cert, dir / copy, fs::copy_options::overwrite_existing);
  }
  write_file(dir / "governance.xml", governance_xml(domains));
  sign(dir, dir / "governance.xml", dir / "governance.p7s");
}

void create_identity(const std::string& dir_text, const std::string& name, const Validity& validity) {
  check_name(name);
  const fs::path dir(dir_text);
  require(dir / "private/ca.key.pem", "make the keystore first: plumb security create-keystore " + dir_text);
  if (validity.start.empty() != validity.end.empty()) {
    throw std::invalid_argument("--valid-from and --valid-until go together");
  }
  const fs::path enclave = enclave_dir(dir_text, name);
  fs::create_directories(enclave);
  fs::permissions(enclave, fs::perms(0755));
  make_key(enclave / "key.pem");
  const fs::path csr = enclave / "request.csr";
  run_openssl({"req", "-new", "-sha256", "-key", (enclave / "key.pem").string(), "-out", csr.string(), "-subj", subject_of(name)});

  // `openssl ca` rather than `x509 -req`: only it takes explicit start and end dates in OpenSSL 3.0.
  const fs::path work = enclave / ".ca";
  fs::create_directories(work);
  write_file(work / "index.txt", "");
  write_file(work / "ca.cnf", "[ca]\ndefault_ca = plumb\n[plumb]\ndatabase = " + (work / "index.txt").string() +
                                   "\nnew_certs_dir = " + work.string() +
                                   "\nrand_serial = yes\ndefault_md = sha256\npolicy = any\nunique_subject = no\n"
                                   "email_in_dn = no\npreserve = yes\n[any]\norganizationName = optional\ncommonName = supplied\n");
  std::vector<std::string> args{"ca", "-batch", "-notext", "-config", (work / "ca.cnf").string(), "-cert",
                                (dir / "public/ca.cert.pem").string(), "-keyfile", (dir / "private/ca.key.pem").string(),
                                "-in", csr.string(), "-out", (enclave / "cert.pem").string()};
  if (validity.start.empty()) {
    args.insert(args.end(), {"-days", std::to_string(validity.days)});
  } else {
    args.insert(args.end(), {"-startdate", validity.start, "-enddate", validity.end});
  }
  run_openssl(args);
  fs::remove_all(work);
  fs::remove(csr);
  fs::permissions(enclave / "cert.pem", fs::perms(0644));
  for (const char* copy : {"identity_ca.cert.pem", "permissions_ca.cert.pem"}) {
    fs::copy_file(dir / "public/ca.cert.pem", enclave / copy, fs::copy_options::overwrite_existing);
  }
  fs::copy_file(dir / "governance.p7s", enclave / "governance.p7s", fs::copy_options::overwrite_existing);
}

void create_permissions(const std::string& dir_text, const std::string& name, const Grant& grant, int days) {
  check_name(name);
  if (grant.publish.empty() && grant.subscribe.empty()) {
    throw std::invalid_argument("no topics to grant: give --publish and/or --subscribe (defaults exist for " +
                                default_grant_names() + ")");
  }
  for (const auto& topics : {grant.publish, grant.subscribe}) {
    for (const auto& t : topics) {
      if (t.empty() || t.find_first_of("<>&\"' ") != std::string::npos) throw std::invalid_argument("invalid topic name '" + t + "'");
    }
  }
  const fs::path dir(dir_text), enclave = enclave_dir(dir_text, name);
  require(enclave / "cert.pem", "make the identity first: plumb security create-identity " + dir_text + " " + name);
  std::string subject = run_openssl({"x509", "-in", (enclave / "cert.pem").string(), "-noout", "-subject", "-nameopt", "RFC2253"});
  subject = subject.substr(subject.find('=') + 1);
  while (!subject.empty() && (subject.back() == '\n' || subject.back() == ' ')) subject.pop_back();
  write_file(enclave / "permissions.xml", permissions_xml(name, subject, keystore_domains(dir), grant, days));
  sign(dir, enclave / "permissions.xml", enclave / "permissions.p7s");
}

std::optional<Grant> default_grant(const std::string& name) {
  // What each component creates (its writers and readers), plumb/status for every one.
  static const std::map<std::string, Grant> grants{
      {"plumb-sim", {{"plumb/sensor/*", "plumb/sim/truth", "plumb/depth", "plumb/status"}, {}}},
      {"plumb-bridge", {{"plumb/sensor/*", "plumb/status"}, {"plumb/sensor/*", "plumb/calibration"}}},
      // plumb/component/*: answers plumb component and plumb param (an operator's requests), and
      // writes its plugins' parameters for those who read them.
      {"plumb-estimator",
       {{"plumb/attitude/*", "plumb/navigation/*", "plumb/status", "plumb/component/reply", "plumb/component/parameters/*"},
        {"plumb/sensor/*", "plumb/depth", "plumb/sim/truth", "plumb/calibration", "plumb/component/request"}}},
      {"plumb-calibrate", {{"plumb/calibration", "plumb/sensor/raw", "plumb/status"}, {"plumb/sensor/*"}}},
      // The sensor topic: the depth clock's estimate matches the stops it sees with the depth's; the
      // navigator's parameters: its gyro error model (--error-model auto).
      {"plumb-survey",
       {{"plumb/survey/*", "plumb/clearance", "plumb/status"},
        {"plumb/attitude/*", "plumb/navigation/*", "plumb/depth", "plumb/sensor/*", "plumb/component/parameters/*"}}},
      {"plumb-wits", {{"plumb/depth", "plumb/status"}, {}}},
      // Its Foxglove server offers every plumb topic: it may read them all.
      {"plumb-display", {{"plumb/status"}, {"plumb/*"}}},
      // The plumb tool as an operator's monitor (topic echo / hz, status, record): reads everything.
      {"plumb-monitor", {{}, {"plumb/*"}}},
      // The plumb tool as an operator: a monitor that may also load, unload and tune the estimator
      // hosts' plugins (plumb component, plumb param). The monitor may not.
      {"plumb-operator", {{"plumb/component/request"}, {"plumb/*"}}},
  };
  const auto it = grants.find(name);
  if (it == grants.end()) return std::nullopt;
  return it->second;
}

std::string default_grant_names() {
  return "plumb-sim, plumb-bridge, plumb-estimator, plumb-calibrate, plumb-survey, plumb-wits, plumb-display, plumb-monitor, plumb-operator";
}

}  // namespace plumb::cli
