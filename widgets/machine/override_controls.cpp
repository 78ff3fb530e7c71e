// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/override_controls.hpp"

#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QKeySequence>
#include <QLabel>
#include <QToolButton>
#include <QVBoxLayout>

namespace fivebar::widgets {

using grbl::OverrideCommand;

OverrideControls::OverrideControls(session::RunController& run, QWidget* parent) : QWidget(parent), run_(run) {
  setObjectName(QStringLiteral("overrideControls"));
  auto* box = new QGroupBox(tr("Overrides"), this);
  box->setToolTip(tr("The machine scales the job's feed (10 to 200 %) and its rapid moves (25, 50 "
                     "or 100 %) at once. It never exceeds its maximum rates ($110, $111): a higher "
                     "feed override stops speeding up where the motors' limit is."));
  const QString feedTip = tr("Feed override: pen-down and other G1 moves");
  const QString rapidTip = tr("Rapid override: G0 travel moves");
  auto* grid = new QGridLayout;
  grid->setHorizontalSpacing(4);
  auto* feedName = new QLabel(tr("Feed"), box);
  grid->addWidget(addButton(OverrideCommand::FeedMinus10, tr("−10 %"), tr("Alt+Down"), feedTip), 1, 0);
  grid->addWidget(addButton(OverrideCommand::FeedMinus1, tr("−1 %"), tr("Alt+Left"), feedTip), 1, 1);
  grid->addWidget(addButton(OverrideCommand::FeedReset, tr("100 %"), tr("Alt+0"), feedTip), 1, 2);
  grid->addWidget(addButton(OverrideCommand::FeedPlus1, tr("+1 %"), tr("Alt+Right"), feedTip), 1, 3);
  grid->addWidget(addButton(OverrideCommand::FeedPlus10, tr("+10 %"), tr("Alt+Up"), feedTip), 1, 4);
  auto* rapidName = new QLabel(tr("Rapid"), box);
  grid->addWidget(addButton(OverrideCommand::RapidQuarter, tr("25 %"), tr("Alt+4"), rapidTip), 3, 0);
  grid->addWidget(addButton(OverrideCommand::RapidHalf, tr("50 %"), tr("Alt+2"), rapidTip), 3, 1);
  grid->addWidget(addButton(OverrideCommand::RapidFull, tr("100 %"), tr("Alt+1"), rapidTip), 3, 2);
  feed_ = new QLabel(box);
  feed_->setObjectName(QStringLiteral("feedOverride"));
  rapid_ = new QLabel(box);
  rapid_->setObjectName(QStringLiteral("rapidOverride"));
  QFont bold = feed_->font();
  bold.setBold(true);
  feed_->setFont(bold);
  rapid_->setFont(bold);
  feed_->setMinimumWidth(feed_->fontMetrics().horizontalAdvance(QStringLiteral("200 %")));
  // Each name with its reported value on a row of its own above its buttons: beside them the
  // Run panel was wider than its dock (tests/widgets/window_fit_test.cpp).
  const auto named = [](QLabel* name, QLabel* value) {
    auto* row = new QHBoxLayout;
    row->setSpacing(6);
    row->addWidget(name);
    row->addWidget(value);
    row->addStretch(1);
    return row;
  };
  grid->addLayout(named(feedName, feed_), 0, 0, 1, 5);
  grid->addLayout(named(rapidName, rapid_), 2, 0, 1, 5);
  grid->setColumnStretch(5, 1);
  box->setLayout(grid);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(box);
  connect(&run_, &session::RunController::runChanged, this, &OverrideControls::refresh);
  connect(&run_, &session::RunController::progressChanged, this, &OverrideControls::refresh);
  refresh();
}

QToolButton* OverrideControls::addButton(OverrideCommand command, const QString& text, const QString& key,
                                         const QString& tip) {
  auto* b = new QToolButton(this);  // compact: the Run panel shares a narrow dock
  b->setText(text);
  b->setToolButtonStyle(Qt::ToolButtonTextOnly);
  b->setObjectName(QStringLiteral("override%1").arg(int(command)));
  b->setShortcut(QKeySequence(key));  // the window's: works wherever the focus is
  b->setToolTip(QStringLiteral("%1 (%2)").arg(tip, b->shortcut().toString(QKeySequence::NativeText)));
  b->setFocusPolicy(Qt::NoFocus);
  connect(b, &QToolButton::clicked, this, [this, command] { run_.sendOverride(command); });
  buttons_[std::size_t(command)] = b;
  return b;
}

void OverrideControls::refresh() {
  const bool running = run_.running();
  for (QToolButton* b : buttons_) b->setEnabled(running);
  // What the board reports (Ov:), not what was clicked: it may clamp (10..200 %) or have reset.
  const auto ov = run_.overrides();
  feed_->setText(ov ? tr("%1 %").arg(ov->feedPct) : QStringLiteral("–"));
  rapid_->setText(ov ? tr("%1 %").arg(ov->rapidPct) : QStringLiteral("–"));
  const bool changed = ov && (ov->feedPct != 100 || ov->rapidPct != 100);
  const QString color = changed ? QStringLiteral("color: #b45309") : QString();
  feed_->setStyleSheet(ov && ov->feedPct != 100 ? color : QString());
  rapid_->setStyleSheet(ov && ov->rapidPct != 100 ? color : QString());
}

}  // namespace fivebar::widgets
