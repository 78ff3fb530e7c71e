// SPDX-License-Identifier: GPL-3.0-or-later
// Batch kinematics (core/batch.hpp) against the exact scalar API: same reach verdicts, angles
// within kBatchAngleToleranceRad, positions within kBatchPositionToleranceMm, NaN where not ok,
// on seeded random points including reach-boundary and out-of-reach ones.
#include "core/kinematics/batch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/singularity.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

const Geometry kAsymmetric{55.0, 130.0, 70.0, 110.0, 42.0};
const Geometry kHoang{70.0, 200.0, 70.0, 200.0, 250.0};
const Geometry kDai{135.0, 135.0, 135.0, 135.0, 180.0};
const Geometry kCoaxial{60.0, 90.0, 75.0, 80.0, 0.0};
const Geometry kAllGeometries[] = {kAsymmetric, kHoang, kDai, kCoaxial};

// Signed angle difference folded into (-pi, pi].
double angleDiff(double a, double b) { return std::remainder(a - b, 2.0 * kPi); }

struct Points {
  std::vector<double> x, y;
  void add(const Vec2& p) {
    x.push_back(p.x());
    y.push_back(p.y());
  }
  std::size_t size() const { return x.size(); }
};

// Uniform points in a box that contains the whole workspace and plenty outside it.
Points randomPoints(const Geometry& g, std::size_t n, std::mt19937_64& rng) {
  const double reach = std::max(g.a1 + g.b1, g.a2 + g.b2) + 0.5 * g.w + 10.0;
  std::uniform_real_distribution<double> u(-reach, reach);
  Points pts;
  for (std::size_t i = 0; i < n; ++i) pts.add(Vec2(u(rng), u(rng)));
  return pts;
}

// Points on (or a rounding error off, or 1e-7 mm inside / 1e-3 mm outside) the four reach
// circles of g, in every direction.
Points boundaryPoints(const Geometry& g, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  const double offsets[] = {0.0, 1e-15, -1e-15, -1e-7, -1e-3, 1e-3};
  Points pts;
  for (int k = 0; k < 400; ++k) {
    const Vec2 dir(std::cos(angle(rng)), std::sin(angle(rng)));
    for (double rel : offsets) {
      pts.add(g.motor1() + (g.a1 + g.b1) * (1.0 + rel) * dir);
      pts.add(g.motor1() + std::abs(g.a1 - g.b1) * (1.0 - rel) * dir);
      pts.add(g.motor2() + (g.a2 + g.b2) * (1.0 + rel) * dir);
      pts.add(g.motor2() + std::abs(g.a2 - g.b2) * (1.0 - rel) * dir);
    }
  }
  return pts;
}

// Runs inverseBatch and compares every point with inverse().
void expectIkMatchesScalar(const Geometry& g, WorkingMode mode, const Points& pts,
                           const BatchOptions& options = {}) {
  const std::size_t n = pts.size();
  std::vector<double> t1(n), t2(n);
  std::vector<std::uint8_t> ok(n, 7);
  inverseBatch(g, mode, pts.x.data(), pts.y.data(), n, t1.data(), t2.data(), ok.data(), options);
  std::size_t reachable = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const IkResult ref = inverse(g, Vec2(pts.x[i], pts.y[i]), mode);
    ASSERT_EQ(ok[i], ref.ok() ? 1 : 0)
        << "point " << pts.x[i] << ", " << pts.y[i] << " mode " << toString(mode);
    if (ref.ok()) {
      ++reachable;
      EXPECT_LE(std::abs(angleDiff(t1[i], ref.angles.theta1)), kBatchAngleToleranceRad)
          << "theta1 at " << pts.x[i] << ", " << pts.y[i] << " mode " << toString(mode);
      EXPECT_LE(std::abs(angleDiff(t2[i], ref.angles.theta2)), kBatchAngleToleranceRad)
          << "theta2 at " << pts.x[i] << ", " << pts.y[i] << " mode " << toString(mode);
      EXPECT_GT(t1[i], -kPi);
      EXPECT_LE(t1[i], kPi);
      EXPECT_GT(t2[i], -kPi);
      EXPECT_LE(t2[i], kPi);
    } else {
      EXPECT_TRUE(std::isnan(t1[i]) && std::isnan(t2[i]));
    }
  }
  EXPECT_GT(reachable, 0u);
}

// Every compiled variant this CPU can run (Generic always).
std::vector<BatchKernel> runnableKernels() {
  std::vector<BatchKernel> kernels;
  for (BatchKernel k : {BatchKernel::Generic, BatchKernel::Avx2, BatchKernel::Avx512})
    if (batchKernelSupported(k)) kernels.push_back(k);
  return kernels;
}

TEST(BatchInverse, MatchesScalarOnRandomPointsAllModesAllKernels) {
  auto rng = test::rng();
  for (BatchKernel kernel : runnableKernels()) {
    SCOPED_TRACE(toString(kernel));
    for (const Geometry& g : kAllGeometries) {
      const Points pts = randomPoints(g, 10000, rng);
      for (WorkingMode m : kAllWorkingModes) expectIkMatchesScalar(g, m, pts, {1, 1, kernel});
    }
  }
}

