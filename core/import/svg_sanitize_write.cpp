// SPDX-License-Identifier: GPL-3.0-or-later
// The Sanitizer's writers: layer sentinels, namespaces, a nested <svg> as a <g>, path data with
// arcs or beyond Qt SVG's element limit, rounded rectangles as the path SVG defines for them
// (see svg_sanitize.hpp).
#include "path_data.hpp"
#include "sanitizer.hpp"

namespace fivebar::svg::detail {

void Sanitizer::writeSentinel(int index) {
  const int code = index + 1;
  writer_.writeStartElement(svgNamespace_, QStringLiteral("line"));
  writer_.writeAttribute(QStringLiteral("x1"), QStringLiteral("0"));
  writer_.writeAttribute(QStringLiteral("y1"), QStringLiteral("0"));
  writer_.writeAttribute(QStringLiteral("x2"), QStringLiteral("1"));
  writer_.writeAttribute(QStringLiteral("y2"), QStringLiteral("0"));
  writer_.writeAttribute(QStringLiteral("stroke"),
                         QStringLiteral("#%1").arg(code, 6, 16, QLatin1Char('0')));
  writer_.writeAttribute(QStringLiteral("stroke-width"), QStringLiteral("0.0009765625"));
  writer_.writeAttribute(QStringLiteral("stroke-opacity"), QStringLiteral("1"));
  writer_.writeAttribute(QStringLiteral("opacity"), QStringLiteral("1"));
  writer_.writeAttribute(QStringLiteral("display"), QStringLiteral("inline"));
  writer_.writeAttribute(QStringLiteral("visibility"), QStringLiteral("visible"));
  // Inline style too, so that a document style sheet ("line { stroke-width: 3 }") cannot
  // override the sentinel's marks.
  writer_.writeAttribute(QStringLiteral("style"),
                         QStringLiteral("stroke:#%1;stroke-width:0.0009765625;stroke-opacity:1;"
                                        "opacity:1;display:inline;visibility:visible")
                             .arg(code, 6, 16, QLatin1Char('0')));
  writer_.writeEndElement();
}

// Declares the element's namespaces (before its start tag, so that the writer uses the
// document's own prefixes); the root also gets xlink, which "href" conversion relies on.
void Sanitizer::writeNamespaces() {
  bool hasXlink = depth_ > 1;
  for (const QXmlStreamNamespaceDeclaration& ns : reader_.namespaceDeclarations()) {
    if (ns.prefix().isEmpty()) {
      writer_.writeDefaultNamespace(ns.namespaceUri().toString());
    } else if (ns.prefix() == u"xlink") {
      if (depth_ == 1) writer_.writeNamespace(kXlinkNs, QStringLiteral("xlink"));
      hasXlink = true;
    } else {
      writer_.writeNamespace(ns.namespaceUri().toString(), ns.prefix().toString());
    }
  }
  if (!hasXlink) writer_.writeNamespace(kXlinkNs, QStringLiteral("xlink"));
}

// Qt SVG 6.4 ignores a nested <svg>'s position and viewBox: write it as a <g> with the
// equivalent transform.
void Sanitizer::writeNestedSvgAsGroup(const QXmlStreamAttributes& attributes) {
  NestedViewport nested;
  QXmlStreamAttributes kept;
  for (const QXmlStreamAttribute& a : attributes) {
    const QStringView n = a.name();
    const QString v = a.value().toString();
    if (!a.namespaceUri().isEmpty()) kept.append(a);
    else if (n == u"x") nested.x = v;
    else if (n == u"y") nested.y = v;
    else if (n == u"width") nested.width = v;
    else if (n == u"height") nested.height = v;
    else if (n == u"viewBox") nested.viewBox = v;
    else if (n == u"preserveAspectRatio") nested.preserveAspectRatio = v;
    else if (n != u"transform") kept.append(a);
  }
  writer_.writeStartElement(reader_.namespaceUri().toString(), QStringLiteral("g"));
  writer_.writeAttributes(kept);
  QSizeF inner;
  writer_.writeAttribute(QStringLiteral("transform"),
                         nestedViewportTransform(nested, viewport_.width, viewport_.height, dpi_, &inner));
  outerViewports_.emplace_back(depth_, viewport_);
  viewport_ = {inner.width(), inner.height()};
}

// Rewrites the path data when Qt SVG would not draw it as SVG means it: elliptical arcs become
// our cubics (path_data.hpp appendArcAsCubics; Qt's own are up to 0.027 mm off on r = 100 mm),
// and data beyond Qt's 32,767-element limit is split into several <path>s.
bool Sanitizer::writeSplitPath(const QXmlStreamAttributes& attributes) {
  const QStringView d = attributes.value(QStringLiteral("d"));
  const bool arcs = d.contains(u'a') || d.contains(u'A');  // no other command has these letters
  if (!arcs && d.size() <= kPathScanChars) return false;
  ParsedPath parsed = parsePathData(d);
  if (arcs) parsed.commands = arcsAsCubics(parsed.commands);
  long long estimate = 0;
  for (const PathCommand& c : parsed.commands) estimate += qtElementEstimate(c);
  const bool split = estimate > kMaxPathElements;
  if (!split && !arcs) return false;
  std::vector<QString> parts = splitPathData(parsed.commands, kMaxPathElements);
  if (parts.empty()) parts.emplace_back();
  if (split) {
    warn(FB_TR("ImportWarning", "long <path> split into %1 parts to avoid Qt SVG's 32,767-element truncation")
             .arg(parts.size()));
    if (parsed.error)
      warnAt(attributes, FB_TR("ImportWarning", "attribute d: invalid path data at character %1: drawn up to the error")
                             .arg(static_cast<long long>(parsed.errorOffset + 1)));
  } else {
    checkPathData(attributes);
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) writer_.writeStartElement(reader_.namespaceUri().toString(), QStringLiteral("path"));
    for (const QXmlStreamAttribute& a : attributes) {
      if (a.name() == u"d" && a.namespaceUri().isEmpty()) continue;
      if (i > 0 && a.name() == u"id") continue;  // ids must stay unique
      writer_.writeAttribute(a);
    }
    if (!parts[i].isEmpty()) writer_.writeAttribute(QStringLiteral("d"), parts[i]);
    if (i + 1 < parts.size()) writer_.writeEndElement();
  }
  return true;
}

