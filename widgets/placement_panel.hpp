// The placement by numbers: centre X/Y (mm, machine frame), rotation (deg), scale (%), and
// "fit to workspace". Every change is an undoable document edit; the spin boxes only mirror the
// document.
#pragma once

#include <QWidget>

class QDoubleSpinBox;
class QPushButton;

namespace fivebar::widgets {

class StudioDocument;
class WorkspaceCache;

class PlacementPanel : public QWidget {
  Q_OBJECT
 public:
  PlacementPanel(StudioDocument& doc, WorkspaceCache& workspace, QWidget* parent = nullptr);

 public slots:
  // Fits the drawing into the largest singularity-free rectangle of the document's mode.
  void fitToWorkspace();

 private:
  void showDocument();
  void commit();

  StudioDocument& doc_;
  WorkspaceCache& workspace_;
  QDoubleSpinBox* x_ = nullptr;
  QDoubleSpinBox* y_ = nullptr;
  QDoubleSpinBox* rotation_ = nullptr;
  QDoubleSpinBox* scale_ = nullptr;
  QPushButton* fit_ = nullptr;
};

}  // namespace fivebar::widgets
