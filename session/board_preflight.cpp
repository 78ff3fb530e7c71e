// SPDX-License-Identifier: GPL-3.0-or-later
#include "session/board_preflight.hpp"

#include "core/output/gcode.hpp"
#include "drivers/stream/gcode_job.hpp"
#include "drivers/check/soft_limits.hpp"
#include "i18n/translated.hpp"

namespace fivebar::session {

QString boardLimitProblem(const MachineSession& session, const MachineProfile& profile,
                          const std::string& gcode, int afterLine) {
  const auto& board = session.boardSettings();
  const auto wco = session.workOffsetDeg();
  if (!board || !wco || !setup::softLimitsOn(*board)) return {};
  stream::GcodeJob parsed = stream::parseJob(gcode, stream::rulesFor(profile));
  std::erase_if(parsed.lines, [afterLine](const stream::JobLine& l) { return l.fileLine <= afterLine; });
  const auto hit = setup::firstSoftLimitHit(parsed, *board, *wco);
  if (!hit) return {};
  return softLimitAdvice(*hit);
}

QString softLimitAdvice(const setup::SoftLimitHit& hit) {
  return BoardPreflight::tr(
             "The board's soft limits would stop this job with an alarm (ALARM:2): %1. The board "
             "checks its travel ($130, $131) in machine coordinates, which the reference pose "
             "shifted against the drawing's. Home the machine, or make the board's settings match "
             "the profile (Machine settings...), then start again.")
      .arg(translated(setup::describeHit(hit)));
}

BoardPreflight::BoardPreflight(const StudioInputs& inputs, const MachineSession& session, QObject* parent)
    : QObject(parent), inputs_(inputs), session_(session) {
  connect(&inputs_, &StudioInputs::plannedJobChanged, this, &BoardPreflight::recompute);
  connect(&session_, &MachineSession::boardSettingsChanged, this, &BoardPreflight::recompute);
  connect(&session_, &MachineSession::connectionChanged, this, &BoardPreflight::recompute);
  // The work offset changes with a new reference (G10 L20): it arrives with a status report.
  connect(&session_, &MachineSession::statusUpdated, this, [this] {
    if (session_.workOffsetDeg() != lastWco_) recompute();
  });
  recompute();
}

void BoardPreflight::recompute() {
  lastWco_ = session_.workOffsetDeg();
  QString now;
  const PlannedJob* job = inputs_.plannedJob();
  if (session_.isConnected() && job != nullptr && session_.boardSettings() &&
      setup::softLimitsOn(*session_.boardSettings()))
    now = boardLimitProblem(session_, inputs_.profile(), writeGcode(*job, inputs_.profile()));
  if (now == problem_) return;
  problem_ = now;
  emit changed(problem_);
}

}  // namespace fivebar::session
