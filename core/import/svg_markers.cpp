// SPDX-License-Identifier: GPL-3.0-or-later
#include "svg_markers.hpp"

#include "svg_lengths.hpp"

#include <QRectF>
#include <QRegularExpression>
#include <QXmlStreamReader>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "path_data.hpp"
#include "svg_units.hpp"

namespace fivebar::svg {
namespace {

QString num(double v) { return QString::number(v, 'g', 17); }

struct Dir {
  double x = 0.0, y = 0.0;
  bool valid() const { return x != 0.0 || y != 0.0; }
};

Dir dir(double x0, double y0, double x1, double y1) { return {x1 - x0, y1 - y0}; }
Dir firstValid(Dir a, Dir b, Dir c = {}) { return a.valid() ? a : b.valid() ? b : c; }

// Start and end tangents of an elliptical arc (SVG implementation notes F.6.5).
void arcTangents(double x0, double y0, const PathCommand& c, Dir& start, Dir& end) {
  double rx = std::abs(c.v[0]), ry = std::abs(c.v[1]);
  const double x1 = c.v[5], y1 = c.v[6];
  start = end = dir(x0, y0, x1, y1);
  if (rx == 0.0 || ry == 0.0 || !start.valid()) return;
  const double phi = c.v[2] * std::numbers::pi / 180.0, cp = std::cos(phi), sp = std::sin(phi);
  const double dx = (x0 - x1) / 2.0, dy = (y0 - y1) / 2.0;
  const double xp = cp * dx + sp * dy, yp = -sp * dx + cp * dy;
  const double lambda = xp * xp / (rx * rx) + yp * yp / (ry * ry);
  if (lambda > 1.0) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);
  const double num2 = rx * rx * ry * ry - rx * rx * yp * yp - ry * ry * xp * xp;
  const double den = rx * rx * yp * yp + ry * ry * xp * xp;
  double k = den > 0.0 ? std::sqrt(std::max(0.0, num2 / den)) : 0.0;
  const bool large = c.v[3] != 0.0, sweep = c.v[4] != 0.0;
  if (large == sweep) k = -k;
  const double cxp = k * rx * yp / ry, cyp = -k * ry * xp / rx;
  const double t1 = std::atan2((yp - cyp) / ry, (xp - cxp) / rx);
  const double t2 = std::atan2((-yp - cyp) / ry, (-xp - cxp) / rx);
  const double s = sweep ? 1.0 : -1.0;  // sweep = 1: increasing angle
  auto tangent = [&](double t) {
    const double ex = -rx * std::sin(t) * s, ey = ry * std::cos(t) * s;
    return Dir{cp * ex - sp * ey, sp * ex + cp * ey};
  };
  start = tangent(t1);
  end = tangent(t2);
}

struct Vertex {
  double x, y;
  Dir in, out;
};

std::vector<MarkerVertex> verticesOf(const std::vector<PathCommand>& commands) {
  std::vector<Vertex> v;
  double cx = 0.0, cy = 0.0;
  std::size_t subStart = 0;
  for (const PathCommand& c : commands) {
    if (c.op == 'M') {
      cx = c.v[0], cy = c.v[1];
      subStart = v.size();
      v.push_back({cx, cy, {}, {}});
      continue;
    }
    if (v.empty()) break;
    double x = cx, y = cy;
    Dir s, e;
    switch (c.op) {
      case 'L': x = c.v[0], y = c.v[1], s = e = dir(cx, cy, x, y); break;
      case 'C':
        x = c.v[4], y = c.v[5];
        s = firstValid(dir(cx, cy, c.v[0], c.v[1]), dir(cx, cy, c.v[2], c.v[3]), dir(cx, cy, x, y));
        e = firstValid(dir(c.v[2], c.v[3], x, y), dir(c.v[0], c.v[1], x, y), dir(cx, cy, x, y));
        break;
      case 'Q':
        x = c.v[2], y = c.v[3];
        s = firstValid(dir(cx, cy, c.v[0], c.v[1]), dir(cx, cy, x, y));
        e = firstValid(dir(c.v[0], c.v[1], x, y), dir(cx, cy, x, y));
        break;
      case 'A': x = c.v[5], y = c.v[6], arcTangents(cx, cy, c, s, e); break;
      case 'Z': x = v[subStart].x, y = v[subStart].y, s = e = dir(cx, cy, x, y); break;
      default: continue;
    }
    if (!s.valid()) s = v.back().in;  // a zero-length segment keeps the direction
    if (!e.valid()) e = s;
    v.back().out = s;
    v.push_back({x, y, e, {}});
    if (c.op == 'Z') {  // closed: the start vertex's way in is the closing segment, and back
      v[subStart].in = e;
      v.back().out = v[subStart].out;
    }
    cx = x, cy = y;
  }
  std::vector<MarkerVertex> out;
  out.reserve(v.size());
  for (const Vertex& p : v) {
    Dir d = p.in.valid() ? p.in : p.out;
    if (p.in.valid() && p.out.valid()) {  // the bisector of the two directions
      const double ni = std::hypot(p.in.x, p.in.y), no = std::hypot(p.out.x, p.out.y);
      const Dir sum{p.in.x / ni + p.out.x / no, p.in.y / ni + p.out.y / no};
      if (std::hypot(sum.x, sum.y) > 1e-12) d = sum;
    }
    out.push_back({p.x, p.y, d.valid() ? std::atan2(d.y, d.x) : 0.0});
  }
  return out;
}

std::optional<double> number(const QXmlStreamAttributes& a, const char* name) {
  const std::optional<Length> l = parseLength(a.value(QLatin1String(name)));
  if (!l || l->unit == LengthUnit::Percent) return std::nullopt;
  return l->value;
}

// "url(#id)" -> "id"; "none" or anything else -> empty.
QString refId(QStringView value) {
  const QString v = value.toString().simplified();
  static const QRegularExpression url(QStringLiteral("^url\\(\\s*['\"]?#([^'\")\\s]+)['\"]?\\s*\\)$"));
  const QRegularExpressionMatch m = url.match(v);
  return m.hasMatch() ? m.captured(1) : QString();
}

// orient: an angle (deg, rad, grad, turn; plain = deg) -> degrees.
std::optional<double> orientDeg(const QString& text) {
  static const QRegularExpression angle(
      QStringLiteral("^\\s*([+-]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][+-]?\\d+)?)\\s*(deg|rad|grad|turn)?\\s*$"));
  const QRegularExpressionMatch m = angle.match(text);
  if (!m.hasMatch()) return std::nullopt;
  const double v = m.captured(1).toDouble();
  const QString unit = m.captured(2);
  if (unit == u"rad") return v * 180.0 / std::numbers::pi;
  if (unit == u"grad") return v * 0.9;
  if (unit == u"turn") return v * 360.0;
  return v;
}

}  // namespace

