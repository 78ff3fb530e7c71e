// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/text/text_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace fivebar::text {
namespace {

struct DecodedChar {
  char32_t codePoint = 0;
  std::size_t byteOffset = 0;
  bool valid = true;
};

// Strict UTF-8 (no overlong forms, no surrogates, nothing past U+10FFFF); a bad byte is one
// invalid character and decoding resumes at the next byte.
std::vector<DecodedChar> decodeUtf8(std::string_view s) {
  std::vector<DecodedChar> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const auto b0 = static_cast<unsigned char>(s[i]);
    int extra = 0;
    char32_t cp = 0, minimum = 0;
    if (b0 < 0x80) {
      cp = b0;
    } else if ((b0 & 0xE0) == 0xC0) {
      extra = 1, cp = b0 & 0x1F, minimum = 0x80;
    } else if ((b0 & 0xF0) == 0xE0) {
      extra = 2, cp = b0 & 0x0F, minimum = 0x800;
    } else if ((b0 & 0xF8) == 0xF0) {
      extra = 3, cp = b0 & 0x07, minimum = 0x10000;
    } else {
      out.push_back({0xFFFD, i, false});
      ++i;
      continue;
    }
    bool ok = i + static_cast<std::size_t>(extra) < s.size();
    for (int k = 1; ok && k <= extra; ++k) {
      const auto b = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
      if ((b & 0xC0) != 0x80) ok = false;
      cp = (cp << 6) | (b & 0x3F);
    }
    if (!ok || cp < minimum || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) {
      out.push_back({0xFFFD, i, false});
      ++i;
      continue;
    }
    out.push_back({cp, i, true});
    i += 1 + static_cast<std::size_t>(extra);
  }
  return out;
}

std::string utf8Of(char32_t cp) {
  std::string s;
  if (cp < 0x80) {
    s += static_cast<char>(cp);
  } else if (cp < 0x800) {
    s += static_cast<char>(0xC0 | (cp >> 6));
    s += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    s += static_cast<char>(0xE0 | (cp >> 12));
    s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    s += static_cast<char>(0xF0 | (cp >> 18));
    s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (cp & 0x3F));
  }
  return s;
}

struct LineItem {
  const HersheyGlyph* glyph;
  char32_t codePoint;
  std::size_t byteOffset;
};

// The text split into lines of glyphs; characters without a glyph go to `missing`.
// newlineBreaks false: '\n' is a space (text on a path is one line).
std::vector<std::vector<LineItem>> splitIntoLines(const HersheyFont& font, std::string_view utf8,
                                                  bool newlineBreaks, std::vector<MissingGlyph>& missing) {
  std::vector<std::vector<LineItem>> lines(1);
  int column = -1;
  for (const DecodedChar& c : decodeUtf8(utf8)) {
    const int lineNo = static_cast<int>(lines.size()) - 1;
    ++column;
    if (!c.valid) {
      missing.push_back({c.codePoint, c.byteOffset, lineNo, column, true});
      continue;
    }
    if (c.codePoint == U'\r') continue;
    if (c.codePoint == U'\n' && newlineBreaks) {
      lines.emplace_back();
      column = -1;
      continue;
    }
    const char32_t cp = (c.codePoint == U'\t' || c.codePoint == U'\n') ? U' ' : c.codePoint;
    const HersheyGlyph* g = font.glyph(cp);
    if (!g) {
      missing.push_back({c.codePoint, c.byteOffset, lineNo, column, false});
      continue;
    }
    lines.back().push_back({g, c.codePoint, c.byteOffset});
  }
  return lines;
}

}  // namespace

std::string validate(const TextStyle& style) {
  char buf[160];
  if (!std::isfinite(style.heightMm) || !(style.heightMm > 0.0)) {
    std::snprintf(buf, sizeof buf, "the height must be a positive number of mm, got %g", style.heightMm);
    return buf;
  }
  if (!std::isfinite(style.lineSpacing) || !(style.lineSpacing > 0.0)) {
    std::snprintf(buf, sizeof buf, "the line spacing must be a positive factor, got %g", style.lineSpacing);
    return buf;
  }
  return {};
}

std::string describe(const MissingGlyph& m) {
  char buf[96];
  if (m.invalidUtf8) {
    std::snprintf(buf, sizeof buf, "invalid UTF-8 at byte %zu", m.byteOffset + 1);
    return buf;
  }
  std::snprintf(buf, sizeof buf, " (U+%04X) at line %d, character %d", static_cast<unsigned>(m.codePoint),
                m.line + 1, m.column + 1);
  const bool printable = m.codePoint >= 0x20 && m.codePoint != 0x7F && !(m.codePoint >= 0x80 && m.codePoint < 0xA0);
  std::string out;
  if (printable) {
    out += '\'';
    out += utf8Of(m.codePoint);
    out += '\'';
  } else {
    out += "a control character";
  }
  out += buf;
  return out;
}

