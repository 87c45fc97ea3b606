// The keystore checks, with libcrypto in process (both vendors link it already): no dependence on
// an `openssl` command at run time, no shell, and each failure is known exactly (which file, which
// check), so it becomes one line.
#include "plumb/transport/security.hpp"

#include <openssl/bio.h>
#include <openssl/err.h>
#include <openssl/pem.h>
#include <openssl/pkcs7.h>
#include <openssl/x509.h>
#include <openssl/x509_vfy.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "plumb/transport/transport.hpp"

namespace plumb::transport {

namespace {

template <class T, void (*Free)(T*)> struct Deleter {
  void operator()(T* p) const { Free(p); }
};
using Bio = std::unique_ptr<BIO, Deleter<BIO, BIO_free_all>>;
using Cert = std::unique_ptr<X509, Deleter<X509, X509_free>>;
using Key = std::unique_ptr<EVP_PKEY, Deleter<EVP_PKEY, EVP_PKEY_free>>;
using Store = std::unique_ptr<X509_STORE, Deleter<X509_STORE, X509_STORE_free>>;
using StoreContext = std::unique_ptr<X509_STORE_CTX, Deleter<X509_STORE_CTX, X509_STORE_CTX_free>>;
using Pkcs7 = std::unique_ptr<PKCS7, Deleter<PKCS7, PKCS7_free>>;
// sk_X509_free is a macro: no function to name. The stack does not own its certificates.
struct CertStackDeleter {
  void operator()(STACK_OF(X509) * s) const { sk_X509_free(s); }
};
using CertStack = std::unique_ptr<STACK_OF(X509), CertStackDeleter>;

[[noreturn]] void refuse(const std::string& file, const std::string& problem) {
  ERR_clear_error();
  throw Error("security: " + file + ": " + problem);
}

// OpenSSL's reason for the last failure, for the end of a line ("" when it kept none).
std::string openssl_reason() {
  const unsigned long code = ERR_peek_last_error();
  ERR_clear_error();
  if (code == 0) return "";
  const char* reason = ERR_reason_error_string(code);
  return reason ? std::string(" (") + reason + ")" : "";
}

std::string time_text(const ASN1_TIME* t) {
  Bio bio(BIO_new(BIO_s_mem()));
  ASN1_TIME_print(bio.get(), t);
  char* data = nullptr;
  const long n = BIO_get_mem_data(bio.get(), &data);
  return std::string(data, static_cast<std::size_t>(n));
}

// Exists, is a regular file, and its mode is safe: nobody but the owner may change any keystore
// file (a writable governance lets anyone on the computer swap the rules once the CA is fooled,
// a writable certificate lets them swap identities), nobody but the owner may read a private key.
void check_file_mode(const std::string& path, bool is_private_key) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) refuse(path, is_private_key ? "private key is missing" : "file is missing");
  if (!S_ISREG(st.st_mode)) refuse(path, "is not a regular file");
  char mode[8];
  std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
  if (is_private_key && (st.st_mode & (S_IRWXG | S_IRWXO)) != 0) {
    refuse(path, std::string("private key is accessible by group or others (mode ") + mode + "); run chmod 600 on it");
  }
  if ((st.st_mode & (S_IWGRP | S_IWOTH)) != 0) {
    refuse(path, std::string("is writable by group or others (mode ") + mode + "); run chmod go-w on it");
  }
}

Bio open_file(const std::string& path) {
  Bio bio(BIO_new_file(path.c_str(), "r"));
  if (!bio) refuse(path, "cannot be read" + openssl_reason());
  return bio;
}

Cert read_certificate(const std::string& path) {
  check_file_mode(path, false);
  Bio bio = open_file(path);
  Cert cert(PEM_read_bio_X509(bio.get(), nullptr, nullptr, nullptr));
  if (!cert) refuse(path, "is not a PEM certificate" + openssl_reason());
  // Checked here rather than left to the chain verification: its message would not say which date.
  if (X509_cmp_current_time(X509_get0_notBefore(cert.get())) >= 0) {
    refuse(path, "certificate is not valid yet (valid from " + time_text(X509_get0_notBefore(cert.get())) + ")");
  }
  if (X509_cmp_current_time(X509_get0_notAfter(cert.get())) <= 0) {
    refuse(path, "certificate has expired (valid until " + time_text(X509_get0_notAfter(cert.get())) + ")");
  }
  return cert;
}

