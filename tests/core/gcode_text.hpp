// SPDX-License-Identifier: GPL-3.0-or-later
// Reading G-code text back in tests: its lines, and the words of one line.
#pragma once

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fivebar::test {

inline std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

// Words of a G-code line ("G1 X1.5 Y-2" -> {G:1, X:1.5, Y:-2}); comments dropped.
inline std::map<char, double> wordsOf(const std::string& line) {
  std::map<char, double> w;
  std::istringstream in(line.substr(0, line.find(';')));
  for (std::string word; in >> word;) w[word[0]] = std::stod(word.substr(1));
  return w;
}

}  // namespace fivebar::test
