// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/calibration/backlash.hpp"

#include <algorithm>
#include <cmath>

#include "core/calibration/rigid_fit.hpp"

namespace fivebar {
namespace {

double clampLag(double lag, double play) { return std::clamp(lag, 0.0, std::max(0.0, play)); }

}  // namespace

PlayState::PlayState(const MotorPlay& play, const JointAngles& motors, const JointAngles& initialLag)
    : play_(play),
      arm_{motors.theta1 + clampLag(initialLag.theta1, play.motor1Rad),
           motors.theta2 + clampLag(initialLag.theta2, play.motor2Rad)} {}

void PlayState::moveTo(const JointAngles& m) {
  arm_.theta1 = std::clamp(arm_.theta1, m.theta1, m.theta1 + std::max(0.0, play_.motor1Rad));
  arm_.theta2 = std::clamp(arm_.theta2, m.theta2, m.theta2 + std::max(0.0, play_.motor2Rad));
}

std::vector<std::vector<Vec2>> drawnWithPlay(const PlannedJob& job, const Geometry& g,
                                             AssemblyMode assembly, const MotorPlay& play,
                                             const JointAngles& initialLag, int samplesPerMove) {
  std::vector<std::vector<Vec2>> out;
  PlayState state(play, job.start, initialLag);
  JointAngles motors = job.start;
  bool down = false;
  auto pen = [&]() { return forward(g, state.arm(), assembly).p; };
  for (const JobMove& m : job.moves) {
    if (m.kind == JobMoveKind::PenDown) {
      down = true;
      out.push_back({pen()});
    } else if (m.kind == JobMoveKind::PenUp) {
      down = false;
    } else if (isMotion(m.kind)) {
      const int n = std::max(1, samplesPerMove);
      for (int k = 1; k <= n; ++k) {
        const double u = static_cast<double>(k) / n;
        state.moveTo({motors.theta1 + u * (m.target.theta1 - motors.theta1),
                      motors.theta2 + u * (m.target.theta2 - motors.theta2)});
        if (down) out.back().push_back(pen());
      }
      motors = m.target;
    }
  }
  return out;
}

BacklashEstimate estimateBacklash(const std::vector<PatternMark>& marks,
                                  const std::map<int, Vec2>& measuredById) {
  BacklashEstimate e;
  std::vector<Vec2> paper, machine;
  for (const PatternMark& m : marks)
    if (m.kind == MarkKind::Grid)
      if (auto it = measuredById.find(m.id); it != measuredById.end()) {
        paper.push_back(it->second);
        machine.push_back(m.nominalMm);
      }
  if (paper.size() < 3) {
    e.error = FB_TR("CalibrationFit", "only %1 grid marks measured: at least 3 are needed to place the sheet").arg(paper.size());
    return e;
  }
  const std::optional<RigidFit> fit = fitRigid(paper, machine);
  if (!fit) {
    e.error = FB_TR("CalibrationFit", "the measured grid marks all lie on one point");
    return e;
  }
  std::map<int, std::vector<const PatternMark*>> rows;
  for (const PatternMark& m : marks)
    if (m.kind == MarkKind::Backlash) rows[m.group].push_back(&m);
  double sum[2] = {0.0, 0.0};
  for (auto& [group, row] : rows) {
    if (row.size() != 3) continue;
    std::sort(row.begin(), row.end(), [](auto* a, auto* b) { return a->rowIndex < b->rowIndex; });
    Vec2 P[3];
    bool complete = true;
    for (int i = 0; i < 3 && complete; ++i) {
      const auto it = measuredById.find(row[static_cast<size_t>(i)]->id);
      complete = it != measuredById.end();
      if (complete) P[i] = fit->map(it->second);
    }
    if (!complete) continue;
    const int k = row[0]->motor;
    const double span = k == 1 ? row[2]->q.theta1 - row[0]->q.theta1 : row[2]->q.theta2 - row[0]->q.theta2;
    if (!(std::abs(span) > 0.0)) continue;
    const Vec2 J = (P[2] - P[0]) / span;  // mm per rad of motor k, measured
    const Vec2 c = row[1]->nominalMm - 0.5 * (row[0]->nominalMm + row[2]->nominalMm);
    const Vec2 r = P[1] - 0.5 * (P[0] + P[2]) - c;
    const double b = J.dot(r) / J.squaredNorm();
    e.rows.push_back({group, k, b});
    sum[k - 1] += b;
    (k == 1 ? e.rowsMotor1 : e.rowsMotor2) += 1;
  }
  if (e.rows.empty()) {
    e.error = FB_TR("CalibrationFit", "no backlash row has all three marks measured");
    return e;
  }
  e.play.motor1Rad = e.rowsMotor1 > 0 ? sum[0] / e.rowsMotor1 : 0.0;
  e.play.motor2Rad = e.rowsMotor2 > 0 ? sum[1] / e.rowsMotor2 : 0.0;
  return e;
}

}  // namespace fivebar
