// SPDX-License-Identifier: GPL-3.0-or-later
// How filled shapes are drawn when a drawing is imported: outline (default), hatch (spacing,
// angle, crosshatch, outline kept or not) or none; "Apply" imports the current file again with
// the new choice (for this session). The geometry is core/planning/hatch.hpp. "Draw dashed
// strokes solid" makes the next imports draw stroke-dasharray strokes whole.
#pragma once

#include <QGroupBox>

#include "core/planning/hatch.hpp"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QPushButton;

namespace fivebar::widgets {

class ImportController;
class StudioDocument;

class FillOptionsBox : public QGroupBox {
  Q_OBJECT
 public:
  FillOptionsBox(ImportController& importer, StudioDocument& doc, QWidget* parent = nullptr);

  // Shows and applies a choice (e.g. from the command line).
  void setChoice(FillMode mode, const HatchSettings& hatch);
  // "Import again with these settings": enabled while the document is a drawing (not a project).
  QPushButton* importAgainButton() const { return apply_; }

 private:
  void push();         // widgets -> importer and QSettings
  void updateEnabled();
  bool canImportAgain() const;

  ImportController& importer_;
  StudioDocument& doc_;
  QComboBox* mode_ = nullptr;
  QDoubleSpinBox* spacing_ = nullptr;
  QDoubleSpinBox* angle_ = nullptr;
  QCheckBox* cross_ = nullptr;
  QCheckBox* outline_ = nullptr;
  QCheckBox* solidDashes_ = nullptr;
  QPushButton* apply_ = nullptr;
};

// "--fill MODE[:SPACING_MM[:ANGLE_DEG]]" for the window's FillOptionsBox (passed by the composition
// root, MainWindow::fillOptions()); false when malformed.
bool applyFillOption(FillOptionsBox& box, const QString& text);

}  // namespace fivebar::widgets
