// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/console_panel.hpp"

#include <QCheckBox>
#include <QFontDatabase>
#include <QLabel>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "paint/studio_palette.hpp"

namespace fivebar::widgets {
namespace {

QColor colourOf(session::ConsoleKind kind) {
  switch (kind) {
    case session::ConsoleKind::Sent: return paint::palette::drawing();
    case session::ConsoleKind::Received: return QColor(0x1f, 0x29, 0x37);
    case session::ConsoleKind::Info: return paint::palette::gridLabel();
    case session::ConsoleKind::Problem: return paint::palette::problem();
  }
  return Qt::black;
}

// The log asks for four lines only: the dock gives it the rest. (A plain text edit asks for
// 192 px, and the docks' scroll area gives a panel with wrapping labels its asked-for height, so
// a refusal shown under the log would push the input line out of the dock.)
class ConsoleLog : public QPlainTextEdit {
 public:
  using QPlainTextEdit::QPlainTextEdit;
  QSize sizeHint() const override {
    return {QPlainTextEdit::sizeHint().width(), 4 * fontMetrics().lineSpacing() + 2 * frameWidth()};
  }
};

}  // namespace

ConsolePanel::ConsolePanel(session::ConsolePort& port, QWidget* parent)
    : QWidget(parent), port_(port) {
  setObjectName(QStringLiteral("consolePanel"));
  log_ = new ConsoleLog(this);
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(kMaxLogLines);
  log_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  log_->setPlaceholderText(tr("Lines sent to and received from the machine appear here."));
  // The log gives way (down to two lines) so that a refusal shown under it never pushes the
  // input line out of the dock.
  log_->setMinimumHeight(2 * log_->fontMetrics().lineSpacing() + 2 * log_->frameWidth());
  input_ = new QLineEdit(this);
  input_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  // X and Y are motor angles: no example move, since what is safe depends on the machine.
  input_->setPlaceholderText(tr("G-code or $ command, e.g. $$ or $I; moves are checked first"));
  input_->installEventFilter(this);
  send_ = new QPushButton(tr("Send"), this);

  unchecked_ = new QCheckBox(tr("Send unchecked (expert)"), this);
  unchecked_->setObjectName(QStringLiteral("consoleUnchecked"));
  unchecked_->setToolTip(tr("Send lines without the motion check. X and Y are motor angles in "
                            "degrees: a wrong number swings an arm across the base."));
  uncheckedBanner_ = new QLabel(
      tr("Unchecked console: lines go to the machine as typed, without the motion check. A wrong "
         "X or Y (motor angles in degrees) can drive the arms into each other or the base."),
      this);
  uncheckedBanner_->setObjectName(QStringLiteral("consoleUncheckedBanner"));
  uncheckedBanner_->setWordWrap(true);
  uncheckedBanner_->setStyleSheet(QStringLiteral(
      "background: #fee2e2; color: #991b1b; border: 1px solid #dc2626; border-radius: 4px; padding: 4px;"));
  uncheckedBanner_->hide();
  refusal_ = new QLabel(this);
  refusal_->setObjectName(QStringLiteral("consoleRefusal"));
  refusal_->setWordWrap(true);
  refusal_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  refusal_->setStyleSheet(QStringLiteral("color: #b91c1c"));
  refusal_->hide();

  auto* row = new QHBoxLayout;
  row->addWidget(input_, 1);
  row->addWidget(send_);
  row->addWidget(unchecked_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(uncheckedBanner_);
  layout->addWidget(log_, 1);
  layout->addWidget(refusal_);
  layout->addLayout(row);
  connect(unchecked_, &QCheckBox::toggled, &port_, &session::ConsolePort::setUncheckedConsole);
  connect(&port_, &session::ConsolePort::uncheckedConsoleChanged, this, [this](bool on) {
    unchecked_->setChecked(on);
    uncheckedBanner_->setVisible(on);
  });

  connect(input_, &QLineEdit::returnPressed, this, &ConsolePanel::submit);
  connect(send_, &QPushButton::clicked, this, &ConsolePanel::submit);
  connect(&port_, &session::ConsolePort::consoleLine, this, &ConsolePanel::appendLine);
  connect(&port_, &session::ConsolePort::canSendChanged, this, &ConsolePanel::updateEnabled);
  updateEnabled();
}

void ConsolePanel::appendLine(const QString& text, session::ConsoleKind kind) {
  const QString prefix = kind == session::ConsoleKind::Sent ? QStringLiteral("&gt; ") : QString();
  log_->appendHtml(QStringLiteral("<span style=\"color:%1\">%2%3</span>")
                       .arg(colourOf(kind).name(), prefix, text.toHtmlEscaped()));
}

void ConsolePanel::submit() {
  const QString line = input_->text().trimmed();
  if (line.isEmpty()) return;
  if (history_.isEmpty() || history_.back() != line) history_.append(line);
  while (history_.size() > kMaxHistory) history_.removeFirst();
  historyPos_ = int(history_.size());
  draft_.clear();
  QString refusal;
  if (port_.sendLine(line, &refusal)) {
    input_->clear();
    refusal_->hide();
  } else {
    // Kept in the field, so it can be corrected.
    refusal_->setText(tr("Not sent: %1").arg(refusal));
    refusal_->setVisible(!refusal.isEmpty());
  }
}

bool ConsolePanel::eventFilter(QObject* watched, QEvent* event) {
  if (watched == input_ && event->type() == QEvent::KeyPress) {
    const int key = static_cast<QKeyEvent*>(event)->key();
    if (key == Qt::Key_Up) {
      showHistory(-1);
      return true;
    }
    if (key == Qt::Key_Down) {
      showHistory(+1);
      return true;
    }
  }
  return QWidget::eventFilter(watched, event);
}

void ConsolePanel::showHistory(int step) {
  if (history_.isEmpty()) return;
  if (historyPos_ == int(history_.size())) draft_ = input_->text();
  historyPos_ = std::clamp(historyPos_ + step, 0, int(history_.size()));
  input_->setText(historyPos_ == int(history_.size()) ? draft_ : history_[historyPos_]);
}

void ConsolePanel::updateEnabled() {
  const bool usable = port_.canSend();
  input_->setEnabled(usable);
  send_->setEnabled(usable);
}

}  // namespace fivebar::widgets
