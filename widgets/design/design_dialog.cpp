// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/design/design_dialog.hpp"

#include <QAction>
#include <QMenu>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "core/design/design_json.hpp"
#include "widgets/canvas/canvas_view.hpp"
#include "widgets/design/pareto_plot.hpp"
#include "i18n/translated.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {
namespace {

struct Paper {
  const char* name;
  double longMm, shortMm;
};
// Sheet sizes, long side first (mm). The last entry is the custom size.
constexpr Paper kPapers[] = {{"A4", 297.0, 210.0}, {"A5", 210.0, 148.0}, {"A6", 148.0, 105.0},
                             {"Letter", 279.4, 215.9}};

QDoubleSpinBox* spin(double lo, double hi, double value, const QString& suffix) {
  auto* s = new QDoubleSpinBox;
  s->setRange(lo, hi);
  s->setDecimals(1);
  s->setValue(value);
  s->setSuffix(suffix);
  return s;
}

QString num(double v, int decimals) { return QLocale().toString(v, 'f', decimals); }

}  // namespace

DesignDialog::DesignDialog(StudioDocument& doc, CanvasView& canvas, QWidget* parent)
    : QDialog(parent), doc_(doc), canvas_(canvas) {
  setObjectName(QStringLiteral("designDialog"));
  setWindowTitle(tr("Design a machine"));
  auto* layout = new QHBoxLayout(this);
  layout->addWidget(makeBriefPanel());
  layout->addWidget(makeResultsPanel(), 1);
  connect(&watcher_, &QFutureWatcher<design::SearchResult>::finished, this, &DesignDialog::onFinished);
  onPaperChanged();
}

DesignDialog::~DesignDialog() {
  cancel_ = true;
  watcher_.waitForFinished();
}

QAction* DesignDialog::createAction(StudioDocument& doc, CanvasView& canvas, QWidget* parent) {
  auto* action = new QAction(tr("&Design..."), parent);
  action->setObjectName(QStringLiteral("designAction"));
  action->setStatusTip(tr("Choose link lengths for a paper size"));
  // The dialog, once created, is the parent's child; the action's holder keeps track of it.
  auto dialog = std::make_shared<QPointer<DesignDialog>>();
  QObject::connect(action, &QAction::triggered, parent, [&doc, &canvas, parent, dialog] {
    if (!*dialog) *dialog = new DesignDialog(doc, canvas, parent);
    (*dialog)->show();
    (*dialog)->raise();
  });
  return action;
}

void DesignDialog::install(const StudioShell& shell) {
  shell.machineMenu->addAction(createAction(*shell.doc, *shell.canvas, shell.window));
}

