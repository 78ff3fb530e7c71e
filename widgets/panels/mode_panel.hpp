// SPDX-License-Identifier: GPL-3.0-or-later
// Working-mode selector (Auto, ++, +-, -+, --) and the workspace overlay switches. The mode is
// document state (an undoable edit); the overlay switches are view state held by the
// WorkspaceLayer.
#pragma once

#include <QWidget>

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QLabel;

namespace fivebar::widgets {

class StudioDocument;
class WorkspaceLayer;
class PreviewController;

class ModePanel : public QWidget {
  Q_OBJECT
 public:
  ModePanel(StudioDocument& doc, WorkspaceLayer& layer, const PreviewController& preview,
            QWidget* parent = nullptr);

 private:
  void showDocument();
  void showOverlays();

  StudioDocument& doc_;
  WorkspaceLayer& layer_;
  const PreviewController& preview_;
  QButtonGroup* modes_ = nullptr;
  QLabel* resolved_ = nullptr;
  QCheckBox* region_ = nullptr;
  QCheckBox* typeII_ = nullptr;
  QCheckBox* rectangleBox_ = nullptr;
  QCheckBox* legendBox_ = nullptr;
  QComboBox* map_ = nullptr;
};

}  // namespace fivebar::widgets
