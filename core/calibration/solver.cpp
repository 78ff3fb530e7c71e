// SPDX-License-Identifier: GPL-3.0-or-later
// Least squares for the calibration fit (docs/calibration.md): Eigen's LevenbergMarquardt (the
// MINPACK lmder port in unsupported/Eigen/NonLinearOptimization) with a central-difference Jacobian.
#include "core/calibration/solver.hpp"

#include <unsupported/Eigen/NonLinearOptimization>

namespace fivebar::calibration::detail {
namespace {

// Residual given where the loop cannot close: large, so the solver steps back.
constexpr double kCannotCloseResidualMm = 1e3;

struct Functor {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  const Problem& problem;
  Eigen::VectorXd full;       // all parameters; the free ones are overwritten
  std::vector<int> freeIndex;
  mutable int evaluations = 0;

  int inputs() const { return int(freeIndex.size()); }
  int values() const { return problem.residualCount(); }

  Eigen::VectorXd expand(const Eigen::VectorXd& x) const {
    Eigen::VectorXd y = full;
    for (std::size_t i = 0; i < freeIndex.size(); ++i) y[freeIndex[i]] = x[Eigen::Index(i)];
    return y;
  }
  void eval(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    ++evaluations;
    r.resize(values());
    if (!problem.residuals(expand(x), r)) r.setConstant(kCannotCloseResidualMm);
  }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    eval(x, r);
    return 0;
  }
  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const {
    J.resize(values(), inputs());
    Eigen::VectorXd xp = x, xm = x, rp, rm;
    for (int j = 0; j < inputs(); ++j) {
      const double h = 1e-6 * std::max(1.0, std::abs(x[j]));
      xp[j] = x[j] + h;
      xm[j] = x[j] - h;
      eval(xp, rp);
      eval(xm, rm);
      J.col(j) = (rp - rm) / (2.0 * h);
      xp[j] = xm[j] = x[j];
    }
    return 0;
  }
};

}  // namespace

MachineParameters Problem::machine(const Eigen::VectorXd& x) const {
  MachineParameters m;
  m.geometry = {x[0], x[1], x[2], x[3], x[4]};
  m.zeroOffsetRad1 = x[5];
  m.zeroOffsetRad2 = x[6];
  if (fitPen) m.penOffset = PenOffset{x[7], x[8]};
  return m;
}

PaperPose Problem::paper(const Eigen::VectorXd& x) const {
  PaperPose p;
  p.mirrored = mirrored;
  if (distances) return p;
  const int k = machineCount();
  p.rotationRad = x[k];
  p.translationMm = Vec2(x[k + 1], x[k + 2]);
  return p;
}

Eigen::VectorXd Problem::pack(const MachineParameters& m, const PaperPose& pose) const {
  Eigen::VectorXd x(parameterCount());
  const Geometry& g = m.geometry;
  x.head(7) << g.a1, g.b1, g.a2, g.b2, g.w, m.zeroOffsetRad1, m.zeroOffsetRad2;
  if (fitPen) {
    const PenOffset pen = m.penOffset.value_or(PenOffset{});
    x[7] = pen.alongMm;
    x[8] = pen.normalMm;
  }
  if (!distances) x.tail(3) << pose.rotationRad, pose.translationMm.x(), pose.translationMm.y();
  return x;
}

bool Problem::residuals(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
  const MachineParameters m = machine(x);
  r.resize(residualCount());
  if (distances) {
    for (std::size_t i = 0; i < dist.size(); ++i) {
      const auto pa = penPosition(m, assembly, a[i]), pb = penPosition(m, assembly, b[i]);
      if (!pa || !pb) return false;
      r[Eigen::Index(i)] = (*pa - *pb).norm() - dist[i];
    }
    return true;
  }
  const PaperPose pose = paper(x);
  for (std::size_t i = 0; i < measured.size(); ++i) {
    const auto p = penPosition(m, assembly, a[i]);
    if (!p) return false;
    const Vec2 d = pose.paperFromMachine(*p) - measured[i];
    r[Eigen::Index(2 * i)] = d.x();
    r[Eigen::Index(2 * i + 1)] = d.y();
  }
  return true;
}

Solution solve(const Problem& problem, const Eigen::VectorXd& x0, const std::vector<bool>& free, int maxEvaluations) {
  Functor f{problem, x0, {}};
  for (int i = 0; i < int(free.size()); ++i)
    if (free[std::size_t(i)]) f.freeIndex.push_back(i);
  Solution s;
  Eigen::VectorXd x(f.inputs());
  for (int i = 0; i < f.inputs(); ++i) x[i] = x0[f.freeIndex[std::size_t(i)]];
  if (f.inputs() > 0) {
    Eigen::LevenbergMarquardt<Functor> lm(f);
    lm.parameters.maxfev = maxEvaluations;
    lm.parameters.xtol = 1e-12;
    lm.parameters.ftol = 1e-12;
    const auto status = lm.minimize(x);
    using namespace Eigen::LevenbergMarquardtSpace;
    s.converged = status == RelativeReductionTooSmall || status == RelativeErrorTooSmall ||
                  status == RelativeErrorAndReductionTooSmall || status == CosinusTooSmall ||
                  status == FtolTooSmall || status == XtolTooSmall || status == GtolTooSmall;
    f.df(x, s.jacobian);
  } else {
    s.converged = true;
  }
  s.x = f.expand(x);
  Eigen::VectorXd r;
  s.converged = s.converged && problem.residuals(s.x, r);
  s.evaluations = f.evaluations;
  return s;
}

std::vector<double> measurementResiduals(const Problem& problem, const Eigen::VectorXd& x) {
  Eigen::VectorXd r;
  const int n = problem.residualCount() / problem.residualsPer();
  std::vector<double> out(std::size_t(n), kCannotCloseResidualMm);
  if (!problem.residuals(x, r)) return out;
  for (int i = 0; i < n; ++i)
    out[std::size_t(i)] = problem.distances ? std::abs(r[i]) : Eigen::Vector2d(r[2 * i], r[2 * i + 1]).norm();
  return out;
}

}  // namespace fivebar::calibration::detail
