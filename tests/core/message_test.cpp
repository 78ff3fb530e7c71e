// SPDX-License-Identifier: GPL-3.0-or-later
// Message (core/support/message.hpp): the English text of a translatable core message, and the
// marker substitution the studio shares with it (QString::arg conventions).
#include "core/support/message.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "core/kinematics/geometry.hpp"

namespace fivebar {
namespace {

TEST(Message, TextSubstitutesArgumentsInOrder) {
  Message m = FB_TR("Preflight", "Stroke %1 leaves the workspace at (%2, %3) mm");
  m.arg(7).arg(-12.345, 2).arg(80.0, 1);
  EXPECT_EQ(m.text(), "Stroke 7 leaves the workspace at (-12.35, 80.0) mm");
  EXPECT_TRUE(m.translatable());
  EXPECT_EQ(m.context(), "Preflight");
  ASSERT_EQ(m.args().size(), 3u);
  EXPECT_EQ(m.args()[1].kind, MessageArg::Kind::Number);
  EXPECT_EQ(m.args()[1].decimals, 2);
}

TEST(Message, NumbersUseThePointWhateverTheValue) {
  EXPECT_EQ(fixedText(0.5, 0), "0");  // round half to even, as printf
  EXPECT_EQ(fixedText(62.4, 0), "62");
  EXPECT_EQ(fixedText(1234567.891, 1), "1234567.9");
  EXPECT_EQ(fixedText(-0.04, 1), "-0.0");
  EXPECT_EQ(fixedText(1e300, 0).size(), 301u);
}

TEST(Message, NestedMessagesAreWrittenInPlace) {
  Message point("Preflight", "point %1 at (%2, %3) mm");
  point.arg(4).arg(1.0, 2).arg(2.0, 2);
  const Message m = Message("Preflight", "%1 is out of reach of leg %2").arg(point).arg(1);
  EXPECT_EQ(m.text(), "point 4 at (1.00, 2.00) mm is out of reach of leg 1");
  ASSERT_EQ(m.args().front().kind, MessageArg::Kind::Nested);
  EXPECT_EQ(m.args().front().message->text(), point.text());
}

TEST(Message, VerbatimTextIsNeitherTranslatedNorSubstituted) {
  const Message m = std::string("100% of %1 kept");
  EXPECT_FALSE(m.translatable());
  EXPECT_EQ(m.text(), "100% of %1 kept");
  EXPECT_TRUE(Message().empty());
}

TEST(Message, SubstitutionFollowsQStringArg) {
  // Markers take the arguments in ascending marker order, wherever they stand.
  EXPECT_EQ(substituteArgs("%2 before %1", {"a", "b"}), "b before a");
  EXPECT_EQ(substituteArgs("%2 and %3", {"a", "b"}), "a and b");
  // Repeated markers, %L markers, two-digit markers read greedily.
  EXPECT_EQ(substituteArgs("%1-%1 %L2", {"x", "y"}), "x-x y");
  EXPECT_EQ(substituteArgs("%10", {"x"}), "x");
  // Markers left without an argument stay; so do a lone %, %0 and "%%".
  EXPECT_EQ(substituteArgs("%1 %2", {"x"}), "x %2");
  EXPECT_EQ(substituteArgs("50 % of %0 %%1", {"x"}), "50 % of %0 %x");
  // One pass: a replacement holding a marker is not substituted again.
  EXPECT_EQ(substituteArgs("%1 %2", {"%2", "b"}), "%2 b");
  EXPECT_EQ(substituteArgs("no markers", {}), "no markers");
}

// Significant digits write a number as an ostream of that precision does (the profile
// validation's sentences kept their CLI text when they became messages).
TEST(Message, SignificantDigitsMatchAnOstream) {
  for (const double v : {-5.0, 0.5, 120.0, 1e-7, 123456789.0, 1.0 / 3.0, -0.0, 2e15}) {
    for (const int digits : {6, 10}) {
      std::ostringstream s;
      s.precision(digits);
      s << v;
      EXPECT_EQ(significantText(v, digits), s.str()) << v << " with " << digits << " digits";
      const Message m = FB_TR("Profile", "got %1").argSignificant(v, digits);
      EXPECT_EQ(m.text(), "got " + s.str());
      EXPECT_TRUE(m.args().front().significant);
    }
  }
}

// A message with a studio wording keeps the CLI's text; the studio wording travels with it,
// also when the message is nested in another.
TEST(Message, StudioWordingLeavesTheTextAlone) {
  Message fix = FB_TR("Planner", "shrink the drawing to %1 % (--scale %2)").arg(55.0, 0).arg("0.550");
  EXPECT_EQ(fix.studioWording(), nullptr);
  fix.inStudio(FB_TR("Planner", "set Scale to %1 % in the Placement panel").arg(55.0, 0));
  EXPECT_EQ(fix.text(), "shrink the drawing to 55 % (--scale 0.550)");
  ASSERT_NE(fix.studioWording(), nullptr);
  EXPECT_EQ(fix.studioWording()->text(), "set Scale to 55 % in the Placement panel");
  const Message outer = FB_TR("Planner", "fix: %1").arg(fix);
  EXPECT_EQ(outer.text(), "fix: shrink the drawing to 55 % (--scale 0.550)");
  ASSERT_NE(outer.args().front().message->studioWording(), nullptr);
}

// Profile validation (ValidationIssue) speaks in messages: the English is the CLI's sentence,
// the template is translatable, numbers are arguments.
TEST(Message, ValidationIssuesAreTranslatable) {
  const std::vector<ValidationIssue> issues = validate(Geometry{-1.5, 10.0, 10.0, 10.0, 5.0});
  ASSERT_FALSE(issues.empty());
  EXPECT_EQ(issues.front().message.text(), "a1 is -1.5 mm; it must be positive");
  EXPECT_TRUE(issues.front().message.translatable());
  EXPECT_EQ(issues.front().message.context(), "Profile");
  EXPECT_EQ(issues.front().message.templ(), "%1 is %2 mm; it must be positive");
}

}  // namespace
}  // namespace fivebar
