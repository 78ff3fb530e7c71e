// SPDX-License-Identifier: GPL-3.0-or-later
// Output files of the calibrate commands: written to FILE.part then renamed, and only once every
// output of a command is ready (bad input writes nothing).
#pragma once

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace fivebar::cli {

// Writes every (path, text) pair; on a failure removes what it wrote and names the path.
inline bool writeAllFiles(const std::vector<std::pair<std::string, std::string>>& files,
                          const std::string& command) {
  std::vector<std::string> done;
  for (const auto& [path, text] : files) {
    const std::string part = path + ".part";
    bool ok = false;
    {
      std::ofstream out(part, std::ios::binary | std::ios::trunc);
      out << text;
      out.flush();
      ok = static_cast<bool>(out);
    }
    if (ok && std::rename(part.c_str(), path.c_str()) == 0) {
      done.push_back(path);
      continue;
    }
    std::remove(part.c_str());
    for (const std::string& d : done) std::remove(d.c_str());
    std::cerr << "fivebar " << command << ": cannot write '" << path << "'\n";
    return false;
  }
  return true;
}

}  // namespace fivebar::cli