std::map<QString, MarkerInfo> scanMarkers(const QByteArray& document) {
  std::map<QString, MarkerInfo> markers;
  if (!document.contains("marker")) return markers;
  QXmlStreamReader reader(document);
  while (!reader.atEnd()) {
    if (reader.readNext() != QXmlStreamReader::StartElement || reader.name() != u"marker") continue;
    const QXmlStreamAttributes a = reader.attributes();
    const QString id = a.value(QStringLiteral("id")).toString();
    if (id.isEmpty()) continue;
    auto get = [&](const char* name) { return a.value(QLatin1String(name)).toString(); };
    QString overflow = get("overflow");
    if (const QString s = styleValue(a.value(QStringLiteral("style")), u"overflow"); !s.isEmpty()) overflow = s;
    markers[id] = MarkerInfo{get("viewBox"), get("preserveAspectRatio"), get("markerWidth"),
                             get("markerHeight"), get("refX"), get("refY"), get("orient"),
                             get("markerUnits"), overflow == u"hidden" || overflow == u"scroll"};
  }
  return markers;  // a reader error is reported by the sanitiser's own pass
}

std::vector<MarkerVertex> markerVertices(QStringView tag, const QXmlStreamAttributes& attributes) {
  if (tag == u"path") {
    const ParsedPath parsed = parsePathData(attributes.value(QStringLiteral("d")));
    return verticesOf(parsed.commands);  // up to an error, as the path is drawn
  }
  std::vector<PathCommand> commands;
  if (tag == u"line") {
    auto coord = [&](const char* n) { return number(attributes, n).value_or(0.0); };
    commands.push_back({'M', {coord("x1"), coord("y1")}});
    commands.push_back({'L', {coord("x2"), coord("y2")}});
  } else if (tag == u"polyline" || tag == u"polygon") {
    static const QRegularExpression separators(QStringLiteral("[\\s,]+"));
    const QStringList parts =
        attributes.value(QStringLiteral("points")).toString().trimmed().split(separators, Qt::SkipEmptyParts);
    for (qsizetype i = 0; i + 1 < parts.size(); i += 2) {  // an odd last number is ignored, as SVG says
      bool okX = false, okY = false;
      const double x = parts[i].toDouble(&okX), y = parts[i + 1].toDouble(&okY);
      if (!okX || !okY) break;
      commands.push_back({commands.empty() ? 'M' : 'L', {x, y}});
    }
    if (tag == u"polygon" && !commands.empty()) commands.push_back({'Z', {}});
  }
  return verticesOf(commands);
}

