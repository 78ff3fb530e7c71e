// SPDX-License-Identifier: GPL-3.0-or-later
#include "svg_text_redraw.hpp"

#include <QRegularExpression>
#include <QXmlStreamReader>

#include <cmath>
#include <optional>
#include <set>

#include "core/output/fixed_decimal.hpp"
#include "core/text/text_layout.hpp"
#include "svg_lengths.hpp"
#include "svg_rewrite.hpp"

namespace fivebar::svg {
namespace {

// What a text run inherits.
struct TextState {
  double fontSizeUser = 16.0;
  QString fill = QStringLiteral("black");
  QString stroke = QStringLiteral("none");
  QString anchor = QStringLiteral("start");
};

// A piece of text in one state, maybe starting at a new absolute position.
struct Run {
  TextState state;
  std::optional<double> x, y;
  double dx = 0.0, dy = 0.0;
  QString text;
};

QString property(const QXmlStreamAttributes& a, const QString& name) {
  const QString styled = styleValue(a.value(QStringLiteral("style")), name);
  return styled.isEmpty() ? a.value(name).toString().trimmed() : styled.trimmed();
}

TextState inherit(const TextState& parent, const QXmlStreamAttributes& a, double dpi) {
  TextState s = parent;
  if (const QString size = property(a, QStringLiteral("font-size")); !size.isEmpty())
    s.fontSizeUser = fontSizeUser(size, parent.fontSizeUser, dpi).value_or(parent.fontSizeUser);
  if (const QString fill = property(a, QStringLiteral("fill")); !fill.isEmpty() && fill != u"inherit") s.fill = fill;
  if (const QString stroke = property(a, QStringLiteral("stroke")); !stroke.isEmpty() && stroke != u"inherit")
    s.stroke = stroke;
  if (const QString anchor = property(a, QStringLiteral("text-anchor")); !anchor.isEmpty() && anchor != u"inherit")
    s.anchor = anchor;
  return s;
}

// The first length of a coordinate list (x="10 20 30": 10), in user units.
std::optional<double> firstCoordinate(const QXmlStreamAttributes& a, const QString& name, double fontSize,
                                      double dpi, bool& more) {
  const QStringList parts = a.value(name).toString().split(QRegularExpression(QStringLiteral("[\\s,]+")),
                                                           Qt::SkipEmptyParts);
  if (parts.isEmpty()) return std::nullopt;
  more = more || parts.size() > 1;
  return resolveLength(parts.front(), LengthAxis::Width, LengthContext{{}, fontSize, dpi});
}

QString number(double v) { return QString::fromStdString(fixedDecimal(v, 4)); }

QString escaped(const QString& s) { return s.toHtmlEscaped(); }

// Collapses white space as CSS does for the whole text: runs of spaces, tabs and newlines become
// one space; the text's leading and trailing spaces go.
void collapseWhiteSpace(std::vector<Run>& runs) {
  bool lastSpace = true;  // drops leading spaces
  for (Run& run : runs) {
    QString out;
    for (const QChar c : run.text) {
      const bool space = c == u' ' || c == u'\t' || c == u'\n' || c == u'\r';
      if (space && lastSpace) continue;
      out += space ? QChar(u' ') : c;
      lastSpace = space;
    }
    run.text = out;
  }
  for (auto it = runs.rbegin(); it != runs.rend(); ++it) {
    if (it->text.isEmpty()) continue;
    if (it->text.endsWith(u' ')) it->text.chop(1);
    break;
  }
}

// The <g> replacing one <text>: its attributes but the positioning ones, one <path> per run.
QString replacement(const QXmlStreamAttributes& textAttributes, std::vector<Run>& runs,
                    const text::HersheyFont& font) {
  static const std::set<QString> positioning = {QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("dx"),
                                                QStringLiteral("dy"), QStringLiteral("rotate"),
                                                QStringLiteral("textLength"), QStringLiteral("lengthAdjust")};
  QString out = QStringLiteral("<g");
  for (const QXmlStreamAttribute& a : textAttributes)
    if (!a.namespaceUri().isEmpty() || !positioning.count(a.name().toString()))
      out += u' ' + a.qualifiedName().toString() + QStringLiteral("=\"") + escaped(a.value().toString()) + u'"';
  out += u'>';
  collapseWhiteSpace(runs);
  // Positions: each run continues from where the last ended unless it sets x or y; a text chunk
  // (from one absolute x to the next) is anchored as a whole.
  struct Placed {
    std::size_t run;
    double x, y;  // start of the run's baseline
    double widthUser;
  };
  std::vector<Placed> placed;
  std::vector<std::size_t> chunkStarts;
  double penX = 0.0, penY = 0.0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    Run& run = runs[i];
    if (run.x || i == 0) chunkStarts.push_back(placed.size());
    if (run.x) penX = *run.x;
    if (run.y) penY = *run.y;
    penX += run.dx;
    penY += run.dy;
    text::TextStyle style;
    style.heightMm = kTextCapHeightPerEm * run.state.fontSizeUser;  // user units here
    const text::TextLayout layout = text::layoutText(font, run.text.toStdString(), style);
    const double width = layout.lineWidthsMm.empty() ? 0.0 : layout.lineWidthsMm.front();
    placed.push_back({i, penX, penY, width});
    penX += width;
  }
  chunkStarts.push_back(placed.size());
  for (std::size_t c = 0; c + 1 < chunkStarts.size(); ++c) {
    const std::size_t first = chunkStarts[c], end = chunkStarts[c + 1];
    if (first >= end) continue;
    const double width = placed[end - 1].x + placed[end - 1].widthUser - placed[first].x;
    const QString& anchor = runs[placed[first].run].state.anchor;
    const double shift = anchor == u"middle" ? -0.5 * width : anchor == u"end" ? -width : 0.0;
    for (std::size_t k = first; k < end; ++k) placed[k].x += shift;
  }
  for (const Placed& p : placed) {
    const Run& run = runs[p.run];
    const QString colour = run.state.fill != u"none" ? run.state.fill : run.state.stroke;
    if (colour == u"none" || colour.isEmpty() || run.text.isEmpty()) continue;
    text::TextStyle style;
    style.heightMm = kTextCapHeightPerEm * run.state.fontSizeUser;
    const text::TextLayout layout = text::layoutText(font, run.text.toStdString(), style);
    QString d;
    for (const Polyline& stroke : layout.strokes)
      for (std::size_t k = 0; k < stroke.points.size(); ++k)
        d += (k == 0 ? (d.isEmpty() ? QStringLiteral("M") : QStringLiteral(" M")) : QStringLiteral(" L")) +
             number(p.x + stroke.points[k].x()) + u' ' + number(p.y - stroke.points[k].y());
    if (d.isEmpty()) continue;
    out += QStringLiteral("<path fill=\"none\" stroke=\"") + escaped(colour) + QStringLiteral("\" stroke-width=\"") +
           number(0.07 * run.state.fontSizeUser) +
           QStringLiteral("\" stroke-linecap=\"round\" stroke-linejoin=\"round\" d=\"") + d + QStringLiteral("\"/>");
  }
  return out + QStringLiteral("</g>");
}

// The offset just after the '>' of the tag starting at `begin` (quotes respected: '>' may stand
// in an attribute value); -1 when there is none.
qint64 tagEnd(const QString& document, qint64 begin) {
  QChar quote;
  for (qint64 i = begin; i < document.size(); ++i) {
    const QChar c = document[i];
    if (!quote.isNull()) {
      if (c == quote) quote = QChar();
    } else if (c == u'"' || c == u'\'') {
      quote = c;
    } else if (c == u'>') {
      return i + 1;
    }
  }
  return -1;
}

}  // namespace

