// SPDX-License-Identifier: GPL-3.0-or-later
// The warnings of the last import (dropped images, unsupported features, path data errors, ...),
// one per line as the importer words them ("line 12: <path id="p3"> ..."), under a translated
// heading; and the point-budget question asked before a huge drawing enters the document.
#pragma once

#include <QString>
#include <QStringList>
#include <QWidget>

#include <cstddef>
#include <string>
#include <vector>

#include "core/planning/drawing.hpp"

class QLabel;
class QListWidget;

namespace fivebar::widgets {

class ImportWarningsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ImportWarningsPanel(QWidget* parent = nullptr);

  QListWidget* list() const { return list_; }

 public slots:
  // Shows the warnings of an import of `fileName` (empty: "no warnings"), already in the UI
  // language (the importer's messages are core Messages: i18n/translated.hpp).
  void showWarnings(const QString& fileName, const QStringList& warnings);

 signals:
  // Emitted when an import brought warnings, so that the window can raise the panel.
  void attentionWanted();

 private:
  QLabel* heading_ = nullptr;
  QListWidget* list_ = nullptr;
};

// Points of the visible layers after flattening.
std::size_t drawingPointCount(const Drawing& drawing);

inline constexpr std::size_t kImportPointBudget = kDefaultMaxPoints;  // drawing.hpp

// Empty when the drawing is within the budget; otherwise what is wrong, naming the file and the
// counts (the import controller asks its budget question with it, or refuses with it).
QString pointBudgetExcess(const Drawing& drawing, const QString& fileName);

// The studio's budget question (ImportController::BudgetQuestion): a Yes/No box over `parent`.
bool askBeyondPointBudget(QWidget* parent, const QString& title, const QString& question);

}  // namespace fivebar::widgets
