#include "core/planning/time_optimal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/kinematics/units.hpp"

namespace fivebar {
namespace {

// Consecutive points closer than this (mm) are one point.
constexpr double kSamePointMm = 1e-9;
// Step (mm) of the central difference that gives q'(s) = dq/ds from the inverse kinematics.
constexpr double kDerivativeStepMm = 1e-3;
// A motor whose |dq/ds| is below this (rad/mm) does not bound the path acceleration.
constexpr double kStillMotor = 1e-12;
// Z acceleration assumed for a Z-axis pen (mm/s^2), as the GRBL time model.
constexpr double kZAccelMmPerS2 = 100.0;

double wrapped(double a) { return std::remainder(a, 2.0 * kPi); }

// One point of the phase-plane grid: dq/ds there, and d2q/ds2 over the interval that follows.
struct GridPoint {
  double s = 0.0;
  double dq[2] = {0.0, 0.0};
  double ddq[2] = {0.0, 0.0};
};

// dq/ds at p along the unit tangent t, or false where the point (or a neighbour) is out of reach.
bool jointRate(const Geometry& g, WorkingMode mode, const Vec2& p, const Vec2& t, double out[2]) {
  const IkResult a = inverse(g, p - kDerivativeStepMm * t, mode);
  const IkResult b = inverse(g, p + kDerivativeStepMm * t, mode);
  if (!a.ok() || !b.ok()) return false;
  out[0] = wrapped(b.angles.theta1 - a.angles.theta1) / (2.0 * kDerivativeStepMm);
  out[1] = wrapped(b.angles.theta2 - a.angles.theta2) / (2.0 * kDerivativeStepMm);
  return true;
}

// The grid of one smooth piece v[0..m] (no sharp corner inside): the tangent at an inner vertex
// bisects its two segments and is interpolated along each segment, so that q'(s) is continuous.
std::vector<GridPoint> gridOf(const Geometry& g, WorkingMode mode, std::span<const Vec2> v,
                              double stepMm) {
  const size_t m = v.size() - 1;
  std::vector<Vec2> dir(m);
  for (size_t j = 0; j < m; ++j) dir[j] = (v[j + 1] - v[j]).normalized();
  std::vector<GridPoint> grid;
  double s = 0.0;
  for (size_t j = 0; j < m; ++j) {
    const Vec2 tA = j == 0 ? dir[j] : (dir[j - 1] + dir[j]).normalized();
    const Vec2 tB = j + 1 == m ? dir[j] : (dir[j] + dir[j + 1]).normalized();
    const double length = (v[j + 1] - v[j]).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(length / stepMm)));
    for (int k = (j == 0 ? 0 : 1); k <= n; ++k) {
      const double f = static_cast<double>(k) / n;
      const Vec2 p = v[j] + f * (v[j + 1] - v[j]);
      const Vec2 t = ((1.0 - f) * tA + f * tB).normalized();
      GridPoint gp;
      gp.s = s + f * length;
      if (jointRate(g, mode, p, t, gp.dq)) grid.push_back(gp);
    }
    s += length;
  }
  for (size_t k = 0; k + 1 < grid.size(); ++k) {
    const double ds = grid[k + 1].s - grid[k].s;
    for (int i = 0; i < 2; ++i) grid[k].ddq[i] = (grid[k + 1].dq[i] - grid[k].dq[i]) / ds;
  }
  return grid;
}

// The admissible path accelerations u = sddot at one grid point are an interval
// [max_i (l0_i + l1 x), min_i (u0_i + l1 x)] that moves with x = sdot^2 (one motor per term).
struct Stage {
  double l0[2], u0[2], slope[2];
  bool bounds[2];
  double maxX;  // largest x at which the constraints admit any u (speed and acceleration)