QWidget* DesignDialog::makeBriefPanel() {
  auto* box = new QGroupBox(tr("Brief"));
  auto* form = new QFormLayout(box);
  paper_ = new QComboBox;
  for (const Paper& p : kPapers) paper_->addItem(QString::fromLatin1(p.name));
  paper_->addItem(tr("Custom"));
  paper_->setCurrentIndex(1);  // A5
  orientation_ = new QComboBox;
  orientation_->addItems({tr("Landscape"), tr("Portrait")});
  width_ = spin(10, 2000, 210, tr(" mm"));
  height_ = spin(10, 2000, 148, tr(" mm"));
  margin_ = spin(0, 200, 10, tr(" mm"));
  minLink_ = spin(5, 2000, 30, tr(" mm"));
  maxLink_ = spin(5, 2000, 200, tr(" mm"));
  minBase_ = spin(0, 2000, 0, tr(" mm"));
  maxBase_ = spin(0, 4000, 250, tr(" mm"));
  clearance_ = spin(0, 500, 10, tr(" mm"));
  typeII_ = spin(0, 80, 15, tr(" deg"));
  symmetric_ = new QCheckBox(tr("Symmetric arms"));
  mode_ = new QComboBox;
  mode_->addItem(tr("Any"));
  for (WorkingMode m : kAllWorkingModes) mode_->addItem(QString::fromUtf8(toString(m).data(), 2));
  objective_ = new QComboBox;
  objective_->addItems({tr("Worst condition number"), tr("Worst resolution"), tr("Footprint"),
                        tr("Weighted mix")});
  // Mix weights on the normalised terms (docs/design.md "Mix"); used by the weighted mix only.
  weightCondition_ = spin(0, 100, 1, QString());
  weightResolution_ = spin(0, 100, 1, QString());
  weightFootprint_ = spin(0, 100, 1, QString());
  auto* weights = new QWidget;
  // One weight a row (label, field): the brief column stays narrow enough for the results table.
  auto* weightRows = new QGridLayout(weights);
  weightRows->setContentsMargins(0, 0, 0, 0);
  const struct {
    QString label;
    const char* name;
    QDoubleSpinBox* box;
  } weightFields[] = {{tr("Condition"), "weightCondition", weightCondition_},
                      {tr("Resolution"), "weightResolution", weightResolution_},
                      {tr("Footprint"), "weightFootprint", weightFootprint_}};
  int row = 0;
  for (const auto& [label, name, field] : weightFields) {
    field->setObjectName(QString::fromLatin1(name));
    field->setToolTip(tr("Weight of this normalised term in the weighted mix"));
    weightRows->addWidget(new QLabel(label), row, 0);
    weightRows->addWidget(field, row, 1);
    ++row;
  }
  weights->setEnabled(false);
  form->addRow(tr("Paper"), paper_);
  form->addRow(tr("Orientation"), orientation_);
  form->addRow(tr("Width"), width_);
  form->addRow(tr("Height"), height_);
  form->addRow(tr("Margin"), margin_);
  form->addRow(tr("Shortest link"), minLink_);
  form->addRow(tr("Longest link"), maxLink_);
  form->addRow(tr("Smallest motor spacing"), minBase_);
  form->addRow(tr("Largest motor spacing"), maxBase_);
  form->addRow(tr("Arm clearance"), clearance_);
  form->addRow(tr("Type II margin"), typeII_);
  form->addRow(QString(), symmetric_);
  form->addRow(tr("Working mode"), mode_);
  form->addRow(tr("Objective"), objective_);
  form->addRow(tr("Mix weights"), weights);
  connect(objective_, &QComboBox::currentIndexChanged, weights,
          [this, weights](int index) { weights->setEnabled(index == 3); });
  search_ = new QPushButton(tr("Search"));
  search_->setDefault(true);
  cancelButton_ = new QPushButton(tr("Cancel"));
  cancelButton_->setEnabled(false);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(search_);
  buttons->addWidget(cancelButton_);
  form->addRow(buttons);
  progress_ = new QProgressBar;
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  form->addRow(progress_);
  connect(paper_, &QComboBox::currentIndexChanged, this, &DesignDialog::onPaperChanged);
  connect(orientation_, &QComboBox::currentIndexChanged, this, &DesignDialog::onPaperChanged);
  connect(search_, &QPushButton::clicked, this, &DesignDialog::startSearch);
  connect(cancelButton_, &QPushButton::clicked, this, &DesignDialog::cancelSearch);
  return box;
}

QWidget* DesignDialog::makeResultsPanel() {
  auto* panel = new QWidget;
  auto* v = new QVBoxLayout(panel);
  status_ = new QLabel(tr("Set the brief and press Search."));
  status_->setWordWrap(true);
  v->addWidget(status_);
  table_ = new QTableWidget(0, 9);
  table_->setHorizontalHeaderLabels({tr("Worst condition"), tr("Footprint (cm\u00b2)"), tr("\u00b5m/step"),
                                     QStringLiteral("a1"), QStringLiteral("b1"), QStringLiteral("a2"),
                                     QStringLiteral("b2"), QStringLiteral("w"), tr("Mode")});
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->verticalHeader()->setVisible(false);
  v->addWidget(table_, 1);
  plot_ = new ParetoPlot;
  v->addWidget(plot_);
  auto* row = new QHBoxLayout;
  mapKind_ = new QComboBox;
  mapKind_->addItems({tr("Workspace"), tr("Conditioning"), tr("Transmission angle"), tr("Resolution")});
  mapKind_->setCurrentIndex(1);
  row->addWidget(new QLabel(tr("Map on the canvas")));
  row->addWidget(mapKind_);
  row->addStretch(1);
  use_ = new QPushButton(tr("Use as profile"));
  export_ = new QPushButton(tr("Export..."));
  use_->setEnabled(false);
  export_->setEnabled(false);
  row->addWidget(use_);
  row->addWidget(export_);
  v->addLayout(row);
  connect(table_, &QTableWidget::currentCellChanged, this, [this](int r) { if (r >= 0) selectDesign(r); });
  connect(plot_, &ParetoPlot::pointClicked, this, [this](int i) { selectDesign(i); });
  connect(mapKind_, &QComboBox::currentIndexChanged, this, [this](int k) {
    const paint::MapKind kinds[] = {paint::MapKind::None, paint::MapKind::Conditioning, paint::MapKind::Transmission, paint::MapKind::Resolution};
    layer_.setMapKind(kinds[std::clamp(k, 0, 3)]);
    canvas_.update();
  });
  connect(use_, &QPushButton::clicked, this, &DesignDialog::useAsProfile);
  connect(export_, &QPushButton::clicked, this, &DesignDialog::exportClicked);
  return panel;
}

