// SPDX-License-Identifier: GPL-3.0-or-later
// Serial wire emulation for fivebar-sim: bytes cross at most baud/10 per second in each
// direction (8 data bits, no parity, 1 stop bit), like a real UART link. baud <= 0: no limit.
// Times are seconds on one monotonic clock.
#pragma once

#include <algorithm>
#include <string>

namespace fivebar::simapp {

class Wire {
 public:
  explicit Wire(double baud) : bytesPerS_(baud / 10.0) {}
  void queueIn(const std::string& bytes, double nowS) { queue(in_, inClockS_, bytes, nowS); }
  void queueOut(const std::string& bytes, double nowS) { queue(out_, outClockS_, bytes, nowS); }
  // Bytes that have finished crossing the wire by nowS.
  std::string deliverIn(double nowS) { return take(in_, inClockS_, nowS); }
  std::string deliverOut(double nowS) { return take(out_, outClockS_, nowS); }

 private:
  // clockS: when the wire finished (or will have finished) sending the bytes delivered so far;
  // bytes queued on an idle wire start crossing when they are queued.
  static void queue(std::string& q, double& clockS, const std::string& bytes, double nowS) {
    if (q.empty()) clockS = std::max(clockS, nowS);
    q += bytes;
  }
  std::string take(std::string& q, double& clockS, double nowS) const {
    if (bytesPerS_ <= 0.0) {
      std::string all;
      all.swap(q);
      return all;
    }
    if (q.empty() || nowS <= clockS) return {};
    const auto n = std::min(q.size(), std::size_t((nowS - clockS) * bytesPerS_ + 1e-9));
    clockS += double(n) / bytesPerS_;
    std::string part = q.substr(0, n);
    q.erase(0, n);
    return part;
  }
  double bytesPerS_;
  std::string in_, out_;
  double inClockS_ = 0.0, outClockS_ = 0.0;
};

}  // namespace fivebar::simapp
