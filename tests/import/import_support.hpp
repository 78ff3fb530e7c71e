// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the import tests: in-memory SVG import and drawing queries.
#pragma once

#include <QByteArray>
#include <QString>

#include <string>

#include "core/import/svg_import.hpp"

namespace fivebar::test {

// Imports an SVG text in-process (no worker) with the given options.
inline svg::ImportResult importText(const std::string& svgText, const svg::ImportOptions& options = {}) {
  return svg::importSvgData(QByteArray::fromStdString(svgText), QStringLiteral("test.svg"), options);
}

// Wraps body in an <svg> root of the given size (mm) with a matching viewBox (1 unit = 1 mm).
inline std::string page(const std::string& body, double widthMm = 100, double heightMm = 50) {
  const std::string w = std::to_string(widthMm), h = std::to_string(heightMm);
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
         "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\"" + w +
         "mm\" height=\"" + h + "mm\" viewBox=\"0 0 " + w + " " + h + "\">" + body + "</svg>";
}

// True when one of the import's warnings contains `text`.
inline bool warned(const svg::ImportResult& r, const std::string& text) {
  for (const Message& w : r.warnings)
    if (w.text().find(text) != std::string::npos) return true;
  return false;
}

// All warnings, a line each (for failure messages).
inline std::string joined(const svg::ImportResult& r) {
  std::string s;
  for (const Message& w : r.warnings) s += w.text() + "\n";
  return s;
}

inline std::size_t pathCount(const Drawing& d) {
  std::size_t n = 0;
  for (const Layer& l : d.layers) n += l.paths.size();
  return n;
}

inline std::vector<Polyline> allPaths(const Drawing& d) {
  std::vector<Polyline> out;
  for (const Layer& l : d.layers) out.insert(out.end(), l.paths.begin(), l.paths.end());
  return out;
}

}  // namespace fivebar::test
