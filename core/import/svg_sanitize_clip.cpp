// SPDX-License-Identifier: GPL-3.0-or-later
// The Sanitizer's clip paths (capture_engine.hpp kClip*): a <clipPath id> becomes a <g id> inside
// <defs> whose shapes are painted plainly (filled black, no stroke, their clip-rule as fill rule:
// the engine takes their geometry only); an element with clip-path="url(#id)" is written between
// a Begin sentinel and a tail <g transform="the element's transform"> holding a Shapes sentinel
// (user space or objectBoundingBox), a <use> of the clip's content and an Apply sentinel. A
// clipPath's own clip-path adds one more Begin ... Apply around it (the regions intersect).
#include <QRegularExpression>

#include <algorithm>

#include "sanitizer.hpp"
#include "svg_lengths.hpp"

namespace fivebar::svg {

std::map<QString, ClipPathInfo> scanClipPaths(const QByteArray& document) {
  std::map<QString, ClipPathInfo> clips;
  if (!document.contains("clipPath")) return clips;
  QXmlStreamReader reader(document);
  while (!reader.atEnd()) {
    if (reader.readNext() != QXmlStreamReader::StartElement || reader.name() != u"clipPath") continue;
    const QXmlStreamAttributes a = reader.attributes();
    const QString id = a.value(QStringLiteral("id")).toString();
    if (id.isEmpty()) continue;
    ClipPathInfo info;
    info.objectBoundingBox = a.value(QStringLiteral("clipPathUnits")).trimmed() == u"objectBoundingBox";
    info.clipRule = a.value(QStringLiteral("clip-rule")).toString();
    info.clipRef = clipPathReference(a);
    clips[id] = info;
  }
  return clips;
}

QString clipPathReference(const QXmlStreamAttributes& attributes) {
  QString value = attributes.value(QStringLiteral("clip-path")).toString();
  if (const QString s = styleValue(attributes.value(QStringLiteral("style")), u"clip-path"); !s.isEmpty())
    value = s;
  static const QRegularExpression url(QStringLiteral("^\\s*url\\(\\s*['\"]?#([^'\")\\s]+)['\"]?\\s*\\)\\s*$"));
  const QRegularExpressionMatch m = url.match(value);
  return m.hasMatch() ? m.captured(1) : QString();
}

namespace detail {

void Sanitizer::writeClipSentinel(std::uint32_t command) {
  writer_.writeStartElement(svgNamespace_, QStringLiteral("line"));
  writer_.writeAttribute(QStringLiteral("x1"), QStringLiteral("0"));
  writer_.writeAttribute(QStringLiteral("y1"), QStringLiteral("0"));
  writer_.writeAttribute(QStringLiteral("x2"), QStringLiteral("1"));
  writer_.writeAttribute(QStringLiteral("y2"), QStringLiteral("0"));
  const QString colour = QStringLiteral("#%1").arg(command, 6, 16, QLatin1Char('0'));
  writer_.writeAttribute(QStringLiteral("style"),
                         QStringLiteral("stroke:%1;stroke-width:0.00048828125;stroke-opacity:1;"
                                        "opacity:1;display:inline;visibility:visible;stroke-dasharray:none")
                             .arg(colour));
  writer_.writeEndElement();
}

bool Sanitizer::writeClipPathDefinition(QStringView tag, const QXmlStreamAttributes& attributes) {
  if (tag != u"clipPath") return false;
  const QString ns = reader_.namespaceUri().toString();
  writer_.writeStartElement(ns, QStringLiteral("defs"));
  writer_.writeStartElement(ns, QStringLiteral("g"));
  writer_.writeAttribute(QStringLiteral("id"), attributes.value(QStringLiteral("id")).toString());
  if (const QStringView t = attributes.value(QStringLiteral("transform")); !t.isEmpty())
    writer_.writeAttribute(QStringLiteral("transform"), t.toString());
  extraEnds_.back() = 1;
  if (clipContentDepth_ == 0) {
    clipContentDepth_ = depth_;
    clipContentRule_ = attributes.value(QStringLiteral("clip-rule")).toString();
  }
  return true;
}

// A shape inside a clip path: its geometry only, filled with its clip-rule, never stroked; style
// sheets cannot change that (inline style), its own clip-path and markers are not applied.
QXmlStreamAttributes Sanitizer::clipContentAttributes(const QXmlStreamAttributes& attributes) const {
  static const QStringList paint{QStringLiteral("fill"),           QStringLiteral("stroke"),       QStringLiteral("fill-rule"),
                                 QStringLiteral("opacity"),        QStringLiteral("fill-opacity"), QStringLiteral("stroke-opacity"),
                                 QStringLiteral("clip-path"),      QStringLiteral("marker"),       QStringLiteral("marker-start"),
                                 QStringLiteral("marker-mid"),     QStringLiteral("marker-end"),   QStringLiteral("stroke-dasharray"),
                                 QStringLiteral("clip-rule"),      QStringLiteral("style"),        QStringLiteral("mask"),
                                 QStringLiteral("filter")};
  QString rule = clipContentRule_;
  QStringView style = attributes.value(QStringLiteral("style"));
  if (const QStringView r = attributes.value(QStringLiteral("clip-rule")); !r.isEmpty()) rule = r.toString();
  if (const QString r = styleValue(style, u"clip-rule"); !r.isEmpty()) rule = r;
  rule = rule.trimmed() == u"evenodd" ? QStringLiteral("evenodd") : QStringLiteral("nonzero");
  QXmlStreamAttributes out;
  for (const QXmlStreamAttribute& a : attributes)
    if (!a.namespaceUri().isEmpty() || !paint.contains(a.name().toString())) out.append(a);
  QString kept;  // display and visibility still decide whether the shape counts
  for (const char16_t* p : {u"display", u"visibility"})
    if (const QString v = styleValue(style, QStringView(p)); !v.isEmpty()) kept += QString::fromUtf16(p) + u':' + v + u';';
  out.append(QStringLiteral("style"), kept + QStringLiteral("fill:black;fill-opacity:1;stroke:none;opacity:1;fill-rule:") + rule);
  return out;
}

void Sanitizer::beginClip(QXmlStreamAttributes& attributes) {
  ClipTail tail;
  if (clipContentDepth_ == 0 && reader_.name() != u"clipPath") {
    QString id = clipPathReference(attributes);
    for (int guard = 0; !id.isEmpty() && guard < 16; ++guard) {  // a chain of clip paths, cycles cut
      const auto clip = clipPaths_.find(id);
      if (clip == clipPaths_.end()) {
        warnAt(attributes, FB_TR("ImportWarning", "clip-path #%1 not found: drawn unclipped").arg(id.toStdString()));
        break;
      }
      if (std::find(tail.ids.begin(), tail.ids.end(), id) != tail.ids.end()) break;
      tail.ids.push_back(id);
      id = clip->second.clipRef;
    }
  }
  if (clipContentDepth_ == 0) tail.viewport = clippedViewport(attributes);
  if (!tail.ids.empty() || tail.viewport) {
    tail.transform = attributes.value(QStringLiteral("transform")).toString();
    if (const QString id = attributes.value(QStringLiteral("id")).toString(); !id.isEmpty()) {
      writer_.writeStartElement(svgNamespace_, QStringLiteral("g"));
      writer_.writeAttribute(QStringLiteral("id"), id);
      QXmlStreamAttributes rest;
      for (const QXmlStreamAttribute& a : attributes)
        if (!(a.name() == u"id" && a.namespaceUri().isEmpty())) rest.append(a);
      attributes = rest;
      tail.wrapped = true;
    }
    for (std::size_t i = 0; i < tail.ids.size() + (tail.viewport ? 1 : 0); ++i) writeClipSentinel(kClipBegin);
  }
  clipTails_.push_back(std::move(tail));
}

// SVG clips a nested <svg> and the content of a used <symbol> to their viewport (overflow hidden,
// their initial value): the rectangle in the element's user space. Lengths are plain numbers by
// now (rewriteAttributes); a missing size is 100 % of the viewport.
std::optional<QRectF> Sanitizer::clippedViewport(const QXmlStreamAttributes& attributes) const {
  const QStringView tag = reader_.name();
  if (!((tag == u"svg" && depth_ > 1) || tag == u"use")) return std::nullopt;
  if (const NestedSvgInfo* svg = sizedSvgOfUse(attributes)) {  // the svg's viewport at the use's size
    const NestedViewport v = viewportAtUse(*svg, attributes);
    auto side = [&](const QString& text, double parent) {
      const QString t = text.isEmpty() ? QStringLiteral("100%") : text;
      return resolveLength(t, LengthAxis::Width, LengthContext{{parent, parent}, 16.0, dpi_}).value_or(parent);
    };
    auto at = [&](const QString& text, double parent) {
      return resolveLength(text, LengthAxis::Width, LengthContext{{parent, parent}, 16.0, dpi_}).value_or(0.0);
    };
    bool ok = false;
    const double ux = attributes.value(QStringLiteral("x")).toDouble(&ok), x = ok ? ux : 0.0;
    const double uy = attributes.value(QStringLiteral("y")).toDouble(&ok), y = ok ? uy : 0.0;
    const double w = side(v.width, rootViewport_.width), h = side(v.height, rootViewport_.height);
    if (!(w > 0.0) || !(h > 0.0)) return std::nullopt;
    return QRectF(x + at(v.x, rootViewport_.width), y + at(v.y, rootViewport_.height), w, h);
  }
  if (tag == u"use") {
    const QStringView href = attributes.value(kXlinkNs, QStringLiteral("href"));
    if (!href.startsWith(u'#') || !symbols_.count(href.mid(1).toString())) return std::nullopt;
  }
  auto number = [&](const char* name, double fallback) {
    bool ok = false;
    const double v = attributes.value(QLatin1String(name)).trimmed().toDouble(&ok);
    return ok ? v : fallback;
  };
  double w = number("width", -1.0), h = number("height", -1.0);
  if (tag == u"use") {  // the use's size, else the symbol's
    const SymbolInfo& symbol = symbols_.at(attributes.value(kXlinkNs, QStringLiteral("href")).mid(1).toString());
    const LengthContext lengths{viewport_, fontSizes_.empty() ? 16.0 : fontSizes_.back(), dpi_};
    if (w < 0.0) w = resolveLength(symbol.width, LengthAxis::Width, lengths).value_or(-1.0);
    if (h < 0.0) h = resolveLength(symbol.height, LengthAxis::Height, lengths).value_or(-1.0);
  }
  if (w < 0.0) w = viewport_.width;
  if (h < 0.0) h = viewport_.height;
  if (!(w > 0.0) || !(h > 0.0)) return std::nullopt;
  return QRectF(number("x", 0.0), number("y", 0.0), w, h);
}

void Sanitizer::endClip() {
  if (clipTails_.empty()) return;
  const ClipTail tail = std::move(clipTails_.back());
  clipTails_.pop_back();
  if (tail.ids.empty() && !tail.viewport) return;
  writer_.writeStartElement(svgNamespace_, QStringLiteral("g"));
  if (!tail.transform.isEmpty()) writer_.writeAttribute(QStringLiteral("transform"), tail.transform);
  for (const QString& id : tail.ids) {
    writeClipSentinel(clipPaths_.at(id).objectBoundingBox ? kClipShapesBox : kClipShapesUser);
    writer_.writeStartElement(svgNamespace_, QStringLiteral("use"));
    writer_.writeAttribute(kXlinkNs, QStringLiteral("href"), u'#' + id);
    writer_.writeEndElement();
    writeClipSentinel(kClipApply);
  }
  if (const std::optional<QRectF> v = tail.viewport) {
    writeClipSentinel(kClipShapesUser);
    writer_.writeStartElement(svgNamespace_, QStringLiteral("rect"));
    auto num = [](double d) { return QString::number(d, 'g', 17); };
    writer_.writeAttribute(QStringLiteral("x"), num(v->x()));
    writer_.writeAttribute(QStringLiteral("y"), num(v->y()));
    writer_.writeAttribute(QStringLiteral("width"), num(v->width()));
    writer_.writeAttribute(QStringLiteral("height"), num(v->height()));
    writer_.writeAttribute(QStringLiteral("style"), QStringLiteral("fill:black;stroke:none;opacity:1;display:inline;visibility:visible"));
    writer_.writeEndElement();
    writeClipSentinel(kClipApply);
  }
  writer_.writeEndElement();
  if (tail.wrapped) writer_.writeEndElement();
}

}  // namespace detail
}  // namespace fivebar::svg
