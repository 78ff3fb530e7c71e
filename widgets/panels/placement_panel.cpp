// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/panels/placement_panel.hpp"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include "core/kinematics/units.hpp"
#include "core/planning/auto_placement.hpp"
#include "widgets/document/studio_document.hpp"

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

// Size of the drawing's visible bounds at 100 % (work mm); zero when empty.
QSizeF trueSizeMm(const Drawing& d) {
  const auto b = drawingBounds(d);
  return b ? QSizeF(b->width(), b->height()) : QSizeF();
}

}  // namespace

PlacementPanel::PlacementPanel(StudioDocument& doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  x_ = spin(this, -5000.0, 5000.0, 2, tr(" mm"), 1.0);
  y_ = spin(this, -5000.0, 5000.0, 2, tr(" mm"), 1.0);
  rotation_ = spin(this, -360.0, 360.0, 2, tr(" deg"), 1.0);
  scale_ = spin(this, 0.1, 10000.0, 2, tr(" %"), 1.0);
  width_ = spin(this, 0.01, 100000.0, 2, tr(" mm"), 1.0);
  height_ = spin(this, 0.01, 100000.0, 2, tr(" mm"), 1.0);
  keepAspect_ = new QCheckBox(tr("Keep aspect ratio"), this);
  keepAspect_->setChecked(true);
  x_->setObjectName(QStringLiteral("placementX"));
  y_->setObjectName(QStringLiteral("placementY"));
  rotation_->setObjectName(QStringLiteral("placementRotation"));
  scale_->setObjectName(QStringLiteral("placementScale"));
  width_->setObjectName(QStringLiteral("placementWidth"));
  height_->setObjectName(QStringLiteral("placementHeight"));
  keepAspect_->setObjectName(QStringLiteral("placementKeepAspect"));
  form->addRow(tr("Centre X:"), x_);
  form->addRow(tr("Centre Y:"), y_);
  form->addRow(tr("Rotation:"), rotation_);
  form->addRow(tr("Scale:"), scale_);
  form->addRow(tr("Width:"), width_);
  form->addRow(tr("Height:"), height_);
  form->addRow(QString(), keepAspect_);
  layout->addLayout(form);
  auto* buttons = new QHBoxLayout;
  actual_ = new QPushButton(tr("Actual size"), this);
  actual_->setObjectName(QStringLiteral("placementActualSize"));
  actual_->setToolTip(tr("Draw the drawing at its true size (100 %)"));
  fit_ = new QPushButton(tr("Fit to workspace"), this);
  fit_->setObjectName(QStringLiteral("placementFit"));
  fit_->setToolTip(tr("Scale the drawing to fill the largest singularity-free rectangle"));
  buttons->addWidget(actual_);
  buttons->addWidget(fit_);
  layout->addLayout(buttons);
  note_ = new QLabel(this);
  note_->setObjectName(QStringLiteral("placementNote"));
  note_->setWordWrap(true);
  note_->setVisible(false);
  layout->addWidget(note_);
  layout->addStretch(1);
  for (QDoubleSpinBox* s : {x_, y_, rotation_, scale_})
    connect(s, &QDoubleSpinBox::valueChanged, this, &PlacementPanel::commit);
  connect(width_, &QDoubleSpinBox::valueChanged, this, [this] { commitSize(true); });
  connect(height_, &QDoubleSpinBox::valueChanged, this, [this] { commitSize(false); });
  connect(fit_, &QPushButton::clicked, this, &PlacementPanel::fitToWorkspace);
  connect(actual_, &QPushButton::clicked, this, &PlacementPanel::actualSize);
  connect(&doc_, &StudioDocument::placementChanged, this, &PlacementPanel::showDocument);
  connect(&doc_, &StudioDocument::drawingChanged, this, &PlacementPanel::showDocument);
  connect(&doc_, &StudioDocument::layersChanged, this, &PlacementPanel::showDocument);
  showDocument();
}

void PlacementPanel::setNote(const QString& note) {
  note_->setText(note);
  note_->setVisible(!note.isEmpty());
}

void PlacementPanel::showDocument() {
  const Placement& p = doc_.placement();
  const QSizeF size = trueSizeMm(doc_.drawing());
  const QSignalBlocker b1(x_), b2(y_), b3(rotation_), b4(scale_), b5(width_), b6(height_);
  x_->setValue(p.centerMm.x());
  y_->setValue(p.centerMm.y());
  rotation_->setValue(degFromRad(p.rotationRad));
  scale_->setValue(p.scale * 100.0);
  width_->setValue(size.width() * p.scale);
  height_->setValue(size.height() * p.scale * p.stretchY);
  if (p.stretchY != 1.0) keepAspect_->setChecked(false);
  setEnabled(doc_.hasDrawing());
}

void PlacementPanel::commit() {
  Placement p = doc_.placement();
  p.centerMm = Vec2(x_->value(), y_->value());
  p.rotationRad = radFromDeg(rotation_->value());
  p.scale = scale_->value() / 100.0;
  doc_.setPlacement(p);
  setNote(QString());
}

void PlacementPanel::commitSize(bool widthEdited) {
  const QSizeF size = trueSizeMm(doc_.drawing());
  Placement p = doc_.placement();
  if (widthEdited && size.width() > 0.0) {
    const double scale = width_->value() / size.width();
    if (!keepAspect_->isChecked()) p.stretchY *= p.scale / scale;  // height stays
    p.scale = scale;
  } else if (!widthEdited && size.height() > 0.0) {
    const double yScale = height_->value() / size.height();
    if (keepAspect_->isChecked()) {
      p.scale = yScale / p.stretchY;
    } else {
      p.stretchY = yScale / p.scale;
    }
  } else {
    return;  // a line with no extent along that axis: nothing to scale by
  }
  doc_.setPlacement(p);
  setNote(QString());
}

void PlacementPanel::fitToWorkspace() {
  if (!doc_.hasDrawing()) return;
  const auto placed = autoPlacement(doc_.drawing(), doc_.profile(), doc_.modeSelection(),
                                    doc_.placement().rotationRad, PlacementSizing::Fit);
  if (!placed) {
    setNote(tr("No singularity-free area to fit the drawing into."));
    return;
  }
  doc_.setPlacement(placed->placement);
  setNote(tr("Fitted: %1 %").arg(QLocale().toString(placed->placement.scale * 100.0, 'f', 0)));
}

void PlacementPanel::actualSize() {
  if (!doc_.hasDrawing()) return;
  Placement p = doc_.placement();
  p.scale = 1.0;
  p.stretchY = 1.0;
  keepAspect_->setChecked(true);
  doc_.setPlacement(p);
  setNote(QString());
}

}  // namespace fivebar::widgets
