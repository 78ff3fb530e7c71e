// SPDX-License-Identifier: GPL-3.0-or-later
// GRBL's $11 from the profile (core/machine/junction_deviation.hpp): the corner cut |J| * $11
// stays within the tolerance at every safe point; profiles that hold a $11 keep it, profiles
// without one get the derived value.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <random>
#include <string>

#include "core/kinematics/singularity.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/junction_deviation.hpp"
#include "core/machine/profile.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

TEST(JunctionDeviation, CornerCutStaysWithinTheToleranceAtEverySafePoint) {
  auto rng = test::rng();
  for (const std::string& name : presetNames()) {
    const MachineProfile p = *preset(name);
    const double jd = junctionDeviationDegFor(p, 0.1);
    EXPECT_EQ(p.motors.junctionDeviationDeg, jd) << name;  // the presets use it
    EXPECT_GT(jd, 0.0) << name;
    const Geometry& g = p.geometry;
    const double reach = std::max(g.a1 + g.b1, g.a2 + g.b2) + g.w;
    std::uniform_real_distribution<double> u(-reach, reach);
    int safe = 0;
    for (int k = 0; k < 20000; ++k) {
      const Vec2 at(u(rng), u(rng));
      const IkResult ik = inverse(g, at, p.defaultMode);
      if (!ik.ok()) continue;
      const Pose pose = makePose(g, ik.angles, at);
      const SingularityMargins m = singularityMargins(g, pose);
      if (m.typeII < p.typeIIMarginRad || m.typeI() < p.typeIMarginRad) continue;
      const auto jac = cartesianJacobian(g, pose);
      ASSERT_TRUE(jac.has_value());
      const double lever = Eigen::JacobiSVD<Eigen::Matrix2d>(*jac).singularValues()(0);
      // The grid can miss the very largest |J| by a little: 2 % of slack.
      EXPECT_LE(lever * radFromDeg(jd), 0.1 * 1.02) << name << " at " << at.transpose();
      ++safe;
    }
    EXPECT_GT(safe, 100) << name;
  }
}

TEST(JunctionDeviation, OldProfilesKeepTheirValueAndNewOnesGetTheDerivedOne) {
  const MachineProfile p = *preset("maker-plotter");
  std::string text = toJson(p);
  const std::string key = "\"junctionDeviationDeg\": ";
  const size_t at = text.find(key);
  ASSERT_NE(at, std::string::npos);
  const size_t end = text.find_first_of(",\n}", at + key.size());
  std::string old = text;
  old.replace(at + key.size(), end - at - key.size(), "0.01");
  const ProfileLoad kept = profileFromJson(old, "old.json");
  ASSERT_TRUE(kept.profile.has_value());
  EXPECT_DOUBLE_EQ(kept.profile->motors.junctionDeviationDeg, 0.01);
  std::string without = text;
  size_t lineStart = text.rfind('\n', at);
  size_t lineEnd = text.find('\n', at);
  without.erase(lineStart, lineEnd - lineStart);
  // the member before it now ends the object with a trailing comma: remove it
  const size_t comma = without.rfind(',', lineStart);
  if (without.find_first_not_of(" \n", comma + 1) != std::string::npos &&
      without[without.find_first_not_of(" \n", comma + 1)] == '}')
    without.erase(comma, 1);
  const ProfileLoad derived = profileFromJson(without, "new.json");
  ASSERT_TRUE(derived.profile.has_value()) << (derived.issues.empty() ? "" : derived.issues[0].message);
  EXPECT_DOUBLE_EQ(derived.profile->motors.junctionDeviationDeg, junctionDeviationDegFor(p, 0.1));
}

}  // namespace
}  // namespace fivebar
