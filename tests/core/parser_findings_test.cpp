// SPDX-License-Identifier: GPL-3.0-or-later
// What the fuzzers found in the JSON readers (fuzz/, docs/reliability.md), each kept as an input
// in fuzz/regressions and asserted here in words: a refusal naming the file, line and column,
// never an exception out of the reader.
#include <gtest/gtest.h>

#include <string>

#include "core/machine/profile.hpp"
#include "core/project/project.hpp"

namespace fivebar {
namespace {

// nlohmann reports a number too large for a double ("1e999") as out_of_range, not as a
// parse_error: the readers let it escape and the CLI or studio ended in std::terminate.
TEST(ParserFindings, ProjectWithANumberTooLargeIsRefusedWithItsPosition) {
  const std::string text = "{\n  \"format\": \"fivebar-project\",\n  \"version\": 35E5556\n}\n";
  const ProjectLoad load = projectFromJson(text, "big.fivebar");
  ASSERT_FALSE(load.project.has_value());
  ASSERT_EQ(load.issues.size(), 1u);
  EXPECT_EQ(load.issues.front().message.text().rfind("big.fivebar:3:14: ", 0), 0u) << load.issues.front().message.text();
}

TEST(ParserFindings, ProfileWithANumberTooLargeIsRefusedWithItsPosition) {
  const std::string text = "{\"version\": 1,\n\"geometry\": {\"a1\": -1e400}}";
  const ProfileLoad load = profileFromJson(text, "big.json");
  ASSERT_FALSE(load.profile.has_value());
  ASSERT_EQ(load.issues.size(), 1u);
  const std::string message = load.issues.front().message.text();
  EXPECT_EQ(message.rfind("big.json:2:20: invalid JSON: ", 0), 0u) << message;
  EXPECT_NE(message.find("1e400"), std::string::npos) << message;
}

// An unsigned integer beyond long long's range read as an int wrapped to a negative number.
TEST(ParserFindings, AnIntegerBeyondEveryRangeIsOutOfRange) {
  const std::string json = toJson(*preset("maker-plotter"));
  const std::string key = "\"version\": ";
  const std::size_t at = json.find(key);
  ASSERT_NE(at, std::string::npos) << json;
  const std::size_t end = json.find_first_of(",\n}", at + key.size());
  const std::string text = json.substr(0, at + key.size()) + "18446744073709551615" + json.substr(end);
  const ProfileLoad load = profileFromJson(text, "baud.json");
  ASSERT_FALSE(load.profile.has_value());
  bool named = false;
  for (const ValidationIssue& issue : load.issues)
    named = named || issue.message.text().find("out of the integer range") != std::string::npos;
  EXPECT_TRUE(named);
}

// An empty key ("": 1) was reported as " is not a known field": a message that names nothing.
TEST(ParserFindings, AnEmptyKeyIsNamedAsSuch) {
  std::string json = toJson(*preset("maker-plotter"));
  json.insert(json.find('{') + 1, "\"\": 1, ");
  const ProfileLoad load = profileFromJson(json, "empty.json");
  ASSERT_FALSE(load.profile.has_value());
  ASSERT_FALSE(load.issues.empty());
  EXPECT_EQ(load.issues.front().field, "\"\"");
  EXPECT_EQ(load.issues.front().message.text().rfind("\"\" is not a known field", 0), 0u)
      << load.issues.front().message.text();
  // A key that starts with a NUL byte (JSON "\u0000mode") is shown with the byte escaped.
  std::string nul = toJson(*preset("maker-plotter"));
  nul.insert(nul.find('{') + 1, "\"\\u0000mode\": 1, ");
  const ProfileLoad withNul = profileFromJson(nul, "nul.json");
  ASSERT_FALSE(withNul.issues.empty());
  EXPECT_EQ(withNul.issues.front().field, "\\x00mode");
}

}  // namespace
}  // namespace fivebar
