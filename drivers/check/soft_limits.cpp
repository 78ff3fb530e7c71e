// SPDX-License-Identifier: GPL-3.0-or-later
#include "drivers/check/soft_limits.hpp"


namespace fivebar::setup {
namespace {

// GRBL compares the float target with the travel exactly; the job's and the offset's 3-decimal
// texts leave only rounding below this.
constexpr double kSoftLimitToleranceDeg = 1e-9;

}  // namespace

std::optional<int> axisOutsideTravel(const std::array<double, 2>& machineDeg,
                                     const std::array<double, 2>& travelDeg) {
  for (int axis = 0; axis < 2; ++axis) {
    const double m = machineDeg[std::size_t(axis)];
    if (m > kSoftLimitToleranceDeg || m < -travelDeg[std::size_t(axis)] - kSoftLimitToleranceDeg) return axis;
  }
  return std::nullopt;
}

bool softLimitsOn(const Settings& board) {
  const auto it = board.find(20);
  return it != board.end() && it->second == 1.0;
}

std::optional<std::array<double, 2>> softLimitTravelDeg(const Settings& board) {
  if (!softLimitsOn(board)) return std::nullopt;
  const auto travel = [&](int id) {
    const auto it = board.find(id);
    return it == board.end() ? 0.0 : it->second;
  };
  return std::array<double, 2>{travel(130), travel(131)};
}

std::optional<SoftLimitHit> firstSoftLimitHit(const stream::GcodeJob& job, const Settings& board,
                                              const std::array<double, 2>& wcoDeg) {
  const auto travel = softLimitTravelDeg(board);
  if (!travel) return std::nullopt;
  const std::array<double, 2> travelDeg = *travel;
  const auto hit = [&](std::size_t index, int fileLine, const std::array<double, 2>& workDeg)
      -> std::optional<SoftLimitHit> {
    const std::array<double, 2> machine{workDeg[0] + wcoDeg[0], workDeg[1] + wcoDeg[1]};
    const auto axis = axisOutsideTravel(machine, travelDeg);
    if (!axis) return std::nullopt;
    return SoftLimitHit{index, fileLine, *axis, machine[std::size_t(*axis)], travelDeg[std::size_t(*axis)]};
  };
  for (std::size_t i = 0; i < job.lines.size(); ++i) {
    const stream::JobLine& line = job.lines[i];
    if (!line.motion) continue;
    if (auto h = hit(i, line.fileLine, {line.endDeg[0], line.endDeg[1]})) return h;
  }
  return std::nullopt;
}

Message describeHit(const SoftLimitHit& hit) {
  return FB_TR("SoftLimits",
               "line %1 moves motor %2 to %3 deg in machine coordinates, outside the board's "
               "soft-limit travel %4..0 ($%5=%6)")
      .arg(hit.fileLine)
      .arg(hit.axis + 1)
      .arg(hit.machineDeg, 3)
      .arg(-hit.travelDeg, 3)
      .arg(130 + hit.axis)
      .arg(hit.travelDeg, 3);
}

std::string describe(const SoftLimitHit& hit) { return describeHit(hit).text(); }

}  // namespace fivebar::setup
