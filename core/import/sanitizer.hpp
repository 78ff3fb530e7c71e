// SPDX-License-Identifier: GPL-3.0-or-later
// The sanitiser's state machine (svg_sanitize.cpp: the streaming rewrite; svg_sanitize_rewrite.cpp:
// the rewrites that make Qt SVG draw what a browser draws). Private to core/import.
#pragma once

#include <QSet>
#include <QXmlStreamReader>
#include <QXmlStreamWriter>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "capture_engine.hpp"
#include "svg_markers.hpp"
#include "svg_rewrite.hpp"
#include "svg_sanitize.hpp"

namespace fivebar::svg::detail {

inline const QString kXlinkNs = QStringLiteral("http://www.w3.org/1999/xlink");
inline const QString kInkscapeNs = QStringLiteral("http://www.inkscape.org/namespaces/inkscape");

class Sanitizer {
 public:
  Sanitizer(QIODevice& input, double dpi, const std::function<bool(double)>& progress,
            std::map<QString, SymbolInfo> symbols, std::map<QString, MarkerInfo> markers)
      : input_(input), dpi_(dpi), progress_(progress), reader_(&input), writer_(&result_.svg),
        symbols_(std::move(symbols)), markers_(std::move(markers)) {
    // The output is about as long as the input: reserve once instead of growing 50 MB by steps.
    result_.svg.reserve(static_cast<qsizetype>(std::min<qint64>(input.size() + 65536, qint64{1} << 30)));
    writer_.setAutoFormatting(false);
  }

  SanitizeResult run();

 private:
  void startElement();
  void endElement();
  void characters();
  QXmlStreamAttributes cleanAttributes(QStringView tag);
  // The first non-finite number of a geometry attribute, worded with line and element; empty if none.
  Message numberProblem(QStringView tag, const QXmlStreamAttributes& attributes) const;
  bool isSvgNamespace(QStringView uri) const {
    return uri == svgNamespace_ || uri == u"http://www.w3.org/2000/svg";
  }
  bool writeSplitPath(const QXmlStreamAttributes& attributes);
  bool writeRoundedRect(const QXmlStreamAttributes& attributes);
  void writeSentinel(int index);
  void recordRoot(const QXmlStreamAttributes& attributes);
  void writeNamespaces();
  void writeNestedSvgAsGroup(const QXmlStreamAttributes& attributes);
  QXmlStreamAttributes rewriteAttributes(QStringView tag, const QXmlStreamAttributes& attributes);
  void warnUnsupported(QStringView tag, const QXmlStreamAttributes& attributes);
  void checkPathData(const QXmlStreamAttributes& attributes);
  bool writeSymbolOrUse(QStringView tag, const QXmlStreamAttributes& attributes);
  void setViewport();
  void pushMarkerState(QStringView tag, const QXmlStreamAttributes& attributes);
  bool writeMarkerDefinition(QStringView tag, const QXmlStreamAttributes& attributes);
  void writeMarkerInstances();
  void warn(Message what);
  void warnAt(const QXmlStreamAttributes& attributes, Message what);
  void fail(ImportStatus status, Message message);
  Message where() const;  // "line N: <tag>"

  QIODevice& input_;
  double dpi_;
  const std::function<bool(double)>& progress_;
  QXmlStreamReader reader_;
  SanitizeResult result_;   // before writer_, which writes into result_.svg
  QXmlStreamWriter writer_;
  int depth_ = 0;
  int skipDepth_ = 0;  // > 0 while inside a dropped element: its depth
  bool inStyle_ = false;
  bool sawRoot_ = false;
  QString svgNamespace_;
  struct Repeated {
    Message what;
    int count = 0;
    qint64 firstLine = 0;
  };
  std::map<std::string, Repeated> warnings_;  // English text -> the warning, count, first line
  std::vector<Message> located_;  // warnings naming their own line, in document order
  Message firstNumberDrop_;       // the first element dropped for a non-finite number
  std::map<QString, SymbolInfo> symbols_;  // from scanSymbols, for <use> of a <symbol>
  UserViewport viewport_;  // the nearest viewport (root, nested <svg>): % lengths, vw/vh
  std::vector<std::pair<int, UserViewport>> outerViewports_;  // depth of a nested <svg>, its parent's
  std::vector<double> fontSizes_;  // user units, one per open written element
  std::vector<int> extraEnds_;     // end tags to add when the element closes (symbol, use)
  std::map<QString, MarkerInfo> markers_;  // from scanMarkers
  MarkerSheet markerSheet_;                // from scanMarkerSheet

