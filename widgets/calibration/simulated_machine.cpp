// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/calibration/simulated_machine.hpp"

#include <QAction>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QMenu>
#include <QMouseEvent>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QVBoxLayout>
#include <array>
#include <cmath>

#include "core/kinematics/units.hpp"
#include "widgets/calibration/sim_trace_layer.hpp"
#include "widgets/calibration/wizard_pages.hpp"
#include "widgets/canvas/canvas_view.hpp"
#include "session/machine_session.hpp"

namespace fivebar::widgets::calibration {

namespace {
const QString kGroup = QStringLiteral("simulatedMachine");
const char* const kKeys[TrueMachineForm::kFields] = {"da1Mm", "db1Mm", "da2Mm", "db2Mm", "dwMm",
                                                     "zeroOffsetDeg1", "zeroOffsetDeg2",
                                                     "backlashDeg1", "backlashDeg2"};

std::array<double, TrueMachineForm::kFields> valuesOf(const TrueMachine& t) {
  return {t.da1Mm, t.db1Mm, t.da2Mm, t.db2Mm, t.dwMm, degFromRad(t.zeroOffsetRad1),
          degFromRad(t.zeroOffsetRad2), degFromRad(t.play.motor1Rad), degFromRad(t.play.motor2Rad)};
}

TrueMachine fromValues(const std::array<double, TrueMachineForm::kFields>& v) {
  TrueMachine t;
  t.da1Mm = v[0], t.db1Mm = v[1], t.da2Mm = v[2], t.db2Mm = v[3], t.dwMm = v[4];
  t.zeroOffsetRad1 = radFromDeg(v[5]);
  t.zeroOffsetRad2 = radFromDeg(v[6]);
  t.play.motor1Rad = radFromDeg(v[7]);
  t.play.motor2Rad = radFromDeg(v[8]);
  return t;
}
}  // namespace

// ---------------------------------------------------------------------------------------------
SimulatedTruth::SimulatedTruth(const StudioDocument& doc, session::MachineSession& session)
    : QObject(&session), doc_(doc), session_(session) {
  setObjectName(QStringLiteral("simulatedTruth"));
  truth_.builtFrom = doc.profile().geometry;
  baseName_ = doc.profile().name;
  connect(&doc_, &StudioDocument::profileChanged, this, &SimulatedTruth::onProfileChanged);
}

std::unique_ptr<QSettings> SimulatedTruth::settings() const {
  if (settingsFile_.isEmpty()) return std::make_unique<QSettings>();
  return std::make_unique<QSettings>(settingsFile_, QSettings::IniFormat);
}

void SimulatedTruth::setTruth(TrueMachine truth, bool persist) {
  truth.builtFrom = truth_.builtFrom;
  truth_ = truth;
  if (persist) {
    auto s = settings();
    s->beginGroup(kGroup);
    const auto v = valuesOf(truth_);
    for (int i = 0; i < TrueMachineForm::kFields; ++i) s->setValue(QLatin1String(kKeys[i]), v[i]);
    const Geometry& g = truth_.builtFrom;
    s->setValue(QStringLiteral("builtFrom"), QVariantList{g.a1, g.b1, g.a2, g.b2, g.w});
    s->setValue(QStringLiteral("profile"), QString::fromStdString(baseName_));
    s->endGroup();
  }
  apply();
  emit changed();
}

TrueMachine SimulatedTruth::saved() const {
  auto s = settings();
  s->beginGroup(kGroup);
  std::array<double, TrueMachineForm::kFields> v{};
  for (int i = 0; i < TrueMachineForm::kFields; ++i) {
    bool ok = false;
    const double x = s->value(QLatin1String(kKeys[i]), 0.0).toDouble(&ok);
    v[static_cast<std::size_t>(i)] = ok && std::isfinite(x) ? x : 0.0;
  }
  TrueMachine t = fromValues(v);
  t.builtFrom = truth_.builtFrom;
  // The amounts were measured from the profile of that name: keep its geometry, so the real
  // machine stays the same when the profile was calibrated since.
  const QVariantList g = s->value(QStringLiteral("builtFrom")).toList();
  if (s->value(QStringLiteral("profile")).toString().toStdString() == doc_.profile().name && g.size() == 5)
    t.builtFrom = Geometry{g[0].toDouble(), g[1].toDouble(), g[2].toDouble(), g[3].toDouble(), g[4].toDouble()};
  return t;
}

void SimulatedTruth::load() {
  const TrueMachine t = saved();
  truth_.builtFrom = t.builtFrom;
  setTruth(t, false);
}

void SimulatedTruth::apply() {
  session_.setSimulatedTrueMachine(active() ? std::optional<MachineProfile>(trueMachineProfile(doc_.profile(), truth_))
                                            : std::nullopt);
}

void SimulatedTruth::onProfileChanged() {
  // Another machine: the amounts now apply to its geometry. The same machine recalibrated: the
  // real machine is unchanged.
  if (doc_.profile().name != baseName_) {
    baseName_ = doc_.profile().name;
    truth_.builtFrom = doc_.profile().geometry;
  }
  apply();
  emit changed();
}

QString SimulatedTruth::describe() const {
  if (!active()) return QString();
  QStringList parts;
  const auto v = valuesOf(truth_);
  const QString names[] = {QStringLiteral("a1"), QStringLiteral("b1"), QStringLiteral("a2"), QStringLiteral("b2"),
                           QStringLiteral("w")};
  for (int i = 0; i < 5; ++i)
    if (v[static_cast<std::size_t>(i)] != 0.0) parts << tr("%1 %2 mm").arg(names[i]).arg(v[static_cast<std::size_t>(i)], 0, 'f', 2);
  for (int k = 0; k < 2; ++k)
    if (v[static_cast<std::size_t>(5 + k)] != 0.0)
      parts << tr("motor %1 zero %2\u00b0").arg(k + 1).arg(v[static_cast<std::size_t>(5 + k)], 0, 'f', 2);
  for (int k = 0; k < 2; ++k)
    if (v[static_cast<std::size_t>(7 + k)] != 0.0)
      parts << tr("motor %1 backlash %2\u00b0").arg(k + 1).arg(v[static_cast<std::size_t>(7 + k)], 0, 'f', 2);
  return parts.join(QStringLiteral(", "));
}

// ---------------------------------------------------------------------------------------------
TrueMachineForm::TrueMachineForm(QWidget* parent) : QWidget(parent) {
  auto* grid = new QGridLayout(this);
  grid->setContentsMargins(0, 0, 0, 0);
  struct F { QString label; double range; QString suffix; QString tip; };
  const QString mmTip = tr("How much longer the real part is than the profile says (negative: shorter).");
  const F fields[kFields] = {
      {tr("a1 longer by"), 5.0, tr(" mm"), mmTip}, {tr("b1 longer by"), 5.0, tr(" mm"), mmTip},
      {tr("a2 longer by"), 5.0, tr(" mm"), mmTip}, {tr("b2 longer by"), 5.0, tr(" mm"), mmTip},
      {tr("motors farther apart by"), 5.0, tr(" mm"), tr("How much farther apart the real motor axes are.")},
      {tr("motor 1 zero off by"), 5.0, tr(" \u00b0"), tr("The real arm angle is the commanded one plus this.")},
      {tr("motor 2 zero off by"), 5.0, tr(" \u00b0"), tr("The real arm angle is the commanded one plus this.")},
      {tr("motor 1 backlash"), 2.0, tr(" \u00b0"), tr("Play in the drive: the arm lags this much when the motor reverses.")},
      {tr("motor 2 backlash"), 2.0, tr(" \u00b0"), tr("Play in the drive: the arm lags this much when the motor reverses.")}};
  for (int i = 0; i < kFields; ++i) {
    auto* spin = new QDoubleSpinBox(this);
    spin->setObjectName(QStringLiteral("trueMachineField%1").arg(i));
    spin->setDecimals(2);
    spin->setSingleStep(0.1);
    spin->setRange(i >= 7 ? 0.0 : -fields[i].range, fields[i].range);
    spin->setSuffix(fields[i].suffix);
    spin->setToolTip(fields[i].tip);
    auto* label = new QLabel(fields[i].label, this);
    label->setBuddy(spin);
    const int row = i % 5, col = (i / 5) * 2;
    grid->addWidget(label, row, col);
    grid->addWidget(spin, row, col + 1);
    fields_.push_back(spin);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this] {
      if (!setting_) emit edited();
    });
  }
}

