// SPDX-License-Identifier: GPL-3.0-or-later
// DocumentInputs: the studio's document and preview controller seen through the session layer's
// StudioInputs (session/studio_inputs.hpp): the profile, the drawing's name and the planned job,
// with the document's and preview's signals forwarded.
#pragma once

#include "session/studio_inputs.hpp"

namespace fivebar::widgets {

class PreviewController;
class StudioDocument;

class DocumentInputs : public session::StudioInputs {
  Q_OBJECT
 public:
  // preview may be nullptr (no planned job ever: tests of the machine session alone).
  DocumentInputs(const StudioDocument& doc, const PreviewController* preview, QObject* parent = nullptr);

  const MachineProfile& profile() const override;
  QString drawingFileName() const override;
  const PlannedJob* plannedJob() const override;

 private:
  const StudioDocument& doc_;
  const PreviewController* preview_;
};

}  // namespace fivebar::widgets
