// SPDX-License-Identifier: GPL-3.0-or-later
// CSV measurement files of the calibration (docs/calibration.md). Deliberately plain CSV: fields
// separated by commas, no quoting (ids and numbers never need it).
#include "core/calibration/measurements.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "core/kinematics/units.hpp"

namespace fivebar::calibration {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") + 1 - b);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// The table of a CSV file: header columns by name, and the data rows with their line numbers.
struct Table {
  std::string source;
  std::map<std::string, std::size_t> column;
  std::vector<std::pair<int, std::vector<std::string>>> rows;
  int headerLine = 0;
  std::string where(int line) const { return source + ":" + std::to_string(line); }
};

Table parse(const std::string& text, const std::string& source) {
  Table t;
  t.source = source;
  std::stringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    if (t.headerLine == 0) {
      t.headerLine = number;
      const std::vector<std::string> names = split(content);
      for (std::size_t i = 0; i < names.size(); ++i) t.column.emplace(names[i], i);
    } else {
      t.rows.emplace_back(number, split(content));
    }
  }
  return t;
}

// Error text for the first column of `names` the header lacks; empty when it has them all.
Message missingColumn(const Table& t, const std::vector<std::string>& names) {
  std::string all;
  for (const std::string& n : names) all += (all.empty() ? "" : ",") + n;
  if (t.headerLine == 0) return FB_TR("CalibrationFile", "%1: the file is empty (expected a header line: %2)").arg(t.source).arg(all);
  for (const std::string& n : names)
    if (!t.column.count(n))
      return FB_TR("CalibrationFile", "%1: the header has no column %2 (expected %3)").arg(t.where(t.headerLine)).arg(n).arg(all);
  return {};
}

// A field of a row: its text, or an error when the row is too short or the field empty.
bool field(const Table& t, int line, const std::vector<std::string>& row, const std::string& name,
           std::string& value, Message& error) {
  const std::size_t i = t.column.at(name);
  if (i >= row.size() || row[i].empty()) {
    error = FB_TR("CalibrationFile", "%1: missing field %2").arg(t.where(line)).arg(name);
    return false;
  }
  value = row[i];
  return true;
}

bool number(const Table& t, int line, const std::vector<std::string>& row, const std::string& name,
            double& value, Message& error) {
  std::string text;
  if (!field(t, line, row, name, text, error)) return false;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) {
    error = FB_TR("CalibrationFile", "%1: %2 is not a number: \"%3\"").arg(t.where(line)).arg(name).arg(text);
    return false;
  }
  return true;
}

// The id and commanded angles of a mark row; checks the id is new.
bool markRow(const Table& t, int line, const std::vector<std::string>& row, std::map<std::string, int>& seen,
             std::string& id, JointAngles& q, Message& error) {
  double t1 = 0.0, t2 = 0.0;
  if (!field(t, line, row, "id", id, error) || !number(t, line, row, "theta1_deg", t1, error) ||
      !number(t, line, row, "theta2_deg", t2, error))
    return false;
  if (auto [it, fresh] = seen.emplace(id, line); !fresh) {
    error = FB_TR("CalibrationFile", "%1: duplicate mark id %2 (first on line %3)").arg(t.where(line)).arg(id).arg(it->second);
    return false;
  }
  q = {radFromDeg(t1), radFromDeg(t2)};
  return true;
}

}  // namespace

MeasurementRead readMeasurements(const std::string& text, const std::string& source) {
  MeasurementRead r;
  const Table t = parse(text, source);
  if (t.column.count("id_a") || t.column.count("id_b") || t.column.count("distance_mm")) {
    r.form = MeasurementForm::Distances;
    if (!(r.error = missingColumn(t, {"id_a", "id_b", "distance_mm"})).empty()) return r;
    std::map<std::pair<std::string, std::string>, int> seen;
    for (const auto& [line, row] : t.rows) {
      DistanceMeasurement d;
      d.line = line;
      if (!field(t, line, row, "id_a", d.idA, r.error) || !field(t, line, row, "id_b", d.idB, r.error) ||
          !number(t, line, row, "distance_mm", d.distanceMm, r.error))
        return r;
      if (d.idA == d.idB) return r.error = FB_TR("CalibrationFile", "%1: a distance from mark %2 to itself").arg(t.where(line)).arg(d.idA), r;
      if (!(d.distanceMm > 0.0)) return r.error = FB_TR("CalibrationFile", "%1: distance_mm must be positive").arg(t.where(line)), r;
      const auto key = std::minmax(d.idA, d.idB);
      if (auto [it, fresh] = seen.emplace(key, line); !fresh)
        return r.error = FB_TR("CalibrationFile", "%1: duplicate distance %2-%3 (first on line %4)")
                             .arg(t.where(line))
                             .arg(d.idA)
                             .arg(d.idB)
                             .arg(it->second),
               r;
      r.distances.push_back(d);
    }
    return r;
  }
  if (!(r.error = missingColumn(t, {"id", "theta1_deg", "theta2_deg", "x_mm", "y_mm"})).empty()) return r;
  std::map<std::string, int> seen;
  for (const auto& [line, row] : t.rows) {
    MarkMeasurement m;
    m.line = line;
    double x = 0.0, y = 0.0;
    if (!markRow(t, line, row, seen, m.id, m.commanded, r.error) || !number(t, line, row, "x_mm", x, r.error) ||
        !number(t, line, row, "y_mm", y, r.error))
      return r;
    m.paperMm = Vec2(x, y);
    r.marks.push_back(m);
  }
  return r;
}

MarkPosesRead readMarkPoses(const std::string& text, const std::string& source) {
  MarkPosesRead r;
  const Table t = parse(text, source);
  if (!(r.error = missingColumn(t, {"id", "theta1_deg", "theta2_deg"})).empty()) return r;
  std::map<std::string, int> seen;
  for (const auto& [line, row] : t.rows) {
    MarkPose m;
    m.line = line;
    if (!markRow(t, line, row, seen, m.id, m.commanded, r.error)) return r;
    r.marks.push_back(m);
  }
  return r;
}

bool readTextFile(const std::string& path, std::string& text, Message& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = FB_TR("CalibrationFile", "cannot open %1: %2").arg(path).arg(std::strerror(errno));
    return false;
  }
  std::ostringstream s;
  s << in.rdbuf();
  text = s.str();
  return true;
}

}  // namespace fivebar::calibration
