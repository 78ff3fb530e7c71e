// SPDX-License-Identifier: GPL-3.0-or-later
// Arcs, circles, ellipses and rounded rectangles are drawn within the tolerance of the TRUE curve
// (issue 9: the reported deviation includes every error source). Qt SVG 6.4 turns an SVG arc or a
// rounded corner into cubics of up to 90 deg, 2.7e-4 x radius off the curve (0.027 mm on
// r = 100 mm); the import hands Qt its own finer cubics and takes their error from the tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <numbers>
#include <random>

#include <Eigen/SVD>

#include "../core/test_support.hpp"
#include "core/import/flatten.hpp"
#include "core/import/path_data.hpp"
#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/placement.hpp"
#include "core/planning/planner.hpp"
#include "geometry_support.hpp"
#include "import_support.hpp"

namespace fivebar::svg {
namespace {

constexpr double kPi = std::numbers::pi;

Vec2 bezier(const Vec2& p0, const Vec2& c1, const Vec2& c2, const Vec2& p3, double t) {
  const double s = 1.0 - t;
  return s * s * s * p0 + 3 * s * s * t * c1 + 3 * s * t * t * c2 + t * t * t * p3;
}

// Distance from (y0, y1) >= 0 to the ellipse with semi-axes e0 >= e1 > 0 on the axes (Eberly,
// "Distance from a point to an ellipse": bisection on the root of the normal equation; robust
// for any eccentricity).
double distanceInQuadrant(double e0, double e1, double y0, double y1) {
  if (y1 > 0.0) {
    if (y0 <= 0.0) return std::abs(y1 - e1);
    const double z0 = y0 / e0, z1 = y1 / e1, g = z0 * z0 + z1 * z1 - 1.0;
    if (g == 0.0) return 0.0;
    const double r0 = (e0 / e1) * (e0 / e1), n0 = r0 * z0;
    double s0 = z1 - 1.0, s1 = g < 0.0 ? 0.0 : std::hypot(n0, z1) - 1.0, sbar = 0.0;
    for (int i = 0; i < 400; ++i) {
      sbar = 0.5 * (s0 + s1);
      if (sbar == s0 || sbar == s1) break;
      const double a = n0 / (sbar + r0), b = z1 / (sbar + 1.0), h = a * a + b * b - 1.0;
      if (h > 0.0) s0 = sbar;
      else if (h < 0.0) s1 = sbar;
      else break;
    }
    return std::hypot(r0 * y0 / (sbar + r0) - y0, y1 / (sbar + 1.0) - y1);
  }
  const double numer = e0 * y0, denom = e0 * e0 - e1 * e1;
  if (numer < denom) {
    const double x = numer / denom;
    return std::hypot(e0 * x - y0, e1 * std::sqrt(1.0 - x * x));
  }
  return std::abs(y0 - e0);
}

// Distance from p to the ellipse centre + M (cos t, sin t) (any affine image of a circle).
double distanceToAffineEllipse(const Vec2& p, const Vec2& centre, const Eigen::Matrix2d& m) {
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(m, Eigen::ComputeFullU);
  const Vec2 q = svd.matrixU().transpose() * (p - centre);
  const Eigen::Vector2d sigma = svd.singularValues();  // descending
  return distanceInQuadrant(sigma(0), sigma(1), std::abs(q.x()), std::abs(q.y()));
}

// The matrix of the ellipse R(phi) diag(rx, ry).
Eigen::Matrix2d ellipseMatrix(double rx, double ry, double phi) {
  Eigen::Matrix2d m;
  m << std::cos(phi) * rx, -std::sin(phi) * ry, std::sin(phi) * rx, std::cos(phi) * ry;
  return m;
}

double distanceToEllipse(const Vec2& p, const Vec2& centre, double rx, double ry, double phi) {
  return distanceToAffineEllipse(p, centre, ellipseMatrix(rx, ry, phi));
}

// Our arc conversion ends exactly at the arc's end point; arcPieceErrorBound is positive for each
// of its pieces and 0 for cubics that are not such pieces (general cubics, quadratics, Qt's own
// 90 deg pieces): their points are the geometry.
TEST(ArcTruth, OurArcCubicsEndExactlyAndOnlyTheyCarryAnErrorBound) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> coord(-300.0, 300.0), radius(0.5, 400.0), angle(-180, 180);
  std::bernoulli_distribution flag(0.5);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec2 start(coord(rng), coord(rng));
    PathCommand arc{'A', {radius(rng), radius(rng), angle(rng), flag(rng) ? 1.0 : 0.0,
                          flag(rng) ? 1.0 : 0.0, coord(rng), coord(rng)}};
    std::vector<PathCommand> cubics;
    appendArcAsCubics(start.x(), start.y(), arc, cubics);
    ASSERT_FALSE(cubics.empty());
    EXPECT_EQ(cubics.back().v[4], arc.v[5]);
    EXPECT_EQ(cubics.back().v[5], arc.v[6]);
    Vec2 p0 = start;
    for (const PathCommand& c : cubics) {
      ASSERT_EQ(c.op, 'C');
      const Vec2 c1(c.v[0], c.v[1]), c2(c.v[2], c.v[3]), p3(c.v[4], c.v[5]);
      EXPECT_GT(arcPieceErrorBound(p0, c1, c2, p3), 0.0) << "trial " << trial;
      p0 = p3;
    }
  }
  // Not arc pieces: a general cubic, a quadratic raised to a cubic, Qt's 90 deg circle quarter.
  EXPECT_EQ(arcPieceErrorBound({0, 0}, {10, 30}, {40, -20}, {50, 5}), 0.0);
  const Vec2 q0(0, 0), q(20, 40), q3(50, 0);
  EXPECT_LT(arcPieceErrorBound(q0, q0 + 2.0 / 3.0 * (q - q0), q3 + 2.0 / 3.0 * (q - q3), q3), 1e-20);
  const double k90 = 4.0 / 3.0 * std::tan(kPi / 8);
  EXPECT_EQ(arcPieceErrorBound({100, 0}, {100, 100 * k90}, {100 * k90, 100}, {0, 100}), 0.0);
}