// A <rect> with rounded corners becomes the <path> SVG defines for it (rx/ry: one stands in for
// a missing other, each at most half the side), its corners our arcs: Qt SVG would round them
// with its own (drawRoundedRect: 90 deg cubics). Only plain numbers (user units) are converted;
// anything else (units, %, auto spelled out) is left to Qt SVG.
bool Sanitizer::writeRoundedRect(const QXmlStreamAttributes& attributes) {
  if (rectStyled_) return false;
  auto number = [&](const char* name, double fallback, bool& ok) {
    const QStringView v = attributes.value(QLatin1String(name)).trimmed();
    if (v.isEmpty()) return fallback;
    const std::optional<Length> length = parseLength(v);
    if (!length || (length->unit != LengthUnit::None && length->unit != LengthUnit::Px)) ok = false;
    return length ? length->value : 0.0;
  };
  bool ok = true;
  const double x = number("x", 0.0, ok), y = number("y", 0.0, ok);
  const double w = number("width", 0.0, ok), h = number("height", 0.0, ok);
  double rx = number("rx", -1.0, ok), ry = number("ry", -1.0, ok);
  if (!ok || !(w > 0.0) || !(h > 0.0)) return false;
  if (rx < 0.0 && ry < 0.0) return false;  // no radius given: square corners
  if (rx < 0.0) rx = ry;
  if (ry < 0.0) ry = rx;
  if (rx == 0.0 || ry == 0.0) return false;  // square corners
  if (attributes.value(QStringLiteral("rx")).trimmed().startsWith(u'-') ||
      attributes.value(QStringLiteral("ry")).trimmed().startsWith(u'-'))
    return false;
  rx = std::min(rx, 0.5 * w);
  ry = std::min(ry, 0.5 * h);
  std::vector<PathCommand> c;
  const double r = x + w, b = y + h;
  auto arc = [&](double ex, double ey) { c.push_back({'A', {rx, ry, 0, 0, 1, ex, ey}}); };
  c.push_back({'M', {x + rx, y}});
  c.push_back({'L', {r - rx, y}});
  arc(r, y + ry);
  c.push_back({'L', {r, b - ry}});
  arc(r - rx, b);
  c.push_back({'L', {x + rx, b}});
  arc(x, b - ry);
  c.push_back({'L', {x, y + ry}});
  arc(x + rx, y);
  c.push_back({'Z', {}});
  const std::vector<QString> parts = splitPathData(arcsAsCubics(c), kMaxPathElements);
  writer_.writeStartElement(reader_.namespaceUri().toString(), QStringLiteral("path"));
  for (const QXmlStreamAttribute& a : attributes) {
    const QStringView n = a.name();
    if (a.namespaceUri().isEmpty() && (n == u"x" || n == u"y" || n == u"width" || n == u"height" ||
                                       n == u"rx" || n == u"ry" || n == u"d"))
      continue;
    writer_.writeAttribute(a);
  }
  writer_.writeAttribute(QStringLiteral("d"), parts.front());
  return true;
}

