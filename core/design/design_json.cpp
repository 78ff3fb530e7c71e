// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/design_json.hpp"

#include <algorithm>
#include <cmath>

#include "core/kinematics/kinematics.hpp"

namespace fivebar::design {
namespace {

// JSON has no infinity: a singular measure is written as null.
nlohmann::json finite(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

// Joint limits beyond the rectangle's poses (rad).
constexpr double kLimitMarginRad = 20.0 * kPi / 180.0;
// Spacing of the samples the limits are taken from (mm).
constexpr double kLimitSamplingMm = 2.0;

}  // namespace

nlohmann::json designJson(const Design& d) {
  const Geometry& g = d.geometry;
  const DesignMeasures& m = d.evaluation.measures;
  nlohmann::json j;
  j["geometry"] = {{"a1", g.a1}, {"b1", g.b1}, {"a2", g.a2}, {"b2", g.b2}, {"w", g.w}};
  j["workingMode"] = std::string(toString(d.mode));
  j["rectangle"] = {{"xMinMm", d.rect.xMin}, {"xMaxMm", d.rect.xMax}, {"yMinMm", d.rect.yMin},
                    {"yMaxMm", d.rect.yMax}};
  j["rotated"] = d.rotated;
  j["rectangleRotated"] = d.rotated;  // the rectangle's width runs along the machine's y
  j["feasible"] = d.evaluation.feasible();
  j["measures"] = {
      {"samples", m.samples},
      {"unreachableSamples", m.unreachableSamples},
      {"reachable", m.unreachableSamples == 0},
      {"minReachSlackMm", finite(m.minReachSlackMm)},
      {"typeIMarginDeg", degFromRad(m.minTypeIMarginRad)},
      {"typeIIMarginDeg", degFromRad(m.minTypeIIMarginRad)},
      {"minTransmissionAngleDeg", degFromRad(m.minTypeIIMarginRad)},
      {"worstConditionNumber", finite(m.worstCondition)},
      {"meanConditionNumber", finite(m.meanCondition)},
      {"worstMmPerStep", finite(m.worstMmPerStep)},
      {"worstMotorSpeedDegPerS", finite(degFromRad(m.worstMotorSpeedRadPerS))},
      {"drivingLinkSpacingMm", m.drivingLinkSpacingMm},
      {"minDrivingLinkDistanceMm", finite(m.minDrivingLinkDistanceMm)},
      {"armsCanCollide", m.armsCanCollide},
      {"footprintMm2", m.footprintMm2},
      {"normalisedCondition", finite(normalisedCondition(m))},
      {"normalisedResolution", finite(normalisedResolution(m))},
      {"normalisedFootprint", finite(normalisedFootprint(m))},
      {"footprint", {{"xMinMm", m.footprint.xMin}, {"xMaxMm", m.footprint.xMax},
                     {"yMinMm", m.footprint.yMin}, {"yMaxMm", m.footprint.yMax}}},
  };
  return j;
}

nlohmann::json searchJson(const DesignBrief& b, const SearchResult& r, const SearchOptions& o) {
  nlohmann::json j = r.best ? designJson(*r.best) : nlohmann::json::object();
  j["found"] = r.status == SearchStatus::Found;
  if (r.status != SearchStatus::Found) {
    j["binding"] = r.binding;
    j["message"] = r.message;
  }
  j["objective"] = std::string(toString(b.objective));
  if (b.objective == Objective::Mix)
    j["weights"] = {{"condition", b.weights.condition}, {"resolution", b.weights.resolution},
                    {"footprint", b.weights.footprint}};
  j["brief"] = {{"widthMm", b.widthMm},
                {"heightMm", b.heightMm},
                {"minLinkMm", b.bounds.minLinkMm},
                {"maxLinkMm", b.bounds.maxLinkMm},
                {"minBaseMm", b.bounds.minBaseMm},
                {"maxBaseMm", b.bounds.maxBaseMm},
                {"symmetric", b.bounds.symmetric},
                {"clearanceMm", b.rules.clearanceMm},
                {"typeIIMarginDeg", degFromRad(b.rules.workspace.typeIIMarginRad)},
                {"typeIMarginDeg", degFromRad(b.rules.workspace.typeIMarginRad)},
                {"penSpeedMmPerS", b.rules.penSpeedMmPerS},
                {"workingMode", b.mode ? nlohmann::json(std::string(toString(*b.mode))) : nlohmann::json("any")}};
  nlohmann::json pareto = nlohmann::json::array();
  for (const Design& d : r.pareto) pareto.push_back(designJson(d));
  j["pareto"] = {{"objectives", {"worstConditionNumber", "footprintMm2"}}, {"designs", pareto}};
  j["search"] = {{"seed", o.seed}, {"threads", o.threads}, {"evaluations", r.evaluations},
                 {"seconds", r.seconds}};
  return j;
}

MachineProfile designProfile(const Design& d, const DesignBrief& brief, const std::string& name,
                             const MachineProfile* base) {
  MachineProfile p = base ? *base : preset("maker-plotter").value();
  p.name = name;
  p.geometry = d.geometry;
  p.defaultMode = d.mode;
  p.typeIIMarginRad = brief.rules.workspace.typeIIMarginRad;
  p.typeIMarginRad = brief.rules.workspace.typeIMarginRad;
  const Vec2 centre(0.5 * (d.rect.xMin + d.rect.xMax), 0.5 * (d.rect.yMin + d.rect.yMax));
  const IkResult home = inverse(d.geometry, centre, d.mode);
  if (!home.ok()) return p;  // an infeasible design: keep the base limits and home
  // Unwrapped angle range over the rectangle, around the centre's angles.
  double lo1 = home.angles.theta1, hi1 = lo1, lo2 = home.angles.theta2, hi2 = lo2;
  for (const Vec2& q : rectangleSamples(d.rect, kLimitSamplingMm)) {
    const IkResult ik = inverse(d.geometry, q, d.mode);
    if (!ik.ok()) continue;
    const double t1 = unwrapNear(ik.angles.theta1, home.angles.theta1);
    const double t2 = unwrapNear(ik.angles.theta2, home.angles.theta2);
    lo1 = std::min(lo1, t1), hi1 = std::max(hi1, t1), lo2 = std::min(lo2, t2), hi2 = std::max(hi2, t2);
  }
  auto widen = [](double& lo, double& hi) {
    const double margin = std::min(kLimitMarginRad, std::max(0.0, 0.5 * (2.0 * kPi - 1e-3 - (hi - lo))));
    lo -= margin;
    hi += margin;
  };
  widen(lo1, hi1);
  widen(lo2, hi2);
  p.limits = {lo1, hi1, lo2, hi2};
  p.homeAngles = home.angles;
  return p;
}

}  // namespace fivebar::design