  Stage(const GridPoint& gp, double askedSq, const MotorLimits& lim) {
    maxX = askedSq;
    for (int i = 0; i < 2; ++i) {
      const double c = gp.dq[i], d = gp.ddq[i], a = lim.maxAccelRadPerS2[i];
      bounds[i] = std::abs(c) > kStillMotor;
      if (bounds[i]) {
        l0[i] = -a / std::abs(c);
        u0[i] = a / std::abs(c);
        slope[i] = -d / c;
        const double v = lim.maxSpeedRadPerS[i] / std::abs(c);
        maxX = std::min(maxX, v * v);
      } else {
        l0[i] = u0[i] = slope[i] = 0.0;
        if (d != 0.0) maxX = std::min(maxX, a / std::abs(d));
      }
    }
    if (bounds[0] && bounds[1]) {  // one motor's lowest u must stay below the other's highest
      const double gap = std::abs(slope[0] - slope[1]);
      if (gap > 0.0) maxX = std::min(maxX, (u0[0] + u0[1]) / gap);
    }
  }
  double uMax(double x) const {
    double u = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 2; ++i)
      if (bounds[i]) u = std::min(u, u0[i] + slope[i] * x);
    return u;
  }
  // Largest x from which a step of 2 ds u can end at or below xNext with an admissible u.
  double maxXReaching(double xNext, double ds) const {
    double x = maxX;
    for (int i = 0; i < 2; ++i) {
      if (!bounds[i]) continue;
      const double coef = 1.0 + 2.0 * ds * slope[i];
      const double rhs = xNext - 2.0 * ds * l0[i];
      if (coef > 0.0) x = std::min(x, rhs / coef);
    }
    return std::max(0.0, x);
  }
};

double timeOfGrid(const std::vector<GridPoint>& grid, double askedMmPerS, const MotorLimits& lim) {
  const size_t n = grid.size();
  if (n < 2) return 0.0;
  const double askedSq = askedMmPerS * askedMmPerS;
  std::vector<Stage> stages;
  stages.reserve(n);
  for (const GridPoint& gp : grid) stages.emplace_back(gp, askedSq, lim);
  std::vector<double> x(n, 0.0);  // backward pass: the largest x that can still stop at the end
  for (size_t k = n - 1; k-- > 0;)
    x[k] = stages[k].maxXReaching(x[k + 1], grid[k + 1].s - grid[k].s);
  x[0] = 0.0;  // forward pass from rest, at the largest admissible acceleration
  double timeS = 0.0;
  for (size_t k = 0; k + 1 < n; ++k) {
    const double ds = grid[k + 1].s - grid[k].s;
    const double reach = x[k] + 2.0 * ds * stages[k].uMax(x[k]);
    x[k + 1] = std::max(0.0, std::min(x[k + 1], reach));
    const double speedSum = std::sqrt(x[k]) + std::sqrt(x[k + 1]);
    if (speedSum > 0.0) timeS += 2.0 * ds / speedSum;
  }
  return timeS;
}

double turnRad(const Vec2& a, const Vec2& b) {
  return std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b));
}

}  // namespace

MotorLimits motorLimitsOf(const MachineProfile& profile) {
  MotorLimits m;
  m.maxSpeedRadPerS[0] = profile.motors.maxSpeedRadPerS1;
  m.maxSpeedRadPerS[1] = profile.motors.maxSpeedRadPerS2;
  m.maxAccelRadPerS2[0] = profile.motors.maxAccelRadPerS2_1;
  m.maxAccelRadPerS2[1] = profile.motors.maxAccelRadPerS2_2;
  return m;
}

double restToRestS(double distanceRad, double maxSpeed, double maxAccel) {
  const double d = std::abs(distanceRad);
  if (d <= 0.0) return 0.0;
  if (d <= maxSpeed * maxSpeed / maxAccel) return 2.0 * std::sqrt(d / maxAccel);
  return d / maxSpeed + maxSpeed / maxAccel;
}