Store store_of(const Cert& ca) {
  Store store(X509_STORE_new());
  if (!store || X509_STORE_add_cert(store.get(), ca.get()) != 1) throw Error("security: out of memory" + openssl_reason());
  return store;
}

void check_signed_by(const Cert& cert, const std::string& cert_path, const Cert& ca, const std::string& ca_path) {
  Store store = store_of(ca);
  StoreContext context(X509_STORE_CTX_new());
  if (!context || X509_STORE_CTX_init(context.get(), store.get(), cert.get(), nullptr) != 1) {
    throw Error("security: out of memory" + openssl_reason());
  }
  if (X509_verify_cert(context.get()) != 1) {
    const int error = X509_STORE_CTX_get_error(context.get());
    refuse(cert_path, "certificate is not signed by " + ca_path + " (" + X509_verify_cert_error_string(error) + ")");
  }
}

// The content of an S/MIME document signed by `ca`, without the text/plain header that
// `openssl smime -sign -text` adds (the vendors verify it the same way).
std::string verified_content(const std::string& path, const Cert& ca, const std::string& ca_path) {
  check_file_mode(path, false);
  Bio bio = open_file(path);
  BIO* content_raw = nullptr;
  Pkcs7 p7(SMIME_read_PKCS7(bio.get(), &content_raw));
  Bio content(content_raw);
  if (!p7) refuse(path, "is not an S/MIME signed document" + openssl_reason());
  Store store = store_of(ca);
  Bio out(BIO_new(BIO_s_mem()));
  // The signer must be the permissions CA itself (how plumb security and ros2 security sign), so the
  // certificates embedded in the document are not trusted: only `ca` may have signed it.
  CertStack signers(sk_X509_new_null());
  sk_X509_push(signers.get(), ca.get());
  const int flags = PKCS7_TEXT | PKCS7_NOINTERN | PKCS7_NOVERIFY;
  if (PKCS7_verify(p7.get(), signers.get(), store.get(), content.get(), out.get(), flags) != 1) {
    const std::string reason = openssl_reason();
    refuse(path, "signature does not verify against " + ca_path + reason + ": tampered, or signed by another CA");
  }
  char* data = nullptr;
  const long n = BIO_get_mem_data(out.get(), &data);
  return std::string(data, static_cast<std::size_t>(n));
}

// Text of the first <tag>...</tag> in xml ("" if absent). The documents are plumb's own or
// ros2 security's, plain XML without CDATA or comments inside these elements.
std::string element_text(const std::string& xml, const std::string& tag) {
  const auto open = xml.find("<" + tag + ">");
  if (open == std::string::npos) return "";
  const auto start = open + tag.size() + 2;
  const auto close = xml.find("</" + tag + ">", start);
  if (close == std::string::npos) return "";
  std::string text = xml.substr(start, close - start);
  const auto first = text.find_first_not_of(" \t\r\n");
  const auto last = text.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

// A distinguished name as a set of "KEY=value" parts, blanks around the separators removed: the
// order differs between how certificates print it and how permissions documents write it.
std::set<std::string> name_parts(const std::string& text) {
  std::set<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, text.find(',') != std::string::npos ? ',' : '/')) {
    part.erase(std::remove_if(part.begin(), part.end(), [](unsigned char c) { return std::isspace(c) != 0; }), part.end());
    if (!part.empty()) parts.insert(part);
  }
  return parts;
}

std::string subject_text(const Cert& cert) {
  Bio bio(BIO_new(BIO_s_mem()));
  X509_NAME_print_ex(bio.get(), X509_get_subject_name(cert.get()), 0, XN_FLAG_RFC2253);
  char* data = nullptr;
  const long n = BIO_get_mem_data(bio.get(), &data);
  return std::string(data, static_cast<std::size_t>(n));
}

// "2026-11-23T21:00:00" (the form of DDS permissions documents) as UTC seconds; -1 if unreadable.
long long parse_utc(const std::string& text) {
  std::tm tm{};
  const char* end = strptime(text.c_str(), "%Y-%m-%dT%H:%M:%S", &tm);
  if (end == nullptr) return -1;
  return static_cast<long long>(timegm(&tm));
}

