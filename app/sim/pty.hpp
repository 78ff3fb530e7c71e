// SPDX-License-Identifier: GPL-3.0-or-later
// A pseudo-terminal for fivebar-sim: the master side is the simulated board, the slave side
// (raw mode, reached through a symlink) is what a sender opens as a serial port.
#pragma once

#include <string>

namespace fivebar::simapp {

class Pty {
 public:
  Pty() = default;
  ~Pty() { close(); }
  Pty(const Pty&) = delete;
  Pty& operator=(const Pty&) = delete;

  // Creates the pty (posix_openpt, grantpt, unlockpt), sets the slave raw (cfmakeraw) and
  // points `linkPath` at it. False with *error on failure.
  bool open(const std::string& linkPath, std::string* error);
  // Closes both sides (the sender sees the port vanish) and removes the symlink.
  void close();
  int masterFd() const { return master_; }
  const std::string& slavePath() const { return slavePath_; }
  // Non-blocking read of whatever is available.
  std::string read();
  // Queues bytes and writes what the slave's input buffer takes now; the rest on later calls.
  void write(const std::string& bytes);

 private:
  int master_ = -1;
  int slaveKeepAlive_ = -1;  // keeps the pty usable while no sender has it open
  std::string slavePath_;
  std::string linkPath_;
  std::string pending_;
};

}  // namespace fivebar::simapp
