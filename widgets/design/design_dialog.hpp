// SPDX-License-Identifier: GPL-3.0-or-later
// Machine > Design...: choose link lengths for a paper size (issue 14, docs/design.md).
// The brief (paper, orientation, margin, bounds, rules, objective) on the left; the search runs
// on worker threads with progress and cancel; the results as a table and a trade-off plot.
// Clicking a design shows it live on the canvas (DesignLayer); "Use as profile" replaces the
// document's profile (undoable), "Export..." writes it as a profile file.
#pragma once

#include "widgets/shell/studio_shell.hpp"

#include <QDialog>
#include <QFutureWatcher>
#include <atomic>
#include <memory>
#include <optional>

#include "core/design/search.hpp"
#include "widgets/design/design_layer.hpp"

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace fivebar::widgets {

class CanvasView;
class ParetoPlot;
class StudioDocument;

class DesignDialog : public QDialog {
  Q_OBJECT
 public:
  DesignDialog(StudioDocument& doc, CanvasView& canvas, QWidget* parent = nullptr);
  ~DesignDialog() override;

  // The Machine menu's "Design..." action; the dialog is made on first use.
  static QAction* createAction(StudioDocument& doc, CanvasView& canvas, QWidget* parent);
  // The design explorer's place in the studio: that action in the shell's Machine menu.
  static void install(const StudioShell& shell);

  design::DesignBrief brief() const;
  void setSearchOptions(const design::SearchOptions& options) { options_ = options; }
  void startSearch();
  void cancelSearch();
  bool searching() const { return watcher_.isRunning(); }
  int designCount() const { return static_cast<int>(designs_.size()); }
  void selectDesign(int row);
  const design::Design* selectedDesign() const;
  const DesignLayer& layer() const { return layer_; }
  QString statusText() const;
  void useAsProfile();
  QString exportProfile(const QString& path);  // error message, empty on success

 signals:
  void searchFinished();

 protected:
  void hideEvent(QHideEvent* event) override;

 private:
  QWidget* makeBriefPanel();
  QWidget* makeResultsPanel();
  void onPaperChanged();
  void onFinished();
  void showResult(const design::SearchResult& r);
  void exportClicked();

  StudioDocument& doc_;
  CanvasView& canvas_;
  DesignLayer layer_;
  bool layerAdded_ = false;
  design::SearchOptions options_;
  design::DesignBrief searchedBrief_;
  std::vector<design::Design> designs_;
  int selected_ = -1;
  std::atomic<bool> cancel_{false};
  QFutureWatcher<design::SearchResult> watcher_;

  QComboBox* paper_ = nullptr;
  QComboBox* orientation_ = nullptr;
  QDoubleSpinBox* width_ = nullptr;
  QDoubleSpinBox* height_ = nullptr;
  QDoubleSpinBox* margin_ = nullptr;
  QDoubleSpinBox* minLink_ = nullptr;
  QDoubleSpinBox* maxLink_ = nullptr;
  QDoubleSpinBox* minBase_ = nullptr;
  QDoubleSpinBox* maxBase_ = nullptr;
  QDoubleSpinBox* clearance_ = nullptr;
  QDoubleSpinBox* typeII_ = nullptr;
  QCheckBox* symmetric_ = nullptr;
  QComboBox* mode_ = nullptr;
  QComboBox* objective_ = nullptr;
  QDoubleSpinBox* weightCondition_ = nullptr;
  QDoubleSpinBox* weightResolution_ = nullptr;
  QDoubleSpinBox* weightFootprint_ = nullptr;
  QComboBox* mapKind_ = nullptr;
  QPushButton* search_ = nullptr;
  QPushButton* cancelButton_ = nullptr;
  QPushButton* use_ = nullptr;
  QPushButton* export_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* status_ = nullptr;
  QTableWidget* table_ = nullptr;
  ParetoPlot* plot_ = nullptr;
};

}  // namespace fivebar::widgets
