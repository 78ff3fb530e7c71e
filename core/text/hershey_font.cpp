// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/text/hershey_font.hpp"

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace fivebar::text {
namespace {

// The original Hershey distribution wraps long glyphs at 72 columns; a line that long whose
// count asks for more continues on the next line.
constexpr std::size_t kWrapColumns = 72;

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    if (end == text.size()) break;
    start = end + 1;
  }
  return lines;
}

bool blank(const std::string& line) {
  return std::all_of(line.begin(), line.end(), [](char c) { return c == ' ' || c == '\t'; });
}

FontError lineError(FontErrorKind kind, const std::string& file, int line, int column, std::string found) {
  return FontError{kind, file, line, column, std::move(found)};
}

bool coordinateChar(char c) { return c >= '!' && c <= '~'; }

// The metrics of docs/text.md: cap height from the 'H', line height from all glyphs.
void measure(HersheyFont& font) {
  int top = INT_MAX, bottom = INT_MIN;
  for (const HersheyGlyph& g : font.glyphs)
    for (const auto& stroke : g.strokes)
      for (const HersheyPoint& p : stroke) {
        top = std::min(top, p.y);
        bottom = std::max(bottom, p.y);
      }
  if (top > bottom) top = bottom = 0;  // only empty glyphs (spaces)
  font.lineHeight = bottom - top;
  int capTop = INT_MAX, capBottom = INT_MIN;
  if (const HersheyGlyph* h = font.glyph(U'H'))
    for (const auto& stroke : h->strokes)
      for (const HersheyPoint& p : stroke) {
        capTop = std::min(capTop, p.y);
        capBottom = std::max(capBottom, p.y);
      }
  if (capTop >= capBottom) {  // no 'H' (or a flat one): the whole extent stands in for it
    capTop = top;
    capBottom = bottom;
  }
  font.capTop = capTop;
  font.baseline = capBottom;
}

}  // namespace

const HersheyGlyph* HersheyFont::glyph(char32_t codePoint) const {
  if (codePoint < kFirstCodePoint) return nullptr;
  const std::size_t i = codePoint - kFirstCodePoint;
  return i < glyphs.size() ? &glyphs[i] : nullptr;
}

std::string toString(const FontError& e) {
  std::ostringstream out;
  out << e.file;
  if (e.line > 0) out << ":" << e.line;
  if (e.column > 0) out << ":" << e.column;
  out << ": ";
  switch (e.kind) {
    case FontErrorKind::None: out << "no error"; break;
    case FontErrorKind::NotFound: out << "no such Hershey font (no .jhf file of that name)"; break;
    case FontErrorKind::Unreadable: out << "cannot read the font file"; break;
    case FontErrorKind::NoGlyphs: out << "not a Hershey .jhf font: no glyph lines"; break;
    case FontErrorKind::ShortLine:
      out << "malformed glyph line: shorter than the 8 columns of glyph number and vertex count";
      break;
    case FontErrorKind::BadCount:
      out << "malformed glyph line: columns 6-8 must hold the vertex count, found '" << e.found << "'";
      break;
    case FontErrorKind::MissingBounds:
      out << "malformed glyph line: a vertex count of 0 leaves no left/right bounds";
      break;
    case FontErrorKind::Truncated:
      out << "malformed glyph line: fewer vertex pairs than its count " << e.found;
      break;
    case FontErrorKind::BadCoordinate:
      out << "malformed glyph line: '" << e.found << "' is not a coordinate character";
      break;
    case FontErrorKind::TooLong:
      out << "malformed glyph line: more characters than its vertex count " << e.found << " says";
      break;
    case FontErrorKind::PenUpFirst:
      out << "malformed glyph line: a pen-up ' R' where the left/right bounds belong";
      break;
  }
  return out.str();
}

