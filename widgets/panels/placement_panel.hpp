// SPDX-License-Identifier: GPL-3.0-or-later
// The placement by numbers: centre X/Y (mm, machine frame), rotation (deg), scale (%), the
// drawing's width and height in mm (editable; the aspect is kept unless unlocked), "Fit to
// workspace" (fills the largest singularity-free rectangle) and "Actual size" (back to 100 %).
// Every change is an undoable document edit; the spin boxes only mirror the document. The
// placement rule is core's (core/planning/auto_placement.hpp), the same as `fivebar plan --fit`.
#pragma once

#include <QWidget>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace fivebar::widgets {

class StudioDocument;

class PlacementPanel : public QWidget {
  Q_OBJECT
 public:
  explicit PlacementPanel(StudioDocument& doc, QWidget* parent = nullptr);

 public slots:
  // Scales the drawing (up or down) to fill the largest singularity-free rectangle, centred in it.
  void fitToWorkspace();
  // Back to true size (100 %, aspect kept), centre unchanged.
  void actualSize();
  // Shows a note under the numbers ("scaled to 62 % to fit the workspace"); empty hides it.
  void setNote(const QString& note);

 private:
  void showDocument();
  void commit();
  void commitSize(bool widthEdited);

  StudioDocument& doc_;
  QDoubleSpinBox* x_ = nullptr;
  QDoubleSpinBox* y_ = nullptr;
  QDoubleSpinBox* rotation_ = nullptr;
  QDoubleSpinBox* scale_ = nullptr;
  QDoubleSpinBox* width_ = nullptr;
  QDoubleSpinBox* height_ = nullptr;
  QCheckBox* keepAspect_ = nullptr;
  QPushButton* fit_ = nullptr;
  QPushButton* actual_ = nullptr;
  QLabel* note_ = nullptr;
};

}  // namespace fivebar::widgets