TrueMachine TrueMachineForm::amounts() const {
  std::array<double, kFields> v{};
  for (int i = 0; i < kFields; ++i) v[static_cast<std::size_t>(i)] = fields_[static_cast<std::size_t>(i)]->value();
  return fromValues(v);
}

void TrueMachineForm::setAmounts(const TrueMachine& truth) {
  setting_ = true;
  const auto v = valuesOf(truth);
  for (int i = 0; i < kFields; ++i) fields_[static_cast<std::size_t>(i)]->setValue(v[static_cast<std::size_t>(i)]);
  setting_ = false;
}

TrueMachine TrueMachineForm::example() {
  return fromValues({0.4, -0.3, 0.5, 0.2, -0.4, 1.0, -0.8, 0.3, 0.2});
}

// ---------------------------------------------------------------------------------------------
SimulatedMachineDialog::SimulatedMachineDialog(SimulatedTruth& truth, QWidget* parent)
    : QDialog(parent), truth_(truth) {
  setObjectName(QStringLiteral("simulatedMachineDialog"));
  setWindowTitle(tr("Simulated machine"));
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(explanation(
      tr("The built-in simulated machine can be built <b>imperfectly</b>, as a real one is: its links "
         "a little longer or shorter than the profile says, its motor zeros off, play in its drives. "
         "It then draws what such a machine really draws (shown on the canvas beside the plan), so "
         "you can try calibration (Machine &gt; Calibrate...) without hardware.<br><br>"
         "The amounts apply at once, also to a simulated machine that is connected, and are kept "
         "until you change them here. The status bar says so while the machine is imperfect."),
      this));
  form_ = new TrueMachineForm(this);
  form_->setAmounts(truth_.truth());
  layout->addWidget(form_);
  auto* buttons = new QDialogButtonBox(this);
  buttons->addButton(tr("OK"), QDialogButtonBox::AcceptRole)->setDefault(true);
  buttons->addButton(tr("Cancel"), QDialogButtonBox::RejectRole);
  QPushButton* perfect = buttons->addButton(tr("Perfect machine"), QDialogButtonBox::ResetRole);
  perfect->setObjectName(QStringLiteral("perfectMachine"));
  perfect->setToolTip(tr("All amounts zero: the simulated machine is exactly the profile"));
  QPushButton* example = buttons->addButton(tr("Example"), QDialogButtonBox::ResetRole);
  example->setToolTip(tr("A typical home-built machine: links off by up to 0.5 mm, zeros by about 1\u00b0, some play"));
  layout->addWidget(buttons);
  connect(perfect, &QPushButton::clicked, this, [this] { form_->setAmounts(TrueMachine{}); });
  connect(example, &QPushButton::clicked, this, [this] { form_->setAmounts(TrueMachineForm::example()); });
  connect(buttons, &QDialogButtonBox::accepted, this, [this] {
    applyForm();
    accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(this, &QDialog::finished, this, [this] { form_->setAmounts(truth_.truth()); });
}

void SimulatedMachineDialog::applyForm() { truth_.setTruth(form_->amounts(), true); }

// ---------------------------------------------------------------------------------------------
SimulatedTruthBadge::SimulatedTruthBadge(SimulatedTruth& truth, QWidget* parent)
    : QLabel(parent), truth_(truth) {
  setObjectName(QStringLiteral("simulatedTruthBadge"));
  setStyleSheet(QStringLiteral("QLabel { background: #ffedd5; color: #9a3412; border: 1px solid #fb923c;"
                               " border-radius: 3px; padding: 0 6px; }"));
  setCursor(Qt::PointingHandCursor);
  connect(&truth_, &SimulatedTruth::changed, this, &SimulatedTruthBadge::refresh);
  refresh();
}

void SimulatedTruthBadge::refresh() {
  setVisible(truth_.active());
  setText(tr("Simulated machine: imperfect"));
  setToolTip(tr("The built-in simulated machine differs from the profile: %1. "
                "Click to change it (Machine > Simulated machine...).")
                 .arg(truth_.describe()));
}

void SimulatedTruthBadge::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) emit clicked();
  QLabel::mousePressEvent(event);
}

// ---------------------------------------------------------------------------------------------
void installSimulatedMachine(SimulatedTruth& truth, session::MachineSession& session, CanvasView& canvas,
                             QMenu& menu, QStatusBar& statusBar, QWidget* window) {
  truth.load();
  auto* dialog = new SimulatedMachineDialog(truth, window);
  QAction* action = menu.addAction(SimulatedMachineDialog::tr("Simulated &machine..."));
  action->setObjectName(QStringLiteral("simulatedMachineAction"));
  action->setStatusTip(SimulatedMachineDialog::tr("Build the simulated machine imperfectly, to try calibration without hardware"));
  QObject::connect(action, &QAction::triggered, dialog, [dialog] {
    dialog->show();
    dialog->raise();
  });
  auto* badge = new SimulatedTruthBadge(truth, &statusBar);
  statusBar.addPermanentWidget(badge);
  QObject::connect(badge, &SimulatedTruthBadge::clicked, dialog, [dialog] {
    dialog->show();
    dialog->raise();
  });
  auto* layer = new SimTraceLayer(session, truth, window);
  canvas.addLayer(layer);
  QObject::connect(layer, &SimTraceLayer::changed, &canvas, qOverload<>(&QWidget::update));
}

}  // namespace fivebar::widgets::calibration
