// SPDX-License-Identifier: GPL-3.0-or-later
// Machine profiles: presets, JSON round trip, validation messages, atomic save, resolution.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/machine/profile.hpp"

namespace fivebar {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The joined messages of a load, for content checks.
std::string messages(const ProfileLoad& load) {
  std::string all;
  for (const ValidationIssue& i : load.issues) all += i.field + ": " + i.message.text() + "\n";
  return all;
}

bool hasIssue(const ProfileLoad& load, const std::string& field, const std::string& text) {
  for (const ValidationIssue& i : load.issues)
    if (i.field == field && i.message.text().find(text) != std::string::npos) return true;
  return false;
}

json presetJson(const std::string& name) { return json::parse(toJson(*preset(name))); }

ProfileLoad loadJson(const json& j) { return profileFromJson(j.dump(2), "test.json"); }

// A fresh empty directory, removed by the destructor.
struct TempDir {
  fs::path path;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "fivebar-profile-XXXXXX").string();
    path = ::mkdtemp(tmpl.data());
  }
  ~TempDir() { fs::remove_all(path); }
};

TEST(Presets, MatchConventionsTable) {
  const auto names = presetNames();
  ASSERT_EQ(names.size(), 4u);
  EXPECT_EQ(preset("hoang2015")->geometry, (Geometry{70, 200, 70, 200, 250}));
  EXPECT_EQ(preset("dai2022")->geometry, (Geometry{135, 135, 135, 135, 180}));
  EXPECT_EQ(preset("article5r")->geometry, (Geometry{40, 60, 40, 60, 30}));
  EXPECT_TRUE(preset("maker-plotter").has_value());
  EXPECT_FALSE(preset("Hoang2015").has_value());
}

TEST(Presets, AreValidAndHomeReachesTheHomePoseInPlusPlus) {
  for (const std::string& name : presetNames()) {
    const MachineProfile p = *preset(name);
    EXPECT_TRUE(validate(p).empty()) << name;
    EXPECT_EQ(p.name, name);
    // The home pose closes the loop and lies in the ++ working mode.
    const FkResult fk = forward(p.geometry, p.homeAngles, p.assembly);
    ASSERT_TRUE(fk.ok()) << name;
    const Pose pose = makePose(p.geometry, p.homeAngles, fk.p);
    EXPECT_EQ(workingModeOf(p.geometry, pose), WorkingMode::PlusPlus) << name;
  }
}

TEST(ProfileJson, RoundTripsEveryPreset) {
  for (const std::string& name : presetNames()) {
    const MachineProfile p = *preset(name);
    const ProfileLoad back = profileFromJson(toJson(p), name);
    ASSERT_TRUE(back.profile) << messages(back);
    const MachineProfile& q = *back.profile;
    EXPECT_EQ(q.geometry, p.geometry);
    EXPECT_NEAR(q.limits.theta1Max, p.limits.theta1Max, 1e-12);
    EXPECT_NEAR(q.limits.theta2Min, p.limits.theta2Min, 1e-12);
    EXPECT_NEAR(q.motors.maxSpeedRadPerS1, p.motors.maxSpeedRadPerS1, 1e-12);
    EXPECT_NEAR(q.motors.maxAccelRadPerS2_2, p.motors.maxAccelRadPerS2_2, 1e-12);
    EXPECT_NEAR(q.typeIIMarginRad, p.typeIIMarginRad, 1e-12);
    EXPECT_NEAR(q.homeAngles.theta1, p.homeAngles.theta1, 1e-10);  // file rounds to 1e-9 deg
    EXPECT_EQ(q.defaultMode, p.defaultMode);
    EXPECT_EQ(q.tool.kind, p.tool.kind);
    EXPECT_EQ(q.baudRate, p.baudRate);
  }
}

TEST(ProfileJson, FileHoldsDegreesAndGrblUnits) {
  MachineProfile p = *preset("hoang2015");
  p.limits.theta1Max = radFromDeg(123.0);
  p.motors.maxSpeedRadPerS1 = radFromDeg(10.0);  // 10 deg/s = 600 deg/min ($110)
  const json j = json::parse(toJson(p));
  EXPECT_EQ(j["schema"], "fivebar-profile");
  EXPECT_EQ(j["version"], 1);
  EXPECT_NEAR(j["limits"]["theta1MaxDeg"].get<double>(), 123.0, 1e-9);
  EXPECT_NEAR(j["motors"]["maxSpeedDegPerMin1"].get<double>(), 600.0, 1e-9);
  EXPECT_NEAR(j["safety"]["typeIIMarginDeg"].get<double>(), 15.0, 1e-3);
}

TEST(ProfileJson, OmittedOptionalSectionsTakeDefaults) {
  const json j = {{"schema", "fivebar-profile"},
                  {"version", 1},
                  {"name", "minimal"},
                  {"geometry", {{"a1", 70}, {"b1", 200}, {"a2", 70}, {"b2", 200}, {"w", 250}}}};
  const ProfileLoad load = loadJson(j);
  ASSERT_TRUE(load.profile) << messages(load);
  EXPECT_EQ(load.profile->limits, JointLimits{});
  EXPECT_EQ(load.profile->defaultMode, WorkingMode::PlusPlus);
  EXPECT_EQ(load.profile->tool.kind, ToolKind::PenServo);
}

TEST(ProfileJson, BrokenJsonNamesLineAndColumn) {
  const std::string text = "{\n  \"schema\": \"fivebar-profile\",\n  \"version\": 1,,\n}\n";
  const ProfileLoad load = profileFromJson(text, "bad.json");
  ASSERT_FALSE(load.profile);
  ASSERT_EQ(load.issues.size(), 1u);
  EXPECT_NE(load.issues[0].message.text().find("bad.json:3:"), std::string::npos) << messages(load);
  EXPECT_NE(load.issues[0].message.text().find("invalid JSON"), std::string::npos);
}

