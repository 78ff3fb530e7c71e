// SPDX-License-Identifier: GPL-3.0-or-later
// GRBL code tables and the line parser.
#include <gtest/gtest.h>

#include <set>

#include "drivers/protocol/grbl_codes.hpp"
#include "drivers/protocol/grbl_parser.hpp"

namespace fivebar::grbl {
namespace {

TEST(GrblCodes, EveryGrbl11ErrorCodeHasAnExplanationAndAnAction) {
  std::set<int> codes;
  for (const CodeInfo& c : errorCodes()) {
    codes.insert(c.code);
    EXPECT_FALSE(c.name.empty()) << c.code;
    EXPECT_GT(c.meaning.size(), 15u) << c.code;
    EXPECT_GT(c.action.size(), 10u) << c.code;
  }
  for (int code = 1; code <= 38; ++code) {
    if (code == 18 || code == 19) {
      EXPECT_EQ(codes.count(code), 0u) << "GRBL 1.1 defines no error " << code;
      continue;
    }
    EXPECT_EQ(codes.count(code), 1u) << "error " << code << " missing";
  }
}

TEST(GrblCodes, EveryAlarmCodeHasAnExplanation) {
  for (int code = 1; code <= 9; ++code) {
    const CodeInfo* info = findAlarm(code);
    ASSERT_NE(info, nullptr) << code;
    EXPECT_GT(info->meaning.size(), 15u);
  }
  EXPECT_EQ(findAlarm(10), nullptr);
}

TEST(GrblCodes, DescriptionsNameTheCodeAndSayWhatToDo) {
  const std::string e9 = describeError(9);
  EXPECT_NE(e9.find("error:9"), std::string::npos) << e9;
  EXPECT_NE(e9.find("$X"), std::string::npos) << e9;
  const std::string a2 = describeAlarm(2);
  EXPECT_NE(a2.find("ALARM:2"), std::string::npos) << a2;
  EXPECT_NE(a2.find("Soft limit"), std::string::npos) << a2;
  EXPECT_NE(describeError(99).find("not a GRBL 1.1 code"), std::string::npos);
}

TEST(GrblParser, SimpleLines) {
  struct Case {
    const char* text;
    LineKind kind;
    int code;
  };
  const Case cases[] = {
      {"ok", LineKind::Ok, 0},          {"ok\r", LineKind::Ok, 0},
      {"error:22", LineKind::Error, 22}, {"ALARM:3", LineKind::Alarm, 3},
      {"error:x", LineKind::Unknown, 0}, {"", LineKind::Empty, 0},
      {"[MSG:Reset to continue]", LineKind::Message, 0},
      {"[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]", LineKind::GcodeState, 0},
      {"[VER:1.1h.20190830:]", LineKind::Version, 0},
      {"[OPT:V,15,128]", LineKind::Option, 0},
      {"[G54:0.000,0.000,0.000]", LineKind::Feedback, 0},
      {">G54:ok", LineKind::StartupEcho, 0},
      {"garbage", LineKind::Unknown, 0},
  };
  for (const Case& c : cases) {
    const ParsedLine p = parseLine(c.text);
    EXPECT_EQ(p.kind, c.kind) << c.text;
    EXPECT_EQ(p.code, c.code) << c.text;
  }
  EXPECT_EQ(parseLine("[MSG:Reset to continue]").text, "Reset to continue");
}

TEST(GrblParser, BannerGivesTheVersion) {
  const ParsedLine p = parseLine("Grbl 1.1h ['$' for help]");
  EXPECT_EQ(p.kind, LineKind::Banner);
  EXPECT_EQ(p.text, "1.1h");
}

TEST(GrblParser, Settings) {
  const ParsedLine p = parseLine("$100=35.556");
  ASSERT_EQ(p.kind, LineKind::Setting);
  EXPECT_EQ(p.settingId, 100);
  EXPECT_DOUBLE_EQ(p.settingValue, 35.556);
  EXPECT_EQ(parseLine("$100=abc").kind, LineKind::Unknown);
}

TEST(GrblParser, FullStatusReport) {
  const ParsedLine p = parseLine(
      "<Hold:0|MPos:12.500,-3.250,0.000|Bf:15,128|FS:0,0|WCO:1.000,2.000,0.000|Ov:100,90,110|Pn:XZ>");
  ASSERT_EQ(p.kind, LineKind::Status);
  const StatusReport& r = p.status;
  EXPECT_EQ(r.state, MachineState::Hold);
  EXPECT_EQ(r.subState, 0);
  ASSERT_TRUE(r.mpos);
  EXPECT_DOUBLE_EQ(r.mpos->x(), 12.5);
  EXPECT_DOUBLE_EQ(r.mpos->y(), -3.25);
  EXPECT_EQ(r.mpos->count, 3);
  EXPECT_EQ(r.plannerBlocksFree, 15);
  EXPECT_EQ(r.rxBytesFree, 128);
  ASSERT_TRUE(r.wco);
  EXPECT_DOUBLE_EQ(r.wco->y(), 2.0);
  ASSERT_TRUE(r.overrides);
  EXPECT_EQ((*r.overrides)[1], 90);
  EXPECT_EQ(r.pins, "XZ");
  EXPECT_FALSE(r.wpos);
}

TEST(GrblParser, StatusReportVariants) {
  const auto run = parseLine("<Run|WPos:1.0,2.0|F:500>");
  ASSERT_EQ(run.kind, LineKind::Status);
  EXPECT_EQ(run.status.state, MachineState::Run);
  ASSERT_TRUE(run.status.wpos);
  EXPECT_EQ(run.status.wpos->count, 2);
  EXPECT_DOUBLE_EQ(*run.status.feed, 500.0);
  for (const char* bad : {"<Flying|MPos:0,0,0>", "<Idle|MPos:0,x,0>", "<Idle|Bf:15>", "<Idle|MPos>"})
    EXPECT_EQ(parseLine(bad).kind, LineKind::Unknown) << bad;
}

// The accessory and line-number fields as GRBL 1.1h's report.c writes them (A: only with Ov:,
// Ln: only from firmware built with USE_LINE_NUMBERS).
TEST(GrblParser, AccessoryAndLineNumberFields) {
  const auto a = parseLine("<Idle|MPos:0.000,0.000,0.000|FS:0,100|Ov:100,100,100|A:CF>");
  ASSERT_EQ(a.kind, LineKind::Status);
  EXPECT_EQ(a.status.accessories, "CF");
  EXPECT_FALSE(a.status.lineNumber);
  const auto s = parseLine("<Run|MPos:0.176,0.000,0.000|Bf:14,127|Ln:10|FS:100,600|Ov:100,100,100|A:S>");
  ASSERT_EQ(s.kind, LineKind::Status);
  EXPECT_EQ(s.status.accessories, "S");
  EXPECT_EQ(s.status.lineNumber, 10);
  EXPECT_EQ(parseLine("<Idle|MPos:0,0,0|FS:0,0>").status.accessories, "");
  for (const char* bad : {"<Idle|MPos:0,0,0|A:>", "<Idle|MPos:0,0,0|A:X>", "<Idle|MPos:0,0,0|Ln:x>"})
    EXPECT_EQ(parseLine(bad).kind, LineKind::Unknown) << bad;
}

// Found by fuzz/grbl_response_fuzz.cpp (fuzz/regressions/grbl_response): numbers GRBL never sends
// (nan, inf, a negative override or buffer count) make the field malformed, as any other garbage
// does, instead of a position or an override the host would act on.
TEST(GrblParser, NumbersGrblNeverSendsAreNotAStatus) {
  EXPECT_FALSE(parseNumber("nan").has_value());
  EXPECT_FALSE(parseNumber("inf").has_value());
  EXPECT_FALSE(parseNumber("-infinity").has_value());
  EXPECT_DOUBLE_EQ(parseNumber("-12.5").value(), -12.5);
  EXPECT_FALSE(parseStatus("Idle|MPos:nan,0.000,0.000|FS:0,0").has_value());
  EXPECT_FALSE(parseStatus("Run|MPos:1,2,0|FS:0,0|Ov:120,-50,100").has_value());
  EXPECT_FALSE(parseStatus("Run|MPos:1,2,0|FS:0,0|Ov:120,256,100").has_value());
  EXPECT_FALSE(parseStatus("Idle|MPos:1,2,0|Bf:-1,128").has_value());
  const auto ok = parseStatus("Run|MPos:1,2,0|FS:0,0|Ov:200,25,10");
  ASSERT_TRUE(ok.has_value());
  EXPECT_EQ((*ok->overrides)[1], 25);
}

// Advice the CLI prints: a $X or $H in it is quoted, so pasting it into a shell sends "$X", not
// the empty expansion of the shell variable X.
TEST(GrblCodes, DollarCommandsInTheAdviceAreQuotedForTheShell) {
  for (auto table : {errorCodes(), alarmCodes()})
    for (const CodeInfo& c : table)
      for (std::string_view text : {c.meaning, c.action})
        for (std::size_t at = text.find('$'); at != std::string_view::npos; at = text.find('$', at + 1)) {
          if (at + 1 < text.size() && (text[at + 1] == 'X' || text[at + 1] == 'H')) {
            EXPECT_TRUE(at > 0 && text[at - 1] == '\'' && text.substr(at + 2, 1) == "'") << text;
          }
        }
}

}  // namespace
}  // namespace fivebar::grbl
