// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar text: single-stroke text in a Hershey font -> an SVG of paths in mm (docs/text.md).
#include <cstdio>
#include <fstream>
#include <iostream>

#include "commands.hpp"
#include "core/output/drawing_svg.hpp"
#include "core/text/hershey_font.hpp"
#include "core/text/text_drawing.hpp"
#include "core/text/text_layout.hpp"
#include "options.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kTextHelp =
    "usage: fivebar text TEXT --height MM [options] -o OUT.svg\n"
    "       fivebar text --list-fonts\n"
    "Writes TEXT in a single-stroke Hershey font as an SVG of paths in mm (one path per stroke,\n"
    "no fill), ready for 'fivebar plan'. A newline in TEXT starts a new line.\n"
    "  --font NAME               Hershey font (default futural); --list-fonts shows them\n"
    "  --height MM               height of a capital letter (the H), in mm\n"
    "  --line-spacing K          baseline to baseline = K x the font's line height (default 1)\n"
    "  --align left|center|right alignment of the lines (default left)\n"
    "  --margin MM               free paper around the text (default 1)\n"
    "  --color #RRGGBB           stroke colour (default #000000)\n"
    "  --stroke-width MM         the line width the SVG shows (default 0.3)\n"
    "  --strict                  refuse a text with characters the font lacks (default: each is\n"
    "                            named on stderr and skipped)\n"
    "  --list-fonts              list the fonts (name and description), one per line\n"
    "  -o, --output OUT.svg      the SVG to write ('-' for stdout)\n"
    "Fonts are read from $FIVEBAR_HERSHEY_DIR, else /usr/share/hershey-fonts (Debian package\n"
    "hershey-fonts-data).\n";

int listFontsCommand() {
  const std::string dir = text::fontDirectory();
  const auto fonts = text::listFonts(dir);
  if (fonts.empty()) {
    std::cerr << "fivebar text: no Hershey fonts (.jhf files) in " << dir
              << " (install hershey-fonts-data, or set FIVEBAR_HERSHEY_DIR)\n";
    return 1;
  }
  for (const text::FontInfo& f : fonts) std::cout << f.name << "\t" << f.description << "\n";
  return 0;
}

std::uint32_t colourArg(const std::string& s) {
  const bool ok = s.size() == 7 && s[0] == '#' &&
                  s.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos;
  if (!ok) throw UsageError("--color needs #RRGGBB, got '" + s + "'");
  return static_cast<std::uint32_t>(std::stoul(s.substr(1), nullptr, 16));
}

text::Align alignArg(const std::string& s) {
  if (s == "left") return text::Align::Left;
  if (s == "center" || s == "centre") return text::Align::Center;
  if (s == "right") return text::Align::Right;
  throw UsageError("--align must be left, center or right, got '" + s + "'");
}

bool writeOutput(const std::string& path, const std::string& svg) {
  if (path == "-") {
    std::cout << svg;
    return static_cast<bool>(std::cout);
  }
  const std::string part = path + ".part";
  bool ok = false;
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out << svg;
    out.flush();
    ok = static_cast<bool>(out);
  }
  if (ok && std::rename(part.c_str(), path.c_str()) == 0) return true;
  std::remove(part.c_str());
  std::cerr << "fivebar text: cannot write '" << path << "'\n";
  return false;
}

int textCommand(const Options& o) {
  if (o.flag("--list-fonts")) {
    if (!o.positional().empty() || o.value("--height")) throw UsageError("--list-fonts takes no text or options");
    return listFontsCommand();
  }
  if (o.positional().size() != 1) throw UsageError("text needs exactly one TEXT (quote it)");
  const std::string& utf8 = o.positional()[0];
  if (utf8.find_first_not_of(" \t\r\n") == std::string::npos) throw UsageError("the text is empty");
  text::TextStyle style;
  style.heightMm = numberArg(o.required("--height"), "--height", true);
  if (const auto k = o.value("--line-spacing")) style.lineSpacing = numberArg(*k, "--line-spacing", true);
  if (const auto a = o.value("--align")) style.align = alignArg(*a);
  text::TextDrawingOptions drawingOptions;
  drawingOptions.marginMm = 1.0;
  if (const auto m = o.value("--margin")) drawingOptions.marginMm = numberArg(*m, "--margin");
  if (drawingOptions.marginMm < 0.0) throw UsageError("--margin must not be negative");
  if (const auto c = o.value("--color")) drawingOptions.rgb = colourArg(*c);
  SvgWriteOptions svgOptions;
  if (const auto w = o.value("--stroke-width")) svgOptions.strokeWidthMm = numberArg(*w, "--stroke-width", true);
  const std::string output = o.required("--output");

  const std::string fontName = o.value("--font").value_or("futural");
  const text::FontLoad load = text::loadFont(fontName);
  if (!load.font) {
    std::cerr << "fivebar text: " << text::toString(load.error) << "\n";
    if (load.error.kind == text::FontErrorKind::NotFound)
      std::cerr << "  'fivebar text --list-fonts' lists the fonts\n";
    return 1;
  }
  const text::TextLayout layout = text::layoutText(*load.font, utf8, style);
  for (const text::MissingGlyph& m : layout.missing)
    std::cerr << "fivebar text: " << (o.flag("--strict") ? "error" : "warning") << ": font " << fontName
              << " has no glyph for " << text::describe(m) << (o.flag("--strict") ? "" : "; skipped") << "\n";
  if (!layout.missing.empty() && o.flag("--strict")) return 1;
  if (layout.strokes.empty()) {
    std::cerr << "fivebar text: nothing to draw: font " << fontName << " has no strokes for this text\n";
    return 1;
  }
  drawingOptions.source = output;
  const Drawing drawing = text::drawingFromText(layout, drawingOptions);
  return writeOutput(output, svgFromDrawing(drawing, svgOptions)) ? 0 : 1;
}

}  // namespace

int runText(const Args& args) {
  try {
    Args normalized = args;
    for (std::string& a : normalized)
      if (a == "-o") a = "--output";
    const Options o(normalized,
                    {"--font", "--height", "--line-spacing", "--align", "--margin", "--color", "--stroke-width",
                     "--output"},
                    {"--list-fonts", "--strict", "--help"});
    if (o.flag("--help")) {
      std::cout << kTextHelp;
      return 0;
    }
    return textCommand(o);
  } catch (const UsageError& e) {
    std::cerr << "fivebar text: " << e.what() << "\n\n" << kTextHelp;
    return 2;
  }
}

}  // namespace fivebar::cli
