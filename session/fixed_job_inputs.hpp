// SPDX-License-Identifier: GPL-3.0-or-later
// StudioInputs for a job of the studio's own beside the document's: the calibration wizard's
// pattern and verification pattern. A fixed profile, name and planned job, so that such a job runs
// through a RunController like any other (the same pose and settings checks before a byte, the
// stream's checks, progress, hold, stop and resume) instead of a second sender.
#pragma once

#include <utility>

#include "session/studio_inputs.hpp"

namespace fivebar::session {

class FixedJobInputs : public StudioInputs {
  Q_OBJECT
 public:
  using StudioInputs::StudioInputs;

  // The job to run: planned for `profile`; its files are named after `fileName` ("pattern.svg"
  // runs as pattern.gcode in the RunController's job folder).
  void set(MachineProfile profile, QString fileName, PlannedJob job) {
    profile_ = std::move(profile);
    fileName_ = std::move(fileName);
    job_ = std::move(job);
    planned_ = true;
    emit profileChanged();
    emit drawingChanged();
    emit plannedJobChanged();
    emit jobChanged();
  }

  const MachineProfile& profile() const override { return profile_; }
  QString drawingFileName() const override { return fileName_; }
  const PlannedJob* plannedJob() const override { return planned_ ? &job_ : nullptr; }

 private:
  MachineProfile profile_;
  QString fileName_;
  PlannedJob job_;
  bool planned_ = false;
};

}  // namespace fivebar::session
