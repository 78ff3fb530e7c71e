// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/calibration/stroke_digits.hpp"

#include <array>

namespace fivebar {
namespace {

// Digit cell: 4 units wide, 6 tall; advance 6 units. Corner and middle points of the segments.
struct P {
  double x, y;
};
constexpr P TL{0, 6}, TR{4, 6}, ML{0, 3}, MR{4, 3}, BL{0, 0}, BR{4, 0}, TC{2, 6}, BC{2, 0};
constexpr double kUnitsHigh = 6.0;
constexpr double kUnitsWide = 4.0;
constexpr double kUnitsAdvance = 6.0;

using Glyph = std::vector<std::vector<P>>;

Glyph makeGlyph(char c) {
  switch (c) {
    case '0': return {{TL, TR, BR, BL, TL}};
    case '1': return {{TC, BC}};
    case '2': return {{TL, TR, MR, ML, BL, BR}};
    case '3': return {{TL, TR, BR, BL}, {ML, MR}};
    case '4': return {{TL, ML, MR}, {TR, BR}};
    case '5': return {{TR, TL, ML, MR, BR, BL}};
    case '6': return {{TR, TL, BL, BR, MR, ML}};
    case '7': return {{TL, TR, BR}};
    case '8': return {{TL, TR, BR, BL, TL}, {ML, MR}};
    case '9': return {{MR, ML, TL, TR, BR, BL}};
    default: return {};
  }
}

const Glyph& glyph(char c) {
  static const std::array<Glyph, 10> glyphs = [] {
    std::array<Glyph, 10> g;
    for (int d = 0; d < 10; ++d) g[static_cast<size_t>(d)] = makeGlyph(static_cast<char>('0' + d));
    return g;
  }();
  static const Glyph none;
  return c >= '0' && c <= '9' ? glyphs[static_cast<size_t>(c - '0')] : none;
}

}  // namespace

std::vector<std::vector<Vec2>> digitStrokes(std::string_view text, const Vec2& originMm,
                                            double heightMm) {
  const double unit = heightMm / kUnitsHigh;
  std::vector<std::vector<Vec2>> out;
  for (size_t i = 0; i < text.size(); ++i) {
    const Vec2 cell = originMm + Vec2(static_cast<double>(i) * kUnitsAdvance * unit, 0.0);
    for (const auto& stroke : glyph(text[i])) {
      std::vector<Vec2>& s = out.emplace_back();
      for (const P& p : stroke) s.push_back(cell + unit * Vec2(p.x, p.y));
    }
  }
  return out;
}

double digitTextWidthMm(std::string_view text, double heightMm) {
  if (text.empty()) return 0.0;
  const double unit = heightMm / kUnitsHigh;
  return (static_cast<double>(text.size() - 1) * kUnitsAdvance + kUnitsWide) * unit;
}

}  // namespace fivebar
