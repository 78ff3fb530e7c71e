// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/machine/profile_fields.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/kinematics/units.hpp"
#include "core/support/message.hpp"

namespace fivebar {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kLengthInputMm = 10000.0;
constexpr double kAngleInputDeg = 3600.0;

using R = FieldRule;

// Field builders; the accessors are captureless lambdas (plain function pointers).
ProfileField field(const char* path, const char* label, const char* unit, R rule, double inputMin,
                   double inputMax, int decimals, double (*get)(const MachineProfile&),
                   void (*set)(MachineProfile&, double)) {
  return {path,     label,    unit,     rule,  0.0,   kInf, inputMin, inputMax,
          decimals, false,    false,    false, get,   set};
}
ProfileField between(ProfileField f, double lo, double hi) {
  f.validMin = lo;
  f.validMax = hi;
  return f;
}
ProfileField required(ProfileField f) {
  f.required = true;
  return f;
}
ProfileField rounded(ProfileField f) {
  f.roundOnWrite = true;
  return f;
}
ProfileField integral(ProfileField f) {
  f.integer = true;
  return f;
}

// The calibration section's accessors: reading an uncalibrated profile gives the defaults,
// writing a field creates the section (and the pen offset) when it is absent.
const MachineCalibration& calibrationOf(const MachineProfile& p) {
  static const MachineCalibration none;
  return p.calibration ? *p.calibration : none;
}
MachineCalibration& calibrationIn(MachineProfile& p) {
  if (!p.calibration) p.calibration.emplace();
  return *p.calibration;
}
PenOffset penOffsetOf(const MachineProfile& p) { return calibrationOf(p).penOffset.value_or(PenOffset{}); }
PenOffset& penOffsetIn(MachineProfile& p) {
  MachineCalibration& c = calibrationIn(p);
  if (!c.penOffset) c.penOffset.emplace();
  return *c.penOffset;
}

std::vector<ProfileField> calibrationFields() {
  using P = MachineProfile;
  const double A = kAngleInputDeg, L = kLengthInputMm;
  return {
      required(integral(between(
          field("calibration.version", FB_TR_NOOP("ProfileField", "Calibration format version"), "", R::Between, 0, 1000, 0,
                [](const P& p) { return double(calibrationOf(p).version); },
                [](P& p, double v) { calibrationIn(p).version = int(v); }),
          1, MachineCalibration::kSchemaVersion))),
      required(rounded(between(
          field("calibration.zeroOffsetDeg1", FB_TR_NOOP("ProfileField", "Motor 1 zero offset"), "deg", R::Between, -A, A, 4,
                [](const P& p) { return degFromRad(calibrationOf(p).zeroOffsetRad1); },
                [](P& p, double v) { calibrationIn(p).zeroOffsetRad1 = radFromDeg(v); }),
          -180.0, 180.0))),
      required(rounded(between(
          field("calibration.zeroOffsetDeg2", FB_TR_NOOP("ProfileField", "Motor 2 zero offset"), "deg", R::Between, -A, A, 4,
                [](const P& p) { return degFromRad(calibrationOf(p).zeroOffsetRad2); },
                [](P& p, double v) { calibrationIn(p).zeroOffsetRad2 = radFromDeg(v); }),
          -180.0, 180.0))),
      rounded(between(field("calibration.backlashDeg1", FB_TR_NOOP("ProfileField", "Motor 1 backlash"), "deg", R::Between, -A, A, 4,
                            [](const P& p) { return degFromRad(calibrationOf(p).backlashRad1); },
                            [](P& p, double v) { calibrationIn(p).backlashRad1 = radFromDeg(v); }),
                      0.0, 10.0)),
      rounded(between(field("calibration.backlashDeg2", FB_TR_NOOP("ProfileField", "Motor 2 backlash"), "deg", R::Between, -A, A, 4,
                            [](const P& p) { return degFromRad(calibrationOf(p).backlashRad2); },
                            [](P& p, double v) { calibrationIn(p).backlashRad2 = radFromDeg(v); }),
                      0.0, 10.0)),
      rounded(between(field("calibration.penOffsetAlongMm", FB_TR_NOOP("ProfileField", "Pen offset along b1"), "mm", R::Between, -L, L, 3,
                            [](const P& p) { return penOffsetOf(p).alongMm; },
                            [](P& p, double v) { penOffsetIn(p).alongMm = v; }),
                      -1000.0, 1000.0)),
      rounded(between(field("calibration.penOffsetNormalMm", FB_TR_NOOP("ProfileField", "Pen offset across b1"), "mm", R::Between, -L, L, 3,
                            [](const P& p) { return penOffsetOf(p).normalMm; },
                            [](P& p, double v) { penOffsetIn(p).normalMm = v; }),
                      -1000.0, 1000.0)),
      integral(field("calibration.marksUsed", FB_TR_NOOP("ProfileField", "Marks used by the fit"), "", R::NonNegative, -1e6, 1e6, 0,
                     [](const P& p) { return double(calibrationOf(p).fit.marksUsed); },
                     [](P& p, double v) { calibrationIn(p).fit.marksUsed = int(v); })),
      integral(field("calibration.heldOutMarks", FB_TR_NOOP("ProfileField", "Held-out marks"), "", R::NonNegative, -1e6, 1e6, 0,
                     [](const P& p) { return double(calibrationOf(p).fit.heldOutMarks); },
                     [](P& p, double v) { calibrationIn(p).fit.heldOutMarks = int(v); })),
      rounded(field("calibration.rmsResidualMm", FB_TR_NOOP("ProfileField", "RMS residual of the fit"), "mm", R::NonNegative, -L, L, 4,
                    [](const P& p) { return calibrationOf(p).fit.rmsResidualMm; },
                    [](P& p, double v) { calibrationIn(p).fit.rmsResidualMm = v; })),
      rounded(field("calibration.maxResidualMm", FB_TR_NOOP("ProfileField", "Largest residual of the fit"), "mm", R::NonNegative, -L, L, 4,
                    [](const P& p) { return calibrationOf(p).fit.maxResidualMm; },
                    [](P& p, double v) { calibrationIn(p).fit.maxResidualMm = v; })),
      rounded(field("calibration.heldOutErrorMm", FB_TR_NOOP("ProfileField", "RMS error on held-out marks"), "mm", R::NonNegative, -L, L, 4,
                    [](const P& p) { return calibrationOf(p).fit.heldOutErrorMm; },
                    [](P& p, double v) { calibrationIn(p).fit.heldOutErrorMm = v; })),
  };
}

std::vector<ProfileField> makeTable() {
  using P = MachineProfile;
  const double L = kLengthInputMm, A = kAngleInputDeg;
  return {
      required(field("geometry.a1", FB_TR_NOOP("ProfileField", "Driving link a1"), "mm", R::Positive, -L, L, 2,
                     [](const P& p) { return p.geometry.a1; }, [](P& p, double v) { p.geometry.a1 = v; })),
      required(field("geometry.b1", FB_TR_NOOP("ProfileField", "Floating link b1"), "mm", R::Positive, -L, L, 2,
                     [](const P& p) { return p.geometry.b1; }, [](P& p, double v) { p.geometry.b1 = v; })),
      required(field("geometry.a2", FB_TR_NOOP("ProfileField", "Driving link a2"), "mm", R::Positive, -L, L, 2,
                     [](const P& p) { return p.geometry.a2; }, [](P& p, double v) { p.geometry.a2 = v; })),
      required(field("geometry.b2", FB_TR_NOOP("ProfileField", "Floating link b2"), "mm", R::Positive, -L, L, 2,
                     [](const P& p) { return p.geometry.b2; }, [](P& p, double v) { p.geometry.b2 = v; })),
      required(field("geometry.w", FB_TR_NOOP("ProfileField", "Motor distance w"), "mm", R::NonNegative, -L, L, 2,
                     [](const P& p) { return p.geometry.w; }, [](P& p, double v) { p.geometry.w = v; })),

      required(rounded(field("limits.theta1MinDeg", FB_TR_NOOP("ProfileField", "θ1 minimum"), "deg", R::Finite, -A, A, 3,
                             [](const P& p) { return degFromRad(p.limits.theta1Min); },
                             [](P& p, double v) { p.limits.theta1Min = radFromDeg(v); }))),
      required(rounded(field("limits.theta1MaxDeg", FB_TR_NOOP("ProfileField", "θ1 maximum"), "deg", R::Finite, -A, A, 3,
                             [](const P& p) { return degFromRad(p.limits.theta1Max); },
                             [](P& p, double v) { p.limits.theta1Max = radFromDeg(v); }))),
      required(rounded(field("limits.theta2MinDeg", FB_TR_NOOP("ProfileField", "θ2 minimum"), "deg", R::Finite, -A, A, 3,
                             [](const P& p) { return degFromRad(p.limits.theta2Min); },
                             [](P& p, double v) { p.limits.theta2Min = radFromDeg(v); }))),
      required(rounded(field("limits.theta2MaxDeg", FB_TR_NOOP("ProfileField", "θ2 maximum"), "deg", R::Finite, -A, A, 3,
                             [](const P& p) { return degFromRad(p.limits.theta2Max); },
                             [](P& p, double v) { p.limits.theta2Max = radFromDeg(v); }))),

      field("motors.stepsPerDeg1", FB_TR_NOOP("ProfileField", "Motor 1 steps per degree"), "steps/deg", R::Positive, -1e6, 1e6, 4,
            [](const P& p) { return p.motors.stepsPerDeg1; }, [](P& p, double v) { p.motors.stepsPerDeg1 = v; }),
      field("motors.stepsPerDeg2", FB_TR_NOOP("ProfileField", "Motor 2 steps per degree"), "steps/deg", R::Positive, -1e6, 1e6, 4,
            [](const P& p) { return p.motors.stepsPerDeg2; }, [](P& p, double v) { p.motors.stepsPerDeg2 = v; }),
      rounded(field("motors.maxSpeedDegPerMin1", FB_TR_NOOP("ProfileField", "Motor 1 maximum speed"), "deg/min", R::Positive, -1e6, 1e6, 0,
                    [](const P& p) { return degPerMinFromRadPerS(p.motors.maxSpeedRadPerS1); },
                    [](P& p, double v) { p.motors.maxSpeedRadPerS1 = radPerSFromDegPerMin(v); })),
      rounded(field("motors.maxSpeedDegPerMin2", FB_TR_NOOP("ProfileField", "Motor 2 maximum speed"), "deg/min", R::Positive, -1e6, 1e6, 0,
                    [](const P& p) { return degPerMinFromRadPerS(p.motors.maxSpeedRadPerS2); },
                    [](P& p, double v) { p.motors.maxSpeedRadPerS2 = radPerSFromDegPerMin(v); })),
      rounded(field("motors.maxAccelDegPerS2_1", FB_TR_NOOP("ProfileField", "Motor 1 acceleration"), "deg/s²", R::Positive, -1e6, 1e6, 1,
                    [](const P& p) { return degPerS2FromRadPerS2(p.motors.maxAccelRadPerS2_1); },
                    [](P& p, double v) { p.motors.maxAccelRadPerS2_1 = radPerS2FromDegPerS2(v); })),
      rounded(field("motors.maxAccelDegPerS2_2", FB_TR_NOOP("ProfileField", "Motor 2 acceleration"), "deg/s²", R::Positive, -1e6, 1e6, 1,
                    [](const P& p) { return degPerS2FromRadPerS2(p.motors.maxAccelRadPerS2_2); },
                    [](P& p, double v) { p.motors.maxAccelRadPerS2_2 = radPerS2FromDegPerS2(v); })),
      field("motors.junctionDeviationDeg", FB_TR_NOOP("ProfileField", "Junction deviation"), "deg", R::Positive, -1e6, 1e6, 3,
            [](const P& p) { return p.motors.junctionDeviationDeg; },
            [](P& p, double v) { p.motors.junctionDeviationDeg = v; }),

      field("tool.penUpS", FB_TR_NOOP("ProfileField", "Pen up S value"), "", R::NonNegative, -1e5, 1e5, 0,
            [](const P& p) { return p.tool.penUpS; }, [](P& p, double v) { p.tool.penUpS = v; }),
      field("tool.penDownS", FB_TR_NOOP("ProfileField", "Pen down S value"), "", R::NonNegative, -1e5, 1e5, 0,
            [](const P& p) { return p.tool.penDownS; }, [](P& p, double v) { p.tool.penDownS = v; }),
      between(field("tool.penUpDelayS", FB_TR_NOOP("ProfileField", "Pen up delay"), "s", R::Between, -100, 100, 2,
                    [](const P& p) { return p.tool.penUpDelayS; }, [](P& p, double v) { p.tool.penUpDelayS = v; }),
              0.0, 10.0),
      between(field("tool.penDownDelayS", FB_TR_NOOP("ProfileField", "Pen down delay"), "s", R::Between, -100, 100, 2,
                    [](const P& p) { return p.tool.penDownDelayS; },
                    [](P& p, double v) { p.tool.penDownDelayS = v; }),
              0.0, 10.0),
      field("tool.zUpMm", FB_TR_NOOP("ProfileField", "Z up"), "mm", R::Finite, -1000, 1000, 2,
            [](const P& p) { return p.tool.zUpMm; }, [](P& p, double v) { p.tool.zUpMm = v; }),
      field("tool.zDownMm", FB_TR_NOOP("ProfileField", "Z down"), "mm", R::Finite, -1000, 1000, 2,
            [](const P& p) { return p.tool.zDownMm; }, [](P& p, double v) { p.tool.zDownMm = v; }),
      field("tool.zFeedMmPerMin", FB_TR_NOOP("ProfileField", "Z feed"), "mm/min", R::Positive, -1e5, 1e5, 0,
            [](const P& p) { return p.tool.zFeedMmPerMin; }, [](P& p, double v) { p.tool.zFeedMmPerMin = v; }),
      field("tool.laserPowerS", FB_TR_NOOP("ProfileField", "Laser power S value"), "", R::NonNegative, -1e5, 1e5, 0,
            [](const P& p) { return p.tool.laserPowerS; }, [](P& p, double v) { p.tool.laserPowerS = v; }),

      field("motion.drawSpeedMmPerS", FB_TR_NOOP("ProfileField", "Drawing speed"), "mm/s", R::Positive, -1e4, 1e4, 1,
            [](const P& p) { return p.drawSpeedMmPerS; }, [](P& p, double v) { p.drawSpeedMmPerS = v; }),
      field("motion.travelSpeedMmPerS", FB_TR_NOOP("ProfileField", "Travel speed"), "mm/s", R::Positive, -1e4, 1e4, 1,
            [](const P& p) { return p.travelSpeedMmPerS; }, [](P& p, double v) { p.travelSpeedMmPerS = v; }),

      rounded(between(field("safety.typeIIMarginDeg", FB_TR_NOOP("ProfileField", "Type II singularity margin"), "deg", R::Between, -180, 180, 2,
                            [](const P& p) { return degFromRad(p.typeIIMarginRad); },
                            [](P& p, double v) { p.typeIIMarginRad = radFromDeg(v); }),
                      0.0, 89.0)),
      rounded(between(field("safety.typeIMarginDeg", FB_TR_NOOP("ProfileField", "Type I singularity margin"), "deg", R::Between, -180, 180, 2,
                            [](const P& p) { return degFromRad(p.typeIMarginRad); },
                            [](P& p, double v) { p.typeIMarginRad = radFromDeg(v); }),
                      0.0, 89.0)),

      [] {
        ProfileField f = field("connection.baudRate", FB_TR_NOOP("ProfileField", "Baud rate"), "baud", R::Positive, -1e7, 1e7, 0,
                               [](const P& p) { return double(p.baudRate); },
                               [](P& p, double v) { p.baudRate = int(v); });
        f.integer = true;
        return f;
      }(),

      rounded(field("home.theta1Deg", FB_TR_NOOP("ProfileField", "Home θ1"), "deg", R::Finite, -A, A, 4,
                    [](const P& p) { return degFromRad(p.homeAngles.theta1); },
                    [](P& p, double v) { p.homeAngles.theta1 = radFromDeg(v); })),
      rounded(field("home.theta2Deg", FB_TR_NOOP("ProfileField", "Home θ2"), "deg", R::Finite, -A, A, 4,
                    [](const P& p) { return degFromRad(p.homeAngles.theta2); },
                    [](P& p, double v) { p.homeAngles.theta2 = radFromDeg(v); })),
  };
}

}  // namespace

