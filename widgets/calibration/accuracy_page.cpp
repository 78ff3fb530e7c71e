// SPDX-License-Identifier: GPL-3.0-or-later
// The accuracy step of the calibration wizard: Hoang's ten 40 mm lines measured with a ruler
// (length, straightness), before and after calibration, and the figures that compare them.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "core/calibration/scan/scan_lines.hpp"
#include "widgets/calibration/wizard_pages.hpp"
#include "i18n/translated.hpp"

namespace fivebar::widgets::calibration {

namespace {
QString mm(double v, int decimals = 2) { return QString::number(v, 'f', decimals); }
}  // namespace

AccuracyPage::AccuracyPage(CalibrationWizard& wizard) : w_(wizard) {
  setTitle(tr("Measure the accuracy lines"));
  auto* layout = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  left->addWidget(explanation(
      tr("Hoang's accuracy pattern is ten lines, each meant to be 40 mm long and straight, 10 mm "
         "apart. Lay a steel ruler along each line. <b>Length</b>: from end to end, in the middle of "
         "the pen's stroke. <b>Straightness</b>: the widest gap between the line and the ruler's "
         "edge when the ruler touches both ends (0 for a straight line). Type the lines drawn "
         "<b>before</b> calibration in the first two columns and those of the verification sheet "
         "(drawn <b>after</b>) in the last two; the figures below compare them.")));
  table_ = new QTableWidget(kAccuracyLineCount, kColumns);
  table_->setObjectName(QStringLiteral("accuracyTable"));
  table_->setHorizontalHeaderLabels({tr("Length before (mm)"), tr("Straightness before (mm)"),
                                     tr("Length after (mm)"), tr("Straightness after (mm)")});
  QStringList rows;
  for (int i = 0; i < kAccuracyLineCount; ++i) {
    rows << tr("Line %1").arg(i + 1);
    for (int c = 0; c < kColumns; ++c) table_->setItem(i, c, new QTableWidgetItem);
  }
  table_->setVerticalHeaderLabels(rows);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  table_->horizontalHeader()->setDefaultAlignment(Qt::Alignment(Qt::AlignCenter));
  left->addWidget(table_, 1);
  figures_ = explanation(QString());
  figures_->setObjectName(QStringLiteral("accuracyFigures"));
  left->addWidget(figures_);
  auto* buttons = new QHBoxLayout;
  fromSheet_ = new QPushButton(tr("Simulation: measure the simulated lines"));
  fromSheet_->setToolTip(tr("Fills the table with the lines as the simulated imperfect machine draws "
                            "them: before with the profile the wizard started from, after with the "
                            "calibrated profile."));
  buttons->addWidget(fromSheet_);
  buttons->addStretch(1);
  left->addLayout(buttons);
  auto* scan = new QHBoxLayout;
  auto* scanButton = new QPushButton(tr("Import scan..."));
  scanButton->setObjectName(QStringLiteral("importAccuracyScan"));
  scanButton->setToolTip(tr("A scan of the sheet with the accuracy lines (PNG or JPEG, taken straight "
                            "from above): each line's length and straightness are measured in the "
                            "image and fill the columns of the chosen sheet."));
  sheet_ = new QComboBox;
  sheet_->addItem(tr("Sheet drawn before calibration"));
  sheet_->addItem(tr("Sheet drawn after calibration"));
  dpi_ = new QDoubleSpinBox;
  dpi_->setRange(50.0, 4800.0);
  dpi_->setDecimals(0);
  dpi_->setValue(600.0);
  dpi_->setSuffix(tr(" dpi"));
  dpi_->setToolTip(tr("The scanner's resolution: the scan's size in mm comes from it."));
  scan->addWidget(scanButton);
  scan->addWidget(sheet_);
  scan->addWidget(dpi_);
  scan->addStretch(1);
  left->addLayout(scan);
  scanStatus_ = explanation(QString());
  scanStatus_->setObjectName(QStringLiteral("accuracyScanStatus"));
  left->addWidget(scanStatus_);
  preview_ = new CalibrationPreview;
  layout->addLayout(left, 2);
  layout->addWidget(preview_, 1);
  connect(fromSheet_, &QPushButton::clicked, this, &AccuracyPage::fillFromSimulatedSheet);
  connect(scanButton, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import a scan of the accuracy lines"), QString(),
                                                      tr("Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)"));
    if (path.isEmpty()) return;
    QString message;
    importScan(path, dpi_->value(), sheet_->currentIndex() == 1, &message);
  });
  connect(table_, &QTableWidget::cellChanged, this, [this] {
    if (!filling_) updateFigures();
  });
}

void AccuracyPage::initializePage() {
  fromSheet_->setEnabled(w_.simulated);
  QString error;
  const auto pattern = makePattern(w_.document().profile(), PatternKind::AccuracyOnly, 0, &error);
  std::vector<std::vector<Vec2>> plan;
  if (pattern)
    for (const Stroke& s : pattern->strokes) plan.push_back(s.points);
  preview_->setPlan(plan);
  preview_->setTrueTrace({});
  preview_->setMarks({}, {});
  updateFigures();
}

