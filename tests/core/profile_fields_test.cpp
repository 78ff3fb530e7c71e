// SPDX-License-Identifier: GPL-3.0-or-later
// The profile field table (core/machine/profile_fields.hpp): it drives validation and JSON, the
// presets still serialise byte for byte as before the table, and messages name the field path.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/machine/profile.hpp"
#include "core/machine/profile_fields.hpp"

using namespace fivebar;
using nlohmann::json;

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool hasIssue(const std::vector<ValidationIssue>& issues, const std::string& field,
              const std::string& fragment) {
  for (const ValidationIssue& i : issues)
    if (i.field == field && i.message.text().find(field) != std::string::npos &&
        i.message.text().find(fragment) != std::string::npos)
      return true;
  return false;
}

}  // namespace

// Golden files written by `fivebar profile show PRESET` before the table existed.
TEST(ProfileFields, PresetJsonIsByteIdenticalToBeforeTheTable) {
  for (const std::string& name : presetNames()) {
    const std::string golden = readFile(std::string(FIVEBAR_CORE_TEST_DATA) + "/preset_" + name + ".json");
    ASSERT_FALSE(golden.empty()) << name;
    EXPECT_EQ(toJson(*preset(name)), golden) << name;
    // and reading it back and writing again gives the same bytes
    const ProfileLoad back = profileFromJson(golden, name);
    ASSERT_TRUE(back.profile) << name;
    EXPECT_EQ(toJson(*back.profile), golden) << name;
  }
}

TEST(ProfileFields, EveryNumericMemberOfTheFileIsInTheTableOnce) {
  std::set<std::string> paths;
  for (const ProfileField& f : profileFields()) {
    EXPECT_TRUE(paths.insert(f.path).second) << f.path;
    EXPECT_EQ(findProfileField(f.path), &f);
    EXPECT_STRNE(f.label, "");
    EXPECT_LT(f.inputMin, f.inputMax) << f.path;
    EXPECT_GE(f.decimals, 0);
  }
  // A calibrated profile with a pen offset writes every optional numeric member.
  MachineProfile calibrated = *preset("hoang2015");
  calibrated.calibration.emplace().penOffset.emplace();
  const json j = json::parse(toJson(calibrated));
  std::set<std::string> numeric;
  for (auto section = j.begin(); section != j.end(); ++section)
    if (section->is_object())
      for (auto member = section->begin(); member != section->end(); ++member)
        if (member->is_number()) numeric.insert(section.key() + "." + member.key());
  EXPECT_EQ(numeric, paths);
  EXPECT_EQ(findProfileField("geometry.nope"), nullptr);
}

TEST(ProfileFields, GetAndSetRoundTripInFileUnits) {
  MachineProfile p = *preset("dai2022");
  for (const ProfileField& f : profileFields()) {
    const double v = f.integer ? 9600.0 : 12.5;
    f.set(p, v);
    EXPECT_NEAR(f.get(p), v, 1e-9) << f.path;
  }
  // conversions come from units.hpp: 21600 deg/min is one turn per second
  findProfileField("motors.maxSpeedDegPerMin1")->set(p, 21600.0);
  EXPECT_NEAR(p.motors.maxSpeedRadPerS1, 2.0 * 3.141592653589793, 1e-12);
  findProfileField("safety.typeIIMarginDeg")->set(p, 90.0);
  EXPECT_NEAR(p.typeIIMarginRad, 3.141592653589793 / 2.0, 1e-12);
}

TEST(ProfileFields, RulesComeFromTheTableAndMessagesNameThePath) {
  for (const ProfileField& f : profileFields()) {
    if (f.rule == FieldRule::Finite) continue;
    MachineProfile p = *preset("maker-plotter");
    const double bad = f.rule == FieldRule::Between ? f.validMax + 1.0 : -1.0;
    f.set(p, bad);
    EXPECT_TRUE(hasIssue(validate(p), f.path, "got")) << f.path;
    EXPECT_FALSE(checkField(f, bad).empty()) << f.path;
    EXPECT_TRUE(checkField(f, f.get(*preset("maker-plotter"))).empty()) << f.path;
  }
  const ProfileField& delay = *findProfileField("tool.penUpDelayS");
  EXPECT_EQ(checkField(delay, 11.0).at(0).message, "tool.penUpDelayS must be between 0 and 10 s, got 11");
  EXPECT_EQ(checkField(*findProfileField("calibration.version"), 5.0).at(0).message,
            "calibration.version must be between 1 and 1, got 5");  // no unit, no gap
  const ProfileField& w = *findProfileField("geometry.w");
  EXPECT_TRUE(checkField(w, 0.0).empty());
  EXPECT_EQ(checkField(w, -2.0).at(0).message, "geometry.w must be zero or positive, got -2");
  EXPECT_EQ(checkField(*findProfileField("geometry.a1"), 0.0).at(0).message,
            "geometry.a1 must be positive, got 0");
}

TEST(ProfileFields, ReaderUsesTheTableForTypesAndRequiredFields) {
  json j = json::parse(toJson(*preset("hoang2015")));
  j["motors"]["maxAccelDegPerS2_1"] = "fast";
  j["geometry"].erase("b1");
  j["connection"]["baudRate"] = 9600.5;
  const ProfileLoad load = profileFromJson(j.dump(), "x.json");
  EXPECT_FALSE(load.profile);
  EXPECT_TRUE(hasIssue(load.issues, "motors.maxAccelDegPerS2_1", "must be a number"));
  EXPECT_TRUE(hasIssue(load.issues, "geometry.b1", "missing"));
  EXPECT_TRUE(hasIssue(load.issues, "connection.baudRate", "integer"));
}