// The bound against the measured error of pieces of a known circle/ellipse (rotated, sheared by
// a transform): measured <= bound, and the bound is not loose by more than 30x.
TEST(ArcTruth, PieceBoundCoversTheMeasuredErrorOfTransformedArcs) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> radius(1.0, 500.0), angle(-kPi, kPi), shear(-0.8, 0.8);
  for (int trial = 0; trial < 40; ++trial) {
    const double rx = radius(rng), ry = radius(rng), phi = angle(rng);
    // A full ellipse as a small and a large arc (two half arcs would leave the centre
    // ill-conditioned: SVG's centre formula takes the root of ~0 there).
    const Vec2 centre(12.5, -7.25);
    const Eigen::Matrix2d m = ellipseMatrix(rx, ry, phi);
    const Vec2 a = centre + m * Vec2(std::cos(0.3), std::sin(0.3));
    const Vec2 b = centre + m * Vec2(std::cos(2.3), std::sin(2.3));
    const double deg = phi * 180.0 / kPi;
    std::vector<PathCommand> cubics;
    appendArcAsCubics(a.x(), a.y(), PathCommand{'A', {rx, ry, deg, 0, 1, b.x(), b.y()}}, cubics);
    appendArcAsCubics(b.x(), b.y(), PathCommand{'A', {rx, ry, deg, 1, 1, a.x(), a.y()}}, cubics);
    EXPECT_EQ(cubics.size(), 11u + 22u);  // 2 rad and 2 pi - 2 rad in pieces of at most 11.25 deg
    // An affine map (shear and scale, as an SVG transform does) keeps an arc piece an arc piece
    // of the mapped ellipse: the bound holds in the mapped frame too.
    Eigen::Matrix2d shearScale;
    shearScale << 1.0, shear(rng), 0.0, 0.5;
    Vec2 p0 = a;
    double worstRatio = 0.0;
    for (const PathCommand& c : cubics) {
      const Vec2 c1(c.v[0], c.v[1]), c2(c.v[2], c.v[3]), p3(c.v[4], c.v[5]);
      for (int frame = 0; frame < 2; ++frame) {
        const Eigen::Matrix2d f = frame == 0 ? Eigen::Matrix2d::Identity() : shearScale;
        const double bound = arcPieceErrorBound(f * p0, f * c1, f * c2, f * p3);
        double measured = 0.0;
        for (int i = 0; i <= 64; ++i)
          measured = std::max(measured, distanceToAffineEllipse(f * bezier(p0, c1, c2, p3, i / 64.0),
                                                                f * centre, f * m));
        EXPECT_LE(measured, bound + 1e-12 * std::max(rx, ry)) << "trial " << trial << " frame " << frame;
        if (frame == 0) worstRatio = std::max(worstRatio, measured / bound);
      }
      p0 = p3;
    }
    EXPECT_GT(worstRatio, 1.0 / 30.0) << "the bound is not absurdly loose";
  }
}

