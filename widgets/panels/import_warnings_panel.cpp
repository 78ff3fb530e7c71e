#include "widgets/panels/import_warnings_panel.hpp"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLocale>
#include <QStyle>
#include <QLabel>
#include <QListWidget>
#include <QRegularExpression>
#include <QMessageBox>
#include <QVBoxLayout>

#include "core/planning/hatch.hpp"

namespace fivebar::widgets {
namespace {

QString trWarning(const char* text) { return QCoreApplication::translate("ImportWarning", text); }

// The importer's messages (core/import, in English) as patterns: the captured parts (tags, ids,
// numbers, selectors) are put into the translated template as %1, %2, ...
struct WarningPattern {
  const char* regex;
  const char* text;  // translatable template
};
const WarningPattern kWarningPatterns[] = {
    {"^attribute d: invalid path data at character (\\d+) (\\(.*\\)): drawn up to the error$",
     QT_TRANSLATE_NOOP("ImportWarning", "attribute d: invalid path data at character %1 %2: drawn up to the error")},
    {"^attribute d: invalid path data at character (\\d+): drawn up to the error$",
     QT_TRANSLATE_NOOP("ImportWarning", "attribute d: invalid path data at character %1: drawn up to the error")},
    {"^transform-origin=\"(.*)\" not understood: ignored$",
     QT_TRANSLATE_NOOP("ImportWarning", "transform-origin=\"%1\" not understood: ignored")},
    {"^marker #(.*) not found: not drawn$",
     QT_TRANSLATE_NOOP("ImportWarning", "marker #%1 not found: not drawn")},
    {"^markers on (<\\w+>) are not drawn \\(drawn on path, line, polyline and polygon\\)$",
     QT_TRANSLATE_NOOP("ImportWarning", "markers on %1 are not drawn (drawn on path, line, polyline and polygon)")},
    {"^markers set in a style sheet for the selector '(.*)' are not drawn \\(only type, #id and \\.class selectors are applied\\)$",
     QT_TRANSLATE_NOOP("ImportWarning", "markers set in a style sheet for the selector '%1' are not drawn (only type, #id and .class selectors are applied)")},
    {"^external reference removed from (<.*>)$",
     QT_TRANSLATE_NOOP("ImportWarning", "external reference removed from %1")},
    {"^(<.*>) element removed$", QT_TRANSLATE_NOOP("ImportWarning", "%1 element removed")},
    {"^long <path> split into (\\d+) parts to avoid Qt SVG's 32,767-element truncation$",
     QT_TRANSLATE_NOOP("ImportWarning", "long <path> split into %1 parts to avoid Qt SVG's 32,767-element truncation")},
};

// Messages without variable parts, translated as they are.
[[maybe_unused]] const char* const kFixedWarnings[] = {
    QT_TRANSLATE_NOOP("ImportWarning", "further element warnings not listed"),
    QT_TRANSLATE_NOOP("ImportWarning", "DOCTYPE with entity declarations removed (internal entities were expanded)"),
    QT_TRANSLATE_NOOP("ImportWarning", "unresolved entity reference dropped"),
    QT_TRANSLATE_NOOP("ImportWarning", "external style sheet (xml-stylesheet) ignored"),
    QT_TRANSLATE_NOOP("ImportWarning", "event attribute (on...) removed"),
    QT_TRANSLATE_NOOP("ImportWarning", "CSS @import removed"),
    QT_TRANSLATE_NOOP("ImportWarning", "transform-origin in a style is not applied"),
    QT_TRANSLATE_NOOP("ImportWarning", "clip-path not applied: clipped shapes are drawn whole"),
    QT_TRANSLATE_NOOP("ImportWarning", "mask not applied: masked shapes are drawn whole"),
    QT_TRANSLATE_NOOP("ImportWarning", "per-glyph rotate on <text> is not applied: glyphs are drawn upright"),
    QT_TRANSLATE_NOOP("ImportWarning", "text on a path (<textPath>) is not drawn"),
    QT_TRANSLATE_NOOP("ImportWarning", "pattern fills are drawn as outlines, without the pattern"),
    QT_TRANSLATE_NOOP("ImportWarning", "more than 100000 marker instances: the rest are not drawn"),
    QT_TRANSLATE_NOOP("ImportWarning", "marker overflow clipping not applied: marker content is drawn whole"),
    QT_TRANSLATE_NOOP("ImportWarning", "no usable width/height/viewBox: page size taken from the drawing's extent"),
};

QString translatedCore(const QString& text) {
  for (const WarningPattern& p : kWarningPatterns) {
    const QRegularExpression re(QString::fromLatin1(p.regex));
    const QRegularExpressionMatch m = re.match(text);
    if (!m.hasMatch()) continue;
    QString out = trWarning(p.text);
    for (int i = 1; i <= m.lastCapturedIndex(); ++i) out = out.arg(m.captured(i));
    return out;
  }
  return trWarning(text.toUtf8().constData());  // a fixed message, or itself when unknown
}

}  // namespace

QString translatedImportWarning(const QString& warning) {
  // "line 12: <path id="p3"> what" and "what (3x, first at line 9)" around the message itself.
  static const QRegularExpression located(QStringLiteral("^line (\\d+): (<[^>]*>) (.*)$"));
  static const QRegularExpression counted(QStringLiteral("^(.*) \\((\\d+)x, first at line (\\d+)\\)$"));
  if (const QRegularExpressionMatch m = located.match(warning); m.hasMatch())
    return trWarning(QT_TRANSLATE_NOOP("ImportWarning", "line %1: %2 %3"))
        .arg(m.captured(1), m.captured(2), translatedCore(m.captured(3)));
  if (const QRegularExpressionMatch m = counted.match(warning); m.hasMatch())
    return trWarning(QT_TRANSLATE_NOOP("ImportWarning", "%1 (%2x, first at line %3)"))
        .arg(translatedCore(m.captured(1)), m.captured(2), m.captured(3));
  return translatedCore(warning);
}

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
    const QString shown = translatedImportWarning(w);
    auto* item = new QListWidgetItem(style()->standardIcon(QStyle::SP_MessageBoxWarning), shown, list_);
    item->setToolTip(shown == w ? w : shown + QStringLiteral("\n\n") + w);  // the importer's words too
  }
  emit attentionWanted();
}