bool AccuracyPage::readColumns(bool after, std::vector<LineMeasure>* out, QString* error) const {
  out->clear();
  const int c0 = after ? kLengthAfter : kLengthBefore;
  for (int r = 0; r < kAccuracyLineCount; ++r) {
    LineMeasure m;
    for (int c = c0; c < c0 + 2; ++c) {
      const QString text = table_->item(r, c)->text().trimmed();
      if (text.isEmpty()) continue;
      const auto v = typedNumber(text);
      if (!v || *v < 0.0) {
        *error = tr("Line %1, %2: '%3' is not a length in mm.")
                     .arg(r + 1)
                     .arg(table_->horizontalHeaderItem(c)->text(), text);
        return false;
      }
      (c == c0 ? m.lengthMm : m.straightnessMm) = *v;
    }
    out->push_back(m);
  }
  return true;
}

void AccuracyPage::updateFigures() {
  QString text;
  before_.reset();
  after_.reset();
  for (bool after : {false, true}) {
    std::vector<LineMeasure> lines;
    QString error;
    if (!readColumns(after, &lines, &error)) {
      figures_->setText(QStringLiteral("<span style='color:#b00000'>%1</span>").arg(error.toHtmlEscaped()));
      return;
    }
    (after ? after_ : before_) = summariseLines(lines);
  }
  auto line = [](const QString& when, const std::optional<AccuracySummary>& a) {
    if (!a) return tr("<b>%1:</b> not measured yet (type a length and a straightness per line).").arg(when);
    return tr("<b>%1:</b> straightness %2 mm at worst (RMS %3 mm); length off by %4 mm at worst "
              "(RMS %5 mm), over %6 lines.")
        .arg(when, mm(a->maxStraightnessMm), mm(a->rmsStraightnessMm), mm(a->maxAbsLengthErrorMm),
             mm(a->rmsLengthErrorMm))
        .arg(a->lines);
  };
  text = line(tr("Before calibration"), before_) + QStringLiteral("<br>") + line(tr("After calibration"), after_);
  if (before_ && after_ && after_->maxAbsLengthErrorMm + after_->maxStraightnessMm > 0.0) {
    const double was = before_->maxAbsLengthErrorMm + before_->maxStraightnessMm;
    const double now = after_->maxAbsLengthErrorMm + after_->maxStraightnessMm;
    text += tr("<br>Worst straightness plus worst length error: %1 mm &rarr; <b>%2 mm</b>.").arg(mm(was), mm(now));
  }
  figures_->setText(text);
}

bool AccuracyPage::importScan(const QString& path, double dpi, bool after, QString* message) {
  const LineScanOutcome scan = scanAccuracyLinesFile(path.toStdString(), dpi);
  if (!scan.ok() || !scan.figures) {
    *message = scan.ok() ? tr("A line in the scan is too short to measure.") : translated(scan.error);
    scanStatus_->setStyleSheet(QStringLiteral("color:#b00000"));
    scanStatus_->setText(*message);
    return false;
  }
  filling_ = true;
  const int c0 = after ? kLengthAfter : kLengthBefore;
  for (int r = 0; r < kAccuracyLineCount; ++r) {
    const bool has = r < static_cast<int>(scan.figures->lines.size());
    const LineAccuracy* l = has ? &scan.figures->lines[static_cast<std::size_t>(r)] : nullptr;
    table_->item(r, c0)->setText(l ? QLocale().toString(l->lengthMm, 'f', 2) : QString());
    table_->item(r, c0 + 1)->setText(l ? QLocale().toString(l->straightnessMm, 'f', 2) : QString());
  }
  filling_ = false;
  std::vector<std::vector<Vec2>> trace;
  for (const ScannedLine& l : scan.lines) trace.push_back(l.pointsMm());
  preview_->setPlan({});
  preview_->setTrueTrace(trace);
  updateFigures();
  *message = tr("Found %1 lines in the scan (%2 mm pen): the %3 columns are filled.")
                 .arg(static_cast<int>(scan.lines.size()))
                 .arg(QLocale().toString(scan.lines.front().penWidthMm, 'f', 2))
                 .arg(after ? tr("after") : tr("before"));
  scanStatus_->setStyleSheet(QString());
  scanStatus_->setText(*message);
  return true;
}

void AccuracyPage::fillFromSimulatedSheet() {
  if (!w_.simulated) return;
  QString error;
  std::vector<std::vector<Vec2>> traceBefore, traceAfter;
  const auto before = simulatedAccuracy(w_.nominal, w_.truth, &traceBefore, &error);
  std::optional<AccuracyFigures> after;
  if (before && w_.applied) after = simulatedAccuracy(w_.document().profile(), w_.truth, &traceAfter, &error);
  filling_ = true;
  for (int r = 0; r < kAccuracyLineCount; ++r) {
    const auto put = [&](const std::optional<AccuracyFigures>& f, int c0) {
      const bool has = f && r < static_cast<int>(f->lines.size());
      table_->item(r, c0)->setText(has ? mm(f->lines[static_cast<std::size_t>(r)].lengthMm) : QString());
      table_->item(r, c0 + 1)->setText(has ? mm(f->lines[static_cast<std::size_t>(r)].straightnessMm) : QString());
    };
    put(before, kLengthBefore);
    put(after, kLengthAfter);
  }
  filling_ = false;
  preview_->setTrueTrace(after ? traceAfter : traceBefore);
  updateFigures();
  if (!before || (w_.applied && !after))
    figures_->setText(figures_->text() + QStringLiteral("<br><span style='color:#b00000'>%1</span>").arg(error.toHtmlEscaped()));
  else if (!w_.applied)
    figures_->setText(figures_->text() + tr("<br><i>Apply the calibration (step 5) to see the lines drawn after it.</i>"));
}

}  // namespace fivebar::widgets::calibration