const NestedSvgInfo* Sanitizer::sizedSvgOfUse(const QXmlStreamAttributes& attributes) const {
  if (reader_.name() != u"use" || nestedSvgs_.empty()) return nullptr;
  if (!attributes.hasAttribute(QStringLiteral("width")) && !attributes.hasAttribute(QStringLiteral("height")))
    return nullptr;
  const QStringView href = attributes.value(kXlinkNs, QStringLiteral("href"));
  const auto svg = href.startsWith(u'#') ? nestedSvgs_.find(href.mid(1).toString()) : nestedSvgs_.end();
  return svg == nestedSvgs_.end() ? nullptr : &svg->second;
}

NestedViewport Sanitizer::viewportAtUse(const NestedSvgInfo& svg, const QXmlStreamAttributes& use) const {
  NestedViewport v{svg.x, svg.y, svg.width, svg.height, svg.viewBox, svg.preserveAspectRatio};
  if (use.hasAttribute(QStringLiteral("width"))) v.width = use.value(QStringLiteral("width")).toString();
  if (use.hasAttribute(QStringLiteral("height"))) v.height = use.value(QStringLiteral("height")).toString();
  return v;
}

// SVG: a <use> of an <svg> with width/height gives that svg its size. The svg's content was
// written for its own size (writeNestedSvgAsGroup): the use gets the matrix that takes that
// mapping to the one at the use's size.
bool Sanitizer::writeUseOfSvg(const QXmlStreamAttributes& attributes) {
  const NestedSvgInfo* svg = sizedSvgOfUse(attributes);
  if (!svg) return false;
  const NestedViewport own{svg->x, svg->y, svg->width, svg->height, svg->viewBox, svg->preserveAspectRatio};
  const QTransform atDefinition = nestedViewportMatrix(own, rootViewport_.width, rootViewport_.height, dpi_);
  const QTransform atUse =
      nestedViewportMatrix(viewportAtUse(*svg, attributes), rootViewport_.width, rootViewport_.height, dpi_);
  bool invertible = false;
  const QTransform c = atDefinition.inverted(&invertible) * atUse;
  if (!invertible) return false;
  auto num = [](double v) { return QString::number(v, 'g', 17); };
  const QString ns = reader_.namespaceUri().toString();
  writer_.writeStartElement(ns, QStringLiteral("g"));
  QString transform = attributes.value(QStringLiteral("transform")).toString();
  for (const QXmlStreamAttribute& a : attributes) {
    const QStringView n = a.name();
    if (a.namespaceUri().isEmpty() && (n == u"x" || n == u"y" || n == u"width" || n == u"height" || n == u"transform"))
      continue;
    if (n == u"href") continue;
    writer_.writeAttribute(a);
  }
  bool okX = false, okY = false;
  const double x = attributes.value(QStringLiteral("x")).toDouble(&okX);
  const double y = attributes.value(QStringLiteral("y")).toDouble(&okY);
  transform += QStringLiteral(" translate(%1,%2) matrix(%3,%4,%5,%6,%7,%8)")
                   .arg(num(okX ? x : 0.0), num(okY ? y : 0.0), num(c.m11()), num(c.m12()), num(c.m21()),
                        num(c.m22()), num(c.dx()), num(c.dy()));
  writer_.writeAttribute(QStringLiteral("transform"), transform.trimmed());
  writer_.writeStartElement(ns, QStringLiteral("use"));
  writer_.writeAttribute(kXlinkNs, QStringLiteral("href"), attributes.value(kXlinkNs, QStringLiteral("href")).toString());
  extraEnds_.back() = 1;
  return true;
}

}  // namespace fivebar::svg::detail