QStringList toQStringList(const std::vector<std::string>& texts) {
  QStringList out;
  out.reserve(static_cast<qsizetype>(texts.size()));
  for (const std::string& t : texts) out << QString::fromStdString(t);
  return out;
}

std::size_t drawingPointCount(const Drawing& drawing) {
  std::size_t n = 0;
  for (const Layer& layer : drawing.layers)
    if (layer.visible)
      for (const Polyline& line : filledPaths(layer)) n += line.points.size();
  return n;
}

bool acceptPointBudget(QWidget* parent, const Drawing& drawing, const QString& fileName,
                       bool interactive, QString& refusal) {
  const std::size_t points = drawingPointCount(drawing);
  if (points <= kImportPointBudget) return true;
  const QString count = QLocale().toString(static_cast<qulonglong>(points));
  const QString budget = QLocale().toString(static_cast<qulonglong>(kImportPointBudget));
  refusal = QCoreApplication::translate("ImportWarningsPanel",
                                        "%1 has %2 points after flattening, more than the budget "
                                        "of %3 (a runaway file?).")
                .arg(QFileInfo(fileName).fileName(), count, budget);
  if (!interactive) return false;
  const auto answer = QMessageBox::question(
      parent, QCoreApplication::translate("ImportWarningsPanel", "Very large drawing"),
      refusal + QStringLiteral("\n\n") +
          QCoreApplication::translate("ImportWarningsPanel",
                                      "Planning and plotting it may take very long. Import it anyway?"),
      QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
  return answer == QMessageBox::Yes;
}

}  // namespace fivebar::widgets
