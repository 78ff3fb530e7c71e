// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/drawing_svg.hpp"

#include <cstdio>

#include "core/output/fixed_decimal.hpp"

namespace fivebar {
namespace {

// XML text with the five special characters escaped (ids and names come from files and users).
std::string escapeXml(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string colour(std::uint32_t rgb) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%06x", static_cast<unsigned>(rgb & 0xFFFFFFu));
  return buf;
}

}  // namespace

std::string svgFromDrawing(const Drawing& drawing, const SvgWriteOptions& options) {
  const int d = options.decimals;
  const std::string w = fixedDecimal(drawing.widthMm, d), h = fixedDecimal(drawing.heightMm, d);
  std::string out;
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w + "mm\" height=\"" + h +
         "mm\" viewBox=\"0 0 " + w + " " + h + "\">\n";
  for (const Layer& layer : drawing.layers) {
    if (!layer.visible) continue;
    out += "  <g id=\"" + escapeXml(layer.id) + "\" fill=\"none\" stroke=\"" + colour(layer.rgb) +
           "\" stroke-width=\"" + fixedDecimal(options.strokeWidthMm, 3) +
           "\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    if (!layer.name.empty() && layer.name != layer.id) out += "    <title>" + escapeXml(layer.name) + "</title>\n";
    for (const Polyline& line : layer.paths) {
      if (line.points.empty()) continue;
      out += "    <path d=\"";
      for (std::size_t i = 0; i < line.points.size(); ++i) {
        out += i == 0 ? "M" : " L";
        out += fixedDecimal(line.points[i].x(), d);
        out += ' ';
        out += fixedDecimal(drawing.heightMm - line.points[i].y(), d);
      }
      if (line.closed) out += " Z";
      out += "\"/>\n";
    }
    out += "  </g>\n";
  }
  out += "</svg>\n";
  return out;
}

}  // namespace fivebar
