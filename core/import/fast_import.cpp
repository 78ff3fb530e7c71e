// SPDX-License-Identifier: GPL-3.0-or-later
// The direct reader (fast_import.hpp): XML subset scanning, styles and capture. The path data
// and number syntax follow Qt SVG's own parser so that the same QPainterPath calls are made; the
// differential tests (tests/import/direct_reader_test.cpp) hold it to the general path.
#include "fast_import.hpp"

#include <QColor>

#include <cmath>
#include <string>
#include <string_view>

#include "direct_syntax.hpp"
#include "page_probe.hpp"

namespace fivebar::svg {
namespace {

constexpr std::string_view kSvgNs = "http://www.w3.org/2000/svg";
constexpr std::string_view kInkscapeNsText = "http://www.inkscape.org/namespaces/inkscape";
constexpr std::size_t kMaxTopLevel = 0xFFFFFE;  // sentinel colours: index + 1 in 24 bits

enum class Tag { Svg, G, Path, Polyline, Polygon, Line, Other };

Tag tagOf(std::string_view name) {
  if (name == "path") return Tag::Path;
  if (name == "g") return Tag::G;
  if (name == "polyline") return Tag::Polyline;
  if (name == "polygon") return Tag::Polygon;
  if (name == "line") return Tag::Line;
  if (name == "svg") return Tag::Svg;
  return Tag::Other;
}

// Resolved paint of an element (what Qt SVG's painter holds when the element draws).
struct Paint {
  bool fill = true;          // SVG initial fill: black
  std::uint32_t fillRgb = 0;
  bool stroke = false;       // SVG initial stroke: none
  std::uint32_t strokeRgb = 0;
};

class DirectReader {
 public:
  DirectReader(std::string_view text, const ImportOptions& options, const ProgressFn& progress,
               DirectCapture& out, const RunSink& sink)
      : text_(text), options_(options), progress_(progress), out_(out), sink_(sink) {}

  DirectStatus run();

 private:
  bool readRoot();
  bool readContent();
  bool element(Tag tag, const std::vector<XmlAttribute>& attributes, bool selfClosing);
  bool applyStyle(const std::vector<XmlAttribute>& attributes, Paint& paint);
  bool resolveColour(std::string_view text, bool& visible, std::uint32_t& rgb);
  bool drawPath(std::string_view d, const Paint& paint);
  bool drawPoints(std::string_view points, bool polygon, const Paint& paint);
  bool drawLine(const std::vector<XmlAttribute>& attributes, const Paint& paint);
  void record(std::vector<Polyline>&& lines, std::uint32_t rgb);
  bool allowedAttribute(Tag tag, const XmlAttribute& a) const;
  bool uniqueExpandedNames(const std::vector<XmlAttribute>& attributes) const;
  const std::string_view* namespaceOf(std::string_view prefix) const;
  bool cancelled() const { return options_.cancel && options_.cancel->load(); }