std::vector<Vec2> circleSamples(const Vec2& centre, double r, int n) {
  std::vector<Vec2> out;
  for (int i = 0; i < n; ++i) out.push_back(centre + r * Vec2(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)));
  return out;
}

// Imported at 0.004 mm: every vertex within the tolerance of the true curve, and every point of
// the true curve within the tolerance of the polyline. Qt's own arcs missed this by 0.027 mm.
TEST(ArcTruth, LargeArcsCirclesEllipsesAndRoundedCornersImportWithinTheTolerance) {
  const double tol = 0.004;
  ImportOptions o;
  o.toleranceMm = tol;
  struct Case {
    const char* body;
    std::function<double(const Vec2&)> distance;  // page frame (y down), mm
    std::function<std::vector<Vec2>()> truth;
  };
  const Vec2 c(150, 150);
  auto circleDistance = [c](double r) { return [c, r](const Vec2& p) { return std::abs((p - c).norm() - r); }; };
  const std::vector<Case> cases{
      {"<path d='M50 150 A100 100 0 0 1 250 150 A100 100 0 0 1 50 150Z' fill='none' stroke='black'/>",
       circleDistance(100), [c] { return circleSamples(c, 100, 20000); }},
      {"<path d='M150 50 a100 100 0 1 0 0.001 0' fill='none' stroke='black'/>",  // nearly full, relative
       circleDistance(100), [c] { return std::vector<Vec2>{}; }},
      {"<circle cx='150' cy='150' r='120' fill='none' stroke='black'/>", circleDistance(120),
       [c] { return circleSamples(c, 120, 20000); }},
      {"<ellipse cx='150' cy='150' rx='140' ry='60' transform='rotate(30 150 150)' fill='none' stroke='black'/>",
       [c](const Vec2& p) { return distanceToEllipse(p, c, 140, 60, kPi / 6); },
       [] { return std::vector<Vec2>{}; }},
  };
  for (const Case& k : cases) {
    const svg::ImportResult r = test::importText(test::page(k.body, 300, 300), o);
    ASSERT_TRUE(r.ok()) << r.message;
    const std::vector<Polyline> paths = test::allPaths(r.drawing);
    ASSERT_EQ(paths.size(), 1u) << k.body;
    EXPECT_TRUE(paths[0].flattened);
    if (!k.distance) continue;
    double worst = 0.0;
    for (const Vec2& w : paths[0].points) worst = std::max(worst, k.distance(Vec2(w.x(), 300 - w.y())));
    EXPECT_LE(worst, tol * (1 + 1e-9)) << k.body;
    std::vector<Vec2> page;
    for (const Vec2& w : paths[0].points) page.emplace_back(w.x(), 300 - w.y());
    double back = 0.0;
    for (const Vec2& t : k.truth()) back = std::max(back, test::distanceToPolyline(t, page, paths[0].closed));
    EXPECT_LE(back, tol * (1 + 1e-9)) << k.body;
  }
}

