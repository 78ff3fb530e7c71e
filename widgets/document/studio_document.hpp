// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's document: the only door to mutation. It owns the drawing, its placement on the
// machine, the machine profile, the chosen working mode and the layer settings, and the undo
// stack; every edit is a small QUndoCommand (document_commands.hpp). Widgets show the state and
// call the edit functions; they never keep a copy as truth.
#pragma once

#include <QObject>
#include <QString>
#include <QUndoStack>
#include <memory>
#include <optional>

#include "core/planning/drawing.hpp"
#include "core/kinematics/modes.hpp"
#include "core/planning/placement.hpp"
#include "core/machine/profile.hpp"
#include "job/job_source.hpp"

namespace fivebar::widgets {

// The working-mode selector's value: a fixed mode, or Auto (nullopt) which lets the planner
// choose the feasible mode with the largest singularity margin.
using ModeSelection = std::optional<WorkingMode>;

// The user-editable settings of one layer (the paths themselves never change in the studio).
struct LayerSettings {
  bool visible = true;
  LayerToolSettings tool;
  FillMode fill = FillMode::Outline;  // how its filled shapes are drawn (Layer::fill)
  HatchSettings hatch;
};

class StudioDocument : public QObject {
  Q_OBJECT
 public:
  explicit StudioDocument(MachineProfile profile, QObject* parent = nullptr);

  const Drawing& drawing() const { return *drawing_; }
  // The drawing as an immutable shared value for a planning run: the document's own, never a
  // copy (a placement change plans again without copying hundreds of thousands of paths).
  std::shared_ptr<const Drawing> drawingSnapshot() const;
  const Placement& placement() const { return placement_; }
  const MachineProfile& profile() const { return profile_; }
  // The SVG text the drawing was imported from (embedded in a saved project).
  const job::DrawingSource& source() const { return source_; }
  // Total tolerance of the drawn line (mm), shared by flattening, rounding and segmentation.
  double toleranceMm() const { return toleranceMm_; }
  ModeSelection modeSelection() const { return modeSelection_; }
  // The mode the canvas shows: the chosen one, or for Auto the planner's last pick (the
  // profile's default mode until a plan exists).
  WorkingMode effectiveMode() const;
  QString fileName() const { return fileName_; }
  bool hasDrawing() const { return !drawing_->layers.empty(); }
  QUndoStack* undoStack() { return &undo_; }

  // --- edits, each one undoable ---
  // Replaces the drawing (an import) and places it; the document becomes a new untitled project
  // (projectPath() empty: Save asks for a name), undone it is the project it was. By value: an
  // import moves its drawing in (hundreds of thousands of paths are not copied on the UI thread).
  // The imported state counts as unmodified (isModified() false until the next edit).
  void replaceDrawing(Drawing drawing, const QString& fileName, const Placement& placement,
                      const job::DrawingSource& source = {});
  // Sets the placement. Calls with the same non-zero `gestureId` merge into one undo step (a
  // drag); see beginGesture().
  void setPlacement(const Placement& placement, int gestureId = 0);
  void setModeSelection(ModeSelection choice);
  void setLayerVisible(int layerIndex, bool visible);
  void moveLayer(int from, int to);
  void setLayerTool(int layerIndex, const LayerToolSettings& tool);
  // How the layer's filled shapes are drawn: outline, hatch (spacing, angle, crosshatch) or none.
  void setLayerFill(int layerIndex, FillMode fill, const HatchSettings& hatch);
  // The machine profile (the profile editor's door). Undoable like every edit.
  void setProfile(const MachineProfile& profile);

  // A fresh id for one mouse gesture, so all its placement updates form one undo step.
  int beginGesture() { return ++lastGesture_; }

  // Not an edit: the planner's Auto pick, shown by the canvas and the mode panel.
  void setAutoResolvedMode(std::optional<WorkingMode> mode);
  std::optional<WorkingMode> autoResolvedMode() const { return autoResolved_; }

  // Not an edit: the document becomes a loaded project (drawing, placement, layers, mode,
  // tolerance, machine); the undo history is cleared and the state counts as saved.
  void loadProject(Drawing drawing, const job::DrawingSource& source, const Placement& placement,
                   ModeSelection mode, double toleranceMm, const MachineProfile& profile,
                   const QString& projectPath);
  // Not an edit: the same drawing flattened more finely (the planner asked for it); keeps the
  // layers' settings, the placement and the undo history.
  void applyRefinedDrawing(const Drawing& drawing);
  // The project file the document was last saved to or opened from ("" if none): the file Save
  // writes (Save asks for one when there is none).
  QString projectPath() const { return projectPath_; }
  // Marks the current state as saved to `path`.
  void markSaved(const QString& path);
  // Something changed since the last save (or since the document was opened empty), other than
  // opening a drawing: the state right after an import is unmodified until the next edit.
  bool isModified() const;

  // --- raw setters used only by the undo commands ---
  void applyDrawing(std::shared_ptr<const Drawing> drawing, const QString& fileName, const job::DrawingSource& source);
  void applyPlacement(const Placement& placement);
  void applyProjectPath(const QString& path);
  void applyModeSelection(ModeSelection choice);
  // Reorders the layers (`order[i]` = current index of the layer moving to i), then sets the
  // settings by new position.
  void applyLayers(const std::vector<int>& order, const std::vector<LayerSettings>& settings);
  std::vector<LayerSettings> layerSettings() const;
  void applyProfile(const MachineProfile& profile);

 signals:
  void drawingChanged();      // new drawing (import, undo of import)
  void layersChanged();       // visibility, order or tool settings of layers
  void placementChanged();
  void modeSelectionChanged();
  void profileChanged();
  void effectiveModeChanged();
  void modifiedChanged(bool modified);
  void projectPathChanged();
  // Anything that changes the planned job (all of the above except effectiveModeChanged).
  void jobInputsChanged();

 private:
  void updateModified();  // emits modifiedChanged when isModified() changed
  int importedIndex_ = -1;  // the undo index right after the last import (-1: none since the save)
  const QUndoCommand* importCommand_ = nullptr;  // that import's command
  bool lastModified_ = false;
  // Immutable and shared: with the planner (drawingSnapshot), the undo stack and the import that
  // made it, so that a drawing of hundreds of thousands of paths is never copied to be shared.
  // An edit of its layers replaces it with an edited copy.
  std::shared_ptr<const Drawing> drawing_ = std::make_shared<const Drawing>();
  Placement placement_;
  MachineProfile profile_;
  ModeSelection modeSelection_;
  std::optional<WorkingMode> autoResolved_;
  QString fileName_;
  job::DrawingSource source_;
  double toleranceMm_ = 0.1;
  QString projectPath_;
  QUndoStack undo_;
  int lastGesture_ = 0;
};

}  // namespace fivebar::widgets
