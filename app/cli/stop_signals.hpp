// SPDX-License-Identifier: GPL-3.0-or-later
// StopSignals: Ctrl+C (SIGINT) and SIGTERM as a request to stop, delivered on the Qt event loop
// (a self-pipe read by a QSocketNotifier: the handler itself only writes one byte). Installed
// with sigaction, so it also works for a command started with '&' from a non-interactive shell
// (which starts with SIGINT ignored). The previous handlers come back when it is destroyed.
#pragma once

#include <QObject>
#include <QSocketNotifier>
#include <functional>
#include <memory>

namespace fivebar::cli {

class StopSignals {
 public:
  // onSignal(n): the n-th request (1 = the first: stop cleanly; 2 and later: stop at once).
  explicit StopSignals(std::function<void(int count)> onSignal);
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

 private:
  std::function<void(int)> onSignal_;
  std::unique_ptr<QSocketNotifier> notifier_;
  int count_ = 0;
};

}  // namespace fivebar::cli