double timeOptimalPathS(const Geometry& g, WorkingMode mode, std::span<const Vec2> pointsMm,
                        double askedMmPerS, const MotorLimits& limits,
                        const TimeOptimalOptions& options) {
  std::vector<Vec2> v;
  v.reserve(pointsMm.size());
  for (const Vec2& p : pointsMm)
    if (v.empty() || (p - v.back()).norm() > kSamePointMm) v.push_back(p);
  if (v.size() < 2 || !(askedMmPerS > 0.0)) return 0.0;
  double timeS = 0.0;
  size_t first = 0;  // the path splits into smooth pieces at its sharp corners
  for (size_t j = 1; j < v.size(); ++j) {
    const bool corner =
        j + 1 < v.size() && turnRad(v[j] - v[j - 1], v[j + 1] - v[j]) > options.sharpCornerRad;
    if (!corner && j + 1 < v.size()) continue;
    const std::span<const Vec2> piece(v.data() + first, j - first + 1);
    timeS += timeOfGrid(gridOf(g, mode, piece, options.gridStepMm), askedMmPerS, limits);
    first = j;
  }
  return timeS;
}

TimeOptimalJob timeOptimalJob(const PlannedJob& job, const MachineProfile& profile,
                              std::span<const double> drawSpeedByLayerMmPerS,
                              const TimeOptimalOptions& options) {
  const MotorLimits lim = motorLimitsOf(profile);
  const auto askedOf = [&](int layer) {
    const double v = layer >= 0 && static_cast<size_t>(layer) < drawSpeedByLayerMmPerS.size()
                         ? drawSpeedByLayerMmPerS[static_cast<size_t>(layer)]
                         : 0.0;
    return v > 0.0 ? v : profile.drawSpeedMmPerS;
  };
  TimeOptimalJob out;
  JointAngles at = job.start;
  Vec2 atXY = job.startXY;
  double z = profile.tool.zUpMm;
  const double zFeed = profile.tool.zFeedMmPerMin / 60.0;
  std::vector<Vec2> stroke;
  int strokeLayer = -1;
  double travel[2] = {0.0, 0.0};  // each motor's rotation along the current travel
  const auto closeStroke = [&] {
    if (stroke.size() > 1)
      out.drawS += timeOptimalPathS(profile.geometry, job.mode, stroke, askedOf(strokeLayer), lim,
                                    options);
    stroke.clear();
  };
  const auto closeTravel = [&] {
    out.travelS += std::max(restToRestS(travel[0], lim.maxSpeedRadPerS[0], lim.maxAccelRadPerS2[0]),
                            restToRestS(travel[1], lim.maxSpeedRadPerS[1], lim.maxAccelRadPerS2[1]));
    travel[0] = travel[1] = 0.0;
  };
  for (const JobMove& m : job.moves) {
    if (m.kind != JobMoveKind::Draw) closeStroke();
    if (m.kind != JobMoveKind::Travel) closeTravel();
    switch (m.kind) {
      case JobMoveKind::Draw:
        if (stroke.empty()) stroke.push_back(atXY);
        stroke.push_back(m.targetXY);
        strokeLayer = m.layerIndex;
        break;
      case JobMoveKind::Travel:
        travel[0] += std::abs(m.target.theta1 - at.theta1);
        travel[1] += std::abs(m.target.theta2 - at.theta2);
        break;
      case JobMoveKind::PenUp:
      case JobMoveKind::PenDown:
        if (profile.tool.kind == ToolKind::ZAxis && zFeed > 0.0) {
          out.travelS += restToRestS(m.toolValue - z, zFeed, kZAccelMmPerS2);
          z = m.toolValue;
        }
        out.dwellS += m.dwellS;
        break;
      case JobMoveKind::Dwell: out.dwellS += m.dwellS; break;
      case JobMoveKind::Pause: break;
    }
    at = m.target;
    atXY = m.targetXY;
  }
  closeStroke();
  closeTravel();
  return out;
}

}  // namespace fivebar
