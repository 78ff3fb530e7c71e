// SPDX-License-Identifier: GPL-3.0-or-later
// A G-code line as words (letter + number), comments and spaces removed. Shared by the job
// reader (which needs targets and tool commands) and the simulated machine.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fivebar::gcode {

struct Word {
  char letter = 0;  // upper case
  double value = 0.0;
};

enum class WordsStatus { Ok, BadLetter, BadNumber, UnclosedComment };

struct Words {
  WordsStatus status = WordsStatus::Ok;
  std::vector<Word> words;
  bool ok() const { return status == WordsStatus::Ok; }
  // Value of the (last) word with this letter.
  std::optional<double> get(char letter) const;
  bool has(char letter) const { return get(letter).has_value(); }
  // True when a G (or M) word with exactly this code is present (e.g. hasCode('G', 10)).
  bool hasCode(char letter, double code) const;
};

// Splits a line into words. Comments "( ... )" and "; ..." and whitespace are dropped.
Words parseWords(std::string_view line);

// The line without comments and whitespace, upper case: what is worth sending to the board.
std::string compact(std::string_view line);

}  // namespace fivebar::gcode
