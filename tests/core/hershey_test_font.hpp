// SPDX-License-Identifier: GPL-3.0-or-later
// Hershey .jhf text built in the tests (hershey_font_test.cpp, text_layout_test.cpp): glyphs
// encoded as the format says (docs/text.md), so the tests know every number they check.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "core/text/hershey_font.hpp"

namespace fivebar::test {

// One .jhf line: glyph number, vertex count, bounds, strokes separated by " R".
inline std::string jhfLine(int left, int right, const std::vector<std::vector<text::HersheyPoint>>& strokes,
                           int number = 12345) {
  std::string body;
  body += static_cast<char>('R' + left);
  body += static_cast<char>('R' + right);
  int count = 1;
  for (std::size_t s = 0; s < strokes.size(); ++s) {
    if (s > 0) {
      body += " R";
      ++count;
    }
    for (const text::HersheyPoint& p : strokes[s]) {
      body += static_cast<char>('R' + p.x);
      body += static_cast<char>('R' + p.y);
      ++count;
    }
  }
  char head[16];
  std::snprintf(head, sizeof head, "%5d%3d", number, count);
  return head + body + "\n";
}

// The 'H' of futural: cap top -12, baseline 9 (cap height 21), bounds -11..11.
inline std::vector<std::vector<text::HersheyPoint>> futuralH() {
  return {{{-7, -12}, {-7, 9}}, {{7, -12}, {7, 9}}, {{-7, -2}, {7, -2}}};
}

// A font of `count` glyphs from the space: the space spans -8..8, 'H' is futural's, 'A' an open
// triangle with its bar (-9..9), every other glyph one stroke from (-5, 0) to (5, -10) (-5..5).
inline std::string testFontText(int count = 96) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    const char32_t cp = 32 + static_cast<char32_t>(i);
    if (cp == U' ') text += jhfLine(-8, 8, {});
    else if (cp == U'H') text += jhfLine(-11, 11, futuralH());
    else if (cp == U'A') text += jhfLine(-9, 9, {{{-8, 9}, {0, -12}, {8, 9}}, {{-5, 2}, {5, 2}}});
    else text += jhfLine(-5, 5, {{{-5, 0}, {5, -10}}});
  }
  return text;
}

}  // namespace fivebar::test
