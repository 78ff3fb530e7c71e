// SPDX-License-Identifier: GPL-3.0-or-later
// The Sanitizer's rewrites for browser fidelity (symbols, lengths, transform-origin, path data
// errors, unsupported features) and the number checks; see svg_rewrite.hpp.
#include <QRectF>
#include <QRegularExpression>

#include "path_data.hpp"
#include "svg_lengths.hpp"
#include "sanitizer.hpp"

namespace fivebar::svg {
namespace detail {

void Sanitizer::setViewport() {
  const RootAttributes& root = result_.root;
  if (const std::optional<QRectF> box = parseViewBox(root.viewBox); box && box->width() > 0.0) {
    viewport_ = rootViewport_ = {box->width(), box->height()};
    return;
  }
  auto side = [&](const QString& text) {
    const std::optional<Length> length = parseLength(text);
    if (!length || length->unit == LengthUnit::Percent) return 0.0;
    return lengthToMm(*length, dpi_).value_or(0.0) * dpi_ / 25.4;
  };
  viewport_ = rootViewport_ = {side(root.width), side(root.height)};
}

// Lengths Qt 6.4 misreads (units, em/ex, % on the wrong axis: svg_lengths.hpp), made user units;
// transform-origin folded into transform.
QXmlStreamAttributes Sanitizer::rewriteAttributes(QStringView tag,
                                                  const QXmlStreamAttributes& attributes) {
  const double parentFont = fontSizes_.empty() ? 16.0 : fontSizes_.back();
  double font = parentFont;
  QStringView fontText = attributes.value(QStringLiteral("font-size"));
  const QString styleFont = styleValue(attributes.value(QStringLiteral("style")), u"font-size");
  if (!styleFont.isEmpty()) fontText = styleFont;
  if (!fontText.isEmpty()) font = fontSizeUser(fontText, parentFont, dpi_).value_or(parentFont);
  fontSizes_.push_back(font);
  const bool text = tag == u"text" || tag == u"tspan";
  const bool root = depth_ == 1;  // its size is the page's (svg_units.hpp computePage)
  // Most elements need nothing: find out without copying a value.
  bool needed = tag == u"ellipse";
  for (const QXmlStreamAttribute& a : attributes) {
    if (needed) break;
    if (!a.namespaceUri().isEmpty()) continue;
    const QStringView n = a.name(), v = a.value();
    needed = n == u"transform-origin" || v.contains(u"vw") || v.contains(u"vh") ||
             v.contains(u"vmin") || v.contains(u"vmax") ||
             (!root && hasLengthUnit(v) &&
              (n == u"font-size" || n == u"stroke-width" || lengthAttributeAxis(tag, n))) ||
             (text && (n == u"x" || n == u"dx" || n == u"y" || n == u"dy") && hasLengthUnit(v)) ||
             (!patternIds_.isEmpty() && (n == u"fill" || n == u"style") && v.contains(u"url(")) ||
             ((n == u"stroke-dasharray" || n == u"stroke-dashoffset") && hasLengthUnit(v));
  }
  if (!needed) return attributes;
  const LengthContext lengths{viewport_, font, dpi_};
  QXmlStreamAttributes out;
  out.reserve(attributes.size());
  QString origin;
  for (const QXmlStreamAttribute& a : attributes) {
    if (!a.namespaceUri().isEmpty()) {
      out.append(a);
      continue;
    }
    const QStringView n = a.name();
    QString value = a.value().toString();
    if (n == u"transform-origin") {
      origin = value;
      continue;
    }
    if (const std::optional<QString> v = resolveViewportUnits(value, viewport_)) value = *v;
    if (!patternIds_.isEmpty() && n == u"fill") value = withoutPatternPaint(value);
    if (!patternIds_.isEmpty() && n == u"style" && value.contains(u"url(")) {
      QStringList declarations = value.split(u';');
      for (QString& d : declarations)
        if (const qsizetype colon = d.indexOf(u':'); colon > 0 && d.left(colon).trimmed() == u"fill")
          d = QStringLiteral("fill:") + withoutPatternPaint(d.mid(colon + 1));
      value = declarations.join(u';');
    }
    if ((n == u"stroke-dasharray" || n == u"stroke-dashoffset") && hasLengthUnit(value)) {
      // Qt SVG reads plain numbers only; % of the normalised diagonal (SVG 2).
      static const QRegularExpression separators(QStringLiteral("[\\s,]+"));
      QStringList parts = value.trimmed().split(separators, Qt::SkipEmptyParts);
      bool all = !parts.isEmpty();
      for (QString& part : parts) {
        const std::optional<double> v = resolveLength(part, LengthAxis::Diagonal, lengths);
        all = all && v.has_value();
        if (v) part = QString::number(*v, 'g', 17);
      }
      if (all) value = parts.join(u' ');
    }
    if (!root && hasLengthUnit(value)) {
      if (n == u"font-size") value = QString::number(font, 'g', 17);
      else if (n == u"stroke-width") {
        if (const std::optional<double> v = resolveLength(value, LengthAxis::Diagonal, lengths))
          value = QString::number(*v, 'g', 17);
      }
      else if (const std::optional<LengthAxis> axis = lengthAttributeAxis(tag, n))
        if (const std::optional<double> v = resolveLength(value, *axis, lengths))
          value = QString::number(*v, 'g', 17);
    }
    if (text && (n == u"x" || n == u"dx" || n == u"y" || n == u"dy")) {
      const double reference = (n == u"x" || n == u"dx") ? viewport_.width : viewport_.height;
      if (const std::optional<QString> v = resolveTextLengths(value, reference, font, dpi_)) value = *v;
    }
    out.append(n.toString(), value);
  }
  if (tag == u"ellipse") {  // SVG 2: a missing radius is "auto", the other one (Qt 6.4: 0)
    const bool rx = out.hasAttribute(QStringLiteral("rx")), ry = out.hasAttribute(QStringLiteral("ry"));
    if (rx && !ry) out.append(QStringLiteral("ry"), out.value(QStringLiteral("rx")).toString());
    if (ry && !rx) out.append(QStringLiteral("rx"), out.value(QStringLiteral("ry")).toString());
  }
  if (!origin.isEmpty()) {
    const QString transform = out.value(QStringLiteral("transform")).toString();
    const std::optional<QString> folded = transformWithOrigin(transform, origin, viewport_, dpi_);
    if (!folded) {
      warnAt(attributes, FB_TR("ImportWarning", "transform-origin=\"%1\" not understood: ignored").arg(origin.toStdString()));
    } else if (!transform.isEmpty()) {
      QXmlStreamAttributes replaced;
      for (const QXmlStreamAttribute& a : out)
        replaced.append(a.name() == u"transform" && a.namespaceUri().isEmpty()
                            ? QXmlStreamAttribute(QStringLiteral("transform"), *folded)
                            : a);
      out = replaced;
    }
  }
  return out;
}

QString Sanitizer::withoutPatternPaint(const QString& paint) const {
  static const QRegularExpression url(
      QStringLiteral("^\\s*url\\(\\s*['\"]?#([^'\")\\s]+)['\"]?\\s*\\)\\s*(.*)$"));
  const QRegularExpressionMatch m = url.match(paint);
  if (!m.hasMatch() || !patternIds_.contains(m.captured(1))) return paint;
  const QString fallback = m.captured(2).trimmed();
  return fallback.isEmpty() || fallback == u"none" ? QStringLiteral("black") : fallback;
}

// Features not drawn: each is named once per file with its first line.
void Sanitizer::warnUnsupported(QStringView tag, const QXmlStreamAttributes& attributes) {
  bool mask = false, rotate = false;
  for (const QXmlStreamAttribute& a : attributes) {
    if (!a.namespaceUri().isEmpty()) continue;
    const QStringView n = a.name();
    if (n == u"style") {
      const QStringView style = a.value();
      mask = mask || style.contains(u"mask");
      if (style.contains(u"transform-origin")) warn(FB_TR("ImportWarning", "transform-origin in a style is not applied"));
    }
    mask = mask || n == u"mask";
    rotate = rotate || n == u"rotate";
  }
  if (mask) warn(FB_TR("ImportWarning", "mask not applied: masked shapes are drawn whole"));
  if (rotate && (tag == u"text" || tag == u"tspan"))
    warn(FB_TR("ImportWarning", "per-glyph rotate on <text> is not applied: glyphs are drawn upright"));
  if (tag == u"textPath") warn(FB_TR("ImportWarning", "text on a path (<textPath>) is not drawn"));
  if (tag == u"pattern") warn(FB_TR("ImportWarning", "pattern fills are drawn as outlines, without the pattern"));
}

// Qt SVG draws a path up to the first error in its data, silently: say so.
void Sanitizer::checkPathData(const QXmlStreamAttributes& attributes) {
  const QStringView d = attributes.value(QStringLiteral("d"));
  if (d.size() > kPathScanChars) return;  // writeSplitPath parses and reports it
  const ParsedPath parsed = parsePathData(d);
  if (!parsed.error) return;
  const QString near = d.mid(parsed.errorOffset, 16).toString().simplified();
  warnAt(attributes, FB_TR("ImportWarning", "attribute d: invalid path data at character %1 %2: drawn up to the error")
                         .arg(static_cast<long long>(parsed.errorOffset + 1))
                         .arg("(\"" + near.toStdString() + "\")"));
}

// <symbol> -> <defs><g>: never drawn by itself. <use> of a symbol -> <g transform><use>.
bool Sanitizer::writeSymbolOrUse(QStringView tag, const QXmlStreamAttributes& attributes) {
  const QString ns = reader_.namespaceUri().toString();
  if (tag == u"symbol") {
    writer_.writeStartElement(ns, QStringLiteral("defs"));
    writer_.writeStartElement(ns, QStringLiteral("g"));
    for (const QXmlStreamAttribute& a : attributes) {
      const QStringView n = a.name();
      if (a.namespaceUri().isEmpty() &&
          (n == u"viewBox" || n == u"preserveAspectRatio" || n == u"x" || n == u"y" ||
           n == u"width" || n == u"height" || n == u"refX" || n == u"refY"))
        continue;
      writer_.writeAttribute(a);
    }
    extraEnds_.back() = 1;
    return true;
  }
  if (tag != u"use") return false;
  const QStringView href = attributes.value(kXlinkNs, QStringLiteral("href"));
  const auto symbol = href.startsWith(u'#') ? symbols_.find(href.mid(1).toString()) : symbols_.end();
  if (symbol == symbols_.end()) return false;
  writer_.writeStartElement(ns, QStringLiteral("g"));
  for (const QXmlStreamAttribute& a : attributes) {
    const QStringView n = a.name();
    if (a.namespaceUri().isEmpty() && (n == u"x" || n == u"y" || n == u"width" ||
                                       n == u"height" || n == u"transform"))
      continue;
    if (n == u"href") continue;
    writer_.writeAttribute(a);
  }
  writer_.writeAttribute(QStringLiteral("transform"),
                         useSymbolTransform(attributes, symbol->second, viewport_, dpi_));
  writer_.writeStartElement(ns, QStringLiteral("use"));
  writer_.writeAttribute(kXlinkNs, QStringLiteral("href"), href.toString());
  extraEnds_.back() = 1;
  return true;
}

// Marker properties are inherited: each written element gets its state; a path, line, polyline
// or polygon with markers gets its instances (written after it by writeMarkerInstances).
void Sanitizer::pushMarkerState(QStringView tag, const QXmlStreamAttributes& attributes) {
  MarkerState state;
  if (!markerStates_.empty()) {
    state.refs = markerStates_.back().refs;
    state.strokeWidth = markerStates_.back().strokeWidth;
  }
  const MarkerRefs inherited = state.refs;
  state.refs = markerRefs(attributes, inherited, tag, &markerSheet_);
  state.strokeWidth = strokeWidthUser(attributes, state.strokeWidth);
  if (markerContentDepth_ == 0 && state.refs.any()) {
    if (tag == u"path" || tag == u"line" || tag == u"polyline" || tag == u"polygon") {
      state.transform = attributes.value(QStringLiteral("transform")).toString();
      const std::vector<MarkerVertex> vertices = markerVertices(tag, attributes);
      constexpr std::size_t kMaxMarkerInstances = 100000;
      auto place = [&](const QString& id, std::size_t i, MarkerSlot slot) {
        if (id.isEmpty()) return;
        const auto marker = markers_.find(id);
        if (marker == markers_.end())
          return warnAt(attributes, FB_TR("ImportWarning", "marker #%1 not found: not drawn").arg(id.toStdString()));
        if (markerInstances_ >= kMaxMarkerInstances)
          return warn(FB_TR("ImportWarning", "more than 100000 marker instances: the rest are not drawn"));
        if (marker->second.clips)
          warn(FB_TR("ImportWarning", "marker overflow clipping not applied: marker content is drawn whole"));
        if (const std::optional<QString> t =
                markerInstanceTransform(marker->second, vertices[i], slot, state.strokeWidth,
                                        LengthContext{viewport_, fontSizes_.back(), dpi_})) {
          state.instances.emplace_back(id, *t);
          ++markerInstances_;
        }
      };
      if (!vertices.empty()) {
        place(state.refs.start, 0, MarkerSlot::Start);
        for (std::size_t i = 1; i + 1 < vertices.size(); ++i) place(state.refs.mid, i, MarkerSlot::Mid);
        place(state.refs.end, vertices.size() - 1, MarkerSlot::End);
      }
    } else if ((tag == u"rect" || tag == u"circle" || tag == u"ellipse") &&
               (state.refs.start != inherited.start || state.refs.mid != inherited.mid ||
                state.refs.end != inherited.end)) {  // SVG draws markers on the four above only
      warn(FB_TR("ImportWarning", "markers on %1 are not drawn (drawn on path, line, polyline and polygon)")
               .arg(QStringLiteral("<%1>").arg(tag).toStdString()));
    }
  }
  markerStates_.push_back(std::move(state));
}

// <marker id> -> <defs><g id>: its content, never drawn by itself, instanced by <use>.
bool Sanitizer::writeMarkerDefinition(QStringView tag, const QXmlStreamAttributes& attributes) {
  if (tag != u"marker") return false;
  const QString ns = reader_.namespaceUri().toString();
  writer_.writeStartElement(ns, QStringLiteral("defs"));
  writer_.writeStartElement(ns, QStringLiteral("g"));
  writer_.writeAttribute(QStringLiteral("id"), attributes.value(QStringLiteral("id")).toString());
  extraEnds_.back() = 1;
  if (markerContentDepth_ == 0) markerContentDepth_ = depth_;
  return true;
}

void Sanitizer::writeMarkerInstances() {
  const MarkerState& state = markerStates_.back();
  if (state.instances.empty()) return;
  writer_.writeStartElement(svgNamespace_, QStringLiteral("g"));
  if (!state.transform.isEmpty()) writer_.writeAttribute(QStringLiteral("transform"), state.transform);
  for (const auto& [id, transform] : state.instances) {
    writer_.writeStartElement(svgNamespace_, QStringLiteral("use"));
    writer_.writeAttribute(kXlinkNs, QStringLiteral("href"), u'#' + id);
    writer_.writeAttribute(QStringLiteral("transform"), transform);
    writer_.writeEndElement();
  }
  writer_.writeEndElement();
}

}  // namespace detail

qsizetype findNonFiniteNumber(QStringView value) {
  const qsizetype n = value.size();
  for (qsizetype i = 0; i < n; ++i) {
    const char16_t c = value[i].unicode() | 0x20;  // ASCII lower case
    if (i + 2 < n && (c == u'n' || c == u'i')) {
      const char16_t c1 = value[i + 1].unicode() | 0x20, c2 = value[i + 2].unicode() | 0x20;
      if ((c == u'n' && c1 == u'a' && c2 == u'n') || (c == u'i' && c1 == u'n' && c2 == u'f'))
        return i;
    }
    if (c == u'e' && i > 0 && value[i - 1].isDigit()) {
      qsizetype j = i + 1;
      bool negative = false;
      if (j < n && (value[j] == u'+' || value[j] == u'-')) negative = value[j++] == u'-';
      int exponent = 0;
      while (j < n && value[j].isDigit() && exponent < 100000)
        exponent = exponent * 10 + (value[j++].unicode() - u'0');
      if (!negative && exponent > 300) {
        qsizetype start = i - 1;
        while (start > 0 && (value[start - 1].isDigit() || value[start - 1] == u'.')) --start;
        if (start > 0 && (value[start - 1] == u'-' || value[start - 1] == u'+')) --start;
        return start;
      }
    }
  }
  return -1;
}

bool hasNonFiniteNumber(QStringView value) { return findNonFiniteNumber(value) >= 0; }

std::optional<NonFiniteNumber> firstNonFiniteNumber(QStringView value) {
  const qsizetype at = findNonFiniteNumber(value);
  if (at < 0) return std::nullopt;
  qsizetype end = at;
  while (end < value.size() && end - at < 24 && !value[end].isSpace() && value[end] != u',' &&
         value[end] != u')' && value[end] != u';' && (end == at || value[end] != u'-'))
    ++end;
  const std::string token = value.mid(at, end - at).toString().toStdString();
  const char16_t c = value[at].unicode() | 0x20;
  return NonFiniteNumber{token, c == u'n' || c == u'i'};
}


}  // namespace fivebar::svg
