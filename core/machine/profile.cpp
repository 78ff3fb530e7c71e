// SPDX-License-Identifier: GPL-3.0-or-later
// Machine profile validation and JSON (schema: docs/profile-schema.md). The file holds degrees;
// the struct holds radians. Files and "--machine" resolution: core/profile_file.cpp.
#include "core/machine/profile.hpp"

#include <cmath>
#include <sstream>

#include "core/machine/junction_deviation.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/profile_fields.hpp"
#include "core/machine/profile_json.hpp"

namespace fivebar {
namespace {

using nlohmann::json;
using detail::ObjectReader;

constexpr const char* kSchemaName = "fivebar-profile";

bool limitsAreUnlimited(const JointLimits& l) { return l == JointLimits{}; }

void validateLimits(std::vector<ValidationIssue>& out, const JointLimits& l) {
  auto pair = [&](const std::string& name, double lo, double hi) {
    const std::string minField = "limits." + name + "MinDeg", maxField = "limits." + name + "MaxDeg";
    if (!std::isfinite(lo)) out.push_back({minField, FB_TR("Profile", "%1 must be a finite number").arg(minField)});
    if (!std::isfinite(hi)) out.push_back({maxField, FB_TR("Profile", "%1 must be a finite number").arg(maxField)});
    if (std::isfinite(lo) && std::isfinite(hi) && !(lo < hi))
      out.push_back({minField, FB_TR("Profile", "%1 (%2) must be below %3 (%4)")
                                   .arg(minField)
                                   .argSignificant(degFromRad(lo), 10)
                                   .arg(maxField)
                                   .argSignificant(degFromRad(hi), 10)});
  };
  pair("theta1", l.theta1Min, l.theta1Max);
  pair("theta2", l.theta2Min, l.theta2Max);
}

// The table's rule for every field of `section` (limits and home are checked against each other).
void validateSection(std::vector<ValidationIssue>& out, const MachineProfile& p, const std::string& section) {
  for (const ProfileField& f : profileFields())
    if (sectionOf(f) == section)
      for (const ValidationIssue& issue : checkField(f, f.get(p))) out.push_back(issue);
}

void validateTool(std::vector<ValidationIssue>& out, const MachineProfile& p) {
  validateSection(out, p, "tool");
  const ToolSettings& t = p.tool;
  if (t.kind == ToolKind::ZAxis && std::isfinite(t.zUpMm) && std::isfinite(t.zDownMm) &&
      !(t.zUpMm > t.zDownMm))
    out.push_back({"tool.zUpMm", FB_TR("Profile", "tool.zUpMm (%1) must be above tool.zDownMm (%2)")
                                     .argSignificant(t.zUpMm, 10)
                                     .argSignificant(t.zDownMm, 10)});
}

void validateHome(std::vector<ValidationIssue>& out, const MachineProfile& p) {
  auto check = [&](const char* field, double v, double lo, double hi) {
    const std::string f = field;
    if (!std::isfinite(v)) {
      out.push_back({f, FB_TR("Profile", "%1 must be a finite number").arg(f)});
    } else if (v < lo || v > hi) {
      out.push_back({f, FB_TR("Profile", "%1 (%2) lies outside the joint limits [%3, %4]")
                            .arg(f)
                            .argSignificant(degFromRad(v), 10)
                            .argSignificant(degFromRad(lo), 10)
                            .argSignificant(degFromRad(hi), 10)});
    }
  };
  check("home.theta1Deg", p.homeAngles.theta1, p.limits.theta1Min, p.limits.theta1Max);
  check("home.theta2Deg", p.homeAngles.theta2, p.limits.theta2Min, p.limits.theta2Max);
}

const char* toolName(ToolKind k) {
  switch (k) {
    case ToolKind::PenServo: return "pen-servo";
    case ToolKind::ZAxis: return "z-axis";
    case ToolKind::Laser: return "laser";
  }
  return "pen-servo";
}

std::optional<ToolKind> parseToolKind(const std::string& s) {
  for (ToolKind k : {ToolKind::PenServo, ToolKind::ZAxis, ToolKind::Laser})
    if (s == toolName(k)) return k;
  return std::nullopt;
}

}  // namespace

std::vector<ValidationIssue> validate(const MachineProfile& p) {
  std::vector<ValidationIssue> out;
  if (p.name.empty()) out.push_back({"name", FB_TR("Profile", "name must not be empty")});
  const Geometry& g = p.geometry;
  validateSection(out, p, "geometry");
  const std::size_t fieldIssues = out.size();
  validateLimits(out, p.limits);
  if (out.size() == fieldIssues) {
    // Cross-field checks (loop closure, limits admitting a pose) from the geometry module.
    for (ValidationIssue issue : fivebar::validate(g, p.limits)) {
      if (issue.field.rfind("limits", 0) != 0) issue.field = "geometry." + issue.field;
      out.push_back(issue);
    }
  }
  for (const char* section : {"motors"}) validateSection(out, p, section);
  validateTool(out, p);
  for (const char* section : {"motion", "safety", "connection"}) validateSection(out, p, section);
  validateHome(out, p);
  detail::validateCalibration(out, p);
  return out;
}

std::string toJson(const MachineProfile& p) {
  json j;
  j["schema"] = kSchemaName;
  j["version"] = MachineProfile::kSchemaVersion;
  j["name"] = p.name;
  for (const ProfileField& f : profileFields()) {
    const std::string section = sectionOf(f);
    if (section == "limits" && limitsAreUnlimited(p.limits)) continue;
    if (section == "calibration") continue;  // detail::writeCalibration
    const double v = f.get(p);
    if (f.integer) j[section][keyOf(f)] = static_cast<int>(v);
    else j[section][keyOf(f)] = f.roundOnWrite ? roundForFile(v) : v;
  }
  j["workingMode"] = std::string(toString(p.defaultMode));
  j["assemblyMode"] = std::string(toString(p.assembly));
  j["tool"]["kind"] = toolName(p.tool.kind);
  j["connection"]["hasHomingSwitches"] = p.hasHomingSwitches;
  detail::writeCalibration(j, p);
  return j.dump(2) + "\n";
}

namespace {

// Reads the table's fields of one section, in file units. An absent field keeps its value.
void readNumbers(ObjectReader& r, const std::string& section, MachineProfile& p) {
  for (const ProfileField& f : profileFields()) {
    if (sectionOf(f) != section) continue;
    const std::string key = keyOf(f);
    if (f.integer) {
      int v = static_cast<int>(f.get(p));
      r.integer(key.c_str(), v, f.required);
      f.set(p, v);
    } else {
      double v = f.get(p);
      r.number(key.c_str(), v, f.required);
      f.set(p, v);
    }
  }
}

void readModes(ObjectReader& root, MachineProfile& p, std::vector<ValidationIssue>& issues) {
  std::string text(toString(p.defaultMode));
  root.string("workingMode", text);
  if (auto m = parseWorkingMode(text)) p.defaultMode = *m;
  else issues.push_back({"workingMode", FB_TR("Profile", "workingMode must be one of ++, +-, -+, --, got \"%1\"").arg(text)});
  text = std::string(toString(p.assembly));
  root.string("assemblyMode", text);
  if (auto a = parseAssemblyMode(text)) p.assembly = *a;
  else issues.push_back({"assemblyMode", FB_TR("Profile", "assemblyMode must be + or -, got \"%1\"").arg(text)});
}

void readTool(const json* o, MachineProfile& p, std::vector<ValidationIssue>& issues) {
  if (!o) return;
  ObjectReader r(*o, "tool", issues);
  ToolSettings& t = p.tool;
  std::string kind = toolName(t.kind);
  r.string("kind", kind);
  if (auto k = parseToolKind(kind)) t.kind = *k;
  else issues.push_back({"tool.kind", FB_TR("Profile", "tool.kind must be pen-servo, z-axis or laser, got \"%1\"").arg(kind)});
  readNumbers(r, "tool", p);
  r.finish();
}

// A section holding only table fields.
void readSection(ObjectReader& root, const char* section, MachineProfile& p,
                 std::vector<ValidationIssue>& issues, bool required = false) {
  if (const json* o = root.object(section, required)) {
    ObjectReader r(*o, section, issues);
    readNumbers(r, section, p);
    r.finish();
  }
}

void readSections(ObjectReader& root, MachineProfile& p, std::vector<ValidationIssue>& issues) {
  if (const json* o = root.object("geometry", true)) {
    ObjectReader r(*o, "geometry", issues);
    p.geometry = {std::nan(""), std::nan(""), std::nan(""), std::nan(""), std::nan("")};
    readNumbers(r, "geometry", p);
    r.finish();
  }
  readSection(root, "limits", p, issues);
  readModes(root, p, issues);
  const json* motors = root.object("motors");
  readSection(root, "motors", p, issues);
  readTool(root.object("tool"), p, issues);
  readSection(root, "motion", p, issues);
  readSection(root, "safety", p, issues);
  if (const json* o = root.object("connection")) {
    ObjectReader r(*o, "connection", issues);
    readNumbers(r, "connection", p);
    r.boolean("hasHomingSwitches", p.hasHomingSwitches);
    r.finish();
  }
  readSection(root, "home", p, issues);
  detail::readCalibration(root, p, issues);
  // A profile without $11 gets the one that keeps corners within the default tolerance.
  if ((!motors || !motors->contains("junctionDeviationDeg")) && validate(p.geometry).empty())
    p.motors.junctionDeviationDeg = junctionDeviationDegFor(p, kCorneringToleranceMm);
}

// Checks "schema" and "version"; false when the rest of the document must not be read.
bool readHeader(ObjectReader& root, std::vector<ValidationIssue>& issues) {
  std::string schema;
  int version = 0;
  root.string("schema", schema, true);
  root.integer("version", version, true);
  if (!issues.empty()) return false;
  if (schema != kSchemaName) {
    issues.push_back({"schema", FB_TR("Profile", "schema must be \"%1\", got \"%2\" (is this a machine profile?)")
                                    .arg(kSchemaName)
                                    .arg(schema)});
    return false;
  }
  if (version != MachineProfile::kSchemaVersion) {
    issues.push_back({"version", FB_TR("Profile", "version %1 is not supported; this program reads version %2")
                                     .arg(version)
                                     .arg(MachineProfile::kSchemaVersion)});
    return false;
  }
  return true;
}

}  // namespace

ProfileLoad profileFromJson(const std::string& text, const std::string& sourceName) {
  ProfileLoad result;
  json doc;
  if (const auto error = detail::parseJsonText(text, doc)) {
    std::string what = error->what;
    if (auto colon = what.find(": "); colon != std::string::npos) what = what.substr(colon + 2);
    result.issues.push_back({"json", FB_TR("Profile", "%1:%2:%3: invalid JSON: %4")
                                         .arg(sourceName)
                                         .arg(error->position.line)
                                         .arg(error->position.column)
                                         .arg(what)});
    return result;
  }
  if (!doc.is_object()) {
    result.issues.push_back({"json", FB_TR("Profile", "the profile must be a JSON object ({...})")});
    return result;
  }
  ObjectReader root(doc, "", result.issues);
  if (!readHeader(root, result.issues)) return result;
  MachineProfile p;
  root.string("name", p.name, true);
  readSections(root, p, result.issues);
  root.finish();
  // Range and cross-field checks too, so one run reports everything; a field already reported
  // as missing or mistyped is not reported again.
  const std::vector<ValidationIssue> readIssues = result.issues;
  for (const ValidationIssue& issue : validate(p)) {
    bool seen = false;
    for (const ValidationIssue& r : readIssues) seen = seen || r.field == issue.field;
    if (!seen) result.issues.push_back(issue);
  }
  if (result.issues.empty()) result.profile = std::move(p);
  return result;
}

}  // namespace fivebar
