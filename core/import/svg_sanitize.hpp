// SPDX-License-Identifier: GPL-3.0-or-later
// First pass over an SVG file: a streaming XML rewrite (QXmlStreamReader -> QXmlStreamWriter)
// that makes the document safe and complete for Qt SVG, and collects what the later passes need.
//  - drops: DTD and entity declarations (entities are expanded by the reader, within its limit),
//    processing instructions, comments, <image>, <script>, <foreignObject>, media elements,
//    event attributes (on*), external references (href not starting with '#', CSS @import);
//  - refuses: malformed XML, a root that is not <svg>, nesting deeper than kMaxDepth,
//    NaN / infinite numbers in geometry attributes (message names line and element);
//  - splits a <path> whose data would exceed Qt's 32,767-element limit into several <path>s;
//  - converts SVG 2 "href" to "xlink:href" and a nested <svg> to an equivalent <g>;
//  - records the root's width/height/viewBox and the top-level elements, and inserts the
//    layer sentinels described in capture_engine.hpp.
#pragma once

#include <QByteArray>
#include <QIODevice>
#include <QString>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "svg_import.hpp"
#include "svg_units.hpp"

namespace fivebar::svg {

inline constexpr int kMaxDepth = 256;               // element nesting refused beyond this
inline constexpr int kMaxPathElements = 16000;      // per emitted <path>; Qt's limit is 32,767
inline constexpr qsizetype kPathScanChars = 16000;  // shorter "d" cannot reach Qt's limit

struct TopLevelElement {
  QString tag;            // local name: g, path, text, ...
  QString id;
  QString label;          // inkscape:label
  bool inkscapeLayer = false;  // <g inkscape:groupmode="layer">
};

struct SanitizeResult {
  ImportStatus status = ImportStatus::Ok;
  Message error;  // without the file name; starts with "line N:" when the line is known
  QString svg;        // the rewritten document (no encoding declaration: already decoded)
  RootAttributes root;
  std::vector<TopLevelElement> topLevel;  // sentinel colour k + 1 marks element k
  long long shapeCount = 0;               // drawable elements, for progress
  std::vector<Message> warnings;          // translatable (context "ImportWarning")
};

// True when the text holds "nan", "inf" or an exponent that overflows a double (the check the
// sanitiser applies to geometry attributes).
bool hasNonFiniteNumber(QStringView value);

// The first non-finite number in the text: its token ("1e308", "nan") and whether it is not a
// number at all (nan, inf) or a number beyond 1e300; nullopt when none.
struct NonFiniteNumber {
  std::string token;
  bool notANumber = false;
};
std::optional<NonFiniteNumber> firstNonFiniteNumber(QStringView value);

// Reads the whole device. dpi: user units per inch (nested <svg> lengths). progress(fraction of
// input read) returns false to cancel.
SanitizeResult sanitizeSvg(QIODevice& input, double dpi,
                           const std::function<bool(double)>& progress = {});

}  // namespace fivebar::svg
