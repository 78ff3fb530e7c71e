// SPDX-License-Identifier: GPL-3.0-or-later
// Internal helpers of the profile JSON reader (core/profile.cpp): a strict object reader that
// records a ValidationIssue for every missing, mistyped or unknown field, naming its path.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/kinematics/geometry.hpp"

namespace fivebar {
struct MachineProfile;
}

namespace fivebar::detail {

// Reads the members of one JSON object. Every accessor marks its key as known; finish() reports
// the keys nobody asked for (typos must not pass silently).
class ObjectReader {
 public:
  ObjectReader(const nlohmann::json& object, std::string path, std::vector<ValidationIssue>& issues);

  // Each reader leaves `out` unchanged when the key is absent (and reports it when required).
  void number(const char* key, double& out, bool required = false);
  void integer(const char* key, int& out, bool required = false);
  void boolean(const char* key, bool& out, bool required = false);
  void string(const char* key, std::string& out, bool required = false);
  // A sub-object; nullptr (with an issue when present but not an object, or when required).
  const nlohmann::json* object(const char* key, bool required = false);
  // An array of strings; leaves `out` unchanged when absent, reports any non-string element.
  void strings(const char* key, std::vector<std::string>& out, bool required = false);
  // Path of a member, e.g. "geometry.a1".
  std::string pathOf(const char* key) const;
  // Reports unknown members; call after all accessors.
  void finish();

 private:
  const nlohmann::json* member(const char* key, bool required);
  void typeError(const char* key, Message expected, const nlohmann::json& value);

  const nlohmann::json& object_;
  std::string path_;
  std::vector<ValidationIssue>& issues_;
  std::set<std::string> known_;
  bool isObject_ = false;
};

// The profile's "calibration" section (core/machine/calibration_section.cpp).
// Adds the section to `j` when the profile has a calibration.
void writeCalibration(nlohmann::json& j, const MachineProfile& p);
// Reads the section when the document has one; an absent section leaves p.calibration empty.
void readCalibration(ObjectReader& root, MachineProfile& p, std::vector<ValidationIssue>& issues);
// Range checks of a present calibration (field paths "calibration.*").
void validateCalibration(std::vector<ValidationIssue>& out, const MachineProfile& p);

// Line and column (1-based) of a byte offset into `text`.
struct TextPosition {
  std::size_t line = 1;
  std::size_t column = 1;
};
TextPosition positionOf(const std::string& text, std::size_t byteOffset);

// Why a JSON text could not be read: where (line and column) and the library's words.
struct JsonSyntaxError {
  TextPosition position;
  std::string what;  // nlohmann's message without its "[json.exception...]" prefix
};
// Parses `text` into `out`; the error when it is not JSON. Every exception of the library is
// taken (a syntax error, and a number too large for a double, "1e999", which nlohmann reports
// as out_of_range without a position: the position is then that of the number's text).
std::optional<JsonSyntaxError> parseJsonText(const std::string& text, nlohmann::json& out);

}  // namespace fivebar::detail
