// SPDX-License-Identifier: GPL-3.0-or-later
// Hershey single-stroke fonts read from their .jhf files (Debian package hershey-fonts-data,
// /usr/share/hershey-fonts). Our own reader rather than libhersheyfont: a malformed file is named
// by file, line and column (libhersheyfont returns NULL and prints to stderr), glyphs past 255
// are kept, and the core stays a C++ library with no extra shared library. docs/text.md.
//
// The .jhf format, one glyph per line (a long glyph may continue on the following lines):
//   columns 1-5  glyph number (Hershey's catalogue number; free text in some files, ignored)
//   columns 6-8  vertex count N, right aligned, counting the left/right pair
//   then N pairs of characters: the first pair is the glyph's left and right bound, every further
//   pair a vertex (x, y) or " R", pen up (a new stroke). Each coordinate is the character's code
//   minus 'R' (so 'R' = 0); x to the right, y DOWN, origin at the glyph's centre.
// The i-th glyph of a file is code point 32 + i (ASCII order from the space, as libhersheyfont
// and the Debian files use it).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fivebar::text {

// A vertex in Hershey units (x right, y down, glyph centre at 0).
struct HersheyPoint {
  int x = 0;
  int y = 0;
  bool operator==(const HersheyPoint&) const = default;
};

struct HersheyGlyph {
  int left = 0;   // left bound: the pen starts |left| units left of the centre
  int right = 0;  // right bound: the advance is right - left (Hershey's spacing, its "kerning")
  std::vector<std::vector<HersheyPoint>> strokes;  // each drawn once, pen down along it
  int sourceLine = 0;                              // 1-based line of the file it starts on
  int advance() const { return right - left; }
};

struct HersheyFont {
  std::string name;  // file stem: "futural"
  std::string file;  // the file it was read from
  std::vector<HersheyGlyph> glyphs;  // glyphs[i] draws code point kFirstCodePoint + i
  static constexpr char32_t kFirstCodePoint = 32;
  // Metrics in Hershey units, measured from the glyph data (docs/text.md):
  int capTop = 0;      // top of the 'H' (its smallest y)
  int baseline = 0;    // bottom of the 'H' (its largest y)
  int lineHeight = 0;  // full vertical extent of all glyphs: deepest bottom - highest top
  int capHeight() const { return baseline - capTop; }
  // The glyph of a code point, nullptr when the font has none.
  const HersheyGlyph* glyph(char32_t codePoint) const;
};

// What is wrong with a font file; the English words are toString's (the CLI's), the studio may
// word the kind itself.
enum class FontErrorKind {
  None,
  NotFound,       // no file NAME.jhf in the font directory
  Unreadable,     // the file exists but cannot be read
  NoGlyphs,       // the file holds no glyph line
  ShortLine,      // a line shorter than the 8 columns of glyph number and count
  BadCount,       // columns 6-8 are not a number >= 1
  MissingBounds,  // the vertex count leaves no left/right pair
  Truncated,      // fewer vertex pairs than the count says (end of file reached)
  BadCoordinate,  // a character outside the coordinate range ('!'..'~' minus control codes)
  TooLong,        // more vertex pairs on the line than the count says
  PenUpFirst,     // a " R" where the left/right pair belongs
};

struct FontError {
  FontErrorKind kind = FontErrorKind::None;
  std::string file;  // the file (or the font name for NotFound)
  int line = 0;      // 1-based, 0 when not about a line
  int column = 0;    // 1-based, 0 when not about a column
  std::string found;  // the offending text (the count field, the character)
  explicit operator bool() const { return kind != FontErrorKind::None; }
};

// "FILE:LINE:COLUMN: what" in English.
std::string toString(const FontError& error);

struct FontLoad {
  std::optional<HersheyFont> font;  // set when error.kind == None
  FontError error;
};

// Parses the text of a .jhf file; `file` names it in errors, `name` is the font's name.
FontLoad parseJhf(const std::string& text, const std::string& name, const std::string& file);

// The font directory: $FIVEBAR_HERSHEY_DIR when set and not empty, else /usr/share/hershey-fonts.
std::string fontDirectory();
inline constexpr const char* kDefaultFontDirectory = "/usr/share/hershey-fonts";

struct FontInfo {
  std::string name;         // file stem, what loadFont takes
  std::string file;         // full path
  std::string description;  // a short English description ("Futura light, single stroke")
};

// The .jhf files of `directory`, sorted by name; empty when the directory is absent.
std::vector<FontInfo> listFonts(const std::string& directory = fontDirectory());

// A short description of a font of the Debian collection by name; "Hershey font" for others.
std::string fontDescription(const std::string& name);

// Loads DIRECTORY/NAME.jhf. A name with '/' or a ".jhf" ending is taken as a file path.
FontLoad loadFont(const std::string& name, const std::string& directory = fontDirectory());

}  // namespace fivebar::text
