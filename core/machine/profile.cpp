// Machine profile validation and JSON (schema: docs/profile-schema.md). The file holds degrees;
// the struct holds radians. Files and "--machine" resolution: core/profile_file.cpp.
#include "core/machine/profile.hpp"

#include <cmath>
#include <sstream>

#include "core/machine/junction_deviation.hpp"
#include "core/machine/profile_json.hpp"

namespace fivebar {
namespace {

using nlohmann::json;
using detail::ObjectReader;

constexpr const char* kSchemaName = "fivebar-profile";

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// Appends an issue when v is not finite or not above (or, with allowZero, at) zero.
void checkPositive(std::vector<ValidationIssue>& out, const std::string& field, double v,
                   bool allowZero = false) {
  if (!std::isfinite(v)) {
    out.push_back({field, field + " must be a finite number"});
  } else if (v < 0.0 || (!allowZero && v == 0.0)) {
    out.push_back({field, field + " must be " + (allowZero ? "zero or positive" : "positive") +
                              ", got " + fmt(v)});
  }
}

void checkRange(std::vector<ValidationIssue>& out, const std::string& field, double v, double lo,
                double hi, const char* unit) {
  if (!std::isfinite(v) || v < lo || v > hi) {
    out.push_back({field, field + " must be between " + fmt(lo) + " and " + fmt(hi) + " " + unit +
                              ", got " + fmt(v)});
  }
}

// Degrees for the file, rounded to 1e-9 deg so that 15 deg does not print as 14.999999999999998.
double fileDeg(double angleRad) { return std::round(degFromRad(angleRad) * 1e9) / 1e9; }

bool limitsAreUnlimited(const JointLimits& l) { return l == JointLimits{}; }

void validateLimits(std::vector<ValidationIssue>& out, const JointLimits& l) {
  auto pair = [&](const std::string& name, double lo, double hi) {
    const std::string minField = "limits." + name + "MinDeg", maxField = "limits." + name + "MaxDeg";
    if (!std::isfinite(lo)) out.push_back({minField, minField + " must be a finite number"});
    if (!std::isfinite(hi)) out.push_back({maxField, maxField + " must be a finite number"});
    if (std::isfinite(lo) && std::isfinite(hi) && !(lo < hi))
      out.push_back({minField, minField + " (" + fmt(degFromRad(lo)) + ") must be below " +
                                   maxField + " (" + fmt(degFromRad(hi)) + ")"});
  };
  pair("theta1", l.theta1Min, l.theta1Max);
  pair("theta2", l.theta2Min, l.theta2Max);
}

void validateMotorsAndTool(std::vector<ValidationIssue>& out, const MachineProfile& p) {
  const MotorSettings& m = p.motors;
  checkPositive(out, "motors.stepsPerDeg1", m.stepsPerDeg1);
  checkPositive(out, "motors.stepsPerDeg2", m.stepsPerDeg2);
  checkPositive(out, "motors.maxSpeedDegPerMin1", degFromRad(m.maxSpeedRadPerS1) * 60.0);
  checkPositive(out, "motors.maxSpeedDegPerMin2", degFromRad(m.maxSpeedRadPerS2) * 60.0);
  checkPositive(out, "motors.maxAccelDegPerS2_1", degFromRad(m.maxAccelRadPerS2_1));
  checkPositive(out, "motors.maxAccelDegPerS2_2", degFromRad(m.maxAccelRadPerS2_2));
  checkPositive(out, "motors.junctionDeviationDeg", m.junctionDeviationDeg);
  const ToolSettings& t = p.tool;
  checkPositive(out, "tool.penUpS", t.penUpS, true);
  checkPositive(out, "tool.penDownS", t.penDownS, true);
  checkRange(out, "tool.penUpDelayS", t.penUpDelayS, 0.0, 10.0, "s");
  checkRange(out, "tool.penDownDelayS", t.penDownDelayS, 0.0, 10.0, "s");
  if (!std::isfinite(t.zUpMm)) out.push_back({"tool.zUpMm", "tool.zUpMm must be a finite number"});
  if (!std::isfinite(t.zDownMm))
    out.push_back({"tool.zDownMm", "tool.zDownMm must be a finite number"});
  if (t.kind == ToolKind::ZAxis && std::isfinite(t.zUpMm) && std::isfinite(t.zDownMm) &&
      !(t.zUpMm > t.zDownMm))
    out.push_back({"tool.zUpMm", "tool.zUpMm (" + fmt(t.zUpMm) + ") must be above tool.zDownMm (" +
                                     fmt(t.zDownMm) + ")"});
  checkPositive(out, "tool.zFeedMmPerMin", t.zFeedMmPerMin);
  checkPositive(out, "tool.laserPowerS", t.laserPowerS, true);
}

void validateHome(std::vector<ValidationIssue>& out, const MachineProfile& p) {
  auto check = [&](const char* field, double v, double lo, double hi) {
    const std::string f = field;
    if (!std::isfinite(v)) {
      out.push_back({f, f + " must be a finite number"});
    } else if (v < lo || v > hi) {
      out.push_back({f, f + " (" + fmt(degFromRad(v)) + ") lies outside the joint limits [" +
                            fmt(degFromRad(lo)) + ", " + fmt(degFromRad(hi)) + "]"});
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
  if (p.name.empty()) out.push_back({"name", "name must not be empty"});
  const Geometry& g = p.geometry;
  checkPositive(out, "geometry.a1", g.a1);
  checkPositive(out, "geometry.b1", g.b1);
  checkPositive(out, "geometry.a2", g.a2);
  checkPositive(out, "geometry.b2", g.b2);
  checkPositive(out, "geometry.w", g.w, true);
  const std::size_t fieldIssues = out.size();
  validateLimits(out, p.limits);
  if (out.size() == fieldIssues) {
    // Cross-field checks (loop closure, limits admitting a pose) from the geometry module.
    for (ValidationIssue issue : fivebar::validate(g, p.limits)) {
      if (issue.field.rfind("limits", 0) != 0) issue.field = "geometry." + issue.field;
      out.push_back(issue);
    }
  }
  validateMotorsAndTool(out, p);
  checkPositive(out, "motion.drawSpeedMmPerS", p.drawSpeedMmPerS);
  checkPositive(out, "motion.travelSpeedMmPerS", p.travelSpeedMmPerS);
  checkRange(out, "safety.typeIIMarginDeg", degFromRad(p.typeIIMarginRad), 0.0, 89.0, "deg");
  checkRange(out, "safety.typeIMarginDeg", degFromRad(p.typeIMarginRad), 0.0, 89.0, "deg");
  if (p.baudRate <= 0)
    out.push_back({"connection.baudRate",
                   "connection.baudRate must be positive, got " + std::to_string(p.baudRate)});
  validateHome(out, p);
  return out;
}

std::string toJson(const MachineProfile& p) {
  json j;
  j["schema"] = kSchemaName;
  j["version"] = MachineProfile::kSchemaVersion;
  j["name"] = p.name;
  const Geometry& g = p.geometry;
  j["geometry"] = {{"a1", g.a1}, {"b1", g.b1}, {"a2", g.a2}, {"b2", g.b2}, {"w", g.w}};
  if (!limitsAreUnlimited(p.limits)) {
    const JointLimits& l = p.limits;
    j["limits"] = {{"theta1MinDeg", fileDeg(l.theta1Min)}, {"theta1MaxDeg", fileDeg(l.theta1Max)},
                   {"theta2MinDeg", fileDeg(l.theta2Min)}, {"theta2MaxDeg", fileDeg(l.theta2Max)}};
  }
  j["workingMode"] = std::string(toString(p.defaultMode));
  j["assemblyMode"] = std::string(toString(p.assembly));
  const MotorSettings& m = p.motors;
  j["motors"] = {{"stepsPerDeg1", m.stepsPerDeg1},
                 {"stepsPerDeg2", m.stepsPerDeg2},
                 {"maxSpeedDegPerMin1", std::round(degFromRad(m.maxSpeedRadPerS1) * 60.0 * 1e9) / 1e9},
                 {"maxSpeedDegPerMin2", std::round(degFromRad(m.maxSpeedRadPerS2) * 60.0 * 1e9) / 1e9},
                 {"maxAccelDegPerS2_1", fileDeg(m.maxAccelRadPerS2_1)},
                 {"maxAccelDegPerS2_2", fileDeg(m.maxAccelRadPerS2_2)},
                 {"junctionDeviationDeg", m.junctionDeviationDeg}};
  const ToolSettings& t = p.tool;
  j["tool"] = {{"kind", toolName(t.kind)},       {"penUpS", t.penUpS},
               {"penDownS", t.penDownS},         {"penUpDelayS", t.penUpDelayS},
               {"penDownDelayS", t.penDownDelayS}, {"zUpMm", t.zUpMm},
               {"zDownMm", t.zDownMm},           {"zFeedMmPerMin", t.zFeedMmPerMin},
               {"laserPowerS", t.laserPowerS}};
  j["motion"] = {{"drawSpeedMmPerS", p.drawSpeedMmPerS}, {"travelSpeedMmPerS", p.travelSpeedMmPerS}};
  j["safety"] = {{"typeIIMarginDeg", fileDeg(p.typeIIMarginRad)},
                 {"typeIMarginDeg", fileDeg(p.typeIMarginRad)}};
  j["connection"] = {{"baudRate", p.baudRate}, {"hasHomingSwitches", p.hasHomingSwitches}};
  j["home"] = {{"theta1Deg", fileDeg(p.homeAngles.theta1)},
               {"theta2Deg", fileDeg(p.homeAngles.theta2)}};
  return j.dump(2) + "\n";
}

namespace {

// Reads "x...Deg" into a radian field.
void degrees(ObjectReader& r, const char* key, double& outRad, bool required = false) {
  double deg = degFromRad(outRad);
  r.number(key, deg, required);
  outRad = radFromDeg(deg);
}

void readModes(ObjectReader& root, MachineProfile& p, std::vector<ValidationIssue>& issues) {
  std::string text(toString(p.defaultMode));
  root.string("workingMode", text);
  if (auto m = parseWorkingMode(text)) p.defaultMode = *m;
  else issues.push_back({"workingMode", "workingMode must be one of ++, +-, -+, --, got \"" + text + "\""});
  text = std::string(toString(p.assembly));
  root.string("assemblyMode", text);
  if (auto a = parseAssemblyMode(text)) p.assembly = *a;
  else issues.push_back({"assemblyMode", "assemblyMode must be + or -, got \"" + text + "\""});
}

void readMotors(const json* o, MachineProfile& p, std::vector<ValidationIssue>& issues) {
  if (!o) return;
  ObjectReader r(*o, "motors", issues);
  MotorSettings& m = p.motors;
  r.number("stepsPerDeg1", m.stepsPerDeg1);
  r.number("stepsPerDeg2", m.stepsPerDeg2);
  double v1 = degFromRad(m.maxSpeedRadPerS1) * 60.0, v2 = degFromRad(m.maxSpeedRadPerS2) * 60.0;
  r.number("maxSpeedDegPerMin1", v1);
  r.number("maxSpeedDegPerMin2", v2);
  m.maxSpeedRadPerS1 = radFromDeg(v1 / 60.0);
  m.maxSpeedRadPerS2 = radFromDeg(v2 / 60.0);
  degrees(r, "maxAccelDegPerS2_1", m.maxAccelRadPerS2_1);
  degrees(r, "maxAccelDegPerS2_2", m.maxAccelRadPerS2_2);
  r.number("junctionDeviationDeg", m.junctionDeviationDeg);
  r.finish();
}

void readTool(const json* o, MachineProfile& p, std::vector<ValidationIssue>& issues) {
  if (!o) return;
  ObjectReader r(*o, "tool", issues);
  ToolSettings& t = p.tool;
  std::string kind = toolName(t.kind);
  r.string("kind", kind);
  if (auto k = parseToolKind(kind)) t.kind = *k;
  else issues.push_back({"tool.kind", "tool.kind must be pen-servo, z-axis or laser, got \"" + kind + "\""});
  r.number("penUpS", t.penUpS);
  r.number("penDownS", t.penDownS);
  r.number("penUpDelayS", t.penUpDelayS);
  r.number("penDownDelayS", t.penDownDelayS);
  r.number("zUpMm", t.zUpMm);
  r.number("zDownMm", t.zDownMm);
  r.number("zFeedMmPerMin", t.zFeedMmPerMin);
  r.number("laserPowerS", t.laserPowerS);
  r.finish();
}

void readSections(ObjectReader& root, MachineProfile& p, std::vector<ValidationIssue>& issues) {
  if (const json* o = root.object("geometry", true)) {
    ObjectReader r(*o, "geometry", issues);
    Geometry& g = p.geometry;
    g = {std::nan(""), std::nan(""), std::nan(""), std::nan(""), std::nan("")};
    r.number("a1", g.a1, true);
    r.number("b1", g.b1, true);
    r.number("a2", g.a2, true);
    r.number("b2", g.b2, true);
    r.number("w", g.w, true);
    r.finish();
  }
  if (const json* o = root.object("limits")) {
    ObjectReader r(*o, "limits", issues);
    degrees(r, "theta1MinDeg", p.limits.theta1Min, true);
    degrees(r, "theta1MaxDeg", p.limits.theta1Max, true);
    degrees(r, "theta2MinDeg", p.limits.theta2Min, true);
    degrees(r, "theta2MaxDeg", p.limits.theta2Max, true);
    r.finish();
  }
  readModes(root, p, issues);
  const json* motors = root.object("motors");
  readMotors(motors, p, issues);
  readTool(root.object("tool"), p, issues);
  if (const json* o = root.object("motion")) {
    ObjectReader r(*o, "motion", issues);
    r.number("drawSpeedMmPerS", p.drawSpeedMmPerS);
    r.number("travelSpeedMmPerS", p.travelSpeedMmPerS);
    r.finish();
  }
  if (const json* o = root.object("safety")) {
    ObjectReader r(*o, "safety", issues);
    degrees(r, "typeIIMarginDeg", p.typeIIMarginRad);
    degrees(r, "typeIMarginDeg", p.typeIMarginRad);
    r.finish();
  }
  if (const json* o = root.object("connection")) {
    ObjectReader r(*o, "connection", issues);
    r.integer("baudRate", p.baudRate);
    r.boolean("hasHomingSwitches", p.hasHomingSwitches);
    r.finish();
  }
  if (const json* o = root.object("home")) {
    ObjectReader r(*o, "home", issues);
    degrees(r, "theta1Deg", p.homeAngles.theta1);
    degrees(r, "theta2Deg", p.homeAngles.theta2);
    r.finish();
  }
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
    issues.push_back({"schema", "schema must be \"" + std::string(kSchemaName) + "\", got \"" +
                                    schema + "\" (is this a machine profile?)"});
    return false;
  }
  if (version != MachineProfile::kSchemaVersion) {
    issues.push_back({"version", "version " + std::to_string(version) +
                                     " is not supported; this program reads version " +
                                     std::to_string(MachineProfile::kSchemaVersion)});
    return false;
  }
  return true;
}

}  // namespace

ProfileLoad profileFromJson(const std::string& text, const std::string& sourceName) {
  ProfileLoad result;
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    const auto pos = detail::positionOf(text, e.byte > 0 ? e.byte - 1 : 0);
    std::string what = e.what();
    if (auto colon = what.find(": "); colon != std::string::npos) what = what.substr(colon + 2);
    result.issues.push_back({"json", sourceName + ":" + std::to_string(pos.line) + ":" +
                                         std::to_string(pos.column) + ": invalid JSON: " + what});
    return result;
  }
  if (!doc.is_object()) {
    result.issues.push_back({"json", "the profile must be a JSON object ({...})"});
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
