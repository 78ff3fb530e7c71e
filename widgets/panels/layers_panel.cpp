#include "widgets/panels/layers_panel.hpp"

#include <QCheckBox>
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

  connect(list_, &QListWidget::itemChanged, this, &LayersPanel::onItemChanged);
  connect(list_, &QListWidget::currentRowChanged, this, &LayersPanel::showSelectedTool);
  connect(up_, &QToolButton::clicked, this, [this] { moveSelected(-1); });
  connect(down_, &QToolButton::clicked, this, [this] { moveSelected(+1); });
  connect(speed_, &QDoubleSpinBox::valueChanged, this, &LayersPanel::commitTool);
  connect(power_, &QDoubleSpinBox::valueChanged, this, &LayersPanel::commitTool);
  connect(pause_, &QCheckBox::toggled, this, &LayersPanel::commitTool);
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
                     static_cast<QWidget*>(pause_)}) {
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
