// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/document_inputs.hpp"

#include "widgets/document/preview_controller.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {

DocumentInputs::DocumentInputs(const StudioDocument& doc, const PreviewController* preview, QObject* parent)
    : session::StudioInputs(parent), doc_(doc), preview_(preview) {
  connect(&doc_, &StudioDocument::profileChanged, this, &StudioInputs::profileChanged);
  connect(&doc_, &StudioDocument::drawingChanged, this, &StudioInputs::drawingChanged);
  for (auto signal : {&StudioDocument::drawingChanged, &StudioDocument::placementChanged,
                      &StudioDocument::profileChanged, &StudioDocument::jobInputsChanged})
    connect(&doc_, signal, this, &StudioInputs::jobChanged);
  if (preview_ != nullptr)
    connect(preview_, &PreviewController::resultChanged, this, &StudioInputs::plannedJobChanged);
}

const MachineProfile& DocumentInputs::profile() const { return doc_.profile(); }

QString DocumentInputs::drawingFileName() const { return doc_.fileName(); }

const PlannedJob* DocumentInputs::plannedJob() const {
  if (preview_ == nullptr) return nullptr;
  const PreviewResult& r = preview_->result();
  return r.status == PreviewStatus::Planned ? r.job.get() : nullptr;
}

}  // namespace fivebar::widgets
