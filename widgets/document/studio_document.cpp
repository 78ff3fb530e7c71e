// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/studio_document.hpp"

#include <numeric>
#include <utility>

#include "widgets/document/document_commands.hpp"

namespace fivebar::widgets {

StudioDocument::StudioDocument(MachineProfile profile, QObject* parent)
    : QObject(parent), profile_(std::move(profile)) {
  connect(&undo_, &QUndoStack::cleanChanged, this, [this] { updateModified(); });
  connect(&undo_, &QUndoStack::indexChanged, this, [this] { updateModified(); });
}

void StudioDocument::loadProject(Drawing drawing, const job::DrawingSource& source,
                                 const Placement& placement, ModeSelection mode, double toleranceMm,
                                 const MachineProfile& profile, const QString& projectPath) {
  undo_.clear();
  toleranceMm_ = toleranceMm;
  applyProfile(profile);
  applyModeSelection(mode);
  applyDrawing(std::make_shared<const Drawing>(std::move(drawing)), projectPath, source);
  applyPlacement(placement);
  markSaved(projectPath);
}

void StudioDocument::applyRefinedDrawing(const Drawing& drawing) {
  Drawing refined = drawing;
  // The settings the user has now win over those the plan was made with.
  for (std::size_t i = 0; i < refined.layers.size() && i < drawing_->layers.size(); ++i) {
    if (refined.layers[i].id != drawing_->layers[i].id) return;  // a different drawing by now
    refined.layers[i].visible = drawing_->layers[i].visible;
    refined.layers[i].tool = drawing_->layers[i].tool;
  }
  drawing_ = std::make_shared<const Drawing>(std::move(refined));
}

std::shared_ptr<const Drawing> StudioDocument::drawingSnapshot() const { return drawing_; }

void StudioDocument::markSaved(const QString& path) {
  undo_.setClean();
  importedIndex_ = -1;
  importCommand_ = nullptr;
  updateModified();
  applyProjectPath(path);
}

void StudioDocument::applyProjectPath(const QString& path) {
  if (path == projectPath_) return;
  projectPath_ = path;
  emit projectPathChanged();
}

WorkingMode StudioDocument::effectiveMode() const {
  if (modeSelection_) return *modeSelection_;
  return autoResolved_.value_or(profile_.defaultMode);
}

void StudioDocument::replaceDrawing(Drawing drawing, const QString& fileName,
                                    const Placement& placement, const job::DrawingSource& source) {
  undo_.push(new ReplaceDrawingCommand(*this, std::move(drawing), fileName, placement, source));
  // Opening a drawing is not a change to save: the file is on disk as it was read. The state
  // right after the import counts as unmodified too (the clean state, the saved one, stays
  // where it was: undoing the import gives the project back unmodified).
  importedIndex_ = undo_.index();
  importCommand_ = undo_.command(importedIndex_ - 1);
  updateModified();
}

bool StudioDocument::isModified() const {
  if (undo_.isClean()) return false;
  return !(undo_.index() == importedIndex_ && undo_.command(importedIndex_ - 1) == importCommand_);
}

void StudioDocument::updateModified() {
  const bool modified = isModified();
  if (modified == lastModified_) return;
  lastModified_ = modified;
  emit modifiedChanged(modified);
}

void StudioDocument::setPlacement(const Placement& placement, int gestureId) {
  undo_.push(new SetPlacementCommand(*this, placement, gestureId));
}

void StudioDocument::setModeSelection(ModeSelection choice) {
  if (choice == modeSelection_) return;
  undo_.push(new SetModeSelectionCommand(*this, choice));
}

std::vector<LayerSettings> StudioDocument::layerSettings() const {
  std::vector<LayerSettings> out;
  out.reserve(drawing_->layers.size());
  for (const Layer& l : drawing_->layers) out.push_back({l.visible, l.tool, l.fill, l.hatch});
  return out;
}

namespace {
std::vector<int> identity(std::size_t n) {
  std::vector<int> v(n);
  std::iota(v.begin(), v.end(), 0);
  return v;
}
}  // namespace

void StudioDocument::setLayerVisible(int layerIndex, bool visible) {
  if (layerIndex < 0 || layerIndex >= static_cast<int>(drawing_->layers.size())) return;
  if (drawing_->layers[layerIndex].visible == visible) return;
  auto settings = layerSettings();
  settings[layerIndex].visible = visible;
  undo_.push(new SetLayersCommand(*this, identity(settings.size()), settings,
                                  visible ? tr("Show layer") : tr("Hide layer")));
}

void StudioDocument::moveLayer(int from, int to) {
  const int n = static_cast<int>(drawing_->layers.size());
  if (from < 0 || from >= n || to < 0 || to >= n || from == to) return;
  std::vector<int> order = identity(n);
  order.erase(order.begin() + from);
  order.insert(order.begin() + to, from);
  const auto current = layerSettings();
  std::vector<LayerSettings> settings;
  for (int i : order) settings.push_back(current[i]);
  undo_.push(new SetLayersCommand(*this, order, settings, tr("Reorder layers")));
}

void StudioDocument::setLayerTool(int layerIndex, const LayerToolSettings& tool) {
  if (layerIndex < 0 || layerIndex >= static_cast<int>(drawing_->layers.size())) return;
  auto settings = layerSettings();
  settings[layerIndex].tool = tool;
  undo_.push(new SetLayersCommand(*this, identity(settings.size()), settings,
                                  tr("Change layer tool settings")));
}

void StudioDocument::setLayerFill(int layerIndex, FillMode fill, const HatchSettings& hatch) {
  if (layerIndex < 0 || layerIndex >= static_cast<int>(drawing_->layers.size())) return;
  auto settings = layerSettings();
  if (settings[layerIndex].fill == fill && settings[layerIndex].hatch == hatch) return;
  settings[layerIndex].fill = fill;
  settings[layerIndex].hatch = hatch;
  undo_.push(new SetLayersCommand(*this, identity(settings.size()), settings, tr("Change layer fill")));
}

void StudioDocument::setProfile(const MachineProfile& profile) {
  undo_.push(new SetProfileCommand(*this, profile));
}

void StudioDocument::setAutoResolvedMode(std::optional<WorkingMode> mode) {
  const WorkingMode before = effectiveMode();
  autoResolved_ = mode;
  if (effectiveMode() != before) emit effectiveModeChanged();
}

void StudioDocument::applyDrawing(std::shared_ptr<const Drawing> drawing, const QString& fileName,
                                  const job::DrawingSource& source) {
  drawing_ = std::move(drawing);
  fileName_ = fileName;
  source_ = source;
  emit drawingChanged();
  emit layersChanged();
  emit jobInputsChanged();
}

void StudioDocument::applyPlacement(const Placement& placement) {
  placement_ = placement;
  emit placementChanged();
  emit jobInputsChanged();
}

void StudioDocument::applyModeSelection(ModeSelection choice) {
  const WorkingMode before = effectiveMode();
  modeSelection_ = choice;
  emit modeSelectionChanged();
  if (effectiveMode() != before) emit effectiveModeChanged();
  emit jobInputsChanged();
}

void StudioDocument::applyLayers(const std::vector<int>& order,
                                 const std::vector<LayerSettings>& settings) {
  auto edited = std::make_shared<Drawing>(*drawing_);
  std::vector<Layer> layers;
  layers.reserve(order.size());
  for (int i : order) layers.push_back(std::move(edited->layers[i]));
  for (std::size_t i = 0; i < layers.size() && i < settings.size(); ++i) {
    layers[i].visible = settings[i].visible;
    layers[i].tool = settings[i].tool;
    layers[i].fill = settings[i].fill;
    layers[i].hatch = settings[i].hatch;
  }
  edited->layers = std::move(layers);
  drawing_ = std::move(edited);
  emit layersChanged();
  emit jobInputsChanged();
}

void StudioDocument::applyProfile(const MachineProfile& profile) {
  const WorkingMode before = effectiveMode();
  profile_ = profile;
  emit profileChanged();
  if (effectiveMode() != before) emit effectiveModeChanged();
  emit jobInputsChanged();
}

}  // namespace fivebar::widgets