const std::vector<ProfileField>& profileFields() {
  static const std::vector<ProfileField> table = [] {
    std::vector<ProfileField> t = makeTable();
    for (ProfileField& f : calibrationFields()) t.push_back(f);
    return t;
  }();
  return table;
}

const ProfileField* findProfileField(const std::string& path) {
  for (const ProfileField& f : profileFields())
    if (path == f.path) return &f;
  return nullptr;
}

std::string sectionOf(const ProfileField& f) {
  const std::string path = f.path;
  return path.substr(0, path.find('.'));
}

std::string keyOf(const ProfileField& f) {
  const std::string path = f.path;
  return path.substr(path.find('.') + 1);
}

std::vector<ValidationIssue> checkField(const ProfileField& f, double v) {
  const std::string path = f.path;
  if (!std::isfinite(v)) return {{path, FB_TR("Profile", "%1 must be a finite number").arg(path)}};
  switch (f.rule) {
    case FieldRule::Positive:
      if (v <= 0.0)
        return {{path, FB_TR("Profile", "%1 must be positive, got %2").arg(path).argSignificant(v, 10)}};
      break;
    case FieldRule::NonNegative:
      if (v < 0.0)
        return {{path, FB_TR("Profile", "%1 must be zero or positive, got %2").arg(path).argSignificant(v, 10)}};
      break;
    case FieldRule::Between:
      if (v < f.validMin || v > f.validMax)
        return {{path, *f.unit ? FB_TR("Profile", "%1 must be between %2 and %3 %4, got %5")
                                     .arg(path)
                                     .argSignificant(f.validMin, 10)
                                     .argSignificant(f.validMax, 10)
                                     .arg(Message("Profile", f.unit))  // "deg": "°" in the studio
                                     .argSignificant(v, 10)
                               : FB_TR("Profile", "%1 must be between %2 and %3, got %4")
                                     .arg(path)
                                     .argSignificant(f.validMin, 10)
                                     .argSignificant(f.validMax, 10)
                                     .argSignificant(v, 10)}};
      break;
    case FieldRule::Finite: break;
  }
  return {};
}

}  // namespace fivebar
