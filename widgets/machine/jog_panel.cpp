// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/jog_panel.hpp"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>

#include "widgets/machine/machine_dialogs.hpp"

#include <QButtonGroup>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

#include "widgets/canvas/canvas_view.hpp"

namespace fivebar::widgets {
namespace {

constexpr double kSteps[] = {0.1, 1.0, 10.0};
constexpr double kDefaultSpeedMmPerS = 20.0;

std::optional<session::JogDirection> directionOfKey(int key) {
  switch (key) {
    case Qt::Key_Left: return session::JogDirection::cartesian(-1, 0);
    case Qt::Key_Right: return session::JogDirection::cartesian(1, 0);
    case Qt::Key_Up: return session::JogDirection::cartesian(0, 1);
    case Qt::Key_Down: return session::JogDirection::cartesian(0, -1);
    default: return std::nullopt;
  }
}

}  // namespace

JogPanel::JogPanel(session::MachineView& view, session::JogPort& jog, session::RecoveryPort& recovery,
                   session::JogController& controller, QWidget* parent)
    : QWidget(parent), view_(view), jog_(jog), recovery_(recovery), controller_(controller), goTo_(view, jog) {
  setObjectName(QStringLiteral("jogPanel"));
  auto* grid = makeArrows();
  auto* motorRow = makeMotorRow();
  auto* stepRow = makeStepRow();
  auto* toolRow = makeToolRow();
  makeConfirmRow();
  message_ = new QLabel(this);
  message_->setWordWrap(true);
  message_->setStyleSheet(QStringLiteral("color: #b45309"));

  // The go-to question and the messages come first, where they are seen without scrolling.
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 6, 8, 6);
  layout->addLayout(stepRow);
  // Rows close together: with the Frame button the panel is otherwise taller than its dock. The
  // speed on a row of its own: beside the steps it is cut off in a side dock's width.
  layout->setSpacing(2);
  auto* speedRow = new QHBoxLayout;
  speedRow->addWidget(new QLabel(tr("Speed"), this));
  speedRow->addWidget(speed_);
  speedRow->addStretch(1);
  layout->addLayout(speedRow);
  layout->addWidget(confirmRow_);
  layout->addWidget(message_);
  layout->addLayout(grid);
  layout->addLayout(motorRow);
  layout->addLayout(toolRow);
  layout->addWidget(frame_);
  layout->addStretch(1);

  connectControls();
}

// The XY arrows around the Go to... button (row 0 is +Y: the machine frame's y points toward the
// work area, up on screen).
QGridLayout* JogPanel::makeArrows() {
  const QString arrowText[3][3] = {{QStringLiteral("↖"), QStringLiteral("↑"), QStringLiteral("↗")},
                                   {QStringLiteral("←"), QString(), QStringLiteral("→")},
                                   {QStringLiteral("↙"), QStringLiteral("↓"), QStringLiteral("↘")}};
  auto* grid = new QGridLayout;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      if (row == 1 && col == 1) continue;
      const int dx = col - 1, dy = 1 - row;
      const QString tip = tr("Jog the pen %1 mm in X, %2 mm in Y per step; hold for a continuous jog")
                              .arg(dx).arg(dy);
      arrows_[row][col] = makeJogButton(arrowText[row][col], tip, session::JogDirection::cartesian(dx, dy));
      grid->addWidget(arrows_[row][col], row, col);
    }
  }
  goToButton_ = new QPushButton(tr("Go to…"), this);
  goToButton_->setCheckable(true);
  goToButton_->setToolTip(tr("Click the canvas to choose where the pen goes; the path is shown "
                             "before you confirm."));
  grid->addWidget(goToButton_, 1, 1);

  return grid;
}

// theta1 -/+ and theta2 -/+ single steps.
QHBoxLayout* JogPanel::makeMotorRow() {
  auto* motorRow = new QHBoxLayout;
  for (int motor = 1; motor <= 2; ++motor) {
    for (int s = 0; s < 2; ++s) {
      const int sign = s == 0 ? -1 : 1;
      const QString text = QStringLiteral("θ%1 %2").arg(motor).arg(sign < 0 ? QStringLiteral("−") : QStringLiteral("+"));
      const QString tip = sign < 0 ? tr("Turn motor %1 clockwise by one step").arg(motor)
                                   : tr("Turn motor %1 counter-clockwise by one step").arg(motor);
      motors_[motor - 1][s] = makeJogButton(text, tip, session::JogDirection::motorJog(motor, sign));
      motorRow->addWidget(motors_[motor - 1][s]);
    }
  }
  return motorRow;
}

