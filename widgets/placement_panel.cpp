#include "widgets/placement_panel.hpp"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include "core/kinematics/units.hpp"
#include "widgets/import_controller.hpp"
#include "widgets/studio_document.hpp"
#include "widgets/workspace_cache.hpp"

namespace fivebar::widgets {
namespace {

QDoubleSpinBox* spin(QWidget* parent, double min, double max, int decimals, const QString& suffix,
                     double step) {
  auto* s = new QDoubleSpinBox(parent);
  s->setRange(min, max);
  s->setDecimals(decimals);
  s->setSuffix(suffix);
  s->setSingleStep(step);
  s->setKeyboardTracking(false);  // commit on Enter / focus loss / arrows, not per keystroke
  s->setAccelerated(true);
  return s;
}

}  // namespace

PlacementPanel::PlacementPanel(StudioDocument& doc, WorkspaceCache& workspace, QWidget* parent)
    : QWidget(parent), doc_(doc), workspace_(workspace) {
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  x_ = spin(this, -5000.0, 5000.0, 2, tr(" mm"), 1.0);
  y_ = spin(this, -5000.0, 5000.0, 2, tr(" mm"), 1.0);
  rotation_ = spin(this, -360.0, 360.0, 2, tr(" deg"), 1.0);
  scale_ = spin(this, 0.1, 10000.0, 2, tr(" %"), 1.0);
  x_->setObjectName(QStringLiteral("placementX"));
  y_->setObjectName(QStringLiteral("placementY"));
  rotation_->setObjectName(QStringLiteral("placementRotation"));
  scale_->setObjectName(QStringLiteral("placementScale"));
  form->addRow(tr("Centre X:"), x_);
  form->addRow(tr("Centre Y:"), y_);
  form->addRow(tr("Rotation:"), rotation_);
  form->addRow(tr("Scale:"), scale_);
  layout->addLayout(form);
  fit_ = new QPushButton(tr("Fit to workspace"), this);
  fit_->setToolTip(tr("Fit the drawing into the largest singularity-free rectangle"));
  layout->addWidget(fit_);
  layout->addStretch(1);
  for (QDoubleSpinBox* s : {x_, y_, rotation_, scale_}) {
    connect(s, &QDoubleSpinBox::valueChanged, this, &PlacementPanel::commit);
  }
  connect(fit_, &QPushButton::clicked, this, &PlacementPanel::fitToWorkspace);
  connect(&doc_, &StudioDocument::placementChanged, this, &PlacementPanel::showDocument);
  connect(&doc_, &StudioDocument::drawingChanged, this, &PlacementPanel::showDocument);
  showDocument();
}

void PlacementPanel::showDocument() {
  const Placement& p = doc_.placement();
  const QSignalBlocker b1(x_), b2(y_), b3(rotation_), b4(scale_);
  x_->setValue(p.centerMm.x());
  y_->setValue(p.centerMm.y());
  rotation_->setValue(degFromRad(p.rotationRad));
  scale_->setValue(p.scale * 100.0);
  setEnabled(doc_.hasDrawing());
}

void PlacementPanel::commit() {
  Placement p = doc_.placement();
  p.centerMm = Vec2(x_->value(), y_->value());
  p.rotationRad = radFromDeg(rotation_->value());
  p.scale = scale_->value() / 100.0;
  doc_.setPlacement(p);
}

void PlacementPanel::fitToWorkspace() {
  if (!doc_.hasDrawing()) return;
  const auto rect = workspace_.fitRectangle(doc_.effectiveMode());
  if (!rect) return;
  const Placement& current = doc_.placement();
  if (auto fitted = fitPlacement(doc_.drawing(), *rect, true, ImportController::kFitMarginMm,
                                 current.rotationRad)) {
    doc_.setPlacement(*fitted);
  }
}

}  // namespace fivebar::widgets
