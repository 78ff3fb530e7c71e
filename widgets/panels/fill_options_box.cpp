// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/panels/fill_options_box.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QPushButton>
#include <QSignalBlocker>

#include <numbers>

#include "core/kinematics/units.hpp"
#include "widgets/document/import_controller.hpp"
#include "job/job_source.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {

FillOptionsBox::FillOptionsBox(ImportController& importer, StudioDocument& doc, QWidget* parent)
    : QGroupBox(tr("Filled shapes"), parent), importer_(importer), doc_(doc) {
  auto* form = new QFormLayout(this);
  mode_ = new QComboBox(this);
  mode_->addItem(tr("Outline"), static_cast<int>(FillMode::Outline));
  mode_->addItem(tr("Hatch"), static_cast<int>(FillMode::Hatch));
  mode_->addItem(tr("Not drawn"), static_cast<int>(FillMode::None));
  mode_->setToolTip(tr("Outline: the shape's edge (as AxiDraw and vpype draw fills). Hatch: "
                       "parallel lines inside the shape. Not drawn: fill-only shapes are left out."));
  spacing_ = new QDoubleSpinBox(this);
  spacing_->setRange(kMinHatchSpacingMm, 50.0);
  spacing_->setDecimals(2);
  spacing_->setSingleStep(0.1);
  spacing_->setSuffix(tr(" mm"));
  angle_ = new QDoubleSpinBox(this);
  angle_->setRange(-180.0, 180.0);
  angle_->setDecimals(1);
  angle_->setSuffix(tr(" deg"));
  cross_ = new QCheckBox(tr("Crosshatch"), this);
  outline_ = new QCheckBox(tr("Keep the outline"), this);
  solidDashes_ = new QCheckBox(tr("Draw dashed strokes solid"), this);
  solidDashes_->setToolTip(tr("Dashed strokes are drawn as their dashes, the pen lifted between "
                              "them; checked: each dashed stroke is drawn as one line."));
  apply_ = new QPushButton(tr("Import again with these settings"), this);
  form->addRow(tr("Fill:"), mode_);
  form->addRow(tr("Line spacing:"), spacing_);
  form->addRow(tr("Angle:"), angle_);
  form->addRow(cross_);
  form->addRow(outline_);
  form->addRow(solidDashes_);
  form->addRow(apply_);

  HatchSettings defaults;
  defaults.spacingMm = 0.5;
  defaults.angleRad = std::numbers::pi / 4.0;
  setChoice(importer_.fill(), defaults);
  connect(mode_, &QComboBox::currentIndexChanged, this, &FillOptionsBox::push);
  connect(spacing_, &QDoubleSpinBox::valueChanged, this, &FillOptionsBox::push);
  connect(angle_, &QDoubleSpinBox::valueChanged, this, &FillOptionsBox::push);
  connect(cross_, &QCheckBox::toggled, this, &FillOptionsBox::push);
  connect(outline_, &QCheckBox::toggled, this, &FillOptionsBox::push);
  solidDashes_->setChecked(importer_.solidDashes());
  connect(solidDashes_, &QCheckBox::toggled, &importer_, &ImportController::setSolidDashes);
  connect(&doc_, &StudioDocument::drawingChanged, this, &FillOptionsBox::updateEnabled);
  connect(apply_, &QPushButton::clicked, this, [this] {
    if (canImportAgain()) importer_.openFile(doc_.fileName());
  });
}

void FillOptionsBox::setChoice(FillMode mode, const HatchSettings& hatch) {
  const QSignalBlocker blockMode(mode_), blockSpacing(spacing_), blockAngle(angle_),
      blockCross(cross_), blockOutline(outline_);
  mode_->setCurrentIndex(mode_->findData(static_cast<int>(mode)));
  spacing_->setValue(hatch.spacingMm);
  angle_->setValue(degFromRad(hatch.angleRad));
  cross_->setChecked(hatch.crosshatch);
  outline_->setChecked(hatch.outline);
  push();
}

void FillOptionsBox::push() {
  const auto mode = static_cast<FillMode>(mode_->currentData().toInt());
  HatchSettings hatch;
  hatch.spacingMm = spacing_->value();
  hatch.angleRad = radFromDeg(angle_->value());  // as the CLI converts
  hatch.crosshatch = cross_->isChecked();
  hatch.outline = outline_->isChecked();
  importer_.setFill(mode, hatch);
  updateEnabled();
}

// Only a drawing is imported again (an undoable edit). A project opened again would drop its
// unsaved edits without a question, and its layers keep their own fills (the Layers panel).
bool FillOptionsBox::canImportAgain() const {
  return QFileInfo(doc_.fileName()).isFile() && !job::isProjectPath(doc_.fileName());
}

void FillOptionsBox::updateEnabled() {
  const bool hatch = mode_->currentData().toInt() == static_cast<int>(FillMode::Hatch);
  spacing_->setEnabled(hatch);
  angle_->setEnabled(hatch);
  cross_->setEnabled(hatch);
  outline_->setEnabled(hatch);
  apply_->setEnabled(canImportAgain() && !importer_.busy());
}

bool applyFillOption(FillOptionsBox& box, const QString& text) {
  const QStringList parts = text.split(u':');
  const auto mode = fillModeFromString(parts.front().toStdString());
  if (!mode || parts.size() > 3 || (parts.size() > 1 && *mode != FillMode::Hatch)) return false;
  HatchSettings hatch;
  hatch.spacingMm = 0.5;
  hatch.angleRad = std::numbers::pi / 4.0;
  bool ok = true;
  if (parts.size() > 1) hatch.spacingMm = parts[1].toDouble(&ok);
  if (ok && parts.size() > 2) hatch.angleRad = radFromDeg(parts[2].toDouble(&ok));
  if (!ok || !validate(hatch).empty()) return false;
  box.setChoice(*mode, hatch);
  return true;
}

}  // namespace fivebar::widgets
