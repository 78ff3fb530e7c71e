// SPDX-License-Identifier: GPL-3.0-or-later
// The profile's versioned "calibration" section (docs/profile-schema.md): written only when the
// profile has one, degrees in the file, round trip, field-named validation, old profiles unchanged.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"
#include "core/machine/profile_fields.hpp"

namespace fivebar {
namespace {

using nlohmann::json;

bool hasIssue(const ProfileLoad& load, const std::string& field, const std::string& text) {
  for (const ValidationIssue& i : load.issues)
    if (i.field == field && i.message.text().find(field) != std::string::npos &&
        i.message.text().find(text) != std::string::npos)
      return true;
  return false;
}

std::string messages(const ProfileLoad& load) {
  std::string all;
  for (const ValidationIssue& i : load.issues) all += i.field + ": " + i.message.text() + "\n";
  return all;
}

MachineProfile calibrated() {
  MachineProfile p = *preset("maker-plotter");
  MachineCalibration c;
  c.zeroOffsetRad1 = radFromDeg(1.25);
  c.zeroOffsetRad2 = radFromDeg(-0.8);
  c.backlashRad1 = radFromDeg(0.12);
  c.backlashRad2 = radFromDeg(0.07);
  c.date = "2026-12-01T22:30:00Z";
  c.fit = {22, 3, 0.041, 0.097, 0.055, {"17"}};
  p.calibration = c;
  return p;
}

TEST(CalibrationSection, UncalibratedProfilesHaveNoSection) {
  for (const std::string& name : presetNames()) {
    const json j = json::parse(toJson(*preset(name)));
    EXPECT_FALSE(j.contains("calibration")) << name;
    const ProfileLoad back = profileFromJson(j.dump(), name);
    ASSERT_TRUE(back.profile) << messages(back);
    EXPECT_FALSE(back.profile->calibration) << name;
  }
}

TEST(CalibrationSection, FileHoldsDegreesAndStatistics) {
  const json j = json::parse(toJson(calibrated()));
  const json& c = j.at("calibration");
  EXPECT_EQ(c.at("version"), 1);
  EXPECT_DOUBLE_EQ(c.at("zeroOffsetDeg1").get<double>(), 1.25);
  EXPECT_DOUBLE_EQ(c.at("zeroOffsetDeg2").get<double>(), -0.8);
  EXPECT_DOUBLE_EQ(c.at("backlashDeg1").get<double>(), 0.12);
  EXPECT_DOUBLE_EQ(c.at("backlashDeg2").get<double>(), 0.07);
  EXPECT_EQ(c.at("marksUsed"), 22);
  EXPECT_EQ(c.at("heldOutMarks"), 3);
  EXPECT_DOUBLE_EQ(c.at("rmsResidualMm").get<double>(), 0.041);
  EXPECT_EQ(c.at("date"), "2026-12-01T22:30:00Z");
  EXPECT_EQ(c.at("outliers"), json::array({"17"}));
  EXPECT_FALSE(c.contains("penOffsetAlongMm"));  // no pen offset: not written
}

TEST(CalibrationSection, RoundTripsExactlyWithAndWithoutPenOffset) {
  for (const bool withPen : {false, true}) {
    MachineProfile p = calibrated();
    if (withPen) p.calibration->penOffset = PenOffset{12.5, -3.25};
    const ProfileLoad back = profileFromJson(toJson(p), "calibrated.json");
    ASSERT_TRUE(back.profile) << messages(back);
    const MachineCalibration& c = *back.profile->calibration;
    EXPECT_NEAR(c.zeroOffsetRad1, p.calibration->zeroOffsetRad1, 1e-12);
    EXPECT_NEAR(c.zeroOffsetRad2, p.calibration->zeroOffsetRad2, 1e-12);
    EXPECT_NEAR(c.backlashRad1, p.calibration->backlashRad1, 1e-12);
    EXPECT_EQ(c.penOffset.has_value(), withPen);
    if (withPen) {
      EXPECT_EQ(*c.penOffset, (PenOffset{12.5, -3.25}));
    }
    EXPECT_EQ(c.fit, p.calibration->fit);
    EXPECT_EQ(c.date, p.calibration->date);
    EXPECT_EQ(toJson(*back.profile), toJson(p));  // and the text is stable
  }
}

TEST(CalibrationSection, EveryNumericMemberIsInTheTable) {
  MachineProfile p = calibrated();
  p.calibration->penOffset = PenOffset{1.0, 2.0};
  const json c = json::parse(toJson(p)).at("calibration");
  std::set<std::string> numeric, table;
  for (auto m = c.begin(); m != c.end(); ++m)
    if (m->is_number()) numeric.insert("calibration." + m.key());
  for (const ProfileField& f : profileFields())
    if (sectionOf(f) == "calibration") table.insert(f.path);
  EXPECT_EQ(numeric, table);
}

TEST(CalibrationSection, MinimalSectionTakesDefaults) {
  json j = json::parse(toJson(*preset("hoang2015")));
  j["calibration"] = {{"version", 1}, {"zeroOffsetDeg1", 0.5}, {"zeroOffsetDeg2", -0.5}};
  const ProfileLoad load = profileFromJson(j.dump(), "min.json");
  ASSERT_TRUE(load.profile) << messages(load);
  const MachineCalibration& c = *load.profile->calibration;
  EXPECT_NEAR(c.zeroOffsetRad1, radFromDeg(0.5), 1e-12);
  EXPECT_EQ(c.backlashRad1, 0.0);
  EXPECT_FALSE(c.penOffset);
  EXPECT_TRUE(c.fit.outlierIds.empty());
}

TEST(CalibrationSection, BadValuesAreNamedByField) {
  json j = json::parse(toJson(calibrated()));
  j["calibration"]["backlashDeg2"] = -0.1;
  j["calibration"]["zeroOffsetDeg1"] = "one";
  j["calibration"].erase("zeroOffsetDeg2");
  j["calibration"]["date"] = "yesterday";
  j["calibration"]["outliers"] = json::array({"3", 4});
  j["calibration"]["penOffsetAlongMm"] = 2.0;  // without its partner
  j["calibration"]["zeroOfset"] = 1.0;
  const ProfileLoad load = profileFromJson(j.dump(), "bad.json");
  EXPECT_FALSE(load.profile);
  EXPECT_TRUE(hasIssue(load, "calibration.backlashDeg2", "between 0 and 10 deg, got -0.1")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "calibration.zeroOffsetDeg1", "must be a number")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "calibration.zeroOffsetDeg2", "missing")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "calibration.date", "ISO 8601")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "calibration.outliers[1]", "must be a string")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "calibration.penOffsetNormalMm", "missing")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "calibration.zeroOfset", "not a known field")) << messages(load);
}