namespace {

bool isMarkerProperty(QStringView name) {
  return name == u"marker" || name == u"marker-start" || name == u"marker-mid" || name == u"marker-end";
}

// One compound selector (type, #id, .class, in any order after the type); false when it is not
// that simple.
bool parseSimpleSelector(QStringView text, MarkerRule& rule) {
  static const QRegularExpression simple(
      QStringLiteral("^([A-Za-z][\\w-]*|\\*)?((?:[.#][A-Za-z_][\\w-]*)*)$"));
  const QRegularExpressionMatch m = simple.match(text.toString());
  if (!m.hasMatch() || text.isEmpty()) return false;
  rule.tag = m.captured(1) == u"*" ? QString() : m.captured(1);
  rule.specificity = rule.tag.isEmpty() ? 0 : 1;
  static const QRegularExpression part(QStringLiteral("([.#])([A-Za-z_][\\w-]*)"));
  for (auto it = part.globalMatch(m.captured(2)); it.hasNext();) {
    const QRegularExpressionMatch p = it.next();
    if (p.captured(1) == u"#") {
      if (!rule.id.isEmpty() && rule.id != p.captured(2)) return false;  // never matches
      rule.id = p.captured(2);
      rule.specificity += 100;
    } else {
      rule.classes.push_back(p.captured(2));
      rule.specificity += 10;
    }
  }
  return true;
}

bool matches(const MarkerRule& rule, QStringView tag, const QXmlStreamAttributes& attributes) {
  if (!rule.tag.isEmpty() && rule.tag != tag) return false;
  if (!rule.id.isEmpty() && attributes.value(QStringLiteral("id")) != rule.id) return false;
  if (rule.classes.isEmpty()) return true;
  static const QRegularExpression spaces(QStringLiteral("\\s+"));
  const QStringList classes =
      attributes.value(QStringLiteral("class")).toString().split(spaces, Qt::SkipEmptyParts);
  for (const QString& c : rule.classes)
    if (!classes.contains(c)) return false;
  return true;
}

}  // namespace

MarkerSheet parseMarkerSheet(QStringView cssText) {
  MarkerSheet sheet;
  QString css = cssText.toString();
  static const QRegularExpression comments(QStringLiteral("/\\*.*?\\*/"),
                                           QRegularExpression::DotMatchesEverythingOption);
  css.remove(comments);
  // Blocks "selectors { declarations }"; at-rules (@media ...) keep their inner blocks out.
  qsizetype at = 0;
  while (at < css.size()) {
    const qsizetype open = css.indexOf(u'{', at);
    if (open < 0) break;
    const qsizetype close = css.indexOf(u'}', open);
    if (close < 0) break;
    const QString selectors = css.mid(at, open - at).trimmed();
    if (selectors.startsWith(u'@')) {  // an at-rule block: skip it whole, nested blocks too
      int depth = 0;
      for (at = open; at < css.size(); ++at) {
        if (css[at] == u'{') ++depth;
        if (css[at] == u'}' && --depth == 0) break;
      }
      if (QStringView(css).mid(open, at - open).contains(u"marker"))
        sheet.unsupported.push_back(selectors.simplified());
      ++at;
      continue;
    }
    const QStringView body = QStringView(css).mid(open + 1, close - open - 1);
    at = close + 1;
    std::vector<std::pair<QString, QString>> declarations;
    for (QStringView decl : body.split(u';')) {
      const qsizetype colon = decl.indexOf(u':');
      if (colon < 0) continue;
      const QString name = decl.left(colon).trimmed().toString();
      QString value = decl.mid(colon + 1).trimmed().toString();
      value.remove(QStringLiteral("!important"));
      if (isMarkerProperty(name)) declarations.emplace_back(name, value.trimmed());
    }
    if (declarations.empty()) continue;
    for (const QString& s : selectors.split(u',')) {
      MarkerRule rule;
      rule.declarations = declarations;
      if (parseSimpleSelector(s.trimmed(), rule)) sheet.rules.push_back(std::move(rule));
      else sheet.unsupported.push_back(s.simplified());
    }
  }
  // Lower specificity first; stable, so document order decides between equals.
  std::stable_sort(sheet.rules.begin(), sheet.rules.end(),
                   [](const MarkerRule& a, const MarkerRule& b) { return a.specificity < b.specificity; });
  return sheet;
}

MarkerSheet scanMarkerSheet(const QByteArray& document) {
  MarkerSheet sheet;
  if (!document.contains("marker") || !document.contains("<style")) return sheet;
  QXmlStreamReader reader(document);
  QString css;
  bool inStyle = false;
  while (!reader.atEnd()) {
    const QXmlStreamReader::TokenType t = reader.readNext();
    if (t == QXmlStreamReader::StartElement) inStyle = reader.name() == u"style";
    else if (t == QXmlStreamReader::EndElement) inStyle = false;
    else if (t == QXmlStreamReader::Characters && inStyle) css += reader.text().toString() + u'\n';
  }
  return css.contains(u"marker") ? parseMarkerSheet(css) : sheet;
}

