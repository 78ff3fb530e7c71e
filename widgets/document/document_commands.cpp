// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/document_commands.hpp"

#include <QCoreApplication>
#include <utility>

namespace fivebar::widgets {
namespace {
QString trCmd(const char* text) { return QCoreApplication::translate("DocumentCommands", text); }
}  // namespace

ReplaceDrawingCommand::ReplaceDrawingCommand(StudioDocument& doc, Drawing drawing,
                                             QString fileName, Placement placement,
                                             job::DrawingSource source)
    : QUndoCommand(trCmd(QT_TRANSLATE_NOOP("DocumentCommands", "Import drawing"))),
      doc_(doc),
      before_(doc.drawingSnapshot()),
      after_(std::make_shared<const Drawing>(std::move(drawing))),
      fileBefore_(doc.fileName()),
      fileAfter_(std::move(fileName)),
      sourceBefore_(doc.source()),
      sourceAfter_(std::move(source)),
      placementBefore_(doc.placement()),
      placementAfter_(placement),
      projectBefore_(doc.projectPath()) {}

void ReplaceDrawingCommand::undo() {
  projectAfter_ = doc_.projectPath();
  doc_.applyDrawing(before_, fileBefore_, sourceBefore_);
  doc_.applyPlacement(placementBefore_);
  doc_.applyProjectPath(projectBefore_);
}

void ReplaceDrawingCommand::redo() {
  doc_.applyDrawing(after_, fileAfter_, sourceAfter_);
  doc_.applyPlacement(placementAfter_);
  doc_.applyProjectPath(projectAfter_);
}

namespace {
// The Edit menu's name of a placement change: what changed, when only one thing did.
QString placementEditText(const Placement& before, const Placement& after) {
  const bool moved = before.centerMm != after.centerMm;
  const bool rotated = before.rotationRad != after.rotationRad;
  const bool sized = before.scale != after.scale || before.stretchY != after.stretchY;
  if (rotated && !moved && !sized) return trCmd(QT_TRANSLATE_NOOP("DocumentCommands", "Rotate drawing"));
  if (sized && !rotated) return trCmd(QT_TRANSLATE_NOOP("DocumentCommands", "Resize drawing"));
  return trCmd(QT_TRANSLATE_NOOP("DocumentCommands", "Move drawing"));
}
}  // namespace

SetPlacementCommand::SetPlacementCommand(StudioDocument& doc, Placement after, int gestureId)
    : QUndoCommand(placementEditText(doc.placement(), after)),
      doc_(doc),
      before_(doc.placement()),
      after_(after),
      gestureId_(gestureId) {}

void SetPlacementCommand::undo() { doc_.applyPlacement(before_); }
void SetPlacementCommand::redo() { doc_.applyPlacement(after_); }

bool SetPlacementCommand::mergeWith(const QUndoCommand* other) {
  const auto* o = dynamic_cast<const SetPlacementCommand*>(other);
  if (o == nullptr || o->gestureId_ != gestureId_ || gestureId_ == 0) return false;
  after_ = o->after_;
  return true;
}

SetModeSelectionCommand::SetModeSelectionCommand(StudioDocument& doc, ModeSelection after)
    : QUndoCommand(trCmd(QT_TRANSLATE_NOOP("DocumentCommands", "Change working mode"))),
      doc_(doc),
      before_(doc.modeSelection()),
      after_(after) {}

void SetModeSelectionCommand::undo() { doc_.applyModeSelection(before_); }
void SetModeSelectionCommand::redo() { doc_.applyModeSelection(after_); }

SetLayersCommand::SetLayersCommand(StudioDocument& doc, std::vector<int> order,
                                   std::vector<LayerSettings> after, const QString& text)
    : QUndoCommand(text),
      doc_(doc),
      order_(std::move(order)),
      before_(doc.layerSettings()),
      after_(std::move(after)) {}

void SetLayersCommand::redo() { doc_.applyLayers(order_, after_); }

void SetLayersCommand::undo() {
  // Inverse permutation: the layer now at i goes back to order_[i].
  std::vector<int> inverse(order_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) inverse[order_[i]] = static_cast<int>(i);
  doc_.applyLayers(inverse, before_);
}

SetProfileCommand::SetProfileCommand(StudioDocument& doc, MachineProfile after)
    : QUndoCommand(trCmd(QT_TRANSLATE_NOOP("DocumentCommands", "Change machine profile"))), doc_(doc), before_(doc.profile()),
      after_(std::move(after)) {}

void SetProfileCommand::undo() { doc_.applyProfile(before_); }
void SetProfileCommand::redo() { doc_.applyProfile(after_); }

}  // namespace fivebar::widgets
