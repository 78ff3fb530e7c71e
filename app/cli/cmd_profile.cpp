// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar profile: machine profile utilities.
//   profile check FILE...       validation report, one "FILE: field: message" line per issue
//   profile show PRESET|FILE    the profile as JSON (a starting point for your own machine)
//   profile list                the built-in preset names
#include <iostream>

#include "commands.hpp"
#include "core/machine/profile.hpp"
#include "machine_arg.hpp"
#include "options.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kHelp =
    "usage: fivebar profile check FILE...\n"
    "       fivebar profile show PRESET|FILE\n"
    "       fivebar profile list\n"
    "check prints one 'FILE: field: message' line per problem and exits 1 when any file is\n"
    "invalid; show prints a profile as JSON (schema: docs/profile-schema.md); list prints the\n"
    "built-in presets.\n";

int check(const std::vector<std::string>& files) {
  if (files.empty()) throw UsageError("profile check needs at least one FILE");
  bool allValid = true;
  for (const std::string& file : files) {
    const ProfileLoad load = loadProfile(file);
    if (load.profile) {
      const Geometry& g = load.profile->geometry;
      std::cout << file << ": ok (" << load.profile->name << ": a1=" << g.a1 << " b1=" << g.b1
                << " a2=" << g.a2 << " b2=" << g.b2 << " w=" << g.w << " mm)\n";
      continue;
    }
    allValid = false;
    for (const ValidationIssue& issue : load.issues) {
      // Unreadable files and broken JSON already carry the file name (and line:column).
      if (issue.field == "file" || issue.field == "json")
        std::cout << (issue.message.text().rfind(file, 0) == 0 ? "" : file + ": ") << issue.message << "\n";
      else
        std::cout << file << ": " << issue.field << ": " << issue.message << "\n";
    }
  }
  return allValid ? 0 : 1;
}

}  // namespace

int runProfile(const Args& args) {
  try {
    const Options o(args, {}, {"--help"});
    const auto& pos = o.positional();
    if (o.flag("--help")) {
      std::cout << kHelp;
      return 0;
    }
    if (pos.empty()) throw UsageError("missing subcommand (check, show or list)");
    const std::vector<std::string> rest(pos.begin() + 1, pos.end());
    if (pos[0] == "check") return check(rest);
    if (pos[0] == "show") {
      if (rest.size() != 1) throw UsageError("profile show takes exactly one PRESET or FILE");
      const auto profile = loadMachine(rest[0], "profile show", std::cerr);
      if (!profile) return 1;
      std::cout << toJson(*profile);
      return 0;
    }
    if (pos[0] == "list") {
      if (!rest.empty()) throw UsageError("profile list takes no arguments");
      for (const std::string& name : presetNames()) std::cout << name << "\n";
      return 0;
    }
    throw UsageError("unknown subcommand '" + pos[0] + "' (expected check, show or list)");
  } catch (const UsageError& e) {
    std::cerr << "fivebar profile: " << e.what() << "\n" << kHelp;
    return 2;
  }
}

}  // namespace fivebar::cli
