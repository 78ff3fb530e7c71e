// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/panels/layers_panel.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QListWidget>
#include <QPainter>
#include <QPixmap>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

#include "core/kinematics/units.hpp"
#include "core/planning/hatch.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {
namespace {

QIcon swatch(std::uint32_t rgb) {
  QPixmap pixmap(14, 14);
  pixmap.fill(Qt::transparent);
  QPainter p(&pixmap);
  p.setRenderHint(QPainter::Antialiasing);
  p.setPen(QPen(QColor(0, 0, 0, 60), 1.0));
  p.setBrush(QColor::fromRgb(static_cast<QRgb>(rgb | 0xff000000u)));
  p.drawRoundedRect(QRectF(1, 1, 12, 12), 3, 3);
  return QIcon(pixmap);
}

}  // namespace

LayersPanel::LayersPanel(StudioDocument& doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  auto* layout = new QVBoxLayout(this);
  list_ = new QListWidget(this);
  list_->setObjectName(QStringLiteral("layersList"));
  layout->addWidget(list_, 1);
  auto* buttons = new QHBoxLayout;
  up_ = new QToolButton(this);
  up_->setArrowType(Qt::UpArrow);
  up_->setToolTip(tr("Plot this layer earlier"));
  down_ = new QToolButton(this);
  down_->setArrowType(Qt::DownArrow);
  down_->setToolTip(tr("Plot this layer later"));
  buttons->addWidget(up_);
  buttons->addWidget(down_);
  buttons->addStretch(1);
  layout->addLayout(buttons);

  auto* toolBox = new QGroupBox(tr("Tool settings of the selected layer"), this);
  auto* form = new QFormLayout(toolBox);
  speed_ = new QDoubleSpinBox(toolBox);
  speed_->setRange(0.0, 1000.0);
  speed_->setDecimals(1);
  speed_->setSuffix(tr(" mm/s"));
  speed_->setSpecialValueText(tr("Profile default"));
  speed_->setKeyboardTracking(false);
  power_ = new QDoubleSpinBox(toolBox);
  power_->setRange(-1.0, 100000.0);
  power_->setDecimals(0);
  power_->setSpecialValueText(tr("Profile default"));
  power_->setKeyboardTracking(false);
  pause_ = new QCheckBox(tr("Pause before this layer (pen change)"), toolBox);
  form->addRow(tr("Draw speed:"), speed_);
  form->addRow(tr("Power / pen S:"), power_);
  form->addRow(pause_);
  layout->addWidget(toolBox);

  auto* fillBox = new QGroupBox(tr("Fill of the selected layer"), this);
  auto* fillForm = new QFormLayout(fillBox);
  fill_ = new QComboBox(fillBox);
  fill_->setObjectName(QStringLiteral("layerFill"));
  fill_->addItem(tr("Outline"), static_cast<int>(FillMode::Outline));
  fill_->addItem(tr("Hatch"), static_cast<int>(FillMode::Hatch));
  fill_->addItem(tr("None"), static_cast<int>(FillMode::None));
  fill_->setToolTip(tr("How the layer's filled shapes are drawn: their outline, parallel hatch "
                       "lines inside them, or not at all (stroked shapes keep their stroke)."));
  spacing_ = new QDoubleSpinBox(fillBox);
  spacing_->setObjectName(QStringLiteral("layerHatchSpacing"));
  spacing_->setRange(kMinHatchSpacingMm, 50.0);
  spacing_->setDecimals(2);
  spacing_->setSingleStep(0.1);
  spacing_->setSuffix(tr(" mm"));
  spacing_->setKeyboardTracking(false);
  angle_ = new QDoubleSpinBox(fillBox);
  angle_->setObjectName(QStringLiteral("layerHatchAngle"));
  angle_->setRange(-180.0, 180.0);
  angle_->setDecimals(1);
  angle_->setSuffix(tr(" °"));
  angle_->setKeyboardTracking(false);
  cross_ = new QCheckBox(tr("Crosshatch"), fillBox);
  cross_->setObjectName(QStringLiteral("layerCrosshatch"));
  fillForm->addRow(tr("Fill:"), fill_);
  fillForm->addRow(tr("Hatch spacing:"), spacing_);
  fillForm->addRow(tr("Hatch angle:"), angle_);
  fillForm->addRow(cross_);
  layout->addWidget(fillBox);

  connect(list_, &QListWidget::itemChanged, this, &LayersPanel::onItemChanged);
  connect(list_, &QListWidget::currentRowChanged, this, &LayersPanel::showSelectedTool);
  connect(up_, &QToolButton::clicked, this, [this] { moveSelected(-1); });
  connect(down_, &QToolButton::clicked, this, [this] { moveSelected(+1); });
  connect(speed_, &QDoubleSpinBox::valueChanged, this, &LayersPanel::commitTool);
  connect(power_, &QDoubleSpinBox::valueChanged, this, &LayersPanel::commitTool);
  connect(pause_, &QCheckBox::toggled, this, &LayersPanel::commitTool);
  connect(fill_, &QComboBox::currentIndexChanged, this, &LayersPanel::commitFill);
  connect(spacing_, &QDoubleSpinBox::valueChanged, this, &LayersPanel::commitFill);
  connect(angle_, &QDoubleSpinBox::valueChanged, this, &LayersPanel::commitFill);
  connect(cross_, &QCheckBox::toggled, this, &LayersPanel::commitFill);
  connect(&doc_, &StudioDocument::layersChanged, this, &LayersPanel::showDocument);
  showDocument();
}

