// SPDX-License-Identifier: GPL-3.0-or-later
// The studio document's undo commands: one small QUndoCommand per kind of edit, each storing the
// value before and after and applying it through StudioDocument's raw setters.
#pragma once

#include <QUndoCommand>
#include <memory>

#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {

// An import: the new drawing, placed. It makes the document a new untitled project (an SVG is
// not the project that was open: Save must ask for a name, never write the project over);
// undone, the document is the project it was again.
class ReplaceDrawingCommand : public QUndoCommand {
 public:
  ReplaceDrawingCommand(StudioDocument& doc, Drawing drawing, QString fileName, Placement placement,
                        job::DrawingSource source);
  void undo() override;
  void redo() override;

 private:
  StudioDocument& doc_;
  std::shared_ptr<const Drawing> before_, after_;  // shared with the document, not copied
  QString fileBefore_, fileAfter_;
  job::DrawingSource sourceBefore_, sourceAfter_;
  Placement placementBefore_, placementAfter_;
  // The project file before the import, and after it: none, or the file the imported state
  // was saved to later (taken when the import is undone, given back when it is redone).
  QString projectBefore_, projectAfter_;
};

class SetPlacementCommand : public QUndoCommand {
 public:
  static constexpr int kId = 1001;
  SetPlacementCommand(StudioDocument& doc, Placement after, int gestureId);
  void undo() override;
  void redo() override;
  int id() const override { return gestureId_ != 0 ? kId : -1; }
  bool mergeWith(const QUndoCommand* other) override;

 private:
  StudioDocument& doc_;
  Placement before_, after_;
  int gestureId_;
};

class SetModeSelectionCommand : public QUndoCommand {
 public:
  SetModeSelectionCommand(StudioDocument& doc, ModeSelection after);
  void undo() override;
  void redo() override;

 private:
  StudioDocument& doc_;
  ModeSelection before_, after_;
};

// Any change of the layer list (visibility, order, tool settings). Stores the permutation and
// the settings, never the paths, so it stays cheap for big drawings.
class SetLayersCommand : public QUndoCommand {
 public:
  // `order[i]` is the current index of the layer that moves to position i; `after` holds the
  // settings by new position.
  SetLayersCommand(StudioDocument& doc, std::vector<int> order, std::vector<LayerSettings> after,
                   const QString& text);
  void undo() override;
  void redo() override;

 private:
  StudioDocument& doc_;
  std::vector<int> order_;
  std::vector<LayerSettings> before_, after_;
};

class SetProfileCommand : public QUndoCommand {
 public:
  SetProfileCommand(StudioDocument& doc, MachineProfile after);
  void undo() override;
  void redo() override;

 private:
  StudioDocument& doc_;
  MachineProfile before_, after_;
};

}  // namespace fivebar::widgets
