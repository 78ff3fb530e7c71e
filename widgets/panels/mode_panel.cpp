// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/panels/mode_panel.hpp"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

#include "core/kinematics/units.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/document/studio_document.hpp"
#include "widgets/canvas/workspace_layer.hpp"

namespace fivebar::widgets {
namespace {
constexpr int kAutoId = 4;  // button ids 0..3 follow kAllWorkingModes
}  // namespace

ModePanel::ModePanel(StudioDocument& doc, WorkspaceLayer& layer,
                     const PreviewController& preview, QWidget* parent)
    : QWidget(parent), doc_(doc), layer_(layer), preview_(preview) {
  auto* layout = new QVBoxLayout(this);
  auto* modeBox = new QGroupBox(tr("Working mode"), this);
  auto* modeLayout = new QVBoxLayout(modeBox);
  auto* buttons = new QHBoxLayout;
  modes_ = new QButtonGroup(this);
  const auto addButton = [&](const QString& text, const QString& tip, int id) {
    auto* b = new QToolButton(modeBox);
    b->setText(text);
    b->setToolTip(tip);
    b->setCheckable(true);
    b->setMinimumWidth(40);
    b->setObjectName(QStringLiteral("mode_%1").arg(id));
    modes_->addButton(b, id);
    buttons->addWidget(b);
  };
  addButton(tr("Auto"), tr("Let the planner pick the feasible mode with the largest margin"),
            kAutoId);
  for (std::size_t i = 0; i < kAllWorkingModes.size(); ++i) {
    const QString name = QString::fromLatin1(toString(kAllWorkingModes[i]).data(), 2);
    addButton(name, tr("Elbows %1 (arm 1 %2, arm 2 %3)")
                        .arg(name, name.at(0) == '+' ? tr("out") : tr("in"),
                             name.at(1) == '+' ? tr("out") : tr("in")),
              static_cast<int>(i));
  }
  modeLayout->addLayout(buttons);
  resolved_ = new QLabel(modeBox);
  resolved_->setWordWrap(true);
  modeLayout->addWidget(resolved_);
  layout->addWidget(modeBox);

  auto* overlayBox = new QGroupBox(tr("Overlays"), this);
  auto* form = new QFormLayout(overlayBox);
  region_ = new QCheckBox(tr("Reachable and singularity-free regions"), overlayBox);
  typeII_ = new QCheckBox(tr("Type II singularity curves"), overlayBox);
  rectangleBox_ = new QCheckBox(tr("Largest singularity-free rectangle"), overlayBox);
  legendBox_ = new QCheckBox(tr("Workspace legend"), overlayBox);
  map_ = new QComboBox(overlayBox);
  map_->addItem(tr("None"), static_cast<int>(paint::MapKind::None));
  map_->addItem(tr("Transmission angle"), static_cast<int>(paint::MapKind::Transmission));
  map_->addItem(tr("Conditioning"), static_cast<int>(paint::MapKind::Conditioning));
  map_->addItem(tr("Resolution (mm per step)"), static_cast<int>(paint::MapKind::Resolution));
  form->addRow(region_);
  form->addRow(typeII_);
  form->addRow(rectangleBox_);
  form->addRow(legendBox_);
  form->addRow(tr("Map:"), map_);
  layout->addWidget(overlayBox);
  layout->addStretch(1);

  connect(modes_, &QButtonGroup::idClicked, this, [this](int id) {
    doc_.setModeSelection(id == kAutoId ? ModeSelection{}
                                        : ModeSelection{kAllWorkingModes[static_cast<std::size_t>(id)]});
  });
  const auto pushOverlays = [this] {
    WorkspaceOverlays o = layer_.overlays();
    o.regions = region_->isChecked();
    o.typeII = typeII_->isChecked();
    o.rectangle = rectangleBox_->isChecked();
    o.legend = legendBox_->isChecked();
    o.map = static_cast<paint::MapKind>(map_->currentData().toInt());
    layer_.setOverlays(o);
  };
  for (QCheckBox* box : {region_, typeII_, rectangleBox_, legendBox_}) {
    connect(box, &QCheckBox::toggled, this, pushOverlays);
  }
  connect(map_, &QComboBox::currentIndexChanged, this, pushOverlays);
  connect(&doc_, &StudioDocument::modeSelectionChanged, this, &ModePanel::showDocument);
  connect(&doc_, &StudioDocument::effectiveModeChanged, this, &ModePanel::showDocument);
  connect(&preview_, &PreviewController::resultChanged, this, &ModePanel::showDocument);
  connect(&layer_, &WorkspaceLayer::changed, this, &ModePanel::showOverlays);
  showDocument();
  showOverlays();
}

void ModePanel::showDocument() {
  const ModeSelection choice = doc_.modeSelection();
  const int id = choice ? static_cast<int>(*choice) : kAutoId;
  if (QAbstractButton* b = modes_->button(id)) b->setChecked(true);
  const QString mode = QString::fromLatin1(toString(doc_.effectiveMode()).data(), 2);
  const PreviewResult& r = preview_.result();
  QString text;
  if (!choice) {
    text = r.mode ? tr("Auto picked %1.").arg(mode)
                  : tr("Auto: no mode draws the whole job; showing %1.").arg(mode);
  } else {
    text = tr("Showing the workspace of %1.").arg(mode);
  }
  if (r.mode && r.status != PreviewStatus::Empty) {
    text += QLatin1Char(' ') +
            tr("Smallest singularity margin: %1 deg.").arg(QLocale().toString(degFromRad(r.minMarginRad), 'f', 1));
  }
  resolved_->setText(text);
}

void ModePanel::showOverlays() {
  const WorkspaceOverlays& o = layer_.overlays();
  const QSignalBlocker b1(region_), b2(typeII_), b3(rectangleBox_), b4(legendBox_), b5(map_);
  region_->setChecked(o.regions);
  typeII_->setChecked(o.typeII);
  rectangleBox_->setChecked(o.rectangle);
  legendBox_->setChecked(o.legend);
  map_->setCurrentIndex(map_->findData(static_cast<int>(o.map)));
}

}  // namespace fivebar::widgets