void DesignDialog::onPaperChanged() {
  const int i = paper_->currentIndex();
  const bool custom = i >= static_cast<int>(std::size(kPapers));
  width_->setEnabled(custom);
  height_->setEnabled(custom);
  if (custom) return;
  const bool landscape = orientation_->currentIndex() == 0;
  width_->setValue(landscape ? kPapers[i].longMm : kPapers[i].shortMm);
  height_->setValue(landscape ? kPapers[i].shortMm : kPapers[i].longMm);
}

design::DesignBrief DesignDialog::brief() const {
  design::DesignBrief b;
  // The rectangle to reach is the sheet less its margin on every side.
  b.widthMm = std::max(1.0, width_->value() - 2.0 * margin_->value());
  b.heightMm = std::max(1.0, height_->value() - 2.0 * margin_->value());
  b.bounds.minLinkMm = minLink_->value();
  b.bounds.maxLinkMm = maxLink_->value();
  b.bounds.minBaseMm = minBase_->value();
  b.bounds.maxBaseMm = maxBase_->value();
  b.bounds.symmetric = symmetric_->isChecked();
  b.rules.clearanceMm = clearance_->value();
  b.rules.workspace.typeIIMarginRad = radFromDeg(typeII_->value());
  b.rules.workspace.typeIMarginRad = doc_.profile().typeIMarginRad;
  b.rules.workspace.stepRad1 = radFromDeg(1.0 / doc_.profile().motors.stepsPerDeg1);
  b.rules.workspace.stepRad2 = radFromDeg(1.0 / doc_.profile().motors.stepsPerDeg2);
  b.rules.penSpeedMmPerS = doc_.profile().drawSpeedMmPerS;
  if (mode_->currentIndex() > 0) b.mode = kAllWorkingModes[static_cast<std::size_t>(mode_->currentIndex() - 1)];
  const design::Objective objectives[] = {design::Objective::Condition, design::Objective::Resolution,
                                          design::Objective::Footprint, design::Objective::Mix};
  b.objective = objectives[std::clamp(objective_->currentIndex(), 0, 3)];
  b.weights = {weightCondition_->value(), weightResolution_->value(), weightFootprint_->value()};
  return b;
}

void DesignDialog::startSearch() {
  if (searching()) return;
  searchedBrief_ = brief();
  if (const auto issues = design::validate(searchedBrief_); !issues.empty()) {
    status_->setText(translated(issues.front().message));
    return;
  }
  cancel_ = false;
  search_->setEnabled(false);
  cancelButton_->setEnabled(true);
  progress_->setValue(0);
  status_->setText(tr("Searching..."));
  const design::ProgressFn progress = [this](const design::SearchProgress& p) {
    const int value = static_cast<int>(1000.0 * p.fraction);
    QMetaObject::invokeMethod(progress_, [bar = progress_, value] { bar->setValue(value); }, Qt::QueuedConnection);
  };
  watcher_.setFuture(QtConcurrent::run([brief = searchedBrief_, options = options_, progress, this] {
    return design::searchDesigns(brief, options, progress, &cancel_);
  }));
}

void DesignDialog::cancelSearch() { cancel_ = true; }

void DesignDialog::onFinished() {
  search_->setEnabled(true);
  cancelButton_->setEnabled(false);
  progress_->setValue(1000);
  showResult(watcher_.result());
  emit searchFinished();
}