// The step size (mm or degrees) and the XY jog speed.
QHBoxLayout* JogPanel::makeStepRow() {
  steps_ = new QButtonGroup(this);
  auto* stepRow = new QHBoxLayout;
  stepRow->addWidget(new QLabel(tr("Step"), this));
  for (int i = 0; i < 3; ++i) {
    auto* b = new QRadioButton(QLocale().toString(kSteps[i]), this);
    steps_->addButton(b, i);
    stepRow->addWidget(b);
    moveWidgets_.push_back(b);
  }
  stepRow->addWidget(new QLabel(tr("mm / °"), this));
  stepRow->addStretch(1);
  steps_->button(1)->setChecked(true);
  speed_ = new QDoubleSpinBox(this);
  speed_->setRange(1.0, 200.0);
  speed_->setDecimals(0);
  speed_->setSuffix(tr(" mm/s"));
  speed_->setValue(kDefaultSpeedMmPerS);
  speed_->setToolTip(tr("Speed of XY jogs"));
  return stepRow;
}

// Home, Go to home pose, Pen up, Pen down; the Frame button under them.
QHBoxLayout* JogPanel::makeToolRow() {
  home_ = new QPushButton(this);
  goHome_ = new QPushButton(tr("Go to home pose"), this);
  goHome_->setObjectName(QStringLiteral("goHomeButton"));
  goHome_->setToolTip(tr("Move the pen up to the profile's home pose by a checked move "
                         "(the reference must be set)"));
  penUp_ = new QPushButton(tr("Pen up"), this);
  penUp_->setToolTip(tr("Lift the pen (Page Up on the canvas)"));
  penDown_ = new QPushButton(tr("Pen down"), this);
  penDown_->setToolTip(tr("Lower the pen (Page Down on the canvas)"));
  frame_ = new QPushButton(tr("Frame the job"), this);
  frame_->setObjectName(QStringLiteral("frameButton"));
  frame_->setToolTip(tr("Trace the outline of the planned job with the pen up (a laser at low "
                        "power), along checked moves, to see where the drawing lands on the paper"));
  // Two columns of two: four buttons in one row do not fit a side dock in German or French.
  auto* toolRow = new QHBoxLayout;
  auto* poses = new QVBoxLayout;
  poses->addWidget(home_);
  poses->addWidget(goHome_);
  auto* pen = new QVBoxLayout;
  pen->addWidget(penUp_);
  pen->addWidget(penDown_);
  toolRow->addLayout(poses);
  toolRow->addLayout(pen);
  return toolRow;
}

// The go-to question: where the pen would go, Go / Cancel (hidden until a point is picked).
void JogPanel::makeConfirmRow() {
  confirmRow_ = new QWidget(this);
  confirmText_ = new QLabel(confirmRow_);
  confirmText_->setWordWrap(true);
  confirm_ = new QPushButton(tr("Go"), confirmRow_);
  cancel_ = new QPushButton(tr("Cancel"), confirmRow_);
  auto* confirmLayout = new QGridLayout(confirmRow_);
  confirmLayout->setContentsMargins(0, 0, 0, 0);
  confirmLayout->addWidget(confirmText_, 0, 0, 1, 2);
  confirmLayout->addWidget(confirm_, 1, 0);
  confirmLayout->addWidget(cancel_, 1, 1);
  confirmRow_->hide();
}

void JogPanel::connectControls() {
  moveWidgets_.insert(moveWidgets_.end(), {goToButton_, home_, goHome_, penUp_, penDown_, speed_});
  connect(steps_, &QButtonGroup::idClicked, this, [this](int id) { controller_.setStep(kSteps[id]); });
  controller_.setStep(kSteps[1]);
  connect(speed_, &QDoubleSpinBox::valueChanged, this, [this](double v) { controller_.setSpeedMmPerS(v); });
  controller_.setSpeedMmPerS(kDefaultSpeedMmPerS);
  connect(home_, &QPushButton::clicked, this, [this] { requestHome(this, view_.profile(), recovery_); });
  connect(goHome_, &QPushButton::clicked, this, [this] {
    QString why;
    if (!jog_.goToHomePose(&why)) message_->setText(why);
  });
  connect(frame_, &QPushButton::clicked, this, [this] {
    QString why;
    message_->setText(jog_.frameJob(&why) ? tr("Tracing the job's outline with the pen up.") : why);
  });
  connect(penUp_, &QPushButton::clicked, this, [this] { jog_.penUp(); });
  connect(penDown_, &QPushButton::clicked, this, [this] { jog_.penDown(); });
  connect(goToButton_, &QPushButton::toggled, this, &JogPanel::setGoToActive);
  connect(confirm_, &QPushButton::clicked, &goTo_, &GoToTool::confirm);
  connect(cancel_, &QPushButton::clicked, &goTo_, &GoToTool::cancel);
  connect(&goTo_, &GoToTool::picked, this, &JogPanel::onPicked);
  connect(&goTo_, &GoToTool::cleared, confirmRow_, &QWidget::hide);
  connect(&goTo_, &GoToTool::moveSent, goToButton_, [this] { goToButton_->setChecked(false); });
  connect(&goTo_, &GoToTool::repaintNeeded, this, [this] {
    if (canvas_) canvas_->update();
  });
  connect(&controller_, &session::JogController::message, message_, &QLabel::setText);
  connect(&view_, &session::MachineView::connectionChanged, this, &JogPanel::refreshEnabled);
  connect(&view_, &session::MachineView::statusUpdated, this, &JogPanel::refreshEnabled);
  connect(&view_, &session::MachineView::jobActiveChanged, this, &JogPanel::refreshEnabled);
  connect(&view_, &session::MachineView::poseKnownChanged, this, &JogPanel::refreshEnabled);
  connect(&view_, &session::MachineView::plannedJobChanged, this, &JogPanel::refreshEnabled);
  refreshEnabled();
}

