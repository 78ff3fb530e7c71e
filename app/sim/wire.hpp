// Serial wire emulation for fivebar-sim: bytes cross at most baud/10 per second in each
// direction (8 data bits, no parity, 1 stop bit), like a real UART link. baud <= 0: no limit.
#pragma once

#include <algorithm>
#include <string>

namespace fivebar::simapp {

class Wire {
 public:
  explicit Wire(double baud) : bytesPerS_(baud / 10.0) {}
  void queueIn(const std::string& bytes) { in_ += bytes; }
  void queueOut(const std::string& bytes) { out_ += bytes; }
  // Bytes that have finished crossing the wire by nowS (seconds, monotonic).
  std::string deliverIn(double nowS) { return take(in_, inClockS_, nowS); }
  std::string deliverOut(double nowS) { return take(out_, outClockS_, nowS); }

 private:
  // clockS: when the wire becomes free for the next byte.
  std::string take(std::string& queue, double& clockS, double nowS) {
    if (bytesPerS_ <= 0.0 || queue.empty()) {
      std::string all;
      all.swap(queue);
      return all;
    }
    clockS = std::max(clockS, nowS - 1.0 / bytesPerS_);  // an idle wire has no credit
    const auto n = std::min(queue.size(), std::size_t((nowS - clockS) * bytesPerS_));
    clockS += double(n) / bytesPerS_;
    std::string part = queue.substr(0, n);
    queue.erase(0, n);
    return part;
  }
  double bytesPerS_;
  std::string in_, out_;
  double inClockS_ = 0.0, outClockS_ = 0.0;
};

}  // namespace fivebar::simapp
