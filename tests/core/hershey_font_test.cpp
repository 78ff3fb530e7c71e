// SPDX-License-Identifier: GPL-3.0-or-later
// The Hershey .jhf reader (core/text/hershey_font.hpp): glyphs, bounds, strokes, metrics, the
// errors of malformed files (file, line, column), the font directory and its listing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/text/hershey_font.hpp"
#include "hershey_test_font.hpp"

namespace fivebar::text {
namespace {

namespace fs = std::filesystem;

// A temporary font directory, set as FIVEBAR_HERSHEY_DIR while the test runs.
class FontDir : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "fivebar-fonts-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
    ::setenv("FIVEBAR_HERSHEY_DIR", dir_.c_str(), 1);
  }
  void TearDown() override {
    ::unsetenv("FIVEBAR_HERSHEY_DIR");
    fs::remove_all(dir_);
  }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name, std::ios::binary) << text; }
  fs::path dir_;
};

TEST(HersheyReader, ReadsGlyphsBoundsAndStrokesInFileOrder) {
  const std::string text = test::testFontText(60);
  const FontLoad load = parseJhf(text, "test", "test.jhf");
  ASSERT_TRUE(load.font) << toString(load.error);
  const HersheyFont& f = *load.font;
  EXPECT_EQ(f.glyphs.size(), 60u);
  const HersheyGlyph* h = f.glyph(U'H');
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->left, -11);
  EXPECT_EQ(h->right, 11);
  EXPECT_EQ(h->advance(), 22);
  EXPECT_EQ(h->strokes, test::futuralH());
  EXPECT_EQ(h->sourceLine, 'H' - 32 + 1);
  EXPECT_TRUE(f.glyph(U' ')->strokes.empty());
  EXPECT_EQ(f.glyph(U' ')->advance(), 16);
  EXPECT_EQ(f.glyph(U'A')->strokes.size(), 2u);
  EXPECT_EQ(f.glyph(31), nullptr);
  EXPECT_EQ(f.glyph(32 + 60), nullptr);  // past the last glyph
  EXPECT_NE(f.glyph(32 + 59), nullptr);
}

TEST(HersheyReader, CapHeightAndBaselineComeFromTheHLineHeightFromAllGlyphs) {
  const FontLoad load = parseJhf(test::testFontText(), "test", "test.jhf");
  ASSERT_TRUE(load.font);
  EXPECT_EQ(load.font->capTop, -12);
  EXPECT_EQ(load.font->baseline, 9);
  EXPECT_EQ(load.font->capHeight(), 21);
  EXPECT_EQ(load.font->lineHeight, 21);  // no glyph reaches past the H or the A
  // A tall bracket widens the line height, not the cap height.
  std::string text = test::testFontText();
  text += test::jhfLine(-4, 4, {{{0, -16}, {0, 16}}});
  const FontLoad tall = parseJhf(text, "test", "test.jhf");
  ASSERT_TRUE(tall.font);
  EXPECT_EQ(tall.font->capHeight(), 21);
  EXPECT_EQ(tall.font->lineHeight, 32);
}

TEST(HersheyReader, AWrappedGlyphContinuesOnTheNextLineAndCrLfIsRead) {
  // 40 vertices: 88 characters, wrapped after 72 as the original distribution does.
  std::vector<text::HersheyPoint> zigzag;
  for (int i = 0; i < 39; ++i) zigzag.push_back({i - 19, (i % 2) * 5});
  std::string line = test::jhfLine(-20, 20, {zigzag});
  line.pop_back();
  const std::string wrapped = line.substr(0, 72) + "\r\n" + line.substr(72) + "\r\n" + test::jhfLine(-3, 3, {});
  const FontLoad load = parseJhf(wrapped, "wrap", "wrap.jhf");
  ASSERT_TRUE(load.font) << toString(load.error);
  ASSERT_EQ(load.font->glyphs.size(), 2u);
  EXPECT_EQ(load.font->glyphs[0].strokes.front(), zigzag);
  EXPECT_EQ(load.font->glyphs[1].sourceLine, 3);
}

struct Malformed {
  std::string line;
  FontErrorKind kind;
  int column;
  std::string words;
};

