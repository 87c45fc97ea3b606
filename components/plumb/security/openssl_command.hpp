// Runs the `openssl` command (Debian package openssl) for `plumb security`: making keys,
// certificates and S/MIME signatures is what its command line is for, and what every DDS Security
// guide shows, so a user can redo or audit each step by hand.
#pragma once

#include <string>
#include <vector>

namespace plumb::cli {

// Runs `openssl ARGS...` (no shell); returns its standard output. Throws std::runtime_error with
// one line (the subcommand and openssl's last error line) when it fails or is not installed.
std::string run_openssl(const std::vector<std::string>& args);

}  // namespace plumb::cli