  std::string_view text_;
  XmlCursor cursor_{text_};
  const ImportOptions& options_;
  const ProgressFn& progress_;
  DirectCapture& out_;
  const RunSink& sink_;
  std::size_t pointsHeld_ = 0;  // points in out_.runs, for handing them to the sink
  std::size_t pointsTotal_ = 0;  // points recorded so far
  bool overBudget_ = false;      // more than options_.maxPoints: stop reading
  QTransform transform_;
  std::vector<std::pair<std::string_view, std::string_view>> namespaces_;  // prefix -> URI
  std::vector<Paint> paints_;  // one per open element, root first
  int topIndex_ = -1;
  long long elements_ = 0;
  bool cancelled_ = false;
  std::vector<std::pair<std::string_view, std::uint32_t>> colourCache_;
};

const std::string_view* DirectReader::namespaceOf(std::string_view prefix) const {
  for (const auto& [p, uri] : namespaces_)
    if (p == prefix) return &uri;
  return nullptr;
}

// Whether Qt SVG and the sanitiser treat the attribute exactly as this reader does.
bool DirectReader::allowedAttribute(Tag tag, const XmlAttribute& a) const {
  const std::string_view n = a.name;
  // Line breaks and tabs become spaces in an XML reader: the same to number lists, not to text.
  if (n != "d" && n != "points" && a.value.find_first_of("\t\n\r") != std::string_view::npos)
    return false;
  if (const std::size_t colon = n.find(':'); colon != std::string_view::npos) {
    const std::string_view prefix = n.substr(0, colon), local = n.substr(colon + 1);
    if (prefix == "xmlns" || prefix == "xml" || local == "href") return false;
    return namespaceOf(prefix) != nullptr;  // ignored by Qt SVG; layers read inkscape:*
  }
  if (n == "id" || n == "fill" || n == "stroke" || n == "stroke-width") return true;
  switch (tag) {
    case Tag::Svg:
      return n == "xmlns" || n == "version" || n == "width" || n == "height" || n == "viewBox" ||
             n == "preserveAspectRatio";
    case Tag::Path: return n == "d";
    case Tag::Polyline:
    case Tag::Polygon: return n == "points";
    case Tag::Line: return n == "x1" || n == "y1" || n == "x2" || n == "y2";
    default: return false;
  }
}

// Two prefixes for one namespace can make two attributes the same (an XML error).
bool DirectReader::uniqueExpandedNames(const std::vector<XmlAttribute>& attributes) const {
  for (std::size_t i = 0; i < attributes.size(); ++i) {
    const std::size_t ci = attributes[i].name.find(':');
    if (ci == std::string_view::npos) continue;
    for (std::size_t j = i + 1; j < attributes.size(); ++j) {
      const std::size_t cj = attributes[j].name.find(':');
      if (cj == std::string_view::npos) continue;
      if (attributes[i].name.substr(ci) == attributes[j].name.substr(cj) &&
          *namespaceOf(attributes[i].name.substr(0, ci)) == *namespaceOf(attributes[j].name.substr(0, cj)))
        return false;
    }
  }
  return true;
}

bool DirectReader::resolveColour(std::string_view text, bool& visible, std::uint32_t& rgb) {
  if (text == "none") {
    visible = false;
    return true;
  }
  for (const auto& [name, cached] : colourCache_) {
    if (name == text) {
      visible = true;
      rgb = cached;
      return true;
    }
  }
  // "#rgb", "#rrggbb" or a lower-case name; Qt SVG hands all of them to the same QColor parsing.
  if (text.empty() || text.size() > 24) return false;
  const bool hex = text[0] == '#';
  for (std::size_t i = hex ? 1 : 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool ok = (c >= 'a' && c <= 'z' && (!hex || c <= 'f')) || (hex && ((c >= '0' && c <= '9') ||
                                                                             (c >= 'A' && c <= 'F')));
    if (!ok) return false;
  }
  if (hex ? (text.size() != 4 && text.size() != 7)
          : (text == "transparent" || text == "currentcolor" || text == "inherit"))
    return false;
  const QColor colour = QColor::fromString(QLatin1StringView(text.data(), static_cast<qsizetype>(text.size())));
  if (!colour.isValid() || colour.alpha() != 255) return false;
  rgb = static_cast<std::uint32_t>(colour.rgb() & 0xFFFFFFu);
  visible = true;
  if (colourCache_.size() < 64) colourCache_.emplace_back(text, rgb);
  return true;
}

bool DirectReader::applyStyle(const std::vector<XmlAttribute>& attributes, Paint& paint) {
  for (const XmlAttribute& a : attributes) {
    if (a.name == "fill") {
      if (!resolveColour(a.value, paint.fill, paint.fillRgb)) return false;
    } else if (a.name == "stroke") {
      if (!resolveColour(a.value, paint.stroke, paint.strokeRgb)) return false;
    } else if (a.name == "stroke-width") {
      double width = 0.0;
      if (!parsePlainNumber(a.value, width) || !(width > 0.0) || width == kSentinelPenWidth)
        return false;
    }
  }
  return true;
}

void DirectReader::record(std::vector<Polyline>&& lines, std::uint32_t rgb) {
  if (lines.empty()) return;
  auto& runs = out_.runs;
  if (runs.empty() || runs.back().topIndex != topIndex_ || runs.back().rgb != rgb)
    runs.push_back(CapturedRun{topIndex_, rgb, {}});
  for (Polyline& line : lines) {
    pointsHeld_ += line.points.size();
    pointsTotal_ += line.points.size();
    runs.back().paths.push_back(std::move(line));
  }
  if (options_.maxPoints > 0 && pointsTotal_ > options_.maxPoints) overBudget_ = true;
  constexpr std::size_t kSinkPoints = std::size_t{1} << 15;  // 512 kB of points
  if (sink_ && pointsHeld_ >= kSinkPoints) {
    sink_.take(runs);
    runs.clear();
    pointsHeld_ = 0;
  }
}

// Qt SVG paints a path twice (fill pass, then stroke pass, same geometry): the capture engine
// keeps the stroke, else the outlined fill.
bool DirectReader::drawPath(std::string_view d, const Paint& paint) {
  QPainterPath path;
  if (!buildQtPath(d, path)) return false;
  if (!paint.stroke && !(paint.fill && options_.outlineFills)) return true;
  std::vector<Polyline> lines;
  // At most one point past the budget: record() then sees the budget passed and stops reading.
  const std::size_t room = options_.maxPoints == 0 ? 0
                           : pointsTotal_ < options_.maxPoints ? options_.maxPoints - pointsTotal_ + 1
                                                               : std::size_t{1};
  if (!appendFlattenedPath(path, transform_, options_.toleranceMm, lines, room)) overBudget_ = true;
  if (paint.stroke && !paint.fill) dropInvisibleStrokes(lines, options_.toleranceMm);  // butt caps
  if (!paint.stroke) closeFillOutlines(lines);
  if (paint.fill) markFill(lines, FillRule::NonZero, !paint.stroke);
  record(std::move(lines), paint.stroke ? paint.strokeRgb : paint.fillRgb);
  return true;
}

// polygon: like a path (both passes draw the same closed polygon). polyline: the fill pass draws
// a closed polygon, the stroke pass an open polyline (stroke only); both are kept.
bool DirectReader::drawPoints(std::string_view points, bool polygon, const Paint& paint) {
  std::vector<double> numbers;
  if (!parseNumberList(points, numbers) || numbers.size() % 2 != 0) return false;
  auto polyline = [&](bool closed, bool stroke) {
    Polyline line;
    line.points.reserve(numbers.size() / 2);
    for (std::size_t i = 0; i + 1 < numbers.size(); i += 2) {
      const QPointF p = transform_.map(QPointF(numbers[i], numbers[i + 1]));
      line.points.emplace_back(p.x(), p.y());
    }
    std::vector<Polyline> lines;
    if (numbers.size() >= 4) finishPolyline(line, closed, lines);
    if (stroke) dropInvisibleStrokes(lines, options_.toleranceMm);  // the capture engine's rule
    return lines;
  };
  auto filled = [&](bool fillOnly) {
    std::vector<Polyline> lines = polyline(true, paint.stroke && !paint.fill);
    if (paint.fill) markFill(lines, FillRule::NonZero, fillOnly);
    return lines;
  };
  if (polygon) {
    if (paint.stroke) record(filled(false), paint.strokeRgb);
    else if (paint.fill && options_.outlineFills) record(filled(true), paint.fillRgb);
    return true;
  }
  if (paint.fill && options_.outlineFills) record(filled(true), paint.fillRgb);
  // The stroke pass (QPainter::drawPolyline) strokes only.
  if (paint.stroke) record(polyline(false, true), paint.strokeRgb);
  return true;
}

bool DirectReader::drawLine(const std::vector<XmlAttribute>& attributes, const Paint& paint) {
  double v[4] = {0, 0, 0, 0};
  const char* names[4] = {"x1", "y1", "x2", "y2"};
  for (const XmlAttribute& a : attributes)
    for (int i = 0; i < 4; ++i)
      if (a.name == names[i] && !parsePlainNumber(a.value, v[i])) return false;
  if (!paint.stroke) return true;
  Polyline line;
  const QPointF p1 = transform_.map(QPointF(v[0], v[1])), p2 = transform_.map(QPointF(v[2], v[3]));
  line.points = {Vec2(p1.x(), p1.y()), Vec2(p2.x(), p2.y())};
  std::vector<Polyline> lines;
  finishPolyline(line, false, lines);
  dropInvisibleStrokes(lines, options_.toleranceMm);
  record(std::move(lines), paint.strokeRgb);
  return true;
}

bool DirectReader::element(Tag tag, const std::vector<XmlAttribute>& attributes, bool selfClosing) {
  if (tag == Tag::Other || tag == Tag::Svg) return false;
  for (const XmlAttribute& a : attributes)
    if (!allowedAttribute(tag, a)) return false;
  if (!uniqueExpandedNames(attributes)) return false;
  const int depth = static_cast<int>(paints_.size()) + 1;
  if (depth > kMaxDepth) return false;
  if (depth == 2) {
    if (out_.topLevel.size() >= kMaxTopLevel) return false;  // the sanitiser's marker limit
    TopLevelElement top;
    top.tag = QString::fromLatin1(tag == Tag::G ? "g" : tag == Tag::Path ? "path"
                                  : tag == Tag::Polyline ? "polyline"
                                  : tag == Tag::Polygon  ? "polygon" : "line");
    for (const XmlAttribute& a : attributes) {
      const std::size_t colon = a.name.find(':');
      const std::string_view* uri = colon == std::string_view::npos ? nullptr : namespaceOf(a.name.substr(0, colon));
      const QString value = QString::fromLatin1(a.value.data(), static_cast<qsizetype>(a.value.size()));
      if (a.name == "id") top.id = value;
      if (uri && *uri == kInkscapeNsText && a.name.substr(colon + 1) == "label") top.label = value;
      if (uri && *uri == kInkscapeNsText && a.name.substr(colon + 1) == "groupmode")
        top.inkscapeLayer = tag == Tag::G && a.value == "layer";
    }
    topIndex_ = static_cast<int>(out_.topLevel.size());
    out_.topLevel.push_back(top);
  }
  Paint paint = paints_.back();
  if (!applyStyle(attributes, paint)) return false;
  std::string_view geometry;
  for (const XmlAttribute& a : attributes)
    if (a.name == "d" || a.name == "points") geometry = a.value;
  bool ok = true;
  switch (tag) {
    case Tag::Path: ok = drawPath(geometry, paint); break;
    case Tag::Polyline: ok = drawPoints(geometry, false, paint); break;
    case Tag::Polygon: ok = drawPoints(geometry, true, paint); break;
    case Tag::Line: ok = drawLine(attributes, paint); break;
    default: break;
  }
  if (!ok) return false;
  if (!selfClosing) paints_.push_back(paint);
  return true;
}

bool DirectReader::readRoot() {
  if (!cursor_.skipProlog()) return false;
  XmlTag tag;
  if (!cursor_.readTag(tag) || tag.kind != XmlTag::Start || tag.name != "svg" || tag.selfClosing)
    return false;
  RootAttributes& root = out_.root;
  Paint paint;
  bool svgNamespace = false;
  for (const XmlAttribute& a : tag.attributes) {
    if (!allowedAttribute(Tag::Svg, a) && !a.name.starts_with("xmlns:")) return false;
    // The page probe quotes root values with '"'; tabs and breaks would be normalised.
    if (a.value.find_first_of("\t\n\r\"") != std::string_view::npos) return false;
    if (a.name.starts_with("xmlns:")) {
      if (a.value.empty() || a.name == "xmlns:xml" || a.name == "xmlns:xmlns") return false;
      namespaces_.emplace_back(a.name.substr(6), a.value);
    }
    if (a.name == "xmlns") svgNamespace = a.value == kSvgNs;
  }
  for (const XmlAttribute& a : tag.attributes) {
    if (a.name.starts_with("xmlns:")) continue;
    if (!allowedAttribute(Tag::Svg, a)) return false;  // now that all prefixes are known
    const QString value = QString::fromLatin1(a.value.data(), static_cast<qsizetype>(a.value.size()));
    const bool geometry = a.name == "width" || a.name == "height" || a.name == "viewBox";
    if (geometry && hasNonFiniteNumber(value)) return false;
    if (a.name == "width") root.width = value, root.hasWidth = true;
    if (a.name == "height") root.height = value, root.hasHeight = true;
    if (a.name == "viewBox") root.viewBox = value, root.hasViewBox = true;
    if (a.name == "preserveAspectRatio") root.preserveAspectRatio = value;
  }
  if (!svgNamespace || !applyStyle(tag.attributes, paint)) return false;
  root.line = cursor_.lineOfTagStart();
  if (!computePage(root, options_.dpi, out_.page).empty()) return false;
  if (!probePageTransform(root, out_.page, transform_)) return false;
  paints_.push_back(paint);
  return true;
}

bool DirectReader::readContent() {
  const double total = static_cast<double>(std::max<std::size_t>(1, text_.size()));
  XmlTag tag;
  std::vector<std::string_view> open{"svg"};
  while (!open.empty()) {
    if (!cursor_.readTag(tag)) return false;
    if (tag.kind == XmlTag::End) {
      if (tag.name != open.back()) return false;
      open.pop_back();
      paints_.pop_back();
      continue;
    }
    if ((++elements_ & 255) == 0) {  // cancel and progress every 256 elements
      if (cancelled()) {
        cancelled_ = true;
        return false;
      }
      if (progress_) progress_(static_cast<double>(cursor_.position()) / total);
    }
    if (!element(tagOf(tag.name), tag.attributes, tag.selfClosing) || overBudget_) return false;
    if (!tag.selfClosing) open.push_back(tag.name);
  }
  return cursor_.skipEpilog();
}

DirectStatus DirectReader::run() {
  if (!asciiWithoutReferences(text_)) return DirectStatus::Declined;
  if (cancelled()) return DirectStatus::Cancelled;
  const bool ok = readRoot() && readContent();
  if (cancelled_) return DirectStatus::Cancelled;
  if (overBudget_) return DirectStatus::TooManyPoints;
  return ok ? DirectStatus::Captured : DirectStatus::Declined;
}

}  // namespace

DirectStatus captureDirect(const QByteArray& data, const ImportOptions& options,
                           const ProgressFn& progress, DirectCapture& out, const RunSink& sink) {
  out = DirectCapture{};
  DirectReader reader(std::string_view(data.constData(), static_cast<std::size_t>(data.size())),
                      options, progress, out, sink);
  const DirectStatus status = reader.run();
  if (status != DirectStatus::Captured) out = DirectCapture{};
  return status;
}

}  // namespace fivebar::svg
