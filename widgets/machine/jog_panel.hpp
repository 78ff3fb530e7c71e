// SPDX-License-Identifier: GPL-3.0-or-later
// The jog panel: XY arrows and diagonals, per-motor buttons (theta1 +/-, theta2 +/-), step sizes
// (0.1, 1, 10 mm or degrees), a tap jogs one step and holding jogs continuously until release;
// keyboard jogging on the canvas (arrow keys; Page Up / Page Down lift and lower the pen; Enter
// confirms a go-to, Escape cancels it); go-to by clicking the canvas with the path previewed;
// home ($H) or "set reference pose"; pen up and down; Frame: the planned job's outline traced
// pen up, so the maker sees where the drawing lands. All moves are checked (drivers/jog).
#pragma once

#include <QWidget>

class QGridLayout;
class QHBoxLayout;
#include <vector>

#include "session/jog_controller.hpp"
#include "widgets/machine/jog_goto_tool.hpp"

class QAbstractButton;
class QButtonGroup;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace fivebar::widgets {

class CanvasView;

class JogPanel : public QWidget {
  Q_OBJECT
 public:
  // The controller (session::MachineSide::jog()) plans and sends the moves; both must outlive the panel.
  // It sees the session's state (view), sends moves only through the JogPort and the
  // controller, and may set the reference pose or home (recovery).
  JogPanel(session::MachineView& view, session::JogPort& jog, session::RecoveryPort& recovery,
           session::JogController& controller, QWidget* parent = nullptr);
  ~JogPanel() override;

  // The go-to tool on the canvas, and keyboard jogging: arrow keys anywhere in the panel's
  // window (unless a text or value field has the focus), Page Up/Down, Return and Escape on the
  // canvas. The canvas must outlive the panel's use.
  void attachCanvas(CanvasView* canvas);

  session::JogController& controller() { return controller_; }
  GoToTool& goToTool() { return goTo_; }
  // The button for a direction, e.g. arrowButton(1, 0) is "+X", arrowButton(-1, 1) "up-left".
  QPushButton* arrowButton(int dx, int dy) const;
  QPushButton* motorButton(int motor, int sign) const;
  QPushButton* goToButton() const { return goToButton_; }
  QPushButton* homeButton() const { return home_; }
  QPushButton* goHomeButton() const { return goHome_; }
  // Enabled while connected with a known pose, idle and a job planned (MachineView::canFrame).
  QPushButton* frameButton() const { return frame_; }
  QPushButton* confirmButton() const { return confirm_; }
  QLabel* messageLabel() const { return message_; }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  QPushButton* makeJogButton(const QString& text, const QString& tip, const session::JogDirection& dir);
  // The constructor's parts.
  QGridLayout* makeArrows();
  QHBoxLayout* makeMotorRow();
  QHBoxLayout* makeStepRow();
  QHBoxLayout* makeToolRow();
  void makeConfirmRow();
  void connectControls();
  void setGoToActive(bool active);
  void refreshEnabled();
  void onPicked(bool ok, const QString& text);

  session::MachineView& view_;
  session::JogPort& jog_;
  session::RecoveryPort& recovery_;
  session::JogController& controller_;
  GoToTool goTo_;
  CanvasView* canvas_ = nullptr;
  CanvasTool* previousTool_ = nullptr;
  QPushButton* arrows_[3][3] = {};
  QPushButton* motors_[2][2] = {};
  QButtonGroup* steps_ = nullptr;
  QDoubleSpinBox* speed_ = nullptr;
  QPushButton* home_ = nullptr;
  QPushButton* goHome_ = nullptr;
  QPushButton* frame_ = nullptr;
  bool keysEverywhere_ = false;
  QPushButton* penUp_ = nullptr;
  QPushButton* penDown_ = nullptr;
  QPushButton* goToButton_ = nullptr;
  QWidget* confirmRow_ = nullptr;
  QLabel* confirmText_ = nullptr;
  QPushButton* confirm_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QLabel* message_ = nullptr;
  std::vector<QWidget*> moveWidgets_;
};

}  // namespace fivebar::widgets