void LayersPanel::showDocument() {
  const QSignalBlocker blocker(list_);
  const int row = list_->currentRow();
  list_->clear();
  const auto& layers = doc_.drawing().layers;
  for (const Layer& layer : layers) {
    std::size_t points = 0;
    for (const Polyline& p : layer.paths) points += p.points.size();
    auto* item = new QListWidgetItem(swatch(layer.rgb), QString::fromStdString(layer.name));
    item->setToolTip(tr("%n path(s)", "", static_cast<int>(layer.paths.size())) +
                     QStringLiteral(", ") + tr("%n point(s)", "", static_cast<int>(points)));
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(layer.visible ? Qt::Checked : Qt::Unchecked);
    list_->addItem(item);
  }
  if (!layers.empty()) list_->setCurrentRow(std::clamp(row, 0, static_cast<int>(layers.size()) - 1));
  showSelectedTool();
}

void LayersPanel::showSelectedTool() {
  const int row = list_->currentRow();
  const auto& layers = doc_.drawing().layers;
  const bool valid = row >= 0 && row < static_cast<int>(layers.size());
  for (QWidget* w : {static_cast<QWidget*>(speed_), static_cast<QWidget*>(power_),
                     static_cast<QWidget*>(pause_), static_cast<QWidget*>(fill_)}) {
    w->setEnabled(valid);
  }
  up_->setEnabled(valid && row > 0);
  down_->setEnabled(valid && row + 1 < static_cast<int>(layers.size()));
  if (!valid) return;
  const LayerToolSettings& tool = layers[static_cast<std::size_t>(row)].tool;
  const QSignalBlocker b1(speed_), b2(power_), b3(pause_);
  speed_->setValue(tool.drawSpeedMmPerS);
  power_->setValue(tool.power < 0.0 ? -1.0 : tool.power);
  pause_->setChecked(tool.pauseBefore);
  const Layer& layer = layers[static_cast<std::size_t>(row)];
  const QSignalBlocker b4(fill_), b5(spacing_), b6(angle_), b7(cross_);
  fill_->setCurrentIndex(fill_->findData(static_cast<int>(layer.fill)));
  spacing_->setValue(layer.hatch.spacingMm);
  angle_->setValue(degFromRad(layer.hatch.angleRad));
  cross_->setChecked(layer.hatch.crosshatch);
  const bool hatch = layer.fill == FillMode::Hatch;
  for (QWidget* w : {static_cast<QWidget*>(spacing_), static_cast<QWidget*>(angle_), static_cast<QWidget*>(cross_)})
    w->setEnabled(hatch);
}

void LayersPanel::commitFill() {
  const int row = list_->currentRow();
  const auto& layers = doc_.drawing().layers;
  if (row < 0 || row >= static_cast<int>(layers.size())) return;
  HatchSettings hatch = layers[static_cast<std::size_t>(row)].hatch;
  hatch.spacingMm = spacing_->value();
  hatch.angleRad = radFromDeg(angle_->value());
  hatch.crosshatch = cross_->isChecked();
  doc_.setLayerFill(row, static_cast<FillMode>(fill_->currentData().toInt()), hatch);
}

void LayersPanel::commitTool() {
  const int row = list_->currentRow();
  if (row < 0) return;
  LayerToolSettings tool;
  tool.drawSpeedMmPerS = speed_->value();
  tool.power = power_->value() < 0.0 ? -1.0 : power_->value();
  tool.pauseBefore = pause_->isChecked();
  doc_.setLayerTool(row, tool);
}

void LayersPanel::onItemChanged(QListWidgetItem* item) {
  doc_.setLayerVisible(list_->row(item), item->checkState() == Qt::Checked);
}

void LayersPanel::moveSelected(int delta) {
  const int row = list_->currentRow();
  const int to = row + delta;
  if (row < 0 || to < 0 || to >= list_->count()) return;
  doc_.moveLayer(row, to);
  list_->setCurrentRow(to);
}

}  // namespace fivebar::widgets
