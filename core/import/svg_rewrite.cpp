// SPDX-License-Identifier: GPL-3.0-or-later
#include "svg_rewrite.hpp"

#include <QRegularExpression>
#include <QXmlStreamReader>

#include <cmath>

#include "svg_lengths.hpp"
#include "svg_units.hpp"

namespace fivebar::svg {
namespace {

QString num(double v) { return QString::number(v, 'g', 17); }

// A length in user units (svg_lengths.hpp) with one reference for %.
std::optional<double> userUnits(QStringView text, double percentReference, double fontSize,
                                double dpi) {
  return resolveLength(text, LengthAxis::Width,
                       LengthContext{{percentReference, percentReference}, fontSize, dpi});
}

std::optional<double> attributeLength(const QXmlStreamAttributes& a, const char16_t* name) {
  const QString key = QString::fromUtf16(name);
  if (!a.hasAttribute(key)) return std::nullopt;
  const std::optional<Length> length = parseLength(a.value(key));
  if (!length) return 1.0;  // not a length we read: let the renderer decide
  return length->value;
}

}  // namespace

std::map<QString, SymbolInfo> scanSymbols(const QByteArray& document) {
  std::map<QString, SymbolInfo> symbols;
  if (!document.contains("<symbol") && !document.contains(":symbol")) return symbols;
  QXmlStreamReader reader(document);
  while (!reader.atEnd()) {
    if (reader.readNext() != QXmlStreamReader::StartElement || reader.name() != u"symbol") continue;
    const QXmlStreamAttributes a = reader.attributes();
    const QString id = a.value(QStringLiteral("id")).toString();
    if (id.isEmpty()) continue;
    symbols[id] = SymbolInfo{a.value(QStringLiteral("viewBox")).toString(),
                             a.value(QStringLiteral("preserveAspectRatio")).toString(),
                             a.value(QStringLiteral("width")).toString(),
                             a.value(QStringLiteral("height")).toString()};
  }
  return symbols;  // a reader error is reported by the sanitiser's own pass
}

std::map<QString, NestedSvgInfo> scanNestedSvgs(const QByteArray& document) {
  std::map<QString, NestedSvgInfo> svgs;
  // Only when a second <svg> element exists (the namespace URI holds "svg" too: not enough).
  const qsizetype first = document.indexOf("<svg");
  const qsizetype prefixed = document.indexOf(":svg");
  if ((first < 0 || document.indexOf("<svg", first + 4) < 0) &&
      (prefixed < 0 || document.indexOf("svg:svg", document.indexOf("svg:svg") + 7) < 0))
    return svgs;
  QXmlStreamReader reader(document);
  int depth = 0;
  while (!reader.atEnd()) {
    const QXmlStreamReader::TokenType t = reader.readNext();
    if (t == QXmlStreamReader::EndElement) --depth;
    if (t != QXmlStreamReader::StartElement) continue;
    ++depth;
    if (depth < 2 || reader.name() != u"svg") continue;
    const QXmlStreamAttributes a = reader.attributes();
    const QString id = a.value(QStringLiteral("id")).toString();
    if (id.isEmpty()) continue;
    svgs[id] = NestedSvgInfo{a.value(QStringLiteral("x")).toString(), a.value(QStringLiteral("y")).toString(),
                             a.value(QStringLiteral("width")).toString(), a.value(QStringLiteral("height")).toString(),
                             a.value(QStringLiteral("viewBox")).toString(),
                             a.value(QStringLiteral("preserveAspectRatio")).toString()};
  }
  return svgs;
}

bool isZeroSizeShape(QStringView tag, const QXmlStreamAttributes& attributes) {
  if (tag == u"rect") {
    const auto w = attributeLength(attributes, u"width");
    const auto h = attributeLength(attributes, u"height");
    return !w || !h || *w <= 0.0 || *h <= 0.0;
  }
  if (tag == u"circle") {
    const auto r = attributeLength(attributes, u"r");
    return !r || *r <= 0.0;
  }
  if (tag == u"ellipse") {
    auto rx = attributeLength(attributes, u"rx");
    auto ry = attributeLength(attributes, u"ry");
    if (!rx) rx = ry;  // SVG 2: a missing radius is "auto", the other one
    if (!ry) ry = rx;
    return !rx || !ry || *rx <= 0.0 || *ry <= 0.0;
  }
  return false;
}

QString useSymbolTransform(const QXmlStreamAttributes& use, const SymbolInfo& symbol,
                           const UserViewport& viewport, double dpi) {
  auto length = [&](const char16_t* name, double reference, double fallback) {
    const QString key = QString::fromUtf16(name);
    if (!use.hasAttribute(key)) return fallback;
    return userUnits(use.value(key), reference, 16.0, dpi).value_or(fallback);
  };
  const double x = length(u"x", viewport.width, 0.0);
  const double y = length(u"y", viewport.height, 0.0);
  QString out = use.value(QStringLiteral("transform")).toString();
  if (!out.isEmpty()) out += u' ';
  out += QStringLiteral("translate(%1,%2)").arg(num(x), num(y));
  const std::optional<QRectF> box = parseViewBox(symbol.viewBox);
  if (!box || box->width() <= 0.0 || box->height() <= 0.0) return out;
  // Viewport size: the use's width/height, else the symbol's, else 100%.
  auto side = [&](const char16_t* name, const QString& own, double reference) {
    const QString key = QString::fromUtf16(name);
    QString text = use.hasAttribute(key) ? use.value(key).toString() : own;
    if (text.isEmpty() || text == u"auto") text = QStringLiteral("100%");
    return userUnits(text, reference, 16.0, dpi).value_or(reference > 0.0 ? reference : 0.0);
  };
  const double w = side(u"width", symbol.width, viewport.width);
  const double h = side(u"height", symbol.height, viewport.height);
  if (w <= 0.0 || h <= 0.0) return out + QStringLiteral(" scale(0)");
  const QRectF place = placeViewBox(*box, QRectF(0, 0, w, h),
                                    parsePreserveAspectRatio(symbol.preserveAspectRatio));
  return out + QStringLiteral(" translate(%1,%2) scale(%3,%4) translate(%5,%6)")
                   .arg(num(place.x()), num(place.y()), num(place.width() / box->width()),
                        num(place.height() / box->height()), num(-box->x()), num(-box->y()));
}

std::optional<QString> resolveViewportUnits(QStringView value, const UserViewport& viewport) {
  static const QRegularExpression unit(
      QStringLiteral("([+-]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][+-]?\\d+)?)(vmin|vmax|vw|vh)\\b"));
  const QString text = value.toString();
  if (!text.contains(u'v')) return std::nullopt;
  QString out;
  qsizetype last = 0;
  bool changed = false;
  QRegularExpressionMatchIterator it = unit.globalMatch(text);
  while (it.hasNext()) {
    const QRegularExpressionMatch m = it.next();
    const double v = m.captured(1).toDouble();
    const QString u = m.captured(2);
    const double w = viewport.width, h = viewport.height;
    const double ref = u == u"vw" ? w : u == u"vh" ? h : u == u"vmin" ? std::min(w, h) : std::max(w, h);
    out += QStringView(text).mid(last, m.capturedStart(0) - last);
    out += num(v * ref / 100.0);
    last = m.capturedEnd(0);
    changed = true;
  }
  if (!changed) return std::nullopt;
  out += QStringView(text).mid(last);
  return out;
}

std::optional<QString> resolveTextLengths(QStringView value, double percentReference,
                                          double fontSize, double dpi) {
  static const QRegularExpression separators(QStringLiteral("[\\s,]+"));
  const QStringList parts = value.toString().trimmed().split(separators, Qt::SkipEmptyParts);
  bool needed = false;
  for (const QString& p : parts) needed = needed || (!p.isEmpty() && !p.back().isDigit() && p.back() != u'.');
  if (!needed) return std::nullopt;
  QStringList out;
  for (const QString& p : parts) {
    const std::optional<double> v = userUnits(p, percentReference, fontSize, dpi);
    if (!v) return std::nullopt;
    out << num(*v);
  }
  return out.join(u' ');
}

std::optional<double> fontSizeUser(QStringView value, double parentUser, double dpi) {
  const QString t = value.toString().trimmed();
  if (t.isEmpty()) return std::nullopt;
  return userUnits(t, parentUser, parentUser, dpi);
}

std::optional<QString> transformWithOrigin(QStringView transform, QStringView origin,
                                           const UserViewport& viewport, double dpi) {
  const QStringList parts = origin.toString().simplified().split(u' ', Qt::SkipEmptyParts);
  if (parts.isEmpty() || parts.size() > 3) return std::nullopt;
  std::optional<double> x, y;
  auto keyword = [&](const QString& p, std::optional<double>& axisX, std::optional<double>& axisY) {
    if (p == u"left") return (axisX = 0.0), true;
    if (p == u"right") return (axisX = viewport.width), true;
    if (p == u"top") return (axisY = 0.0), true;
    if (p == u"bottom") return (axisY = viewport.height), true;
    return false;
  };
  bool centre[2] = {false, false};
  for (int i = 0; i < std::min<qsizetype>(2, parts.size()); ++i) {
    const QString& p = parts[i];
    if (p == u"center") {
      centre[i] = true;
      continue;
    }
    if (keyword(p, x, y)) continue;
    const std::optional<double> v = userUnits(p, i == 0 ? viewport.width : viewport.height, 16.0, dpi);
    if (!v) return std::nullopt;
    (i == 0 ? x : y) = *v;
  }
  for (int i = 0; i < 2; ++i) {
    if (!centre[i]) continue;
    // "center" fills whichever axis the other value did not take.
    if (!x) x = 0.5 * viewport.width;
    else if (!y) y = 0.5 * viewport.height;
  }
  const double ox = x.value_or(parts.size() == 1 && y ? 0.5 * viewport.width : 0.0);
  const double oy = y.value_or(parts.size() == 1 && x ? 0.5 * viewport.height : 0.0);
  if (ox == 0.0 && oy == 0.0) return transform.toString();
  return QStringLiteral("translate(%1,%2) %3 translate(%4,%5)")
      .arg(num(ox), num(oy), transform.toString(), num(-ox), num(-oy));
}

}  // namespace fivebar::svg
