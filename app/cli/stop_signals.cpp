// SPDX-License-Identifier: GPL-3.0-or-later
#include "stop_signals.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

namespace fivebar::cli {
namespace {

int pipeFds[2] = {-1, -1};
struct sigaction previousInt, previousTerm;

void onStopSignal(int) {
  const char byte = 1;
  [[maybe_unused]] const ssize_t n = ::write(pipeFds[1], &byte, 1);
}

}  // namespace

StopSignals::StopSignals(std::function<void(int)> onSignal) : onSignal_(std::move(onSignal)) {
  if (::pipe(pipeFds) != 0) return;
  for (int fd : pipeFds) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  notifier_ = std::make_unique<QSocketNotifier>(pipeFds[0], QSocketNotifier::Read);
  QObject::connect(notifier_.get(), &QSocketNotifier::activated, [this] {
    char buf[16];
    while (::read(pipeFds[0], buf, sizeof buf) > 0) {
    }
    onSignal_(++count_);
  });
  struct sigaction sa {};
  sa.sa_handler = onStopSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &sa, &previousInt);
  ::sigaction(SIGTERM, &sa, &previousTerm);
}

StopSignals::~StopSignals() {
  if (!notifier_) return;
  ::sigaction(SIGINT, &previousInt, nullptr);
  ::sigaction(SIGTERM, &previousTerm, nullptr);
  notifier_.reset();
  ::close(pipeFds[0]);
  ::close(pipeFds[1]);
  pipeFds[0] = pipeFds[1] = -1;
}

}  // namespace fivebar::cli
