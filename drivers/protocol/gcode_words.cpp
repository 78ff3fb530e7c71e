// SPDX-License-Identifier: GPL-3.0-or-later
#include "gcode_words.hpp"

#include <cctype>
#include <cmath>

#include "grbl_parser.hpp"

namespace fivebar::gcode {

std::optional<double> Words::get(char letter) const {
  std::optional<double> v;
  for (const Word& w : words)
    if (w.letter == letter) v = w.value;
  return v;
}

bool Words::hasCode(char letter, double code) const {
  for (const Word& w : words)
    if (w.letter == letter && std::abs(w.value - code) < 1e-6) return true;
  return false;
}

std::string compact(std::string_view line) {
  std::string out;
  int depth = 0;
  for (char c : line) {
    if (c == ';' && depth == 0) break;
    if (c == '(') { ++depth; continue; }
    if (c == ')' && depth > 0) { --depth; continue; }
    if (depth > 0 || std::isspace(static_cast<unsigned char>(c))) continue;
    out.push_back(char(std::toupper(static_cast<unsigned char>(c))));
  }
  return out;
}

Words parseWords(std::string_view line) {
  Words w;
  int depth = 0;
  for (char c : line) {
    if (c == ';' && depth == 0) break;
    if (c == '(') ++depth;
    if (c == ')' && depth > 0) --depth;
  }
  if (depth > 0) { w.status = WordsStatus::UnclosedComment; return w; }
  const std::string s = compact(line);
  size_t i = 0;
  while (i < s.size()) {
    const char letter = s[i];
    if (letter < 'A' || letter > 'Z') { w.status = WordsStatus::BadLetter; return w; }
    size_t j = i + 1;
    while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.' ||
                            s[j] == '-' || s[j] == '+'))
      ++j;
    const auto v = grbl::parseNumber(std::string_view(s).substr(i + 1, j - i - 1));
    if (!v) { w.status = WordsStatus::BadNumber; return w; }
    w.words.push_back({letter, *v});
    i = j;
  }
  return w;
}

}  // namespace fivebar::gcode
