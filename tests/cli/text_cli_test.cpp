// SPDX-License-Identifier: GPL-3.0-or-later
// `fivebar text` end to end (app/cli/cmd_text.cpp): the SVG it writes (mm, one path per stroke,
// the H at the asked height), its errors, --list-fonts, and the check that `fivebar plan`
// draws the text at true size with the pen-down length of the glyphs' strokes within 1 %.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "cli_support.hpp"
#include "core/text/hershey_font.hpp"
#include "core/text/text_layout.hpp"

namespace fivebar {
namespace {

namespace fs = std::filesystem;
using cli_test::CliResult;
using cli_test::quote;
using cli_test::slurp;

bool haveFonts() { return fs::is_regular_file(fs::path(text::kDefaultFontDirectory) / "futural.jhf"); }
#define REQUIRE_FONTS() \
  if (!haveFonts()) GTEST_SKIP() << text::kDefaultFontDirectory << "/futural.jhf absent (install hershey-fonts-data)"

class TextCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "fivebar-text-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Runs `fivebar args...`, with `env` ("NAME=value ...") before it.
  CliResult run(const std::vector<std::string>& args, const std::string& env = "") {
    std::string cmd = env + " QT_QPA_PLATFORM=offscreen " + quote(FIVEBAR_CLI);
    for (const std::string& a : args) cmd.append(" ").append(quote(a));
    cmd += " >" + quote((dir_ / "stdout").string()) + " 2>" + quote((dir_ / "stderr").string());
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "stdout"), slurp(dir_ / "stderr")};
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

// The polylines of an SVG as `fivebar text` writes it: "M x y L x y ..." per path, in user
// units (= mm), y down.
struct SvgPaths {
  double widthMm = 0, heightMm = 0, viewW = 0, viewH = 0;
  std::vector<std::vector<std::pair<double, double>>> lines;
};

SvgPaths readSvg(const std::string& svg) {
  SvgPaths out;
  std::smatch m;
  if (std::regex_search(svg, m, std::regex("width=\"([0-9.]+)mm\" height=\"([0-9.]+)mm\" viewBox=\"0 0 ([0-9.]+) ([0-9.]+)\""))) {
    out.widthMm = std::stod(m[1]), out.heightMm = std::stod(m[2]);
    out.viewW = std::stod(m[3]), out.viewH = std::stod(m[4]);
  }
  const std::regex path("<path d=\"([^\"]*)\"");
  const std::regex point("[ML](-?[0-9.]+) (-?[0-9.]+)");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator(); ++it) {
    const std::string d = (*it)[1];
    std::vector<std::pair<double, double>> line;
    for (auto p = std::sregex_iterator(d.begin(), d.end(), point); p != std::sregex_iterator(); ++p)
      line.emplace_back(std::stod((*p)[1]), std::stod((*p)[2]));
    out.lines.push_back(std::move(line));
  }
  return out;
}

double lengthOf(const SvgPaths& svg) {
  double total = 0.0;
  for (const auto& line : svg.lines)
    for (std::size_t i = 1; i < line.size(); ++i)
      total += std::hypot(line[i].first - line[i - 1].first, line[i].second - line[i - 1].second);
  return total;
}

