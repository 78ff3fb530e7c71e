// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/calibration/marks_csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "core/output/fixed_decimal.hpp"

namespace fivebar {
namespace {

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(cur);
  for (std::string& f : out) {
    const size_t a = f.find_first_not_of(" \t");
    const size_t b = f.find_last_not_of(" \t");
    f = a == std::string::npos ? std::string() : f.substr(a, b - a + 1);
  }
  return out;
}

std::optional<double> number(const std::string& s) {
  double v = 0.0;
  const char* end = s.data() + s.size();
  const auto r = std::from_chars(s.data(), end, v);
  if (r.ec != std::errc() || r.ptr != end || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<int> integer(const std::string& s) {
  int v = 0;
  const char* end = s.data() + s.size();
  const auto r = std::from_chars(s.data(), end, v);
  if (r.ec != std::errc() || r.ptr != end) return std::nullopt;
  return v;
}

// Reads lines of a CSV with a fixed header; calls row(fields, where) for each non-empty line.
// Returns an error message or empty.
template <typename Row>
Message readCsv(const std::string& text, const std::string& source, const std::string& header,
                    Row row) {
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  const std::vector<std::string> names = splitFields(header);
  bool sawHeader = false;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string where = source + ":" + std::to_string(lineNo);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::vector<std::string> f = splitFields(line);
    if (!sawHeader) {
      if (f != names) return FB_TR("CalibrationFile", "%1: header must be '%2'").arg(where).arg(header);
      sawHeader = true;
      continue;
    }
    if (f.size() != names.size())
      return FB_TR("CalibrationFile", "%1: %2 fields, expected %3").arg(where).arg(f.size()).arg(names.size());
    if (Message e = row(f, names, where); !e.empty()) return e;
  }
  if (!sawHeader) return FB_TR("CalibrationFile", "%1: empty file (expected the header '%2')").arg(source).arg(header);
  return {};
}

Message notNumber(const std::string& where, const std::string& field, const std::string& v) {
  return FB_TR("CalibrationFile", "%1: %2: '%3' is not a number").arg(where).arg(field).arg(v);
}

std::optional<Approach> approachOf(const std::string& s) {
  if (s == "+") return Approach::Plus;
  if (s == "-") return Approach::Minus;
  return std::nullopt;
}

std::string fileText(const std::string& path, Message& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = FB_TR("CalibrationFile", "%1: cannot open the file").arg(path);
    return {};
  }
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string marksCsv(const CalibrationPattern& pattern) {
  std::string out = std::string(kMarksCsvHeader) + "\n";
  for (const PatternMark& m : pattern.marks) {
    out += std::to_string(m.id) + "," + fixedDecimal(degFromRad(m.q.theta1), 4) + "," +
           fixedDecimal(degFromRad(m.q.theta2), 4) + "," + fixedDecimal(m.nominalMm.x(), 4) + "," +
           fixedDecimal(m.nominalMm.y(), 4) + "," + (m.kind == MarkKind::Grid ? "grid" : "backlash") +
           "," + (m.approach1 == Approach::Plus ? "+" : "-") + "," +
           (m.approach2 == Approach::Plus ? "+" : "-") + "," + std::to_string(m.group) + "," +
           std::to_string(m.motor) + "," + fixedDecimal(pattern.ringRadiusMm, 3) + "\n";
  }
  return out;
}

MarksLoad parseMarksCsv(const std::string& text, const std::string& source) {
  MarksLoad out;
  std::set<int> ids;
  std::map<int, int> rowCount;
  out.error = readCsv(text, source, kMarksCsvHeader, [&](const std::vector<std::string>& f,
                                                        const std::vector<std::string>& names,
                                                        const std::string& where) -> Message {
    MarkRecord r;
    const auto id = integer(f[0]);
    if (!id || *id <= 0) return FB_TR("CalibrationFile", "%1: id: '%2' is not a positive integer").arg(where).arg(f[0]);
    if (!ids.insert(*id).second) return FB_TR("CalibrationFile", "%1: id: duplicate id %2").arg(where).arg(f[0]);
    r.mark.id = *id;
    double v[4];
    for (int k = 0; k < 4; ++k) {
      const auto x = number(f[static_cast<size_t>(k + 1)]);
      if (!x) return notNumber(where, names[static_cast<size_t>(k + 1)], f[static_cast<size_t>(k + 1)]);
      v[k] = *x;
    }
    r.mark.q = {radFromDeg(v[0]), radFromDeg(v[1])};
    r.mark.nominalMm = Vec2(v[2], v[3]);
    if (f[5] == "grid") r.mark.kind = MarkKind::Grid;
    else if (f[5] == "backlash") r.mark.kind = MarkKind::Backlash;
    else return FB_TR("CalibrationFile", "%1: kind: '%2' is not grid or backlash").arg(where).arg(f[5]);
    const auto a1 = approachOf(f[6]), a2 = approachOf(f[7]);
    if (!a1) return FB_TR("CalibrationFile", "%1: %2: '%3' is not + or -").arg(where).arg("approach1").arg(f[6]);
    if (!a2) return FB_TR("CalibrationFile", "%1: %2: '%3' is not + or -").arg(where).arg("approach2").arg(f[7]);
    r.mark.approach1 = *a1;
    r.mark.approach2 = *a2;
    const auto group = integer(f[8]), motor = integer(f[9]);
    if (!group || *group < 0) return FB_TR("CalibrationFile", "%1: group: '%2' is not a non-negative integer").arg(where).arg(f[8]);
    if (!motor || *motor < 0 || *motor > 2) return FB_TR("CalibrationFile", "%1: motor: '%2' is not 0, 1 or 2").arg(where).arg(f[9]);
    r.mark.group = *group;
    r.mark.motor = *motor;
    if ((r.mark.kind == MarkKind::Backlash) != (*group > 0 && *motor > 0))
      return FB_TR("CalibrationFile", "%1: a backlash mark needs a group and a motor, a grid mark neither").arg(where);
    if (r.mark.kind == MarkKind::Backlash) r.mark.rowIndex = rowCount[*group]++;
    const auto ring = number(f[10]);
    if (!ring || *ring <= 0.0) return FB_TR("CalibrationFile", "%1: ring_radius_mm: '%2' is not a positive number").arg(where).arg(f[10]);
    r.ringRadiusMm = *ring;
    out.marks.push_back(r);
    return {};
  });
  if (out.error.empty() && out.marks.empty()) out.error = FB_TR("CalibrationFile", "%1: no marks").arg(source);
  for (const auto& [group, n] : rowCount)
    if (out.error.empty() && n != 3)
      out.error = FB_TR("CalibrationFile", "%1: backlash row %2 has %3 marks, expected 3").arg(source).arg(group).arg(n);
  if (!out.error.empty()) out.marks.clear();
  return out;
}

MarksLoad loadMarksCsv(const std::string& path) {
  MarksLoad out;
  const std::string text = fileText(path, out.error);
  if (!out.error.empty()) return out;
  return parseMarksCsv(text, path);
}

std::string measuredCsv(const std::vector<MeasuredMark>& marks) {
  std::string out = std::string(kMeasuredCsvHeader) + "\n";
  for (const MeasuredMark& m : marks)
    out += std::to_string(m.id) + "," + fixedDecimal(m.theta1Deg, 4) + "," + fixedDecimal(m.theta2Deg, 4) +
           "," + fixedDecimal(m.measuredMm.x(), 4) + "," + fixedDecimal(m.measuredMm.y(), 4) + "\n";
  return out;
}

MeasuredLoad parseMeasuredCsv(const std::string& text, const std::string& source) {
  MeasuredLoad out;
  std::set<int> ids;
  out.error = readCsv(text, source, kMeasuredCsvHeader, [&](const std::vector<std::string>& f,
                                                           const std::vector<std::string>& names,
                                                           const std::string& where) -> Message {
    MeasuredMark m;
    const auto id = integer(f[0]);
    if (!id || *id <= 0) return FB_TR("CalibrationFile", "%1: id: '%2' is not a positive integer").arg(where).arg(f[0]);
    if (!ids.insert(*id).second) return FB_TR("CalibrationFile", "%1: id: duplicate id %2").arg(where).arg(f[0]);
    m.id = *id;
    double v[4];
    for (int k = 0; k < 4; ++k) {
      const auto x = number(f[static_cast<size_t>(k + 1)]);
      if (!x) return notNumber(where, names[static_cast<size_t>(k + 1)], f[static_cast<size_t>(k + 1)]);
      v[k] = *x;
    }
    m.theta1Deg = v[0];
    m.theta2Deg = v[1];
    m.measuredMm = Vec2(v[2], v[3]);
    out.marks.push_back(m);
    return {};
  });
  if (!out.error.empty()) out.marks.clear();
  return out;
}

}  // namespace fivebar
