// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/time_optimal.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/kinematics/singularity.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "core/support/parallel.hpp"

namespace fivebar {
namespace {

// Consecutive points closer than this (mm) are one point.
constexpr double kSamePointMm = 1e-9;
// A motor whose |dq/ds| is below this (rad/mm) does not bound the path acceleration.
constexpr double kStillMotor = 1e-12;
// Grid points added towards each end of a smooth piece, halving the step each time.
constexpr int kEndRefinements = 12;
// Z acceleration assumed for a Z-axis pen (mm/s^2), as the GRBL time model.
constexpr double kZAccelMmPerS2 = 100.0;

// One point of the phase-plane grid: dq/ds there, and d2q/ds2 over the interval that follows.
struct GridPoint {
  double s = 0.0;
  double dq[2] = {0.0, 0.0};
  double ddq[2] = {0.0, 0.0};
};

// dq/ds at p along the unit tangent t (A t = B dq/ds, Hoang 2015 eq. 7, B diagonal), or false
// where the point is out of reach or a leg is stretched (B singular). With a pen offset p is the
// pen: its velocity is P's (J = A^-1 B) plus the offset turning with link b1,
// d(pen)/dq = J + (along I + normal Rot90) de/dq with e = (P - R1) / b1,
// de/dq = (J - [dR1/dtheta1, 0]) / b1, and dq/ds = (d(pen)/dq)^-1 t.
bool jointRate(const Geometry& g, const std::optional<PenOffset>& pen, WorkingMode mode, const Vec2& p,
               const Vec2& t, double out[2]) {
  Vec2 P = p;
  const IkResult ik = pen ? penInverse(g, pen, p, mode, &P) : inverse(g, p, mode);
  if (!ik.ok()) return false;
  const Jacobians j = jacobians(g, makePose(g, ik.angles, P));
  if (std::abs(j.B(0, 0)) < kStillMotor || std::abs(j.B(1, 1)) < kStillMotor) return false;
  if (!pen) {
    const Eigen::Vector2d at = j.A * t;
    out[0] = at[0] / j.B(0, 0);
    out[1] = at[1] / j.B(1, 1);
    return true;
  }
  if (std::abs(j.A.determinant()) < kStillMotor) return false;
  const Eigen::Matrix2d J = j.A.inverse() * j.B;
  Eigen::Matrix2d dR1 = Eigen::Matrix2d::Zero();
  dR1.col(0) = Eigen::Vector2d(-g.a1 * std::sin(ik.angles.theta1), g.a1 * std::cos(ik.angles.theta1));
  const Eigen::Matrix2d de = (J - dR1) / g.b1;
  Eigen::Matrix2d rot90;
  rot90 << 0.0, -1.0, 1.0, 0.0;
  const Eigen::Matrix2d Jpen = J + pen->alongMm * de + pen->normalMm * rot90 * de;
  if (std::abs(Jpen.determinant()) < kStillMotor) return false;
  const Eigen::Vector2d dq = Jpen.inverse() * t;
  out[0] = dq[0];
  out[1] = dq[1];
  return true;
}

// The grid of one smooth piece v[0..m] (no sharp corner inside): the tangent at an inner vertex
// bisects its two segments and is interpolated along each segment, so that q'(s) is continuous.
void gridOf(const Geometry& g, const std::optional<PenOffset>& pen, WorkingMode mode, std::span<const Vec2> v, double stepMm,
            std::vector<Vec2>& dir, std::vector<double>& fractions, std::vector<GridPoint>& grid) {
  const size_t m = v.size() - 1;
  dir.resize(m);
  for (size_t j = 0; j < m; ++j) dir[j] = (v[j + 1] - v[j]).normalized();
  grid.clear();
  double s = 0.0;
  for (size_t j = 0; j < m; ++j) {
    const Vec2 tA = j == 0 ? dir[j] : (dir[j - 1] + dir[j]).normalized();
    const Vec2 tB = j + 1 == m ? dir[j] : (dir[j] + dir[j + 1]).normalized();
    const double length = (v[j + 1] - v[j]).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(length / stepMm)));
    // Fractions along the segment: uniform, and geometrically finer towards the piece's ends
    // (the path starts and ends at rest: a first or last interval of the plain grid would be
    // crossed at half speed however fast the motors can accelerate).
    fractions.clear();
    for (int k = (j == 0 ? 0 : 1); k <= n; ++k) fractions.push_back(static_cast<double>(k) / n);
    for (int i = 1; i <= kEndRefinements; ++i) {
      const double f = std::ldexp(1.0, -i) / n;
      if (j == 0) fractions.push_back(f);
      if (j + 1 == m) fractions.push_back(1.0 - f);
    }
    std::sort(fractions.begin(), fractions.end());
    for (const double f : fractions) {
      const Vec2 p = v[j] + f * (v[j + 1] - v[j]);
      const Vec2 t = ((1.0 - f) * tA + f * tB).normalized();
      GridPoint gp;
      gp.s = s + f * length;
      if (jointRate(g, pen, mode, p, t, gp.dq)) grid.push_back(gp);
    }
    s += length;
  }
  for (size_t k = 0; k + 1 < grid.size(); ++k) {
    const double ds = grid[k + 1].s - grid[k].s;
    for (int i = 0; i < 2; ++i) grid[k].ddq[i] = (grid[k + 1].dq[i] - grid[k].dq[i]) / ds;
  }
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

// Buffers reused from piece to piece (one per thread).
struct Scratch {
  std::vector<Vec2> points, dir;
  std::vector<double> fractions;
  std::vector<GridPoint> grid;
  std::vector<Stage> stages;
  std::vector<double> x;
};

double timeOfGrid(const std::vector<GridPoint>& grid, double askedMmPerS, const MotorLimits& lim,
                  Scratch& scratch) {
  const size_t n = grid.size();
  if (n < 2) return 0.0;
  const double askedSq = askedMmPerS * askedMmPerS;
  std::vector<Stage>& stages = scratch.stages;
  stages.clear();
  for (const GridPoint& gp : grid) stages.emplace_back(gp, askedSq, lim);
  std::vector<double>& x = scratch.x;  // backward pass: the largest x that can still stop at the end
  x.assign(n, 0.0);
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

namespace {

double pathTimeS(const Geometry& g, const std::optional<PenOffset>& pen, WorkingMode mode, std::span<const Vec2> pointsMm,
                 double askedMmPerS, const MotorLimits& limits, const TimeOptimalOptions& options,
                 Scratch& scratch) {
  std::vector<Vec2>& v = scratch.points;
  v.clear();
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
    gridOf(g, pen, mode, piece, options.gridStepMm, scratch.dir, scratch.fractions, scratch.grid);
    timeS += timeOfGrid(scratch.grid, askedMmPerS, limits, scratch);
    first = j;
  }
  return timeS;
}

}  // namespace

double timeOptimalPathS(const Geometry& g, WorkingMode mode, std::span<const Vec2> pointsMm,
                        double askedMmPerS, const MotorLimits& limits,
                        const TimeOptimalOptions& options) {
  return timeOptimalPathS(g, std::nullopt, mode, pointsMm, askedMmPerS, limits, options);
}

double timeOptimalPathS(const Geometry& g, const std::optional<PenOffset>& pen, WorkingMode mode,
                        std::span<const Vec2> pointsMm, double askedMmPerS, const MotorLimits& limits,
                        const TimeOptimalOptions& options) {
  Scratch scratch;
  return pathTimeS(g, pen, mode, pointsMm, askedMmPerS, limits, options, scratch);
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
  // Strokes are collected (points and asked speed) and timed afterwards on every planning
  // thread, in chunks summed in job order (the figure does not depend on the thread count).
  std::vector<Vec2> points;
  struct StrokeRange {
    size_t begin, end;
    double askedMmPerS;
  };
  std::vector<StrokeRange> strokes;
  points.reserve(job.moves.size() + 1);
  JointAngles at = job.start;
  Vec2 atXY = job.startXY;
  double z = profile.tool.zUpMm;
  const double zFeed = profile.tool.zFeedMmPerMin / 60.0;
  size_t strokeBegin = 0;
  int strokeLayer = -1;
  double travel[2] = {0.0, 0.0};  // each motor's rotation along the current travel
  const auto closeStroke = [&] {
    if (points.size() > strokeBegin + 1)
      strokes.push_back({strokeBegin, points.size(), askedOf(strokeLayer)});
    strokeBegin = points.size();
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
        if (points.size() == strokeBegin) points.push_back(atXY);
        points.push_back(m.targetXY);
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
  constexpr size_t kStrokesPerChunk = 256;
  const size_t chunks = (strokes.size() + kStrokesPerChunk - 1) / kStrokesPerChunk;
  std::vector<double> chunkS(chunks, 0.0);
  parallelFor(chunks, planningThreads(), [&](size_t c) {
    Scratch scratch;
    const size_t end = std::min(strokes.size(), (c + 1) * kStrokesPerChunk);
    for (size_t k = c * kStrokesPerChunk; k < end; ++k) {
      const StrokeRange& s = strokes[k];
      chunkS[c] += pathTimeS(profile.geometry, calibratedPenOffset(profile), job.mode,
                             std::span<const Vec2>(points.data() + s.begin, s.end - s.begin),
                             s.askedMmPerS, lim, options, scratch);
    }
  });
  for (double s : chunkS) out.drawS += s;
  return out;
}

}  // namespace fivebar