TEST(BatchInverse, MatchesScalarAtTheReachBoundary) {
  auto rng = test::rng();
  for (BatchKernel kernel : runnableKernels()) {
    SCOPED_TRACE(toString(kernel));
    for (const Geometry& g : kAllGeometries) {
      const Points pts = boundaryPoints(g, rng);
      for (WorkingMode m : kAllWorkingModes) expectIkMatchesScalar(g, m, pts, {1, 1, kernel});
    }
  }
}

TEST(BatchKernels, UnsupportedRequestFallsBackAndNamesAreKnown) {
  EXPECT_TRUE(batchKernelSupported(BatchKernel::Auto));
  EXPECT_TRUE(batchKernelSupported(BatchKernel::Generic));
  EXPECT_EQ(toString(BatchKernel::Avx2), "avx2+fma");
  const std::string_view best = batchKernelName();
  EXPECT_TRUE(best == "generic" || best == "avx2+fma" || best == "avx512") << best;
  // Whatever is requested, the results are right (an unsupported variant runs as Auto).
  auto rng = test::rng();
  const Points pts = randomPoints(kAsymmetric, 1000, rng);
  expectIkMatchesScalar(kAsymmetric, WorkingMode::MinusMinus, pts, {1, 1, BatchKernel::Avx512});
}

TEST(BatchInverse, OutOfReachAndMotorAxisGiveNaN) {
  const Geometry& g = kAsymmetric;
  Points pts;
  pts.add(g.motor1() + Vec2(0.0, g.a1 + g.b1 + 1e-6));  // just beyond leg 1
  pts.add(Vec2(1e6, 1e6));                              // far away
  pts.add(g.motor1());                                  // on motor axis 1 (d = 0)
  pts.add(Vec2(std::nan(""), 10.0));                    // not a number
  std::vector<double> t1(pts.size()), t2(pts.size());
  std::vector<std::uint8_t> ok(pts.size(), 1);
  inverseBatch(g, WorkingMode::PlusPlus, pts.x.data(), pts.y.data(), pts.size(), t1.data(),
               t2.data(), ok.data());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_EQ(ok[i], 0) << "point " << i;
    EXPECT_TRUE(std::isnan(t1[i])) << "point " << i;
    EXPECT_TRUE(std::isnan(t2[i])) << "point " << i;
  }
}

TEST(BatchInverse, ThreadSplitGivesIdenticalResults) {
  auto rng = test::rng();
  const Points pts = randomPoints(kHoang, 10007, rng);  // odd size: uneven chunks and tails
  const std::size_t n = pts.size();
  std::vector<double> a1(n), a2(n), b1(n), b2(n);
  std::vector<std::uint8_t> okA(n), okB(n);
  inverseBatch(kHoang, WorkingMode::PlusMinus, pts.x.data(), pts.y.data(), n, a1.data(), a2.data(),
               okA.data(), BatchOptions{1, 1});
  inverseBatch(kHoang, WorkingMode::PlusMinus, pts.x.data(), pts.y.data(), n, b1.data(), b2.data(),
               okB.data(), BatchOptions{3, 1000});
  EXPECT_EQ(okA, okB);
  for (std::size_t i = 0; i < n; ++i) {
    if (!okA[i]) continue;
    EXPECT_EQ(a1[i], b1[i]);
    EXPECT_EQ(a2[i], b2[i]);
  }
  expectIkMatchesScalar(kHoang, WorkingMode::MinusPlus, pts, BatchOptions{2, 100});
}

TEST(BatchInverse, EmptyBatchIsANoOp) {
  inverseBatch(kHoang, WorkingMode::PlusPlus, nullptr, nullptr, 0, nullptr, nullptr, nullptr);
  forwardBatch(kHoang, AssemblyMode::Plus, nullptr, nullptr, 0, nullptr, nullptr, nullptr);
  EXPECT_FALSE(batchKernelName().empty());
}

TEST(BatchInverse, MisalignedBuffersAndShortTails) {
  // Buffers starting one element past an aligned address, with lengths that are not a multiple
  // of any vector width: the vector loops' peeling and tails must give the scalar answers.
  auto rng = test::rng();
  const Points pts = randomPoints(kAsymmetric, 64, rng);
  for (std::size_t n : {std::size_t{1}, std::size_t{3}, std::size_t{17}, std::size_t{63}}) {
    std::vector<double> t1(n + 1), t2(n + 1);
    std::vector<std::uint8_t> ok(n + 1);
    inverseBatch(kAsymmetric, WorkingMode::PlusMinus, pts.x.data() + 1, pts.y.data() + 1, n,
                 t1.data() + 1, t2.data() + 1, ok.data() + 1);
    for (std::size_t i = 0; i < n; ++i) {
      const IkResult ref =
          inverse(kAsymmetric, Vec2(pts.x[i + 1], pts.y[i + 1]), WorkingMode::PlusMinus);
      ASSERT_EQ(ok[i + 1], ref.ok() ? 1 : 0) << "n " << n << " i " << i;
      if (ref.ok()) {
        EXPECT_LE(std::abs(angleDiff(t1[i + 1], ref.angles.theta1)), kBatchAngleToleranceRad);
      }
    }
  }
}

