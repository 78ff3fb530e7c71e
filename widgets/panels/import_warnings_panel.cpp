// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/panels/import_warnings_panel.hpp"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLocale>
#include <QStyle>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QVBoxLayout>

#include "core/planning/hatch.hpp"

namespace fivebar::widgets {
ImportWarningsPanel::ImportWarningsPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  heading_ = new QLabel(tr("No drawing imported yet."), this);
  heading_->setWordWrap(true);
  list_ = new QListWidget(this);
  list_->setWordWrap(true);
  list_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  list_->setToolTip(tr("What the importer dropped, approximated or could not draw. "
                       "docs/svg-import.md lists what is supported."));
  layout->addWidget(heading_);
  layout->addWidget(list_, 1);
}

void ImportWarningsPanel::showWarnings(const QString& fileName, const QStringList& warnings) {
  const QString name = QFileInfo(fileName).fileName();
  list_->clear();
  if (warnings.isEmpty()) {
    heading_->setText(tr("%1 imported without warnings.").arg(name));
    return;
  }
  heading_->setText(warnings.size() == 1
                        ? tr("1 warning while importing %1: part of the drawing may differ from "
                             "what a browser shows.").arg(name)
                        : tr("%1 warnings while importing %2: parts of the drawing may differ "
                             "from what a browser shows.").arg(warnings.size()).arg(name));
  for (const QString& w : warnings) {
    auto* item = new QListWidgetItem(style()->standardIcon(QStyle::SP_MessageBoxWarning), w, list_);
    item->setToolTip(w);
  }
  emit attentionWanted();
}

std::size_t drawingPointCount(const Drawing& drawing) {
  std::size_t n = 0;
  for (const Layer& layer : drawing.layers)
    if (layer.visible)
      for (const Polyline& line : filledPaths(layer)) n += line.points.size();
  return n;
}

QString pointBudgetExcess(const Drawing& drawing, const QString& fileName) {
  const std::size_t points = drawingPointCount(drawing);
  if (points <= kImportPointBudget) return {};
  const QString count = QLocale().toString(static_cast<qulonglong>(points));
  const QString budget = QLocale().toString(static_cast<qulonglong>(kImportPointBudget));
  return QCoreApplication::translate("ImportWarningsPanel",
                                     "%1 has %2 points after flattening, more than the budget "
                                     "of %3 (a runaway file?).")
      .arg(QFileInfo(fileName).fileName(), count, budget);
}

bool askBeyondPointBudget(QWidget* parent, const QString& title, const QString& question) {
  return QMessageBox::question(parent, title, question, QMessageBox::Yes | QMessageBox::No,
                               QMessageBox::No) == QMessageBox::Yes;
}

}  // namespace fivebar::widgets