TEST(CalibrationSection, NewerSectionVersionIsRefusedByItsVersion) {
  json j = json::parse(toJson(calibrated()));
  j["calibration"]["version"] = 2;
  const ProfileLoad load = profileFromJson(j.dump(), "new.json");
  EXPECT_FALSE(load.profile);
  EXPECT_TRUE(hasIssue(load, "calibration.version", "version 2 is not supported")) << messages(load);
  j["calibration"] = 3;
  EXPECT_TRUE(hasIssue(profileFromJson(j.dump(), "x.json"), "calibration", "must be an object"));
}

TEST(CalibrationSection, ValidateChecksAPresentCalibration) {
  MachineProfile p = calibrated();
  EXPECT_TRUE(validate(p).empty());
  p.calibration->zeroOffsetRad2 = radFromDeg(200.0);
  p.calibration->fit.maxResidualMm = std::nan("");
  const std::vector<ValidationIssue> issues = validate(p);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].message, "calibration.zeroOffsetDeg2 must be between -180 and 180 deg, got 200");
  EXPECT_EQ(issues[1].message, "calibration.maxResidualMm must be a finite number");
}

TEST(CalibrationSection, CommandedAndKinematicAnglesDifferByTheOffset) {
  const MachineProfile p = calibrated();
  const JointAngles commanded{0.3, 2.1};
  const JointAngles k = kinematicFromCommanded(p.calibration, commanded);
  EXPECT_DOUBLE_EQ(k.theta1, 0.3 + radFromDeg(1.25));
  EXPECT_DOUBLE_EQ(k.theta2, 2.1 + radFromDeg(-0.8));
  const JointAngles back = commandedFromKinematic(p.calibration, k);
  EXPECT_NEAR(back.theta1, commanded.theta1, 1e-15);
  EXPECT_NEAR(back.theta2, commanded.theta2, 1e-15);
  EXPECT_EQ(kinematicFromCommanded(std::nullopt, commanded), commanded);
}

}  // namespace
}  // namespace fivebar
