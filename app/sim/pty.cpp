// SPDX-License-Identifier: GPL-3.0-or-later
#include "pty.hpp"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace fivebar::simapp {

bool Pty::open(const std::string& linkPath, std::string* error) {
  const auto fail = [&](const std::string& what) {
    *error = what + ": " + std::strerror(errno);
    close();
    return false;
  };
  master_ = posix_openpt(O_RDWR | O_NOCTTY);
  if (master_ < 0) return fail("posix_openpt");
  if (grantpt(master_) != 0) return fail("grantpt");
  if (unlockpt(master_) != 0) return fail("unlockpt");
  const char* name = ptsname(master_);
  if (!name) return fail("ptsname");
  slavePath_ = name;
  slaveKeepAlive_ = ::open(name, O_RDWR | O_NOCTTY);
  if (slaveKeepAlive_ < 0) return fail("open " + slavePath_);
  termios tio{};
  if (tcgetattr(slaveKeepAlive_, &tio) != 0) return fail("tcgetattr");
  cfmakeraw(&tio);
  cfsetispeed(&tio, B115200);
  cfsetospeed(&tio, B115200);
  if (tcsetattr(slaveKeepAlive_, TCSANOW, &tio) != 0) return fail("tcsetattr");
  const int flags = fcntl(master_, F_GETFL);
  if (flags < 0 || fcntl(master_, F_SETFL, flags | O_NONBLOCK) != 0) return fail("fcntl");
  ::unlink(linkPath.c_str());  // a stale link from an earlier run
  if (::symlink(slavePath_.c_str(), linkPath.c_str()) != 0) return fail("symlink " + linkPath);
  linkPath_ = linkPath;
  return true;
}

void Pty::close() {
  if (!linkPath_.empty()) ::unlink(linkPath_.c_str());
  linkPath_.clear();
  if (slaveKeepAlive_ >= 0) ::close(slaveKeepAlive_);
  if (master_ >= 0) ::close(master_);
  slaveKeepAlive_ = master_ = -1;
}

std::string Pty::read() {
  std::string out;
  char buf[4096];
  while (master_ >= 0) {
    const ssize_t n = ::read(master_, buf, sizeof buf);
    if (n <= 0) break;
    out.append(buf, size_t(n));
  }
  return out;
}

void Pty::write(const std::string& bytes) {
  pending_ += bytes;
  while (master_ >= 0 && !pending_.empty()) {
    const ssize_t n = ::write(master_, pending_.data(), pending_.size());
    if (n <= 0) break;  // EAGAIN: the sender is not reading; keep the rest for later
    pending_.erase(0, size_t(n));
  }
}

}  // namespace fivebar::simapp