QString redrawTextInFont(const QString& document, const text::HersheyFont& font, double dpi,
                         std::vector<Message>& warnings) {
  if (!document.contains(QStringLiteral("<text"))) return document;
  QXmlStreamReader reader(document);
  std::vector<TextState> states{TextState{}};
  QString out;
  qint64 copied = 0;       // document characters written to `out` so far
  // Inside a <text>: its depth in `states`, where it began, its attributes and its runs.
  int textDepth = 0;
  qint64 textBegin = 0, textStartEnd = 0;  // its '<' and the end of its start tag
  QXmlStreamAttributes textAttributes;
  std::vector<Run> runs;
  bool perGlyph = false, textPath = false;
  int skipDepth = 0;  // > 0 inside a <textPath>
  while (!reader.atEnd()) {
    const QXmlStreamReader::TokenType token = reader.readNext();
    if (token == QXmlStreamReader::StartElement) {
      const QXmlStreamAttributes a = reader.attributes();
      states.push_back(inherit(states.back(), a, dpi));
      const QStringView tag = reader.name();
      const int depth = static_cast<int>(states.size()) - 1;
      if (skipDepth > 0) {
        // inside a textPath: nothing
      } else if (textDepth == 0 && tag == u"text") {
        textDepth = depth;
        // The reader's offset may be past the start tag already (it reads ahead): its '<' is the
        // last "<text" before the offset.
        textBegin = document.lastIndexOf(u'<' + reader.qualifiedName().toString(), reader.characterOffset() - 1);
        textStartEnd = textBegin < 0 ? -1 : tagEnd(document, textBegin);
        if (textStartEnd < 0) return document;  // cannot happen in a document the reader read
        textAttributes = a;
        runs.clear();
        Run run;
        run.state = states.back();
        run.x = firstCoordinate(a, QStringLiteral("x"), run.state.fontSizeUser, dpi, perGlyph).value_or(0.0);
        run.y = firstCoordinate(a, QStringLiteral("y"), run.state.fontSizeUser, dpi, perGlyph).value_or(0.0);
        run.dx = firstCoordinate(a, QStringLiteral("dx"), run.state.fontSizeUser, dpi, perGlyph).value_or(0.0);
        run.dy = firstCoordinate(a, QStringLiteral("dy"), run.state.fontSizeUser, dpi, perGlyph).value_or(0.0);
        runs.push_back(run);
      } else if (textDepth > 0 && tag == u"tspan") {
        Run run;
        run.state = states.back();
        run.x = firstCoordinate(a, QStringLiteral("x"), run.state.fontSizeUser, dpi, perGlyph);
        run.y = firstCoordinate(a, QStringLiteral("y"), run.state.fontSizeUser, dpi, perGlyph);
        run.dx = firstCoordinate(a, QStringLiteral("dx"), run.state.fontSizeUser, dpi, perGlyph).value_or(0.0);
        run.dy = firstCoordinate(a, QStringLiteral("dy"), run.state.fontSizeUser, dpi, perGlyph).value_or(0.0);
        runs.push_back(run);
      } else if (textDepth > 0) {
        textPath = textPath || tag == u"textPath";
        skipDepth = depth;
      }
    } else if (token == QXmlStreamReader::EndElement) {
      const int depth = static_cast<int>(states.size()) - 1;
      states.pop_back();
      if (skipDepth > 0) {
        if (depth == skipDepth) skipDepth = 0;
      } else if (textDepth > 0 && depth == textDepth) {
        textDepth = 0;
        const bool selfClosing = document[textStartEnd - 2] == u'/';
        const qint64 close = selfClosing ? -1 : document.lastIndexOf(QStringLiteral("</") + reader.qualifiedName().toString(),
                                                                      reader.characterOffset() - 1);
        const qint64 end = selfClosing ? textStartEnd : close < 0 ? -1 : tagEnd(document, close);
        if (end < 0 || end < textBegin) return document;
        // Replaced in place, padded with the newlines it covered so later lines keep their numbers.
        const QStringView original = QStringView(document).mid(textBegin, end - textBegin);
        out += QStringView(document).mid(copied, textBegin - copied);
        out += replacement(textAttributes, runs, font);
        out += QString(original.count(u'\n'), u'\n');
        copied = end;
      } else if (textDepth > 0) {
        // The end of a tspan: what follows continues in the parent's state.
        Run run;
        run.state = states.back();
        runs.push_back(run);
      }
    } else if (token == QXmlStreamReader::Characters && textDepth > 0 && skipDepth == 0) {
      runs.back().text += reader.text();
    }
  }
  if (reader.hasError()) return document;  // the sanitiser names the error
  out += QStringView(document).mid(copied);
  if (perGlyph)
    warnings.push_back(FB_TR("ImportWarning", "text in a single-stroke font: per-glyph x/y/dx/dy lists are not "
                                              "followed, only their first value"));
  if (textPath)
    warnings.push_back(FB_TR("ImportWarning", "text in a single-stroke font: text on a path (<textPath>) is not drawn"));
  return out;
}

}  // namespace fivebar::svg