// A rounded rectangle (rx = 40 mm corners): its corners are within the tolerance of true quarter
// ellipses, its sides exact.
TEST(ArcTruth, RoundedRectangleCornersAreTrueQuarterEllipses) {
  const double tol = 0.001;
  ImportOptions o;
  o.toleranceMm = tol;
  const svg::ImportResult r = test::importText(
      test::page("<rect x='20' y='30' width='200' height='150' rx='80' ry='50' fill='none' stroke='black'/>", 300, 300), o);
  ASSERT_TRUE(r.ok()) << r.message;
  const std::vector<Polyline> paths = test::allPaths(r.drawing);
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_TRUE(paths[0].closed);
  const double x0 = 20, y0 = 30, x1 = 220, y1 = 180, rx = 80, ry = 50;
  auto distance = [&](const Vec2& p) {  // to the rounded rectangle's outline, page frame
    const double cx = std::clamp(p.x(), x0 + rx, x1 - rx), cy = std::clamp(p.y(), y0 + ry, y1 - ry);
    if (cx == p.x() || cy == p.y()) {  // beside a straight side
      return std::min({std::abs(p.x() - x0), std::abs(p.x() - x1), std::abs(p.y() - y0), std::abs(p.y() - y1)});
    }
    return distanceToEllipse(p, {cx, cy}, rx, ry, 0.0);
  };
  double worst = 0.0;
  int onCorners = 0;
  for (const Vec2& w : paths[0].points) {
    const Vec2 p(w.x(), 300 - w.y());
    worst = std::max(worst, distance(p));
    onCorners += p.x() < x0 + rx || p.x() > x1 - rx ? 1 : 0;
  }
  EXPECT_LE(worst, tol * (1 + 1e-9));
  EXPECT_GT(onCorners, 40);
  // Qt's 90 deg corners would be 2.7e-4 x 80 = 0.022 mm off at 45 deg: the corner point there is
  // on our polyline's side of the tolerance.
  std::vector<Vec2> page;
  for (const Vec2& w : paths[0].points) page.emplace_back(w.x(), 300 - w.y());
  const Vec2 corner(x1 - rx + rx * std::cos(kPi / 4), y1 - ry + ry * std::sin(kPi / 4));
  EXPECT_LE(test::distanceToPolyline(corner, page, true), tol * (1 + 1e-9));
}

// A style sheet that selects <rect> by type keeps the rect a <rect> (its style still applies).
TEST(ArcTruth, RectTypeSelectorsStillStyleRoundedRectangles) {
  const svg::ImportResult r = test::importText(test::page(
      "<style>rect { stroke: #ff0000; fill: none }</style>"
      "<rect x='20' y='20' width='60' height='20' rx='5'/>", 100, 50));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.drawing.layers.size(), 1u);
  EXPECT_EQ(r.drawing.layers[0].rgb, 0xff0000u);
}