QPushButton* JogPanel::makeJogButton(const QString& text, const QString& tip, const session::JogDirection& dir) {
  auto* b = new QPushButton(text, this);
  b->setToolTip(tip);
  b->setMinimumSize(40, 32);
  b->setAutoRepeat(false);
  connect(b, &QPushButton::pressed, this, [this, dir] { controller_.press(dir); });
  connect(b, &QPushButton::released, this, [this] { controller_.release(); });
  moveWidgets_.push_back(b);
  return b;
}

QPushButton* JogPanel::arrowButton(int dx, int dy) const { return arrows_[1 - dy][dx + 1]; }

QPushButton* JogPanel::motorButton(int motor, int sign) const {
  return motors_[motor - 1][sign < 0 ? 0 : 1];
}

void JogPanel::attachCanvas(CanvasView* canvas) {
  canvas_ = canvas;
  canvas_->installEventFilter(this);
  // The arrow keys jog wherever the focus is in the studio's window, unless a field that edits
  // text or a value has it (those keep their arrows).
  if (!keysEverywhere_) {
    qApp->installEventFilter(this);
    keysEverywhere_ = true;
  }
}

JogPanel::~JogPanel() {
  if (keysEverywhere_) qApp->removeEventFilter(this);
}

// True for widgets whose own arrow keys matter: text fields, spin boxes, combo boxes, sliders.
static bool keepsItsArrows(const QObject* o) {
  return qobject_cast<const QLineEdit*>(o) || qobject_cast<const QAbstractSpinBox*>(o) ||
         qobject_cast<const QTextEdit*>(o) || qobject_cast<const QPlainTextEdit*>(o) ||
         qobject_cast<const QComboBox*>(o) || qobject_cast<const QAbstractSlider*>(o);
}

bool JogPanel::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() != QEvent::KeyPress && event->type() != QEvent::KeyRelease)
    return QWidget::eventFilter(watched, event);
  auto* widget = qobject_cast<QWidget*>(watched);
  if (widget == nullptr) return false;
  const bool onCanvas = watched == canvas_;
  if (!onCanvas) {
    // Keys reach the focus widget first (then its parents): act there, once, in this window.
    QWidget* focus = QApplication::focusWidget();
    const bool here = widget->window() == window() && (widget == focus || (focus == nullptr && widget->isWindow()));
    if (!here || keepsItsArrows(widget)) return false;
  }
  auto* key = static_cast<QKeyEvent*>(event);
  if (!view_.isConnected()) return false;
  const bool press = event->type() == QEvent::KeyPress;
  if (const auto dir = directionOfKey(key->key())) {
    if (!key->isAutoRepeat()) press ? controller_.press(*dir) : controller_.release();
    return true;
  }
  if (!press || key->isAutoRepeat()) return false;
  if (!onCanvas) return false;  // Page Up/Down, Return and Escape stay the canvas's
  switch (key->key()) {
    case Qt::Key_PageUp: jog_.penUp(); return true;
    case Qt::Key_PageDown: jog_.penDown(); return true;
    case Qt::Key_Return:
    case Qt::Key_Enter: return goTo_.confirm();
    case Qt::Key_Escape:
      if (!goTo_.target()) return false;
      goTo_.cancel();
      return true;
    default: return false;
  }
}

void JogPanel::setGoToActive(bool active) {
  if (canvas_ == nullptr) return;
  if (active) {
    if (canvas_->tool() != &goTo_) previousTool_ = canvas_->tool();
    canvas_->setTool(&goTo_);
    canvas_->setFocus();
    message_->setText(tr("Click the canvas where the pen should go."));
  } else {
    goTo_.cancel();
    if (canvas_->tool() == &goTo_) canvas_->setTool(previousTool_);
    message_->clear();
  }
}

void JogPanel::onPicked(bool ok, const QString& text) {
  message_->clear();
  confirmText_->setText(text);
  confirm_->setEnabled(ok);
  confirmRow_->show();
}

void JogPanel::refreshEnabled() {
  const bool usable = view_.isConnected() && !view_.jobActive() &&
                      view_.state() != grbl::MachineState::Alarm;
  for (QWidget* w : moveWidgets_) w->setEnabled(usable);
  frame_->setEnabled(usable && view_.canFrame());
  const bool homing = view_.profile().hasHomingSwitches;
  home_->setText(homing ? tr("Home ($H)") : tr("Set reference pose"));
  home_->setToolTip(homing ? tr("Run the homing cycle")
                           : tr("Declare that the machine now stands at the profile's home pose"));
  if (!usable && goToButton_->isChecked()) goToButton_->setChecked(false);
}

}  // namespace fivebar::widgets
