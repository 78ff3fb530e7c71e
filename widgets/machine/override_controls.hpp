// SPDX-License-Identifier: GPL-3.0-or-later
// The Run panel's overrides: feed (-10, -1, 100 %, +1, +10 %) and rapid (25, 50, 100 %) during a
// run, with keyboard shortcuts, and the values the board reports (its Ov: field), never the ones
// last clicked. GRBL applies them at once to the moves queued on the board and caps every rate
// at the machine's $110/$111, so an override never drives a motor past its limits. The bytes go
// through the RunController (the session); the ETA beside them follows the reported values.
#pragma once

#include <QWidget>
#include <array>

#include "session/run_controller.hpp"

class QLabel;
class QToolButton;

namespace fivebar::widgets {

class OverrideControls : public QWidget {
  Q_OBJECT
 public:
  explicit OverrideControls(session::RunController& run, QWidget* parent = nullptr);

  // The button sending a command (tests, the screenshot).
  QToolButton* button(grbl::OverrideCommand command) const { return buttons_[std::size_t(command)]; }
  QLabel* feedLabel() const { return feed_; }
  QLabel* rapidLabel() const { return rapid_; }

 public slots:
  // Enables the buttons while a run streams; shows the reported values.
  void refresh();

 private:
  QToolButton* addButton(grbl::OverrideCommand command, const QString& text, const QString& key,
                         const QString& tip);

  session::RunController& run_;
  std::array<QToolButton*, 8> buttons_{};
  QLabel* feed_ = nullptr;
  QLabel* rapid_ = nullptr;
};

}  // namespace fivebar::widgets