// End to end (the check): a 60 mm circle and a 60 mm circle drawn with two arcs, planned at
// --tolerance 0.01 on maker-plotter at true size. The drawn line (FK of every move, densely)
// stays within the reported deviation of the exact circles, each exact circle within it of the
// drawn line, and the reported deviation is within the tolerance.
TEST(ArcTruth, PlannedCirclesAndArcsAreDrawnWithinTheReportedDeviation) {
  const MachineProfile p = *preset("maker-plotter");
  const double r = 60.0;
  const std::string body =
      "<circle cx='70' cy='70' r='60' fill='none' stroke='black'/>"
      "<path d='M150 70 A60 60 0 0 1 270 70 A60 60 0 0 1 150 70' fill='none' stroke='black'/>";
  PlanOptions options;
  options.toleranceMm = 0.01;
  ImportOptions io;
  io.toleranceMm = importToleranceMm(options.toleranceMm);
  svg::ImportResult imported = test::importText(test::page(body, 280, 140), io);
  ASSERT_TRUE(imported.ok()) << imported.message;
  imported.drawing.flatteningToleranceMm = io.toleranceMm;
  PlanResult plan = planJob(imported.drawing, p, options);
  if (plan.status == PlanStatus::CoarseDrawing) {
    io.toleranceMm = plan.requiredFlatteningToleranceMm;
    imported = test::importText(test::page(body, 280, 140), io);
    ASSERT_TRUE(imported.ok());
    imported.drawing.flatteningToleranceMm = io.toleranceMm;
    plan = planJob(imported.drawing, p, options);
  }
  ASSERT_TRUE(plan.ok()) << plan.message.text();
  // Qt's arcs would be 2.7e-4 x the placed radius off: more than the tolerance at this size.
  const double placedR = r * plan.placementScale;
  ASSERT_GT(2.7e-4 * placedR, options.toleranceMm) << "placed too small to tell";
  EXPECT_LE(plan.report.maxDeviationMm, options.toleranceMm);
  // The exact circles in the machine frame, mapped as the planner placed the drawing.
  const Eigen::Affine2d machineFromWorkT = machineFromWork(imported.drawing, plan.placement);
  std::vector<Vec2> centres;
  std::vector<std::vector<Vec2>> dense;
  for (const Vec2& pageCentre : {Vec2(70, 70), Vec2(210, 70)}) {
    const Vec2 work(pageCentre.x(), 140 - pageCentre.y());
    centres.push_back(machineFromWorkT * work);
    dense.emplace_back();
    for (const Vec2& q : circleSamples(work, r, 4096)) dense.back().push_back(machineFromWorkT * q);
  }
  // The drawn line, FK-sampled.
  std::vector<std::vector<Vec2>> drawn;
  JointAngles at = plan.job.start;
  bool down = false;
  for (const JobMove& m : plan.job.moves) {
    if (m.kind == JobMoveKind::PenDown) down = true, drawn.emplace_back();
    if (m.kind == JobMoveKind::PenUp) down = false;
    if (m.kind == JobMoveKind::Draw && down) {
      for (int k = drawn.back().empty() ? 0 : 1; k <= 16; ++k) {
        const double u = k / 16.0;
        const JointAngles q{at.theta1 + u * (m.target.theta1 - at.theta1), at.theta2 + u * (m.target.theta2 - at.theta2)};
        const FkResult fk = forward(p.geometry, q, plan.job.assembly);
        ASSERT_TRUE(fk.ok());
        drawn.back().push_back(fk.p);
      }
    }
    if (isMotion(m.kind)) at = m.target;
  }
  ASSERT_EQ(drawn.size(), 2u);
  double outward = 0.0;  // drawn -> exact
  for (const std::vector<Vec2>& line : drawn) {
    double worst = 0.0;
    for (const Vec2& q : line) {
      double d = 1e300;
      for (const Vec2& c : centres) d = std::min(d, std::abs((q - c).norm() - placedR));
      worst = std::max(worst, d);
    }
    outward = std::max(outward, worst);
  }
  double inward = 0.0;  // exact -> drawn (each circle against its nearest drawn stroke)
  for (const std::vector<Vec2>& ring : dense)
    for (std::size_t i = 0; i < ring.size(); i += 2) {
      double d = 1e300;
      for (const std::vector<Vec2>& line : drawn) d = std::min(d, test::distanceToPolyline(ring[i], line, false));
      inward = std::max(inward, d);
    }
  std::cout << "placed radius " << placedR << " mm: drawn within " << outward << " / " << inward
            << " mm of the exact circles, reported " << plan.report.maxDeviationMm << " mm\n";
  EXPECT_LE(outward, plan.report.maxDeviationMm + 1e-6);
  EXPECT_LE(inward, plan.report.maxDeviationMm + 1e-6);
}

}  // namespace
}  // namespace fivebar::svg