TextLayout layoutText(const HersheyFont& font, std::string_view utf8, const TextStyle& style) {
  TextLayout layout;
  if (!validate(style).empty() || font.capHeight() <= 0) return layout;
  const double s = style.heightMm / font.capHeight();
  layout.scaleMmPerUnit = s;
  layout.capHeightMm = style.heightMm;
  layout.lineAdvanceMm = style.lineSpacing * font.lineHeight * s;
  const auto lines = splitIntoLines(font, utf8, true, layout.missing);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    double widthUnits = 0.0;
    for (const LineItem& item : lines[n]) widthUnits += item.glyph->advance();
    const double widthMm = widthUnits * s;
    layout.lineWidthsMm.push_back(widthMm);
    double penXMm = style.align == Align::Left ? 0.0 : style.align == Align::Center ? -0.5 * widthMm : -widthMm;
    const double baselineYMm = -static_cast<double>(n) * layout.lineAdvanceMm;
    for (const LineItem& item : lines[n]) {
      const HersheyGlyph& g = *item.glyph;
      PlacedGlyph placed{item.codePoint, item.byteOffset, static_cast<int>(n), penXMm, g.advance() * s,
                         layout.strokes.size(), g.strokes.size()};
      for (const auto& stroke : g.strokes) {
        Polyline line;
        line.points.reserve(stroke.size());
        for (const HersheyPoint& p : stroke)
          line.points.emplace_back(penXMm + (p.x - g.left) * s, baselineYMm + (font.baseline - p.y) * s);
        layout.strokes.push_back(std::move(line));
      }
      layout.glyphs.push_back(placed);
      penXMm += placed.advanceMm;
    }
  }
  return layout;
}

TextLayout layoutTextOnPath(const HersheyFont& font, std::string_view utf8, const TextStyle& style,
                            const std::vector<Vec2>& baselineMm) {
  // The path without repeated points, and its cumulative length.
  std::vector<Vec2> path;
  for (const Vec2& p : baselineMm)
    if (p.allFinite() && (path.empty() || (p - path.back()).norm() > 1e-12)) path.push_back(p);
  std::string oneLine(utf8);
  TextStyle straight = style;
  straight.align = Align::Left;
  std::replace(oneLine.begin(), oneLine.end(), '\n', ' ');
  TextLayout layout = layoutText(font, oneLine, straight);
  if (path.size() < 2 || layout.glyphs.empty()) {
    if (path.size() < 2) layout.strokes.clear(), layout.glyphs.clear();
    return layout;
  }
  std::vector<double> along(path.size(), 0.0);
  for (std::size_t i = 1; i < path.size(); ++i) along[i] = along[i - 1] + (path[i] - path[i - 1]).norm();
  const double total = along.back();
  const double width = layout.lineWidthsMm.front();
  const double start = style.align == Align::Left ? 0.0 : style.align == Align::Center ? 0.5 * (total - width)
                                                                                      : total - width;
  // Point and unit tangent at arc length d (straight on past either end).
  auto at = [&](double d, Vec2& point, Vec2& tangent) {
    std::size_t k = 1;
    while (k + 1 < path.size() && along[k] < d) ++k;
    tangent = (path[k] - path[k - 1]).normalized();
    point = path[k - 1] + (d - along[k - 1]) * tangent;
  };
  for (PlacedGlyph& g : layout.glyphs) {
    const double middle = g.penXMm + 0.5 * g.advanceMm;
    Vec2 origin, t;
    at(start + middle, origin, t);
    const Vec2 n(-t.y(), t.x());
    for (std::size_t k = g.firstStroke; k < g.firstStroke + g.strokeCount; ++k)
      for (Vec2& p : layout.strokes[k].points) p = origin + (p.x() - middle) * t + p.y() * n;
    g.penXMm += start;  // now the arc length of its left bound along the path
  }
  return layout;
}

double strokeLengthMm(const std::vector<Polyline>& strokes) {
  double total = 0.0;
  for (const Polyline& line : strokes) {
    for (std::size_t i = 1; i < line.points.size(); ++i) total += (line.points[i] - line.points[i - 1]).norm();
    if (line.closed && line.points.size() > 2) total += (line.points.front() - line.points.back()).norm();
  }
  return total;
}

bool strokeBounds(const std::vector<Polyline>& strokes, Vec2& minMm, Vec2& maxMm) {
  const double inf = std::numeric_limits<double>::infinity();
  minMm = Vec2(inf, inf);
  maxMm = Vec2(-inf, -inf);
  for (const Polyline& line : strokes)
    for (const Vec2& p : line.points) {
      minMm = minMm.cwiseMin(p);
      maxMm = maxMm.cwiseMax(p);
    }
  return minMm.x() <= maxMm.x();
}

}  // namespace fivebar::text