FontLoad parseJhf(const std::string& text, const std::string& name, const std::string& file) {
  FontLoad result;
  HersheyFont font;
  font.name = name;
  font.file = file;
  const std::vector<std::string> lines = splitLines(text);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (blank(lines[i])) continue;
    const int lineNo = static_cast<int>(i) + 1;
    const std::string& line = lines[i];
    if (line.size() < 8) {
      result.error = lineError(FontErrorKind::ShortLine, file, lineNo, 0, line);
      return result;
    }
    const std::string countField = line.substr(5, 3);
    const std::size_t digits = countField.find_first_not_of(' ');
    int count = -1;
    if (digits != std::string::npos &&
        std::all_of(countField.begin() + static_cast<long>(digits), countField.end(),
                    [](char c) { return c >= '0' && c <= '9'; }))
      count = std::atoi(countField.c_str() + digits);
    if (count < 0) {
      result.error = lineError(FontErrorKind::BadCount, file, lineNo, 6, countField);
      return result;
    }
    if (count == 0) {
      result.error = lineError(FontErrorKind::MissingBounds, file, lineNo, 6, countField);
      return result;
    }
    // The pairs, with the line numbers and columns they came from.
    std::string body = line.substr(8);
    std::vector<std::pair<int, int>> where;  // (line, first column) of each body character
    for (std::size_t c = 0; c < body.size(); ++c) where.emplace_back(lineNo, static_cast<int>(c) + 9);
    std::size_t lastLine = i;
    while (body.size() < 2 * static_cast<std::size_t>(count) && lines[lastLine].size() >= kWrapColumns &&
           lastLine + 1 < lines.size()) {
      ++lastLine;
      for (std::size_t c = 0; c < lines[lastLine].size(); ++c)
        where.emplace_back(static_cast<int>(lastLine) + 1, static_cast<int>(c) + 1);
      body += lines[lastLine];
    }
    if (body.size() < 2 * static_cast<std::size_t>(count)) {
      result.error = lineError(FontErrorKind::Truncated, file, static_cast<int>(lastLine) + 1,
                               static_cast<int>(lines[lastLine].size()) + 1, std::to_string(count));
      return result;
    }
    if (body.size() > 2 * static_cast<std::size_t>(count)) {
      const auto [l, c] = where[2 * static_cast<std::size_t>(count)];
      result.error = lineError(FontErrorKind::TooLong, file, l, c, std::to_string(count));
      return result;
    }
    HersheyGlyph glyph;
    glyph.sourceLine = lineNo;
    std::vector<HersheyPoint> stroke;
    for (int k = 0; k < count; ++k) {
      const char cx = body[2 * k], cy = body[2 * k + 1];
      if (cx == ' ' && cy == 'R') {
        if (k == 0) {
          const auto [l, c] = where[0];
          result.error = lineError(FontErrorKind::PenUpFirst, file, l, c, " R");
          return result;
        }
        if (!stroke.empty()) glyph.strokes.push_back(std::move(stroke));
        stroke.clear();
        continue;
      }
      for (int j = 0; j < 2; ++j) {
        const char ch = body[2 * k + j];
        if (!coordinateChar(ch)) {
          const auto [l, c] = where[2 * static_cast<std::size_t>(k) + static_cast<std::size_t>(j)];
          result.error = lineError(FontErrorKind::BadCoordinate, file, l, c, std::string(1, ch));
          return result;
        }
      }
      const HersheyPoint p{cx - 'R', cy - 'R'};
      if (k == 0) {
        glyph.left = p.x;
        glyph.right = p.y;
      } else {
        stroke.push_back(p);
      }
    }
    if (!stroke.empty()) glyph.strokes.push_back(std::move(stroke));
    // A single vertex draws nothing a pen can follow: such strokes are dropped.
    std::erase_if(glyph.strokes, [](const std::vector<HersheyPoint>& s) { return s.size() < 2; });
    font.glyphs.push_back(std::move(glyph));
    i = lastLine;
  }
  if (font.glyphs.empty()) {
    result.error = FontError{FontErrorKind::NoGlyphs, file, 0, 0, {}};
    return result;
  }
  measure(font);
  result.font = std::move(font);
  return result;
}

std::string fontDirectory() {
  const char* env = std::getenv("FIVEBAR_HERSHEY_DIR");
  return env && *env ? std::string(env) : std::string(kDefaultFontDirectory);
}

std::string fontDescription(const std::string& name) {
  static const std::map<std::string, std::string> kDescriptions = {
      {"astrology", "astrological symbols"},
      {"cursive", "cursive script, single stroke"},
      {"cyrilc_1", "Cyrillic complex (alternative)"},
      {"cyrillic", "Cyrillic complex, double stroke"},
      {"futural", "Futura light: simplex sans serif, single stroke"},
      {"futuram", "Futura medium: duplex sans serif, double stroke"},
      {"gothgbt", "Gothic English triplex (blackletter)"},
      {"gothgrt", "Gothic German triplex (Fraktur)"},
      {"gothiceng", "Gothic English (blackletter)"},
      {"gothicger", "Gothic German (Fraktur)"},
      {"gothicita", "Gothic Italian (rotunda)"},
      {"gothitt", "Gothic Italian triplex (rotunda)"},
      {"greek", "Greek simplex, single stroke"},
      {"greekc", "Greek complex, double stroke"},
      {"greeks", "Greek simplex (serif), single stroke"},
      {"japanese", "Japanese kana and kanji (selection)"},
      {"markers", "plot markers (circle, square, triangle...)"},
      {"mathlow", "mathematical symbols (lower case Greek)"},
      {"mathupp", "mathematical symbols (upper case Greek)"},
      {"meteorology", "meteorological symbols"},
      {"music", "musical notation symbols"},
      {"rowmand", "Roman duplex: sans serif, double stroke"},
      {"rowmans", "Roman simplex: sans serif, single stroke"},
      {"rowmant", "Roman triplex: serif, triple stroke"},
      {"scriptc", "script complex, double stroke"},
      {"scripts", "script simplex, single stroke"},
      {"symbolic", "miscellaneous symbols"},
      {"timesg", "Times Greek"},
      {"timesi", "Times italic"},
      {"timesib", "Times italic bold"},
      {"timesr", "Times roman"},
      {"timesrb", "Times roman bold"},
  };
  const auto it = kDescriptions.find(name);
  return it == kDescriptions.end() ? std::string("Hershey font") : it->second;
}

std::vector<FontInfo> listFonts(const std::string& directory) {
  std::vector<FontInfo> fonts;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
    const std::filesystem::path& path = it->path();
    if (path.extension() != ".jhf" || !it->is_regular_file(ec)) continue;
    const std::string name = path.stem().string();
    fonts.push_back(FontInfo{name, path.string(), fontDescription(name)});
  }
  std::sort(fonts.begin(), fonts.end(), [](const FontInfo& a, const FontInfo& b) { return a.name < b.name; });
  return fonts;
}

FontLoad loadFont(const std::string& name, const std::string& directory) {
  const bool isPath = name.find('/') != std::string::npos ||
                      (name.size() > 4 && name.compare(name.size() - 4, 4, ".jhf") == 0);
  const std::filesystem::path path = isPath ? std::filesystem::path(name)
                                            : std::filesystem::path(directory) / (name + ".jhf");
  FontLoad result;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    result.error = FontError{FontErrorKind::NotFound, isPath ? path.string() : name + " (in " + directory + ")",
                             0, 0, {}};
    return result;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) {
    result.error = FontError{FontErrorKind::Unreadable, path.string(), 0, 0, {}};
    return result;
  }
  return parseJhf(text.str(), path.stem().string(), path.string());
}

}  // namespace fivebar::text