TEST(HersheyReader, AMalformedLineIsNamedByFileLineAndColumn) {
  const std::vector<Malformed> cases = {
      {"12345", FontErrorKind::ShortLine, 0, "shorter than the 8 columns"},
      {"12345 x3JZNFNM", FontErrorKind::BadCount, 6, "found ' x3'"},
      {"12345  0", FontErrorKind::MissingBounds, 6, "no left/right bounds"},
      {"12345  4JZNFNM", FontErrorKind::Truncated, 15, "fewer vertex pairs than its count 4"},
      {"12345  2JZNFNM", FontErrorKind::TooLong, 13, "more characters than its vertex count 2"},
      {"12345  3JZN\x01NM", FontErrorKind::BadCoordinate, 12, "is not a coordinate character"},
      {"12345  2 RNF", FontErrorKind::PenUpFirst, 9, "where the left/right bounds belong"},
  };
  for (const Malformed& c : cases) {
    const std::string text = test::jhfLine(-8, 8, {}) + test::jhfLine(-5, 5, {{{0, 0}, {1, 1}}}) + c.line + "\n";
    const FontLoad load = parseJhf(text, "bad", "/fonts/bad.jhf");
    EXPECT_FALSE(load.font) << c.line;
    EXPECT_EQ(load.error.kind, c.kind) << c.line;
    EXPECT_EQ(load.error.line, 3) << c.line;
    EXPECT_EQ(load.error.column, c.column) << c.line;
    const std::string message = toString(load.error);
    EXPECT_EQ(message.rfind("/fonts/bad.jhf:3", 0), 0u) << message;
    EXPECT_NE(message.find(c.words), std::string::npos) << message;
  }
  const FontLoad empty = parseJhf("\n  \n", "empty", "empty.jhf");
  EXPECT_EQ(empty.error.kind, FontErrorKind::NoGlyphs);
  EXPECT_NE(toString(empty.error).find("empty.jhf: not a Hershey .jhf font"), std::string::npos);
}

TEST_F(FontDir, LoadsByNameFromTheDirectoryOfTheEnvironmentAndNamesAMalformedFile) {
  EXPECT_EQ(fontDirectory(), dir_.string());
  write("mine.jhf", test::testFontText());
  write("broken.jhf", test::testFontText(10) + "12345  9G]KFK[\n");
  write("notes.txt", "not a font");
  const FontLoad mine = loadFont("mine");
  ASSERT_TRUE(mine.font) << toString(mine.error);
  EXPECT_EQ(mine.font->name, "mine");
  EXPECT_EQ(fs::path(mine.font->file), dir_ / "mine.jhf");

  const FontLoad broken = loadFont("broken");
  ASSERT_FALSE(broken.font);
  EXPECT_EQ(broken.error.kind, FontErrorKind::Truncated);
  EXPECT_EQ(toString(broken.error).rfind((dir_ / "broken.jhf").string() + ":11:", 0), 0u) << toString(broken.error);

  const FontLoad missing = loadFont("futurax");
  EXPECT_EQ(missing.error.kind, FontErrorKind::NotFound);
  EXPECT_NE(toString(missing.error).find("futurax"), std::string::npos);
  EXPECT_NE(toString(missing.error).find(dir_.string()), std::string::npos);

  const auto fonts = listFonts();
  ASSERT_EQ(fonts.size(), 2u);  // .jhf files only, sorted
  EXPECT_EQ(fonts[0].name, "broken");
  EXPECT_EQ(fonts[1].name, "mine");
  EXPECT_EQ(fonts[1].description, "Hershey font");
  EXPECT_TRUE(listFonts((dir_ / "absent").string()).empty());
}

TEST(HersheyReader, WithoutTheEnvironmentTheDebianDirectoryIsUsed) {
  ::unsetenv("FIVEBAR_HERSHEY_DIR");
  EXPECT_EQ(fontDirectory(), std::string(kDefaultFontDirectory));
  ::setenv("FIVEBAR_HERSHEY_DIR", "", 1);
  EXPECT_EQ(fontDirectory(), std::string(kDefaultFontDirectory));  // empty counts as unset
  ::unsetenv("FIVEBAR_HERSHEY_DIR");
}

// Every font of hershey-fonts-data reads; the text fonts have Hershey's 21-unit cap height.
TEST(HersheyReader, EveryDebianFontReads) {
  if (!fs::is_directory(kDefaultFontDirectory)) GTEST_SKIP() << kDefaultFontDirectory << " absent (install hershey-fonts-data)";
  const auto fonts = listFonts(kDefaultFontDirectory);
  ASSERT_FALSE(fonts.empty());
  for (const FontInfo& info : fonts) {
    const FontLoad load = loadFont(info.name, kDefaultFontDirectory);
    ASSERT_TRUE(load.font) << toString(load.error);
    EXPECT_GE(load.font->glyphs.size(), 95u) << info.name;
    EXPECT_GT(load.font->capHeight(), 0) << info.name;
    EXPECT_GE(load.font->lineHeight, load.font->capHeight()) << info.name;
    EXPECT_NE(info.description, "Hershey font") << info.name;  // each described
  }
  const FontLoad futural = loadFont("futural", kDefaultFontDirectory);
  ASSERT_TRUE(futural.font);
  EXPECT_EQ(futural.font->capHeight(), 21);
  EXPECT_EQ(futural.font->lineHeight, 32);
  EXPECT_EQ(futural.font->glyph(U'H')->strokes, test::futuralH());
}

}  // namespace
}  // namespace fivebar::text
