// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration fit's procedure (docs/calibration.md): split off held-out measurements, try both
// paper mirror hypotheses, reject mis-measured marks one at a time by a robust rule, refit, then
// report conditioning, standard deviations and before/after errors.
#include "core/calibration/fit.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/calibration/solver.hpp"

namespace fivebar::calibration {
namespace {

using detail::Problem;
using detail::Solution;

// Equations beyond the parameter count a fit needs, so that the residual variance (and with it
// the standard deviations and the outlier rule) means something.
constexpr int kMinRedundancy = 4;
// Median of |N(0, s)| is 0.6745 s; median of a 2-D Rayleigh(s) norm is 1.1774 s.
constexpr double kHalfNormalMedian = 0.6744897501960817;
constexpr double kRayleighMedian = 1.1774100225154747;

std::string fmt(double v, int precision = 3) {
  std::ostringstream s;
  s.precision(precision);
  s << v;
  return s.str();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Measurements {
  std::vector<std::string> ids;
  Problem all;  // every measurement
};

Problem subset(const Problem& all, const std::vector<int>& idx) {
  Problem p = all;
  p.a.clear(), p.b.clear(), p.measured.clear(), p.dist.clear();
  for (int i : idx) {
    p.a.push_back(all.a[std::size_t(i)]);
    if (all.distances) {
      p.b.push_back(all.b[std::size_t(i)]);
      p.dist.push_back(all.dist[std::size_t(i)]);
    } else {
      p.measured.push_back(all.measured[std::size_t(i)]);
    }
  }
  return p;
}

std::vector<bool> allFree(const Problem& p) { return std::vector<bool>(std::size_t(p.parameterCount()), true); }
std::vector<bool> paperOnly(const Problem& p) {
  std::vector<bool> f(std::size_t(p.parameterCount()), false);
  if (!p.distances)
    for (int i = p.machineCount(); i < p.parameterCount(); ++i) f[std::size_t(i)] = true;
  return f;
}

// Start values: the nominal machine, the paper placed by Kabsch on the nominal predictions.
std::optional<Eigen::VectorXd> startFor(const Problem& p, const MachineParameters& nominal) {
  PaperPose pose;
  pose.mirrored = p.mirrored;
  if (!p.distances) {
    std::vector<Vec2> predicted;
    for (const JointAngles& q : p.a) {
      const auto pen = penPosition(nominal, p.assembly, q);
      if (!pen) return std::nullopt;
      predicted.push_back(*pen);
    }
    pose = bestRigidPlacement(predicted, p.measured, p.mirrored);
  }
  return p.pack(nominal, pose);
}

double robustSigma(const Problem& p, const std::vector<double>& r) {
  return median(r) / (p.distances ? kHalfNormalMedian : kRayleighMedian);
}

struct Stats {
  double rms = 0.0, max = 0.0;
};
Stats statsOf(const std::vector<double>& r) {
  Stats s;
  for (double v : r) {
    s.rms += v * v;
    s.max = std::max(s.max, v);
  }
  s.rms = r.empty() ? 0.0 : std::sqrt(s.rms / double(r.size()));
  return s;
}

std::vector<std::string> parameterNames(const Problem& p) {
  std::vector<std::string> n = {"a1", "b1", "a2", "b2", "w", "zeroOffset1", "zeroOffset2"};
  if (p.fitPen) n.insert(n.end(), {"penOffsetAlong", "penOffsetNormal"});
  if (!p.distances) n.insert(n.end(), {"paperRotation", "paperX", "paperY"});
  return n;
}
bool isAngle(const std::string& name) { return name.rfind("zeroOffset", 0) == 0 || name == "paperRotation"; }

// Condition number, standard deviations and estimates from the Jacobian at the solution.
FitStatus analyse(const Problem& p, const Solution& s, const FitOptions& o, CalibrationFit& out) {
  const Eigen::MatrixXd& J = s.jacobian;
  const Eigen::VectorXd norms = J.colwise().norm();
  const std::vector<std::string> names = parameterNames(p);
  for (int j = 0; j < J.cols(); ++j)
    if (!(norms[j] > 0.0)) {
      out.reason = std::move(Message(FB_TR("CalibrationFit", "the measurements do not depend on %1 at all"))
                                 .arg(names[std::size_t(j)]));
      return FitStatus::IllConditioned;
    }
  const Eigen::MatrixXd Jn = J * norms.cwiseInverse().asDiagonal();
  Eigen::JacobiSVD<Eigen::MatrixXd> svdN(Jn, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svdN.singularValues();
  out.conditionNumber = sv[sv.size() - 1] > 0.0 ? sv[0] / sv[sv.size() - 1] : INFINITY;
  if (!(out.conditionNumber <= o.maxConditionNumber)) {
    const Eigen::VectorXd weak = svdN.matrixV().col(sv.size() - 1);
    std::string combo;
    for (int j = 0; j < weak.size(); ++j)
      if (std::abs(weak[j]) > 0.3) combo += (combo.empty() ? "" : ", ") + names[std::size_t(j)];
    out.reason = std::move(Message(FB_TR("CalibrationFit",
                                         "the fit is ill-conditioned (condition number %1 > %2): the marks "
                                         "cannot separate %3; spread the marks over the whole working area"))
                               .arg(fmt(out.conditionNumber))
                               .arg(fmt(o.maxConditionNumber))
                               .arg(combo));
    return FitStatus::IllConditioned;
  }
  Eigen::VectorXd r;
  p.residuals(s.x, r);
  const int dof = int(r.size()) - int(J.cols());
  const double sigma2 = r.squaredNorm() / double(dof);
  out.residualSigmaMm = std::sqrt(sigma2);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinV);
  const Eigen::MatrixXd V = svd.matrixV();
  const Eigen::VectorXd inv2 = svd.singularValues().cwiseAbs2().cwiseInverse();
  const Eigen::MatrixXd cov = sigma2 * V * inv2.asDiagonal() * V.transpose();
  for (int j = 0; j < J.cols(); ++j) {
    const std::string& name = names[std::size_t(j)];
    const double scale = isAngle(name) ? degFromRad(1.0) : 1.0;
    out.estimates.push_back({name, isAngle(name) ? "deg" : "mm", s.x[j] * scale,
                             std::sqrt(std::max(0.0, cov(j, j))) * scale, j < p.machineCount()});
  }
  return FitStatus::Ok;
}

CalibrationFit run(const MachineProfile& nominalProfile, const Measurements& m, const FitOptions& o) {
  CalibrationFit out;
  const Problem& all = m.all;
  const MachineParameters nominal = parametersOf(nominalProfile);
  const int n = int(m.ids.size());
  // Held-out measurements: every Nth, in file order.
  std::vector<int> train, held;
  for (int i = 0; i < n; ++i)
    (o.holdOutEvery > 0 && n >= o.minMeasurementsToHoldOut && i % o.holdOutEvery == o.holdOutEvery - 1 ? held : train)
        .push_back(i);
  const int needed = (all.parameterCount() + kMinRedundancy + all.residualsPer() - 1) / all.residualsPer();
  if (int(train.size()) < needed) {
    out.status = FitStatus::TooFewMeasurements;
    out.reason = std::move(Message(all.distances ? FB_TR("CalibrationFit",
                                                         "%1 distances are too few for %2 parameters: at least "
                                                         "%3 distances are needed")
                                                 : FB_TR("CalibrationFit",
                                                         "%1 marks are too few for %2 parameters: at least %3 "
                                                         "marks are needed"))
                               .arg(n)
                               .arg(all.parameterCount())
                               .arg(needed));
    return out;
  }
  // Both mirror hypotheses of the paper frame; the better one is kept.
  Problem best;
  Solution bestSolution;
  double bestCost = INFINITY;
  for (bool mirrored : all.distances ? std::vector<bool>{false} : std::vector<bool>{false, true}) {
    Problem p = subset(all, train);
    p.mirrored = mirrored;
    const auto x0 = startFor(p, nominal);
    if (!x0) {
      out.status = FitStatus::BadInput;
      out.reason = FB_TR("CalibrationFit", "a mark's commanded angles do not close the nominal machine's loop");
      return out;
    }
    Solution s = detail::solve(p, *x0, allFree(p), o.maxFunctionEvaluations);
    out.functionEvaluations += s.evaluations;
    Eigen::VectorXd r;
    const double cost = p.residuals(s.x, r) ? r.squaredNorm() : INFINITY;
    if (cost < bestCost) bestCost = cost, best = p, bestSolution = s;
  }
  // Outliers: the worst measurement beyond the robust rule is rejected and the fit repeated.
  std::vector<int> outliers;
  const int maxOutliers = int(std::floor(o.maxOutlierShare * n));
  for (;;) {
    const Problem p = subset(all, train);
    Problem pm = p;
    pm.mirrored = best.mirrored;
    const std::vector<double> r = detail::measurementResiduals(pm, bestSolution.x);
    const double sigma = robustSigma(pm, r);
    const auto worst = std::max_element(r.begin(), r.end()) - r.begin();
    if (r.empty() || r[std::size_t(worst)] <= std::max(o.outlierSigmas * sigma, o.minOutlierResidualMm) ||
        int(outliers.size()) >= maxOutliers || int(train.size()) - 1 < needed)
      break;
    outliers.push_back(train[std::size_t(worst)]);
    train.erase(train.begin() + worst);
    best = subset(all, train);
    best.mirrored = pm.mirrored;
    bestSolution = detail::solve(best, bestSolution.x, allFree(best), o.maxFunctionEvaluations);
    out.functionEvaluations += bestSolution.evaluations;
  }
  // Conditioning first: an ill-conditioned problem is the usual reason for not converging.
  out.status = analyse(best, bestSolution, o, out);
  if (out.ok() && !bestSolution.converged) {
    out.status = FitStatus::DidNotConverge;
    out.reason = std::move(Message(FB_TR("CalibrationFit",
                                         "the fit did not converge within %1 evaluations (are the commanded "
                                         "angles and measurements of the same marks?)"))
                               .arg(o.maxFunctionEvaluations));
  }
  if (!out.ok()) return out;
  // Held-out measurements, under the model and paper pose fitted without them; the same robust
  // rule applies to them.
  Problem heldProblem = subset(all, held);
  heldProblem.mirrored = best.mirrored;
  const std::vector<double> heldR = detail::measurementResiduals(heldProblem, bestSolution.x);
  const double threshold = std::max(o.outlierSigmas * out.residualSigmaMm, o.minOutlierResidualMm);
  std::vector<double> heldKept;
  std::vector<int> heldOutliers, finalIdx = train;
  for (std::size_t k = 0; k < held.size(); ++k) {
    if (heldR[k] > threshold && int(outliers.size() + heldOutliers.size()) < maxOutliers) {
      heldOutliers.push_back(held[k]);
    } else {
      heldKept.push_back(heldR[k]);
      finalIdx.push_back(held[k]);
    }
  }
  const Stats heldStats = statsOf(heldKept);
  out.heldOutRmsMm = heldStats.rms;
  out.heldOutMaxMm = heldStats.max;
  // The calibration itself: refit on every kept measurement, the held-out ones included.
  std::sort(finalIdx.begin(), finalIdx.end());
  best = subset(all, finalIdx);
  best.mirrored = heldProblem.mirrored;
  bestSolution = detail::solve(best, bestSolution.x, allFree(best), o.maxFunctionEvaluations);
  out.functionEvaluations += bestSolution.evaluations;
  if (!bestSolution.converged) {
    out.status = FitStatus::DidNotConverge;
    out.reason = std::move(Message(FB_TR("CalibrationFit", "the final fit did not converge within %1 evaluations"))
                               .arg(o.maxFunctionEvaluations));
    return out;
  }
  out.estimates.clear();
  out.status = analyse(best, bestSolution, o, out);
  if (!out.ok()) return out;
  const Eigen::VectorXd& x = bestSolution.x;
  out.parameters = best.machine(x);
  if (!all.distances) out.paper = best.paper(x);
  const Stats after = statsOf(detail::measurementResiduals(best, x));
  out.afterRmsMm = after.rms;
  out.afterMaxMm = after.max;
  // Roles and residuals, in input order.
  std::vector<Role> role(std::size_t(n), Role::Fitted);
  for (int i : held) role[std::size_t(i)] = Role::HeldOut;
  for (int i : outliers) role[std::size_t(i)] = Role::Outlier;
  for (int i : heldOutliers) role[std::size_t(i)] = Role::Outlier;
  Problem everyone = all;
  everyone.mirrored = best.mirrored;
  Eigen::VectorXd rAll;
  const bool closes = everyone.residuals(x, rAll);
  std::vector<int> kept, keptHeld;
  for (int i = 0; i < n; ++i) {
    MeasurementResidual res{m.ids[std::size_t(i)], role[std::size_t(i)], 0.0, Vec2::Zero()};
    if (closes && all.distances) res.residualMm = std::abs(rAll[i]);
    if (closes && !all.distances) {
      res.residualVecMm = -Vec2(rAll[2 * i], rAll[2 * i + 1]);
      res.residualMm = res.residualVecMm.norm();
    }
    out.residuals.push_back(res);
    if (role[std::size_t(i)] == Role::Outlier) out.outlierIds.push_back(res.id);
    else kept.push_back(i);
    if (role[std::size_t(i)] == Role::HeldOut) keptHeld.push_back(i);
  }
  out.used = int(finalIdx.size());
  out.heldOut = int(keptHeld.size());
  // Before: the nominal machine, the paper pose fitted to it (all kept measurements).
  Problem before = subset(all, kept);
  before.mirrored = best.mirrored;
  if (const auto x0 = startFor(before, nominal)) {
    const Solution s = detail::solve(before, *x0, paperOnly(before), o.maxFunctionEvaluations);
    const Stats b = statsOf(detail::measurementResiduals(before, s.x));
    out.beforeRmsMm = b.rms;
    out.beforeMaxMm = b.max;
    Problem heldBefore = subset(all, keptHeld);
    heldBefore.mirrored = best.mirrored;
    out.heldOutBeforeRmsMm = statsOf(detail::measurementResiduals(heldBefore, s.x)).rms;
  }
  return out;
}

}  // namespace

MachineParameters parametersOf(const MachineProfile& p) {
  MachineParameters m;
  m.geometry = p.geometry;
  if (p.calibration) {
    m.zeroOffsetRad1 = p.calibration->zeroOffsetRad1;
    m.zeroOffsetRad2 = p.calibration->zeroOffsetRad2;
    m.penOffset = p.calibration->penOffset;
  }
  return m;
}

CalibrationFit fitMarks(const MachineProfile& nominal, std::span<const MarkMeasurement> marks, const FitOptions& o) {
  Measurements m;
  m.all.assembly = nominal.assembly;
  m.all.fitPen = o.fitPenOffset;
  for (const MarkMeasurement& mark : marks) {
    m.ids.push_back(mark.id);
    m.all.a.push_back(mark.commanded);
    m.all.measured.push_back(mark.paperMm);
  }
  return run(nominal, m, o);
}

CalibrationFit fitDistances(const MachineProfile& nominal, std::span<const MarkPose> marks,
                            std::span<const DistanceMeasurement> distances, const FitOptions& o) {
  Measurements m;
  m.all.assembly = nominal.assembly;
  m.all.distances = true;
  m.all.fitPen = o.fitPenOffset;
  auto find = [&](const std::string& id) -> const MarkPose* {
    for (const MarkPose& p : marks)
      if (p.id == id) return &p;
    return nullptr;
  };
  for (const DistanceMeasurement& d : distances) {
    const MarkPose* a = find(d.idA);
    const MarkPose* b = find(d.idB);
    if (!a || !b) {
      CalibrationFit out;
      out.reason = std::move(Message(FB_TR("CalibrationFit", "line %1: mark %2 is not in the marks file"))
                                 .arg(d.line)
                                 .arg(a ? d.idB : d.idA));
      return out;
    }
    m.ids.push_back(d.idA + "-" + d.idB);
    m.all.a.push_back(a->commanded);
    m.all.b.push_back(b->commanded);
    m.all.dist.push_back(d.distanceMm);
  }
  return run(nominal, m, o);
}

std::string calibratedProfileName(const std::string& nominalName, const std::string& dateIso) {
  static const std::string kMark = " (calibrated";
  std::string base = nominalName;
  if (const auto at = base.rfind(kMark); at != std::string::npos && !base.empty() && base.back() == ')')
    base.erase(at);  // calibrated again: one mark, the newest date
  return base + kMark + (dateIso.empty() ? std::string() : " " + dateIso.substr(0, 10)) + ")";  // the day of an ISO time
}

MachineProfile calibratedProfile(const MachineProfile& nominal, const CalibrationFit& fit, const std::string& dateIso) {
  MachineProfile p = nominal;
  p.name = calibratedProfileName(nominal.name, dateIso);
  p.geometry = fit.parameters.geometry;
  MachineCalibration c = nominal.calibration.value_or(MachineCalibration{});
  c.version = MachineCalibration::kSchemaVersion;
  c.zeroOffsetRad1 = fit.parameters.zeroOffsetRad1;
  c.zeroOffsetRad2 = fit.parameters.zeroOffsetRad2;
  if (fit.parameters.penOffset) c.penOffset = fit.parameters.penOffset;
  c.date = dateIso;
  c.fit = {fit.used, fit.heldOut, fit.afterRmsMm, fit.afterMaxMm, fit.heldOutRmsMm, fit.outlierIds};
  p.calibration = c;
  return p;
}

}  // namespace fivebar::calibration
