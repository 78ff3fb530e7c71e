// SPDX-License-Identifier: GPL-3.0-or-later
// StudioInputs: what the machine side needs from the studio's document, and nothing more: the
// machine profile, the drawing's file name (job files are named after it) and the job the preview
// planned, with a signal for each change. The session layer knows no document, undo stack or
// widget; the studio implements this over its document and preview controller
// (widgets/machine/document_inputs.hpp), tests may implement it directly.
#pragma once

#include <QObject>
#include <QString>

#include "core/machine/profile.hpp"
#include "core/planning/job.hpp"

namespace fivebar::session {

class StudioInputs : public QObject {
  Q_OBJECT
 public:
  using QObject::QObject;

  virtual const MachineProfile& profile() const = 0;
  // The drawing's file name ("" before one is opened).
  virtual QString drawingFileName() const = 0;
  // The planned job Start would stream; nullptr while there is none (not planned, failed, busy).
  virtual const PlannedJob* plannedJob() const = 0;

 signals:
  void profileChanged();
  void drawingChanged();
  void plannedJobChanged();
  // The job, its placement, the profile or the job inputs changed: a finished run is stale.
  void jobChanged();
};

}  // namespace fivebar::session