void DesignDialog::showResult(const design::SearchResult& r) {
  designs_.clear();
  selected_ = -1;
  if (r.status == design::SearchStatus::Cancelled) {
    status_->setText(tr("Search cancelled."));
  } else if (r.status == design::SearchStatus::Impossible) {
    status_->setText(tr("No design meets the brief: %1").arg(QString::fromStdString(r.message)));
  } else {
    status_->setText(tr("Best worst-case condition number %1; %2 designs on the trade-off, %3 evaluations in %4 s.")
                         .arg(num(r.best->evaluation.measures.worstCondition, 2))
                         .arg(r.pareto.size())
                         .arg(r.evaluations)
                         .arg(num(r.seconds, 1)));
    designs_ = r.pareto;
    if (designs_.empty()) designs_.push_back(*r.best);
  }
  table_->setRowCount(static_cast<int>(designs_.size()));
  std::vector<ParetoPlot::Point> points;
  for (int i = 0; i < static_cast<int>(designs_.size()); ++i) {
    const design::Design& d = designs_[static_cast<std::size_t>(i)];
    const design::DesignMeasures& m = d.evaluation.measures;
    const Geometry& g = d.geometry;
    const QString cells[] = {num(m.worstCondition, 2), num(m.footprintMm2 / 100.0, 0), num(m.worstMmPerStep * 1000.0, 1),
                             num(g.a1, 1), num(g.b1, 1), num(g.a2, 1), num(g.b2, 1), num(g.w, 1),
                             QString::fromUtf8(toString(d.mode).data(), 2)};
    for (int c = 0; c < 9; ++c) table_->setItem(i, c, new QTableWidgetItem(cells[c]));
    points.push_back({m.footprintMm2 / 100.0, m.worstCondition});
  }
  plot_->setPoints(points);
  use_->setEnabled(false);
  export_->setEnabled(false);
  if (!designs_.empty() && r.best) {  // select the brief's best design
    int best = 0;
    for (int i = 0; i < static_cast<int>(designs_.size()); ++i)
      if (designs_[static_cast<std::size_t>(i)].score < designs_[static_cast<std::size_t>(best)].score) best = i;
    selectDesign(best);
  }
}

void DesignDialog::selectDesign(int row) {
  if (row < 0 || row >= designCount() || row == selected_) return;
  selected_ = row;
  const design::Design& d = designs_[static_cast<std::size_t>(row)];
  if (!layerAdded_) {
    canvas_.addLayer(&layer_);
    layerAdded_ = true;
  }
  paint::DesignMaps maps = paint::computeDesignMaps(d, searchedBrief_.rules);
  QRectF box = paint::designBoxMm(d, maps);
  box.setBottom(box.bottom() + 0.2 * box.height());  // room above for the measures card (y up)
  layer_.show(d, std::move(maps));
  table_->selectRow(row);
  table_->scrollToItem(table_->item(row, 0));
  plot_->setSelected(row);
  use_->setEnabled(true);
  export_->setEnabled(true);
  canvas_.fitRect(box);
  canvas_.update();
}

const design::Design* DesignDialog::selectedDesign() const {
  return selected_ >= 0 && selected_ < designCount() ? &designs_[static_cast<std::size_t>(selected_)] : nullptr;
}

QString DesignDialog::statusText() const { return status_->text(); }

void DesignDialog::useAsProfile() {
  const design::Design* d = selectedDesign();
  if (!d) return;
  const std::string name = doc_.profile().name + "-design";
  doc_.setProfile(design::designProfile(*d, searchedBrief_, name, &doc_.profile()));
  status_->setText(tr("The document now uses this design (Edit > Undo restores the previous profile)."));
}

QString DesignDialog::exportProfile(const QString& path) {
  const design::Design* d = selectedDesign();
  if (!d) return tr("No design is selected.");
  const MachineProfile p = design::designProfile(*d, searchedBrief_, QFileInfo(path).completeBaseName().toStdString(), &doc_.profile());
  return QString::fromStdString(saveProfile(p, path.toStdString()));
}

void DesignDialog::exportClicked() {
  const QString path = QFileDialog::getSaveFileName(this, tr("Export profile"), QString(),
                                                    tr("Machine profiles (*.json)"));
  if (path.isEmpty()) return;
  const QString err = exportProfile(path);
  status_->setText(err.isEmpty() ? tr("Profile written to %1.").arg(path) : err);
}

void DesignDialog::hideEvent(QHideEvent* event) {
  layer_.hide();
  canvas_.update();
  QDialog::hideEvent(event);
}

}  // namespace fivebar::widgets
