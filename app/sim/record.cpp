// SPDX-License-Identifier: GPL-3.0-or-later
#include "record.hpp"

#include <QSaveFile>
#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace fivebar::simapp {

std::string recordJson(const sim::SimMachine& m) {
  nlohmann::json strokes = nlohmann::json::array();
  for (const auto& s : m.strokes()) strokes.push_back(s);
  const nlohmann::json j = {{"strokesDeg", strokes},
                            {"machinePosition", m.machinePosition()},
                            {"workPosition", m.workPosition()},
                            {"state", std::string(grbl::toString(m.state()))},
                            {"linesReceived", m.linesReceived()},
                            {"rxOverflowBytes", m.rxOverflowBytes()},
                            {"plannerStarvationsInStroke", m.plannerStarvationsInStroke()}};
  return j.dump() + "\n";
}

namespace {

std::string saveText(const std::string& text, const std::string& path) {
  QSaveFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::WriteOnly)) return "cannot write " + path;
  file.write(text.data(), qint64(text.size()));
  return file.commit() ? "" : "cannot save " + path;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

}  // namespace

std::string drawnText(const sim::SimMachine& m, bool svg) {
  const auto& strokes = m.drawnTrace();
  std::string out;
  if (!svg) {
    out = "stroke,x_mm,y_mm\n";
    for (size_t i = 0; i < strokes.size(); ++i)
      for (const Vec2& p : strokes[i]) out += std::to_string(i) + "," + num(p.x()) + "," + num(p.y()) + "\n";
    return out;
  }
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  bool first = true;
  for (const auto& s : strokes)
    for (const Vec2& p : s) {
      x0 = first ? p.x() : std::min(x0, p.x());
      x1 = first ? p.x() : std::max(x1, p.x());
      y0 = first ? p.y() : std::min(y0, p.y());
      y1 = first ? p.y() : std::max(y1, p.y());
      first = false;
    }
  const double margin = 5.0, w = x1 - x0 + 2 * margin, h = y1 - y0 + 2 * margin;
  // SVG's y points down: y_svg = -y_machine, so the drawing stands as on the machine.
  out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
        num(w) + "mm\" height=\"" + num(h) + "mm\" viewBox=\"" + num(x0 - margin) + " " + num(-y1 - margin) +
        " " + num(w) + " " + num(h) + "\">\n<!-- fivebar-sim: what the pen of the true machine drew; machine "
        "frame in mm, y flipped (y_svg = -y) -->\n<g fill=\"none\" stroke=\"black\" stroke-width=\"0.3\">\n";
  for (const auto& s : strokes) {
    out += "<polyline points=\"";
    for (size_t i = 0; i < s.size(); ++i)
      out.append(i ? " " : "").append(num(s[i].x())).append(",").append(num(-s[i].y()));
    out += "\"/>\n";
  }
  return out + "</g>\n</svg>\n";
}

std::string writeDrawn(const sim::SimMachine& m, const std::string& path) {
  const bool svg = path.size() >= 4 && path.compare(path.size() - 4, 4, ".svg") == 0;
  return saveText(drawnText(m, svg), path);
}

std::string writeRecord(const sim::SimMachine& m, const std::string& path) {
  return saveText(recordJson(m), path);
}

}  // namespace fivebar::simapp
