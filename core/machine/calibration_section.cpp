// SPDX-License-Identifier: GPL-3.0-or-later
// The profile's versioned "calibration" section (docs/profile-schema.md): written only when the
// profile has a calibration, so uncalibrated profiles (and the preset golden files) are unchanged.
// Numeric members come from the one table (profile_fields.cpp); date and outliers are handled here.
#include <cctype>
#include <cmath>

#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"
#include "core/machine/profile_fields.hpp"
#include "core/machine/profile_json.hpp"

namespace fivebar::detail {
namespace {

constexpr const char* kSection = "calibration";

bool isPenOffsetField(const ProfileField& f) { return keyOf(f).rfind("penOffset", 0) == 0; }

// "YYYY-MM-DD", optionally followed by a time ("THH:MM[:SS][Z|+HH:MM]"); only the date is checked.
bool looksLikeIsoDate(const std::string& s) {
  if (s.size() < 10) return false;
  for (std::size_t i = 0; i < 10; ++i) {
    const bool dash = i == 4 || i == 7;
    if (dash ? s[i] != '-' : !std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  }
  const int month = std::stoi(s.substr(5, 2)), day = std::stoi(s.substr(8, 2));
  return month >= 1 && month <= 12 && day >= 1 && day <= 31 && (s.size() == 10 || s[10] == 'T' || s[10] == ' ');
}

}  // namespace

void writeCalibration(nlohmann::json& j, const MachineProfile& p) {
  if (!p.calibration) return;
  const MachineCalibration& c = *p.calibration;
  nlohmann::json& section = j[kSection];
  for (const ProfileField& f : profileFields()) {
    if (sectionOf(f) != kSection || (isPenOffsetField(f) && !c.penOffset)) continue;
    const double v = f.get(p);
    if (f.integer) section[keyOf(f)] = static_cast<int>(v);
    else section[keyOf(f)] = f.roundOnWrite ? roundForFile(v) : v;
  }
  section["date"] = c.date;
  section["outliers"] = c.fit.outlierIds;
}

void readCalibration(ObjectReader& root, MachineProfile& p, std::vector<ValidationIssue>& issues) {
  const nlohmann::json* o = root.object(kSection);
  if (!o) return;
  ObjectReader r(*o, kSection, issues);
  // The version first: a section from a newer program is refused as a whole, by its version.
  int version = 0;
  const std::size_t before = issues.size();
  r.integer("version", version, true);
  if (issues.size() != before) return;
  if (version < 1 || version > MachineCalibration::kSchemaVersion) {
    issues.push_back({"calibration.version",
                      FB_TR("Profile", "calibration.version %1 is not supported; this program reads version %2")
                          .arg(version)
                          .arg(MachineCalibration::kSchemaVersion)});
    return;
  }
  MachineCalibration& c = p.calibration.emplace();
  c.version = version;
  const bool hasPenOffset = o->contains("penOffsetAlongMm") || o->contains("penOffsetNormalMm");
  if (hasPenOffset) c.penOffset.emplace();
  for (const ProfileField& f : profileFields()) {
    if (sectionOf(f) != kSection || keyOf(f) == "version") continue;
    const std::string key = keyOf(f);
    const bool required = f.required || (hasPenOffset && isPenOffsetField(f));
    if (isPenOffsetField(f) && !hasPenOffset) {
      double unused = 0.0;
      r.number(key.c_str(), unused);  // marks the key as known
      continue;
    }
    if (f.integer) {
      int v = static_cast<int>(f.get(p));
      r.integer(key.c_str(), v, required);
      f.set(p, v);
    } else {
      double v = f.get(p);
      r.number(key.c_str(), v, required);
      f.set(p, v);
    }
  }
  r.string("date", c.date);
  r.strings("outliers", c.fit.outlierIds);
  r.finish();
}

void validateCalibration(std::vector<ValidationIssue>& out, const MachineProfile& p) {
  if (!p.calibration) return;
  const MachineCalibration& c = *p.calibration;
  for (const ProfileField& f : profileFields()) {
    if (sectionOf(f) != kSection || (isPenOffsetField(f) && !c.penOffset)) continue;
    for (const ValidationIssue& issue : checkField(f, f.get(p))) out.push_back(issue);
  }
  if (!c.date.empty() && !looksLikeIsoDate(c.date))
    out.push_back({"calibration.date", FB_TR("Profile", "calibration.date must be an ISO 8601 date like "
                                                        "2026-12-01 or 2026-12-01T22:30:00Z, got \"%1\"")
                                           .arg(c.date)});
  for (std::size_t i = 0; i < c.fit.outlierIds.size(); ++i)
    if (c.fit.outlierIds[i].empty())
      out.push_back({"calibration.outliers",
                     FB_TR("Profile", "calibration.outliers[%1] must be a mark id, got an empty string").arg(i)});
}

}  // namespace fivebar::detail
