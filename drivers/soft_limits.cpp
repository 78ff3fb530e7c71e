#include "drivers/soft_limits.hpp"

#include <cstdio>

namespace fivebar::setup {
namespace {

// GRBL compares the float target with the travel exactly; the job's and the offset's 3-decimal
// texts leave only rounding below this.
constexpr double kSoftLimitToleranceDeg = 1e-9;

std::optional<int> outside(const std::array<double, 2>& machineDeg, const std::array<double, 2>& travelDeg) {
  for (int axis = 0; axis < 2; ++axis) {
    const double m = machineDeg[std::size_t(axis)];
    if (m > kSoftLimitToleranceDeg || m < -travelDeg[std::size_t(axis)] - kSoftLimitToleranceDeg) return axis;
  }
  return std::nullopt;
}

}  // namespace

bool softLimitsOn(const Settings& board) {
  const auto it = board.find(20);
  return it != board.end() && it->second == 1.0;
}

std::optional<SoftLimitHit> firstSoftLimitHit(const job::GcodeJob& job, const Settings& board,
                                              const std::array<double, 2>& wcoDeg) {
  if (!softLimitsOn(board)) return std::nullopt;
  const auto travel = [&](int id) {
    const auto it = board.find(id);
    return it == board.end() ? 0.0 : it->second;
  };
  const std::array<double, 2> travelDeg{travel(130), travel(131)};
  const auto hit = [&](std::size_t index, int fileLine, const std::array<double, 2>& workDeg)
      -> std::optional<SoftLimitHit> {
    const std::array<double, 2> machine{workDeg[0] + wcoDeg[0], workDeg[1] + wcoDeg[1]};
    const auto axis = outside(machine, travelDeg);
    if (!axis) return std::nullopt;
    return SoftLimitHit{index, fileLine, *axis, machine[std::size_t(*axis)], travelDeg[std::size_t(*axis)]};
  };
  for (std::size_t i = 0; i < job.lines.size(); ++i) {
    const job::JobLine& line = job.lines[i];
    if (!line.motion) continue;
    if (auto h = hit(i, line.fileLine, {line.endDeg[0], line.endDeg[1]})) return h;
  }
  return std::nullopt;
}

std::string describe(const SoftLimitHit& hit) {
  char text[320];
  std::snprintf(text, sizeof text,
                "line %d moves motor %d to %.3f deg in machine coordinates, outside the board's "
                "soft-limit travel %.3f..0 ($%d=%.3f)",
                hit.fileLine, hit.axis + 1, hit.machineDeg, -hit.travelDeg, 130 + hit.axis, hit.travelDeg);
  return text;
}

}  // namespace fivebar::setup
