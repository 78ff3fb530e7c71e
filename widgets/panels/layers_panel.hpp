// SPDX-License-Identifier: GPL-3.0-or-later
// The layers of the drawing: visibility (check box), plotting order (up/down) and the tool
// settings of the selected layer (draw speed, power, pause for a pen change) and its fill (outline,
// hatch with spacing, angle and crosshatch, or none). Every change is an undoable document edit;
// the list mirrors the document.
#pragma once

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QListWidget;
class QListWidgetItem;
class QToolButton;

namespace fivebar::widgets {

class StudioDocument;

class LayersPanel : public QWidget {
  Q_OBJECT
 public:
  explicit LayersPanel(StudioDocument& doc, QWidget* parent = nullptr);

  QListWidget* list() const { return list_; }

 private:
  void showDocument();
  void showSelectedTool();
  void commitTool();
  void commitFill();
  void onItemChanged(QListWidgetItem* item);
  void moveSelected(int delta);

  StudioDocument& doc_;
  QListWidget* list_ = nullptr;
  QToolButton* up_ = nullptr;
  QToolButton* down_ = nullptr;
  QDoubleSpinBox* speed_ = nullptr;
  QDoubleSpinBox* power_ = nullptr;
  QCheckBox* pause_ = nullptr;
  QComboBox* fill_ = nullptr;
  QDoubleSpinBox* spacing_ = nullptr;
  QDoubleSpinBox* angle_ = nullptr;
  QCheckBox* cross_ = nullptr;
};

}  // namespace fivebar::widgets
