// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the CLI test executables: shell quoting, reading a file, a run's result.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fivebar::cli_test {

// What one run of a command gave: its exit code and what it printed.
struct CliResult {
  int exitCode = -1;
  std::string out, err;
};

// `s` quoted for /bin/sh.
inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The whole file, bytes as they are ("" when it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace fivebar::cli_test
