// SPDX-License-Identifier: GPL-3.0-or-later
// The machine console: the lines sent to and received from the board (status reports left out,
// and the job's thousands of "ok"s while a job streams), and an input line with a history
// walked with the up and down arrow keys. Everything goes through the session's ConsolePort
// (session/console_port.hpp: the panel sees only that), and MachineSession runs
// every line through the motion check (a refused line is not sent; the panel shows why) unless
// the expert switch "send unchecked" is on (a red banner says so while it is).
#pragma once

#include <QStringList>
#include <QWidget>

#include "session/console_port.hpp"

class QCheckBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;

namespace fivebar::widgets {

class ConsolePanel : public QWidget {
  Q_OBJECT
 public:
  static constexpr int kMaxLogLines = 2000;
  static constexpr int kMaxHistory = 100;

  explicit ConsolePanel(session::ConsolePort& port, QWidget* parent = nullptr);

  QLineEdit* input() const { return input_; }
  // "Send unchecked (expert)": off by default; a warning banner shows while it is on.
  QCheckBox* uncheckedSwitch() const { return unchecked_; }
  QLabel* uncheckedBanner() const { return uncheckedBanner_; }
  // Why the last line was refused (hidden when the last line was sent).
  QLabel* refusalLabel() const { return refusal_; }
  QPlainTextEdit* log() const { return log_; }
  const QStringList& history() const { return history_; }

 public slots:
  void appendLine(const QString& text, fivebar::session::ConsoleKind kind);
  void submit();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void showHistory(int step);
  void updateEnabled();

  session::ConsolePort& port_;
  QPlainTextEdit* log_ = nullptr;
  QLineEdit* input_ = nullptr;
  QPushButton* send_ = nullptr;
  QCheckBox* unchecked_ = nullptr;
  QLabel* uncheckedBanner_ = nullptr;
  QLabel* refusal_ = nullptr;
  QStringList history_;
  int historyPos_ = 0;  // == history_.size() when editing a new line
  QString draft_;       // the new line being typed, kept while browsing the history
};

}  // namespace fivebar::widgets