TEST(ProfileJson, NegativeLengthNamesFieldAndValue) {
  json j = presetJson("hoang2015");
  j["geometry"]["a1"] = -3;
  const ProfileLoad load = loadJson(j);
  EXPECT_FALSE(load.profile);
  EXPECT_TRUE(hasIssue(load, "geometry.a1", "geometry.a1 must be positive, got -3")) << messages(load);
}

TEST(ProfileJson, UnknownFieldsAreErrorsNamingThem) {
  json j = presetJson("hoang2015");
  j["geometry"]["a3"] = 5;
  j["motor"] = json::object();
  const ProfileLoad load = loadJson(j);
  EXPECT_FALSE(load.profile);
  EXPECT_TRUE(hasIssue(load, "geometry.a3", "not a known field")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "geometry.a3", "a1")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "motor", "not a known field")) << messages(load);
}

TEST(ProfileJson, WrongTypesAndMissingFieldsAreNamed) {
  json j = presetJson("dai2022");
  j["geometry"]["b2"] = "135";
  j["geometry"].erase("w");
  j["connection"]["baudRate"] = 115200.5;
  const ProfileLoad load = loadJson(j);
  EXPECT_FALSE(load.profile);
  EXPECT_TRUE(hasIssue(load, "geometry.b2", "must be a number, got a string \"135\"")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "geometry.w", "missing")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "connection.baudRate", "integer")) << messages(load);
}

TEST(ProfileJson, SchemaAndVersionAreChecked) {
  json j = presetJson("dai2022");
  j["schema"] = "something-else";
  EXPECT_TRUE(hasIssue(loadJson(j), "schema", "fivebar-profile"));
  j = presetJson("dai2022");
  j["version"] = 2;
  EXPECT_TRUE(hasIssue(loadJson(j), "version", "version 2 is not supported"));
  EXPECT_FALSE(profileFromJson("[1, 2]", "x.json").profile);
}

TEST(ProfileJson, ValuesOutOfRangeAreNamed) {
  json j = presetJson("article5r");
  j["limits"]["theta1MinDeg"] = 300;
  j["tool"]["kind"] = "pencil";
  j["safety"]["typeIIMarginDeg"] = 95;
  j["workingMode"] = "+ +";
  j["motors"]["stepsPerDeg2"] = 0;
  const ProfileLoad load = loadJson(j);
  EXPECT_FALSE(load.profile);
  EXPECT_TRUE(hasIssue(load, "limits.theta1MinDeg", "must be below limits.theta1MaxDeg")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "tool.kind", "\"pencil\"")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "workingMode", "\"+ +\"")) << messages(load);
  // Range checks run in the same pass as the type checks: one run reports everything.
  EXPECT_TRUE(hasIssue(load, "safety.typeIIMarginDeg", "got 95")) << messages(load);
  EXPECT_TRUE(hasIssue(load, "motors.stepsPerDeg2", "must be positive, got 0")) << messages(load);
}

TEST(ProfileJson, CrossFieldChecksNameTheGeometry) {
  json j = presetJson("article5r");
  j["geometry"]["w"] = 500;  // legs can never meet
  EXPECT_TRUE(hasIssue(loadJson(j), "geometry.w", "never meet"));
  j = presetJson("article5r");
  j["home"]["theta1Deg"] = 300;  // beyond theta1MaxDeg = 270
  EXPECT_TRUE(hasIssue(loadJson(j), "home.theta1Deg", "outside the joint limits"));
}

TEST(ProfileFile, SaveIsAtomicAndLoadsBack) {
  TempDir dir;
  const std::string path = (dir.path / "machine.json").string();
  MachineProfile p = *preset("maker-plotter");
  p.name = "first";
  ASSERT_EQ(saveProfile(p, path), "");
  p.name = "second";
  ASSERT_EQ(saveProfile(p, path), "");
  const ProfileLoad load = loadProfile(path);
  ASSERT_TRUE(load.profile) << messages(load);
  EXPECT_EQ(load.profile->name, "second");
  // Only the final file remains: no temporary left beside it.
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path)) ++files;
  EXPECT_EQ(files, 1);
  const std::string err = saveProfile(p, (dir.path / "missing" / "m.json").string());
  EXPECT_NE(err.find("missing"), std::string::npos) << err;
}

TEST(ProfileFile, ResolveMachineTakesPresetsFilesAndNamesBadOnes) {
  ASSERT_TRUE(resolveMachine("dai2022").profile);
  TempDir dir;
  const std::string path = (dir.path / "m.json").string();
  ASSERT_EQ(saveProfile(*preset("article5r"), path), "");
  const ProfileLoad fromFile = resolveMachine(path);
  ASSERT_TRUE(fromFile.profile) << messages(fromFile);
  EXPECT_EQ(fromFile.profile->geometry, preset("article5r")->geometry);

  const ProfileLoad unknown = resolveMachine("hoang2016");
  ASSERT_FALSE(unknown.profile);
  const std::string m = messages(unknown);
  EXPECT_NE(m.find("hoang2016"), std::string::npos) << m;
  for (const std::string& n : presetNames()) EXPECT_NE(m.find(n), std::string::npos) << m;

  const ProfileLoad missing = resolveMachine((dir.path / "nope.json").string());
  EXPECT_TRUE(hasIssue(missing, "file", "nope.json")) << messages(missing);
}

}  // namespace
}  // namespace fivebar