void check_grant(const std::string& path, const std::string& xml, const Cert& cert, const std::string& cert_path) {
  const std::string subject = element_text(xml, "subject_name");
  if (subject.empty()) refuse(path, "grants no <subject_name>");
  if (name_parts(subject) != name_parts(subject_text(cert))) {
    refuse(path, "grants subject '" + subject + "', but " + cert_path + " is '" + subject_text(cert) + "'");
  }
  const long long now = static_cast<long long>(std::time(nullptr));
  const std::string not_before = element_text(xml, "not_before");
  const std::string not_after = element_text(xml, "not_after");
  if (!not_before.empty() && parse_utc(not_before) > now) refuse(path, "grant is not valid yet (from " + not_before + ")");
  if (!not_after.empty() && parse_utc(not_after) >= 0 && parse_utc(not_after) <= now) {
    refuse(path, "grant has expired (valid until " + not_after + ")");
  }
}

std::string absolute(const std::string& path) {
  char resolved[PATH_MAX];
  return ::realpath(path.c_str(), resolved) != nullptr ? std::string(resolved) : path;
}

}  // namespace

SecurityFiles check_security_files(const std::string& dir_in) {
  if (dir_in.empty()) throw Error("security: no identity folder given");
  struct stat st {};
  if (::stat(dir_in.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    refuse(dir_in, "is not a folder (expected an identity folder made by `plumb security create-identity`)");
  }
  // A keystore root (plumb security create-keystore) is the most likely wrong folder: name the
  // identity folders it holds.
  if (::stat((dir_in + "/enclaves").c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    std::vector<std::string> names;
    std::error_code ec;
    const std::filesystem::path enclaves = std::filesystem::path(dir_in) / "enclaves";
    for (auto it = std::filesystem::recursive_directory_iterator(enclaves, ec); !ec && it != std::filesystem::recursive_directory_iterator();
         it.increment(ec)) {
      if (it->is_directory(ec) && std::filesystem::exists(it->path() / "cert.pem", ec))
        names.push_back(it->path().lexically_relative(enclaves).string());
    }
    std::sort(names.begin(), names.end());
    std::string found;
    for (const auto& n : names) found += (found.empty() ? "" : ", ") + n;
    refuse(dir_in, "this is a keystore root: give --security " + dir_in + "/enclaves/NAME (found: " +
                       (found.empty() ? "no identity yet: plumb security create-identity " + dir_in + " NAME" : found) + ")");
  }
  const std::string dir = absolute(dir_in);
  SecurityFiles f{dir + "/identity_ca.cert.pem", dir + "/cert.pem",      dir + "/key.pem",
                  dir + "/permissions_ca.cert.pem", dir + "/governance.p7s", dir + "/permissions.p7s"};

  // The key first: its absence or exposure is the most likely mistake, and the gravest.
  check_file_mode(f.private_key, true);
  const Cert identity_ca = read_certificate(f.identity_ca);
  const Cert permissions_ca = read_certificate(f.permissions_ca);
  const Cert cert = read_certificate(f.certificate);
  check_signed_by(cert, f.certificate, identity_ca, f.identity_ca);

  Bio key_bio = open_file(f.private_key);
  // No passphrase: without this callback OpenSSL would ask for one on the terminal and block.
  pem_password_cb* no_passphrase = [](char*, int, int, void*) { return 0; };
  Key key(PEM_read_bio_PrivateKey(key_bio.get(), nullptr, no_passphrase, nullptr));
  if (!key) refuse(f.private_key, "is not a PEM private key (or is encrypted)" + openssl_reason());
  if (X509_check_private_key(cert.get(), key.get()) != 1) refuse(f.private_key, "does not belong to " + f.certificate);

  const std::string governance = verified_content(f.governance, permissions_ca, f.permissions_ca);
  if (governance.find("domain_access_rules") == std::string::npos) refuse(f.governance, "is not a DDS governance document");
  const std::string permissions = verified_content(f.permissions, permissions_ca, f.permissions_ca);
  if (permissions.find("<grant") == std::string::npos) refuse(f.permissions, "is not a DDS permissions document");
  check_grant(f.permissions, permissions, cert, f.certificate);
  return f;
}

}  // namespace plumb::transport