TEST_F(TextCli, TheHInTheSvgIsTheAskedHeightInMillimetres) {
  REQUIRE_FONTS();
  for (const char* height : {"13.5", "4", "31.25"}) {
    const CliResult r = run({"text", "H", "--font", "futural", "--height", height, "-o", path("h.svg")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const SvgPaths svg = readSvg(slurp(path("h.svg")));
    EXPECT_GT(svg.widthMm, 0.0);
    EXPECT_EQ(svg.widthMm, svg.viewW);  // 1 user unit = 1 mm
    EXPECT_EQ(svg.heightMm, svg.viewH);
    ASSERT_EQ(svg.lines.size(), 3u);  // the H's three strokes, one path each
    double top = 1e300, bottom = -1e300;
    for (const auto& line : svg.lines)
      for (const auto& [x, y] : line) top = std::min(top, y), bottom = std::max(bottom, y);
    EXPECT_NEAR(bottom - top, std::stod(height), 2e-4) << height;
    EXPECT_NEAR(top, 1.0, 2e-4);  // the default 1 mm margin
    EXPECT_NEAR(svg.heightMm, std::stod(height) + 2.0, 2e-4);
  }
}

#ifdef FIVEBAR_CLI_HAS_IMPORT
TEST_F(TextCli, PlanDrawsTheTextAtTrueSizeWithItsStrokesPenDownLength) {
  REQUIRE_FONTS();
  const std::string words = "HELLO FiveBar\nsingle strokes, 0123";
  for (const char* font : {"futural", "scripts", "rowmand"}) {
    const CliResult t = run({"text", words, "--font", font, "--height", "7", "--line-spacing", "1.2",
                             "--align", "center", "-o", path("text.svg")});
    ASSERT_EQ(t.exitCode, 0) << t.err;
    EXPECT_EQ(t.err, "");  // every character has a glyph
    // The length the layout gives, computed here from the font independently of the CLI.
    const text::FontLoad load = text::loadFont(font, text::kDefaultFontDirectory);
    ASSERT_TRUE(load.font) << text::toString(load.error);
    text::TextStyle style;
    style.heightMm = 7.0;
    style.lineSpacing = 1.2;
    style.align = text::Align::Center;
    const double layoutMm = text::strokeLengthMm(text::layoutText(*load.font, words, style).strokes);
    const SvgPaths svg = readSvg(slurp(path("text.svg")));
    EXPECT_NEAR(lengthOf(svg), layoutMm, 1e-3 * layoutMm) << font;

    const CliResult p = run({"plan", path("text.svg"), "--machine", "maker-plotter", "--report", path("r.json"),
                             "-o", path("job.gcode")});
    ASSERT_EQ(p.exitCode, 0) << p.err;
    EXPECT_NE(p.out.find("scale 100.0 %"), std::string::npos) << p.out;  // true size
    const auto report = nlohmann::json::parse(slurp(path("r.json")));
    const double penDownMm = report.at("pen_down_mm").get<double>();
    EXPECT_NEAR(penDownMm, layoutMm, 0.01 * layoutMm) << font << ": " << p.out;
  }
}

// SVG <text> redrawn with `plan --text-font`: the pen-down length of the font's strokes at a cap
// height of 0.7 x the font size (docs/svg-import.md).
TEST_F(TextCli, PlanTextFontRedrawsSvgTextInTheSingleStrokeFont) {
  REQUIRE_FONTS();
  std::ofstream(path("label.svg")) << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"80mm\" height=\"30mm\" "
                                      "viewBox=\"0 0 80 30\"><text x=\"40\" y=\"20\" font-size=\"10\" "
                                      "text-anchor=\"middle\">HELLO</text></svg>\n";
  const CliResult p = run({"plan", path("label.svg"), "--machine", "maker-plotter", "--text-font", "futural",
                           "--report", path("r.json"), "-o", path("job.gcode")});
  ASSERT_EQ(p.exitCode, 0) << p.err;
  const text::FontLoad load = text::loadFont("futural", text::kDefaultFontDirectory);
  ASSERT_TRUE(load.font);
  text::TextStyle style;
  style.heightMm = 7.0;
  const double layoutMm = text::strokeLengthMm(text::layoutText(*load.font, "HELLO", style).strokes);
  const double penDownMm = nlohmann::json::parse(slurp(path("r.json"))).at("pen_down_mm").get<double>();
  EXPECT_NEAR(penDownMm, layoutMm, 0.01 * layoutMm) << p.out;
  const CliResult outlines = run({"plan", path("label.svg"), "--machine", "maker-plotter", "--report", path("o.json"),
                                  "-o", path("job.gcode")});
  ASSERT_EQ(outlines.exitCode, 0) << outlines.err;
  EXPECT_GT(std::abs(nlohmann::json::parse(slurp(path("o.json"))).at("pen_down_mm").get<double>() - penDownMm),
            0.05 * layoutMm);  // outlines are another drawing
  const CliResult unknown = run({"plan", path("label.svg"), "--machine", "maker-plotter", "--text-font", "futurax",
                                 "-o", path("job.gcode")});
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.err.find("--text-font: futurax"), std::string::npos) << unknown.err;
}
#endif

TEST_F(TextCli, AMissingGlyphIsNamedAndSkippedOrRefusedWithStrict) {
  REQUIRE_FONTS();
  const CliResult r = run({"text", "Gr\xC3\xBC\xC3\x9F" "e", "--height", "5", "-o", path("g.svg")});  // "Grüße"
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("warning: font futural has no glyph for '\xC3\xBC' (U+00FC) at line 1, character 3; skipped"),
            std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(U+00DF) at line 1, character 4"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(path("g.svg")));
  const CliResult strict = run({"text", "Gr\xC3\xBC\xC3\x9F" "e", "--height", "5", "--strict", "-o", path("s.svg")});
  EXPECT_EQ(strict.exitCode, 1);
  EXPECT_NE(strict.err.find("error: font futural has no glyph for '\xC3\xBC'"), std::string::npos) << strict.err;
  EXPECT_FALSE(fs::exists(path("s.svg")));
  const CliResult nothing = run({"text", "\xC3\xBC", "--height", "5", "-o", path("n.svg")});
  EXPECT_EQ(nothing.exitCode, 1);
  EXPECT_NE(nothing.err.find("nothing to draw"), std::string::npos) << nothing.err;
}

TEST_F(TextCli, BadInputGetsAClearMessageAndANonZeroExit) {
  REQUIRE_FONTS();
  const CliResult unknown = run({"text", "Hi", "--font", "futurax", "--height", "5", "-o", path("x.svg")});
  EXPECT_EQ(unknown.exitCode, 1);
  EXPECT_NE(unknown.err.find("futurax"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("no such Hershey font"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("--list-fonts"), std::string::npos) << unknown.err;
  const CliResult empty = run({"text", "", "--height", "5", "-o", path("x.svg")});
  EXPECT_EQ(empty.exitCode, 2);
  EXPECT_NE(empty.err.find("fivebar text: the text is empty"), std::string::npos) << empty.err;
  for (const char* height : {"0", "-3", "abc", "5mm"}) {
    const CliResult bad = run({"text", "Hi", "--height", height, "-o", path("x.svg")});
    EXPECT_EQ(bad.exitCode, 2) << height;
    EXPECT_NE(bad.err.find(std::string("--height needs a positive number, got '") + height + "'"), std::string::npos)
        << bad.err;
  }
  const CliResult noHeight = run({"text", "Hi", "-o", path("x.svg")});
  EXPECT_EQ(noHeight.exitCode, 2);
  EXPECT_NE(noHeight.err.find("missing required option --height"), std::string::npos) << noHeight.err;
  const CliResult align = run({"text", "Hi", "--height", "5", "--align", "justify", "-o", path("x.svg")});
  EXPECT_EQ(align.exitCode, 2);
  EXPECT_NE(align.err.find("--align must be left, center or right, got 'justify'"), std::string::npos);
  EXPECT_FALSE(fs::exists(path("x.svg")));
}

TEST_F(TextCli, ListFontsAndAMalformedFontFromTheEnvironmentsDirectory) {
  fs::create_directory(dir_ / "fonts");
  std::ofstream(dir_ / "fonts" / "tiny.jhf") << "12345  1JZ\n12345  3JZNF\n";
  const std::string env = "FIVEBAR_HERSHEY_DIR=" + quote((dir_ / "fonts").string());
  const CliResult list = run({"text", "--list-fonts"}, env);
  EXPECT_EQ(list.exitCode, 0) << list.err;
  EXPECT_EQ(list.out, "tiny\tHershey font\n");
  const CliResult bad = run({"text", "!", "--font", "tiny", "--height", "5", "-o", path("x.svg")}, env);
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find((dir_ / "fonts" / "tiny.jhf").string() + ":2:"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("fewer vertex pairs than its count 3"), std::string::npos) << bad.err;
  const CliResult none = run({"text", "--list-fonts"}, "FIVEBAR_HERSHEY_DIR=" + quote(path("absent")));
  EXPECT_EQ(none.exitCode, 1);
  EXPECT_NE(none.err.find("no Hershey fonts"), std::string::npos) << none.err;
  if (haveFonts()) {
    const CliResult debian = run({"text", "--list-fonts"});
    EXPECT_EQ(debian.exitCode, 0);
    EXPECT_NE(debian.out.find("futural\tFutura light: simplex sans serif, single stroke\n"), std::string::npos)
        << debian.out;
  }
}

}  // namespace
}  // namespace fivebar