MarkerRefs markerRefs(const QXmlStreamAttributes& attributes, const MarkerRefs& inherited,
                      QStringView tag, const MarkerSheet* sheet) {
  MarkerRefs refs = inherited;
  auto apply = [&](const QString& name, QStringView value) {
    if (value.isEmpty() || value.trimmed() == u"inherit") return;
    const QString id = refId(value);
    if (name == u"marker-start" || name == u"marker") refs.start = id;
    if (name == u"marker-mid" || name == u"marker") refs.mid = id;
    if (name == u"marker-end" || name == u"marker") refs.end = id;
  };
  for (const char* n : {"marker-start", "marker-mid", "marker-end"})
    apply(QString::fromLatin1(n), attributes.value(QString::fromLatin1(n)));
  if (sheet != nullptr)
    for (const MarkerRule& rule : sheet->rules)
      if (matches(rule, tag, attributes))
        for (const auto& [name, value] : rule.declarations) apply(name, value);
  const QStringView style = attributes.value(QStringLiteral("style"));
  if (style.contains(u"marker"))
    for (const char* n : {"marker", "marker-start", "marker-mid", "marker-end"})
      apply(QString::fromLatin1(n), styleValue(style, QString::fromLatin1(n)));
  return refs;
}

double strokeWidthUser(const QXmlStreamAttributes& attributes, double inherited) {
  QString text = attributes.value(QStringLiteral("stroke-width")).toString();
  if (const QString s = styleValue(attributes.value(QStringLiteral("style")), u"stroke-width"); !s.isEmpty())
    text = s;
  const std::optional<Length> l = parseLength(text);
  if (!l || l->unit == LengthUnit::Percent || l->unit == LengthUnit::Em || l->unit == LengthUnit::Ex ||
      l->value < 0.0)
    return inherited;
  return l->value;  // px and plain numbers; absolute units are rare in stroke-width
}

std::optional<QString> markerInstanceTransform(const MarkerInfo& marker, const MarkerVertex& vertex,
                                               MarkerSlot slot, double strokeWidth,
                                               const LengthContext& lengths) {
  auto length = [&](const QString& text, LengthAxis axis, double fallback) {
    return resolveLength(text, axis, lengths).value_or(fallback);
  };
  const double width = length(marker.markerWidth, LengthAxis::Width, 3.0);
  const double height = length(marker.markerHeight, LengthAxis::Height, 3.0);
  if (width <= 0.0 || height <= 0.0) return std::nullopt;
  double sx = 1.0, sy = 1.0;
  QRectF box(0, 0, width, height);
  if (!marker.viewBox.isEmpty()) {
    const std::optional<QRectF> vb = parseViewBox(marker.viewBox);
    if (!vb || vb->width() <= 0.0 || vb->height() <= 0.0) return std::nullopt;
    box = *vb;
    const QRectF place = placeViewBox(*vb, QRectF(0, 0, width, height),
                                      parsePreserveAspectRatio(marker.preserveAspectRatio));
    sx = place.width() / vb->width();
    sy = place.height() / vb->height();
  }
  auto ref = [&](const QString& text, LengthAxis axis, double lo, double size) {
    const QString t = text.trimmed();
    if (t == u"left" || t == u"top") return lo;
    if (t == u"center") return lo + size / 2.0;
    if (t == u"right" || t == u"bottom") return lo + size;
    return length(t, axis, 0.0);
  };
  const double refX = ref(marker.refX, LengthAxis::Width, box.x(), box.width());
  const double refY = ref(marker.refY, LengthAxis::Height, box.y(), box.height());
  const QString orient = marker.orient.trimmed();
  double angleDeg = 0.0;
  if (orient == u"auto" || orient == u"auto-start-reverse") {
    angleDeg = vertex.angleRad * 180.0 / std::numbers::pi;
    if (orient == u"auto-start-reverse" && slot == MarkerSlot::Start) angleDeg += 180.0;
  } else if (!orient.isEmpty()) {
    angleDeg = orientDeg(orient).value_or(0.0);
  }
  const double units = marker.markerUnits.trimmed() == u"userSpaceOnUse" ? 1.0 : strokeWidth;
  return QStringLiteral("translate(%1,%2) rotate(%3) scale(%4,%5) translate(%6,%7)")
      .arg(num(vertex.x), num(vertex.y), num(angleDeg), num(units * sx), num(units * sy),
           num(-refX), num(-refY));
}

}  // namespace fivebar::svg
