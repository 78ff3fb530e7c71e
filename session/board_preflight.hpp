// SPDX-License-Identifier: GPL-3.0-or-later
// BoardPreflight: the planned job against the connected board itself, kept current for the
// studio's pre-flight problem list. With the board's soft limits on ($20=1, its $$ read on
// connect), every target of the job is checked in MACHINE coordinates (work + the reported WCO)
// against the travel $130/$131, as GRBL checks it (drivers/check/soft_limits.hpp, the board part of the
// one motion check): a job the board would stop part-way with ALARM:2 is named before Start.
// Recomputed when the plan, the board's settings, its work offset or the connection change.
#pragma once

#include <QObject>
#include <QString>
#include <array>
#include <optional>
#include <string>

#include "drivers/check/soft_limits.hpp"
#include "session/machine_session.hpp"
#include "session/studio_inputs.hpp"

namespace fivebar::session {

// Why the board's soft limits would stop gcode after file line afterLine (in the user's
// language, naming the line, the motor and what to do), or "" when they let it through or are
// off or not known.
QString boardLimitProblem(const MachineSession& session, const MachineProfile& profile,
                          const std::string& gcode, int afterLine = 0);
// The same words for a hit the drivers found (StreamStop::limitHit).
QString softLimitAdvice(const setup::SoftLimitHit& hit);

class BoardPreflight : public QObject {
  Q_OBJECT
 public:
  BoardPreflight(const StudioInputs& inputs, const MachineSession& session, QObject* parent = nullptr);
  // The problem with the planned job on this board ("" when there is none).
  const QString& problem() const { return problem_; }

 signals:
  void changed(const QString& problem);

 private:
  void recompute();

  const StudioInputs& inputs_;
  const MachineSession& session_;
  QString problem_;
  std::optional<std::array<double, 2>> lastWco_;
};

}  // namespace fivebar::session