TEST(BatchForward, LargeUnwrappedAnglesMatchScalar) {
  // Continuous motion carries unwrapped angles: thousands of radians must still reduce exactly.
  auto rng = test::rng();
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  std::uniform_int_distribution<int> turns(-15000, 15000);  // |theta| up to about 9.4e4 rad
  const std::size_t n = 5000;
  std::vector<double> t1(n), t2(n), x(n), y(n);
  std::vector<std::uint8_t> ok(n);
  for (std::size_t i = 0; i < n; ++i) {
    t1[i] = angle(rng) + 2.0 * kPi * turns(rng);
    t2[i] = angle(rng) + 2.0 * kPi * turns(rng);
  }
  forwardBatch(kHoang, AssemblyMode::Plus, t1.data(), t2.data(), n, x.data(), y.data(),
               ok.data());
  std::size_t compared = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const JointAngles q{t1[i], t2[i]};
    const FkResult ref = forward(kHoang, q, AssemblyMode::Plus);
    ASSERT_EQ(ok[i], ref.ok() ? 1 : 0) << "angles " << t1[i] << ", " << t2[i];
    if (!ref.ok()) continue;
    ++compared;
    EXPECT_LE((Vec2(x[i], y[i]) - ref.p).norm(), kBatchPositionToleranceMm)
        << "angles " << t1[i] << ", " << t2[i];
  }
  EXPECT_GT(compared, n / 10);
}

// Random motor angles (some unwrapped by whole turns) through forwardBatch and forward().
void expectFkMatchesScalar(const Geometry& g, AssemblyMode mode, std::mt19937_64& rng,
                           BatchKernel kernel) {
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  std::uniform_int_distribution<int> turns(-3, 3);
  const std::size_t n = 10000;
  std::vector<double> t1(n), t2(n), x(n), y(n);
  std::vector<std::uint8_t> ok(n, 7);
  for (std::size_t i = 0; i < n; ++i) {
    t1[i] = angle(rng) + 2.0 * kPi * turns(rng);
    t2[i] = angle(rng) + 2.0 * kPi * turns(rng);
  }
  forwardBatch(g, mode, t1.data(), t2.data(), n, x.data(), y.data(), ok.data(), {1, 1, kernel});
  std::size_t compared = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const JointAngles q{t1[i], t2[i]};
    const FkResult ref = forward(g, q, mode);
    ASSERT_EQ(ok[i], ref.ok() ? 1 : 0) << "angles " << t1[i] << ", " << t2[i];
    if (!ref.ok()) {
      EXPECT_TRUE(std::isnan(x[i]) && std::isnan(y[i]));
      continue;
    }
    // Near a type II singularity FK itself is ill-conditioned (error ~ rounding / sin(mu)), so
    // the two implementations are only compared where the floating links are 1e-3 rad away.
    if (singularityMargins(g, makePose(g, q, ref.p)).typeII < 1e-3) continue;
    ++compared;
    EXPECT_LE((Vec2(x[i], y[i]) - ref.p).norm(), kBatchPositionToleranceMm)
        << "angles " << t1[i] << ", " << t2[i];
  }
  EXPECT_GT(compared, n / 10);
}

TEST(BatchForward, MatchesScalarOnRandomAnglesBothModesAllKernels) {
  auto rng = test::rng();
  for (BatchKernel kernel : runnableKernels()) {
    SCOPED_TRACE(toString(kernel));
    for (const Geometry& g : kAllGeometries)
      for (AssemblyMode m : kAllAssemblyModes) expectFkMatchesScalar(g, m, rng, kernel);
  }
}

TEST(BatchForward, RoundTripThroughBatchInverse) {
  auto rng = test::rng();
  const Geometry& g = kAsymmetric;
  const Points pts = randomPoints(g, 20000, rng);
  const std::size_t n = pts.size();
  std::vector<double> t1(n), t2(n), x(n), y(n);
  std::vector<std::uint8_t> okIk(n), okFk(n);
  for (WorkingMode wm : kAllWorkingModes) {
    inverseBatch(g, wm, pts.x.data(), pts.y.data(), n, t1.data(), t2.data(), okIk.data());
    for (AssemblyMode am : kAllAssemblyModes) {
      forwardBatch(g, am, t1.data(), t2.data(), n, x.data(), y.data(), okFk.data());
      for (std::size_t i = 0; i < n; ++i) {
        if (!okIk[i]) {
          EXPECT_EQ(okFk[i], 0);  // NaN angles never close
          continue;
        }
        const Vec2 p(pts.x[i], pts.y[i]);
        const Pose pose = makePose(g, inverse(g, p, wm).angles, p);
        if (assemblyModeOf(pose) != am || singularityMargins(g, pose).typeII < 1e-3) continue;
        ASSERT_EQ(okFk[i], 1);
        EXPECT_LT((Vec2(x[i], y[i]) - p).norm(), 1e-6) << "at " << p.transpose();
      }
    }
  }
}

}  // namespace
}  // namespace fivebar
