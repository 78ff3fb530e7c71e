// SPDX-License-Identifier: GPL-3.0-or-later
// Machine profile files: loading, atomic saving and "--machine PRESET|FILE" resolution.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/machine/profile.hpp"

namespace fivebar {

ProfileLoad loadProfile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ProfileLoad r;
    r.issues.push_back({"file", FB_TR("Profile", "cannot open %1: %2").arg(path).arg(std::strerror(errno))});
    return r;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return profileFromJson(text.str(), path);
}

std::string saveProfile(const MachineProfile& p, const std::string& path) {
  const std::string text = toJson(p);
  std::string tmp = path + ".tmp-XXXXXX";
  const int fd = ::mkstemp(tmp.data());
  if (fd < 0) return "cannot create a temporary file beside " + path + ": " + std::strerror(errno);
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string err = std::strerror(errno);
      ::close(fd);
      ::unlink(tmp.c_str());
      return "cannot write " + tmp + ": " + err;
    }
    written += static_cast<std::size_t>(n);
  }
  ::fchmod(fd, 0644);
  const bool synced = ::fsync(fd) == 0;
  const int syncErrno = errno;
  const bool closed = ::close(fd) == 0;
  if (!synced || !closed) {
    const std::string err = std::strerror(synced ? errno : syncErrno);
    ::unlink(tmp.c_str());
    return "cannot flush " + tmp + ": " + err;
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string err = std::strerror(errno);
    ::unlink(tmp.c_str());
    return "cannot replace " + path + ": " + err;
  }
  return {};
}

ProfileLoad resolveMachine(const std::string& presetOrPath) {
  if (auto p = preset(presetOrPath)) return {std::move(*p), {}};
  // Not a preset: a file. A bare word that is no file gets the list of presets.
  std::ifstream probe(presetOrPath);
  if (!probe && presetOrPath.find('/') == std::string::npos &&
      presetOrPath.find('.') == std::string::npos) {
    std::string names;
    for (const std::string& n : presetNames()) names += (names.empty() ? "" : ", ") + n;
    ProfileLoad r;
    r.issues.push_back({"machine", FB_TR("Profile", "unknown machine preset '%1' (presets: %2; or give a profile file path)")
                                       .arg(presetOrPath)
                                       .arg(names)});
    return r;
  }
  return loadProfile(presetOrPath);
}

}  // namespace fivebar