 public:
  void setMarkerSheet(MarkerSheet sheet) { markerSheet_ = std::move(sheet); }
  // A style sheet selects <rect> by type: rounded rectangles stay <rect> (Qt's own arcs).
  void setRectStyled(bool styled) { rectStyled_ = styled; }
  // The document's <pattern> ids: a fill referring to one is drawn as its fallback colour (else
  // black), so that the outline the warning promises is drawn (the pattern itself is dropped).
  void setPatternIds(QSet<QString> ids) { patternIds_ = std::move(ids); }
  void setClipPaths(std::map<QString, ClipPathInfo> clips) { clipPaths_ = std::move(clips); }
  void setNestedSvgs(std::map<QString, NestedSvgInfo> svgs) { nestedSvgs_ = std::move(svgs); }

 private:
  struct MarkerState {
    MarkerRefs refs;            // inherited marker properties
    double strokeWidth = 1.0;   // user units, inherited
    QString transform;          // the marked element's transform
    std::vector<std::pair<QString, QString>> instances;  // marker id, instance transform
  };
  std::vector<MarkerState> markerStates_;  // one per open written element
  int markerContentDepth_ = 0;
  int gradientDepth_ = 0;  // > 0 inside a gradient: its depth (children other than stops dropped)             // > 0 inside a <marker>: its depth (no markers drawn)
  std::size_t markerInstances_ = 0;        // written so far (bounded)
  bool rectStyled_ = false;
  QSet<QString> patternIds_;
  // Clip paths (svg_sanitize_clip.cpp).
  struct ClipTail {
    std::vector<QString> ids;  // the element's clip path, then the one clipping that, ...
    QString transform;         // the element's transform (the clip's user space)
    std::optional<QRectF> viewport;  // a nested <svg>'s or a used <symbol>'s viewport (overflow hidden)
    bool wrapped = false;            // inside a <g id> that took the element's id (for <use>)
  };
  std::optional<QRectF> clippedViewport(const QXmlStreamAttributes& attributes) const;
  void writeClipSentinel(std::uint32_t command);
  bool writeClipPathDefinition(QStringView tag, const QXmlStreamAttributes& attributes);
  QXmlStreamAttributes clipContentAttributes(const QXmlStreamAttributes& attributes) const;
  // Writes what comes before a clipped element; moves its id onto a wrapping <g> (so that a <use>
  // of it replays the clip too).
  void beginClip(QXmlStreamAttributes& attributes);
  void endClip();
  std::map<QString, ClipPathInfo> clipPaths_;
  // A <use width height> of a nested <svg> (svg_sanitize_write.cpp): the svg's content at the
  // use's size. The nested svg's own viewport is taken against the root's.
  std::map<QString, NestedSvgInfo> nestedSvgs_;
  UserViewport rootViewport_;
  const NestedSvgInfo* sizedSvgOfUse(const QXmlStreamAttributes& attributes) const;
  NestedViewport viewportAtUse(const NestedSvgInfo& svg, const QXmlStreamAttributes& use) const;
  bool writeUseOfSvg(const QXmlStreamAttributes& attributes);
  std::vector<ClipTail> clipTails_;  // one per open written element
  int clipContentDepth_ = 0;         // > 0 inside a <clipPath>: its depth
  QString clipContentRule_;          // the clipPath's clip-rule
  QString withoutPatternPaint(const QString& paint) const;  // fill value; unchanged if no pattern
};

}  // namespace fivebar::svg::detail
