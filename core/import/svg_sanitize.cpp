// SPDX-License-Identifier: GPL-3.0-or-later
#include "svg_sanitize.hpp"

#include <QBuffer>
#include <QSet>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

#include "path_data.hpp"
#include "sanitizer.hpp"

namespace fivebar::svg {
namespace detail {
namespace {

bool isDropped(QStringView tag) {
  static const QSet<QStringView> dropped{u"image", u"script", u"foreignObject", u"video", u"audio",
                                     u"iframe", u"canvas", u"feImage", u"handler"};
  return dropped.contains(tag);
}

bool isRendering(QStringView tag) {
  static const QSet<QStringView> rendering{u"g", u"path", u"rect", u"circle", u"ellipse", u"line",
                                       u"polyline", u"polygon", u"text", u"use", u"svg", u"a",
                                       u"switch", u"textArea"};
  return rendering.contains(tag);
}

// Never drawn by themselves, wherever they stand (SVG "never-rendered elements" and metadata);
// Qt SVG 6.4 draws the content of those it does not know. Markers and symbols are rewritten
// (svg_sanitize_rewrite.cpp); gradients are kept for Qt's brushes (their <stop>s draw nothing).
bool isNeverRendered(QStringView tag) {
  static const QSet<QStringView> never{u"clipPath", u"mask", u"pattern", u"filter", u"metadata",
                                       u"title", u"desc", u"cursor", u"view"};
  return never.contains(tag);
}

// The first command of path data when it is not a moveto (SVG: the data is in error from it
// and nothing is drawn); empty for a good start or empty data.
QString badFirstCommand(QStringView d) {
  const QStringView t = d.trimmed();
  if (t.isEmpty() || t.front() == u'M' || t.front() == u'm') return {};
  if (t.front().isLetter()) return t.left(1).toString();  // the command
  qsizetype n = 1;  // data without a command: its first token
  while (n < t.size() && n < 24 && !t[n].isSpace() && t[n] != u',') ++n;
  return t.left(n).toString();
}

bool isShape(QStringView tag) {
  static const QSet<QStringView> shapes{u"path", u"rect", u"circle", u"ellipse", u"line", u"polyline",
                                    u"polygon", u"text", u"use", u"textArea"};
  return shapes.contains(tag);
}

bool isGeometryAttribute(QStringView name) {
  static const QSet<QStringView> geometry{u"d", u"points", u"x", u"y", u"x1", u"y1", u"x2", u"y2", u"cx",
                                      u"cy", u"r", u"rx", u"ry", u"width", u"height", u"transform",
                                      u"viewBox"};
  return geometry.contains(name);
}


// True when a <style> sheet may select <rect> by its type (a "rect" selector token).
bool styleSheetSelectsRect(const QByteArray& document) {
  if (!document.contains("<style") || !document.contains("rect")) return false;
  QXmlStreamReader reader(document);
  QString css;
  bool inStyle = false;
  while (!reader.atEnd()) {
    const QXmlStreamReader::TokenType t = reader.readNext();
    if (t == QXmlStreamReader::StartElement) inStyle = reader.name() == u"style";
    else if (t == QXmlStreamReader::EndElement) inStyle = false;
    else if (t == QXmlStreamReader::Characters && inStyle) css += reader.text().toString() + u'\n';
  }
  static const QRegularExpression selector(QStringLiteral("(^|[^-\\w#.])rect($|[^-\\w])"));
  return css.contains(selector);
}

// The ids of the document's <pattern> elements (one quick pass, only when the text holds one).
QSet<QString> scanPatternIds(const QByteArray& document) {
  QSet<QString> ids;
  if (!document.contains("pattern")) return ids;
  QXmlStreamReader reader(document);
  while (!reader.atEnd())
    if (reader.readNext() == QXmlStreamReader::StartElement && reader.name() == u"pattern")
      if (const QStringView id = reader.attributes().value(QStringLiteral("id")); !id.isEmpty())
        ids.insert(id.toString());
  return ids;
}

}  // namespace

Message Sanitizer::where() const {
  return FB_TR("ImportError", "line %1: <%2>")
      .arg(static_cast<long long>(reader_.lineNumber()))
      .arg(reader_.name().toString().toStdString());
}

void Sanitizer::warn(Message what) {
  std::string key = what.text();
  auto [it, inserted] = warnings_.try_emplace(std::move(key), Repeated{std::move(what), 0, reader_.lineNumber()});
  ++it->second.count;
}

// A warning about one element: "line 12: <path id="p3"> what".
void Sanitizer::warnAt(const QXmlStreamAttributes& attributes, Message what) {
  constexpr std::size_t kMaxLocated = 50;
  if (located_.size() >= kMaxLocated) return warn(FB_TR("ImportWarning", "further element warnings not listed"));
  const QString id = attributes.value(QStringLiteral("id")).toString();
  std::string element = "<";  // appended piece by piece (GCC 12 warns falsely on "literal" + std::string&&)
  element += reader_.name().toString().toStdString();
  if (!id.isEmpty()) (element += " id=\"") += id.toStdString() + "\"";
  element += ">";
  located_.push_back(FB_TR("ImportWarning", "line %1: %2 %3")
                         .arg(static_cast<long long>(reader_.lineNumber())).arg(element).arg(std::move(what)));
}

void Sanitizer::fail(ImportStatus status, Message message) {
  if (result_.status == ImportStatus::Ok) {
    result_.status = status;
    result_.error = std::move(message);
  }
}

SanitizeResult Sanitizer::run() {
  const qint64 total = std::max<qint64>(1, input_.size());
  long long tokens = 0;
  writer_.writeStartDocument(QStringLiteral("1.0"));
  while (!reader_.atEnd() && result_.status == ImportStatus::Ok) {
    const QXmlStreamReader::TokenType token = reader_.readNext();
    if (progress_ && (++tokens & 4095) == 0 &&
        !progress_(static_cast<double>(input_.pos()) / static_cast<double>(total))) {
      fail(ImportStatus::Cancelled, FB_TR("ImportError", "import cancelled"));
      break;
    }
    switch (token) {
      case QXmlStreamReader::StartElement: startElement(); break;
      case QXmlStreamReader::EndElement: endElement(); break;
      case QXmlStreamReader::Characters: characters(); break;
      case QXmlStreamReader::DTD:
        if (!reader_.entityDeclarations().isEmpty())
          warn(FB_TR("ImportWarning", "DOCTYPE with entity declarations removed (internal entities were expanded)"));
        break;
      case QXmlStreamReader::EntityReference:
        warn(FB_TR("ImportWarning", "unresolved entity reference dropped"));
        break;
      case QXmlStreamReader::ProcessingInstruction:
        if (reader_.processingInstructionTarget() == u"xml-stylesheet")
          warn(FB_TR("ImportWarning", "external style sheet (xml-stylesheet) ignored"));
        break;
      default: break;  // comments, StartDocument, EndDocument
    }
  }
  if (reader_.hasError() && result_.status == ImportStatus::Ok) {
    fail(ImportStatus::MalformedXml, FB_TR("ImportError", "line %1, column %2: %3")
                                         .arg(static_cast<long long>(reader_.lineNumber()))
                                         .arg(static_cast<long long>(reader_.columnNumber()))
                                         .arg(reader_.errorString().toStdString()));
  }
  if (result_.status == ImportStatus::Ok && !sawRoot_)
    fail(ImportStatus::InvalidDocument, FB_TR("ImportError", "no <svg> element found"));
  if (result_.status == ImportStatus::Ok && !firstNumberDrop_.empty() && result_.shapeCount == 0)
    fail(ImportStatus::InvalidNumber, std::move(firstNumberDrop_));  // nothing drawable left
  writer_.writeEndDocument();
  result_.warnings = std::move(located_);
  for (auto& [text, repeated] : warnings_) {
    result_.warnings.push_back(FB_TR("ImportWarning", "%1 (%2x, first at line %3)")
                                   .arg(std::move(repeated.what))
                                   .arg(repeated.count)
                                   .arg(static_cast<long long>(repeated.firstLine)));
  }
  return std::move(result_);
}

void Sanitizer::recordRoot(const QXmlStreamAttributes& attributes) {
  RootAttributes& root = result_.root;
  root.line = reader_.lineNumber();
  root.hasWidth = attributes.hasAttribute(QStringLiteral("width"));
  root.hasHeight = attributes.hasAttribute(QStringLiteral("height"));
  root.hasViewBox = attributes.hasAttribute(QStringLiteral("viewBox"));
  root.width = attributes.value(QStringLiteral("width")).toString();
  root.height = attributes.value(QStringLiteral("height")).toString();
  root.viewBox = attributes.value(QStringLiteral("viewBox")).toString();
  root.preserveAspectRatio = attributes.value(QStringLiteral("preserveAspectRatio")).toString();
}

Message Sanitizer::numberProblem(QStringView tag, const QXmlStreamAttributes& attributes) const {
  for (const QXmlStreamAttribute& a : attributes) {
    if (!a.namespaceUri().isEmpty() || !isGeometryAttribute(a.name())) continue;
    if (const std::optional<NonFiniteNumber> bad = firstNonFiniteNumber(a.value())) {
      const QString id = attributes.value(QStringLiteral("id")).toString();
      return Message(bad->notANumber
                         ? FB_TR("ImportError", "line %1: <%2> attribute %3 contains a value that is not a number (%4)")
                         : FB_TR("ImportError", "line %1: <%2> attribute %3 contains a number beyond 1e300 (%4)"))
          .arg(static_cast<long long>(reader_.lineNumber()))
          .arg(tag.toString().toStdString() + (id.isEmpty() ? "" : " id=\"" + id.toStdString() + "\""))
          .arg(a.name().toString().toStdString())
          .arg(bad->token);
    }
  }
  return {};
}

QXmlStreamAttributes Sanitizer::cleanAttributes(QStringView tag) {
  QXmlStreamAttributes out;
  out.reserve(reader_.attributes().size());
  // SVG 2: a plain href wins over xlink:href; keep only one of them.
  const bool plainHref = reader_.attributes().hasAttribute(QStringLiteral("href"));
  for (const QXmlStreamAttribute& a : reader_.attributes()) {
    if (plainHref && a.name() == u"href" && a.namespaceUri() == kXlinkNs) continue;
    const QStringView name = a.name();
    if (name.startsWith(u"on") && a.namespaceUri().isEmpty()) {
      warn(FB_TR("ImportWarning", "event attribute (on...) removed"));
      continue;
    }
    if (name == u"href" && (a.namespaceUri() == kXlinkNs || a.namespaceUri().isEmpty())) {
      if (!a.value().startsWith(u'#')) {
        warn(FB_TR("ImportWarning", "external reference removed from %1").arg(QStringLiteral("<%1>").arg(tag).toStdString()));
        continue;
      }
      if (a.namespaceUri().isEmpty()) {
        out.append(kXlinkNs, QStringLiteral("href"), a.value().toString());
        continue;
      }
    }
    out.append(a);
  }
  return out;
}

void Sanitizer::startElement() {
  ++depth_;
  if (skipDepth_ > 0) return;
  const QString tag = reader_.name().toString();
  if (depth_ > kMaxDepth) {
    fail(ImportStatus::InvalidDocument,
         FB_TR("ImportError", "%1: nesting deeper than %2 elements").arg(where()).arg(kMaxDepth));
    return;
  }
  if (isDropped(tag)) {
    warn(FB_TR("ImportWarning", "%1 element removed").arg("<" + tag.toStdString() + ">"));
    skipDepth_ = depth_;
    return;
  }
  if (depth_ == 1) {
    if (tag != u"svg") {
      fail(ImportStatus::InvalidDocument, FB_TR("ImportError", "%1: the root element is not <svg>").arg(where()));
      return;
    }
    sawRoot_ = true;
    svgNamespace_ = reader_.namespaceUri().toString();
    recordRoot(reader_.attributes());
    setViewport();
  }
  // Inside a gradient only <stop> (and animation) belongs: Qt SVG would draw anything else.
  const bool inGradient = gradientDepth_ > 0 && depth_ == gradientDepth_ + 1 && tag != u"stop" &&
                          tag != u"animate" && tag != u"set";
  const bool clipDefinition =
      tag == u"clipPath" && clipPaths_.count(reader_.attributes().value(QStringLiteral("id")).toString());
  if (depth_ > 1 && ((isNeverRendered(tag) && !clipDefinition) || inGradient ||
                     !isSvgNamespace(reader_.namespaceUri()))) {
    if (tag == u"pattern") warn(FB_TR("ImportWarning", "pattern fills are drawn as outlines, without the pattern"));
    skipDepth_ = depth_;
    return;
  }
  const QXmlStreamAttributes cleaned = cleanAttributes(tag);
  // A non-finite number: the root refuses the file; any other element is dropped (the file is
  // refused at the end only when nothing drawable is left).
  if (Message bad = numberProblem(tag, cleaned); !bad.empty()) {
    if (depth_ == 1) return fail(ImportStatus::InvalidNumber, std::move(bad));
    if (firstNumberDrop_.empty()) firstNumberDrop_ = bad;
    located_.push_back(FB_TR("ImportWarning", "%1: the element is not drawn").arg(std::move(bad)));
    skipDepth_ = depth_;
    return;
  }
  // Not drawn, as SVG says: a marker without an id, zero-size shapes, path data whose first
  // command is not a moveto.
  QXmlStreamAttributes attributes = rewriteAttributes(tag, cleaned);
  if (clipContentDepth_ > 0) attributes = clipContentAttributes(attributes);
  const QString badStart = tag == u"path" ? badFirstCommand(attributes.value(QStringLiteral("d"))) : QString();
  if (!badStart.isEmpty())
    warnAt(attributes, FB_TR("ImportWarning", "attribute d: path data begins with \"%1\", not a moveto (M or m): "
                                              "in error from its first command, nothing drawn")
                           .arg(badStart.toStdString()));
  if ((tag == u"marker" && !markers_.count(attributes.value(QStringLiteral("id")).toString())) ||
      isZeroSizeShape(tag, attributes) || !badStart.isEmpty()) {
    fontSizes_.pop_back();
    skipDepth_ = depth_;
    return;
  }
  warnUnsupported(tag, cleaned);
  extraEnds_.push_back(0);
  pushMarkerState(tag, attributes);
  // The sentinel colour holds index + 1 in 24 bits; later elements share the last marker.
  constexpr std::size_t kMaxMarkers = 0xFFFFFE;
  if (depth_ == 2 && isRendering(tag) && result_.topLevel.size() < kMaxMarkers) {
    const int index = static_cast<int>(result_.topLevel.size());
    TopLevelElement top;
    top.tag = tag;
    top.id = attributes.value(QStringLiteral("id")).toString();
    top.label = attributes.value(kInkscapeNs, QStringLiteral("label")).toString();
    top.inkscapeLayer = tag == u"g" &&
                        attributes.value(kInkscapeNs, QStringLiteral("groupmode")) == u"layer";
    result_.topLevel.push_back(top);
    writeSentinel(index);
  }
  if (isShape(tag)) ++result_.shapeCount;
  if (tag == u"linearGradient" || tag == u"radialGradient") gradientDepth_ = depth_;
  inStyle_ = tag == u"style";
  beginClip(attributes);
  writeNamespaces();
  if (depth_ > 1 && tag == u"svg") return writeNestedSvgAsGroup(attributes);
  if (writeUseOfSvg(attributes) || writeSymbolOrUse(tag, attributes) || writeMarkerDefinition(tag, attributes) ||
      writeClipPathDefinition(tag, attributes))
    return;
  if (tag == u"rect" && writeRoundedRect(attributes)) return;
  writer_.writeStartElement(reader_.namespaceUri().toString(), tag);
  if (tag == u"path") {
    if (writeSplitPath(attributes)) return;
    checkPathData(attributes);
  }
  writer_.writeAttributes(attributes);
}

void Sanitizer::endElement() {
  if (skipDepth_ > 0) {
    if (depth_ == skipDepth_) skipDepth_ = 0;
    --depth_;
    return;
  }
  if (depth_ == markerContentDepth_) markerContentDepth_ = 0;
  if (depth_ == gradientDepth_) gradientDepth_ = 0;
  if (depth_ == clipContentDepth_) clipContentDepth_ = 0;
  if (!outerViewports_.empty() && outerViewports_.back().first == depth_) {
    viewport_ = outerViewports_.back().second;
    outerViewports_.pop_back();
  }
  --depth_;
  inStyle_ = false;
  if (result_.status != ImportStatus::Ok) return;
  writer_.writeEndElement();
  if (extraEnds_.empty()) return;
  for (int i = 0; i < extraEnds_.back(); ++i) writer_.writeEndElement();
  extraEnds_.pop_back();
  writeMarkerInstances();
  endClip();
  markerStates_.pop_back();
  fontSizes_.pop_back();
}

void Sanitizer::characters() {
  if (skipDepth_ > 0 || depth_ == 0) return;
  QString text = reader_.text().toString();
  if (inStyle_ && text.contains(QStringLiteral("marker")))
    for (const QString& selector : parseMarkerSheet(text).unsupported)
      warn(FB_TR("ImportWarning", "markers set in a style sheet for the selector '%1' are not drawn "
                                  "(only type, #id and .class selectors are applied)")
               .arg(selector.toStdString()));
  if (inStyle_ && text.contains(QStringLiteral("clip-path")))
    warn(FB_TR("ImportWarning", "clip-path set in a style sheet is not applied: those shapes are drawn unclipped"));
  if (inStyle_ && text.contains(QStringLiteral("@import"))) {
    static const QRegularExpression import(QStringLiteral("@import[^;]*;?"));
    text.remove(import);
    warn(FB_TR("ImportWarning", "CSS @import removed"));
  }
  if (reader_.isCDATA()) writer_.writeCDATA(text);
  else writer_.writeCharacters(text);
}

}  // namespace detail

SanitizeResult sanitizeSvg(QIODevice& input, double dpi,
                           const std::function<bool(double)>& progress) {
  std::map<QString, SymbolInfo> symbols;
  std::map<QString, MarkerInfo> markers;
  MarkerSheet sheet;
  bool rectStyled = false;
  if (const auto* buffer = qobject_cast<const QBuffer*>(&input)) {
    symbols = scanSymbols(buffer->data());
    markers = scanMarkers(buffer->data());
    sheet = scanMarkerSheet(buffer->data());
    rectStyled = detail::styleSheetSelectsRect(buffer->data());
  }
  detail::Sanitizer sanitizer(input, dpi, progress, std::move(symbols), std::move(markers));
  sanitizer.setMarkerSheet(std::move(sheet));
  sanitizer.setRectStyled(rectStyled);
  if (const auto* buffer = qobject_cast<const QBuffer*>(&input))
    sanitizer.setPatternIds(detail::scanPatternIds(buffer->data()));
  if (const auto* buffer = qobject_cast<const QBuffer*>(&input)) {
    sanitizer.setClipPaths(scanClipPaths(buffer->data()));
    sanitizer.setNestedSvgs(scanNestedSvgs(buffer->data()));
  }
  return sanitizer.run();
}

}  // namespace fivebar::svg
