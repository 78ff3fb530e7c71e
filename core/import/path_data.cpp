// SPDX-License-Identifier: GPL-3.0-or-later
#include "path_data.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>
#include <numbers>

namespace fivebar::svg {
namespace {

class Scanner {
 public:
  explicit Scanner(QStringView d) : d_(d) {}

  void skipSeparators() {
    while (pos_ < d_.size() && (d_[pos_].isSpace() || d_[pos_] == u',')) ++pos_;
  }
  bool atEnd() {
    skipSeparators();
    return pos_ >= d_.size();
  }
  QChar peek() const { return d_[pos_]; }
  qsizetype pos() const { return pos_; }
  void advance() { ++pos_; }
  bool startsNumber() {
    skipSeparators();
    if (pos_ >= d_.size()) return false;
    const QChar c = d_[pos_];
    return c.isDigit() || c == u'-' || c == u'+' || c == u'.';
  }

  // An SVG number: sign, digits, fraction, exponent. Any length: the text is copied whole
  // (a 64-character buffer once overflowed, and cut a longer number in two).
  bool number(double& out) {
    skipSeparators();
    const auto digit = [&](qsizetype i) { return i < d_.size() && d_[i] >= u'0' && d_[i] <= u'9'; };
    qsizetype p = pos_;
    qsizetype from = p;  // the copied text starts here (after a '+', which from_chars refuses)
    if (p < d_.size() && (d_[p] == u'+' || d_[p] == u'-')) {
      if (d_[p] == u'+') ++from;
      ++p;
    }
    qsizetype digits = 0;
    for (; digit(p); ++p) ++digits;
    if (p < d_.size() && d_[p] == u'.') {
      ++p;
      for (; digit(p); ++p) ++digits;
    }
    if (digits == 0) return false;
    if (p < d_.size() && (d_[p] == u'e' || d_[p] == u'E')) {
      qsizetype q = p + 1;
      if (q < d_.size() && (d_[q] == u'+' || d_[q] == u'-')) ++q;
      if (digit(q)) {
        for (p = q; digit(p); ++p) {
        }
      }
    }
    const qsizetype length = p - from;
    char small[64];
    std::string large;
    char* text = small;
    if (length > qsizetype(sizeof small)) {
      large.resize(static_cast<std::size_t>(length));
      text = large.data();
    }
    for (qsizetype i = 0; i < length; ++i) {
      const char16_t c = d_[from + i].unicode();
      text[i] = c == u'E' ? 'e' : static_cast<char>(c);
    }
    // An exponent sign after the 'e' is kept; a '+' there is read by from_chars.
    const auto [end, ec] = std::from_chars(text, text + length, out);
    if (ec != std::errc() || end != text + length || !std::isfinite(out)) return false;
    pos_ = p;
    return true;
  }

  bool flag(double& out) {
    skipSeparators();
    if (pos_ < d_.size() && (d_[pos_] == u'0' || d_[pos_] == u'1')) {
      out = d_[pos_] == u'1' ? 1.0 : 0.0;
      ++pos_;
      return true;
    }
    return false;
  }

 private:
  QStringView d_;
  qsizetype pos_ = 0;
};

int arity(char lower) {
  switch (lower) {
    case 'm': case 'l': case 't': return 2;
    case 'h': case 'v': return 1;
    case 'c': return 6;
    case 's': case 'q': return 4;
    case 'a': return 7;
    default: return 0;
  }
}

struct State {
  double x = 0, y = 0;          // current point
  double sx = 0, sy = 0;        // subpath start
  double cx = 0, cy = 0;        // last control point for S/T reflection
  char last = 'M';              // previous absolute op (after S->C, T->Q)
};

// Converts one command with raw numbers to its absolute form and updates the state.
PathCommand absolute(char op, const double* a, State& s) {
  const bool rel = std::islower(static_cast<unsigned char>(op));
  const double ox = rel ? s.x : 0.0;
  const double oy = rel ? s.y : 0.0;
  const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(op)));
  PathCommand c;
  const bool prevCubic = s.last == 'C';
  const bool prevQuad = s.last == 'Q';
  switch (lower) {
    case 'm': c = {'M', {a[0] + ox, a[1] + oy}}; s.sx = c.v[0]; s.sy = c.v[1]; break;
    case 'l': c = {'L', {a[0] + ox, a[1] + oy}}; break;
    case 'h': c = {'L', {a[0] + ox, s.y}}; break;
    case 'v': c = {'L', {s.x, a[0] + oy}}; break;
    case 'c': c = {'C', {a[0] + ox, a[1] + oy, a[2] + ox, a[3] + oy, a[4] + ox, a[5] + oy}}; break;
    case 's': {
      const double x1 = prevCubic ? 2 * s.x - s.cx : s.x;
      const double y1 = prevCubic ? 2 * s.y - s.cy : s.y;
      c = {'C', {x1, y1, a[0] + ox, a[1] + oy, a[2] + ox, a[3] + oy}};
      break;
    }
    case 'q': c = {'Q', {a[0] + ox, a[1] + oy, a[2] + ox, a[3] + oy}}; break;
    case 't': {
      const double x1 = prevQuad ? 2 * s.x - s.cx : s.x;
      const double y1 = prevQuad ? 2 * s.y - s.cy : s.y;
      c = {'Q', {x1, y1, a[0] + ox, a[1] + oy}};
      break;
    }
    case 'a': c = {'A', {a[0], a[1], a[2], a[3], a[4], a[5] + ox, a[6] + oy}}; break;
    default: c = {'Z', {}}; break;
  }
  switch (c.op) {
    case 'Z': s.x = s.sx; s.y = s.sy; break;
    case 'C': s.cx = c.v[2]; s.cy = c.v[3]; s.x = c.v[4]; s.y = c.v[5]; break;
    case 'Q': s.cx = c.v[0]; s.cy = c.v[1]; s.x = c.v[2]; s.y = c.v[3]; break;
    case 'A': s.x = c.v[5]; s.y = c.v[6]; break;
    default: s.x = c.v[0]; s.y = c.v[1]; break;
  }
  s.last = c.op;
  return c;
}

void appendNumber(std::string& out, double v) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  if (!out.empty() && out.back() != ' ') out.push_back(' ');
  out.append(buffer, ec == std::errc() ? end : buffer);
}

int numberCount(char op) {
  switch (op) {
    case 'M': case 'L': return 2;
    case 'C': return 6;
    case 'Q': return 4;
    case 'A': return 7;
    default: return 0;
  }
}

}  // namespace

ParsedPath parsePathData(QStringView d) {
  ParsedPath result;
  Scanner scan(d);
  State state;
  char op = 0;
  while (!scan.atEnd()) {
    const QChar c = scan.peek();
    if (op == 0 && c != u'M' && c != u'm') {  // SVG: in error from a first command that is no moveto
      result.error = true;
      result.errorOffset = scan.pos();
      return result;
    }
    if (c.isLetter() && c != u'e' && c != u'E') {
      op = static_cast<char>(c.unicode());
      scan.advance();
      if (std::tolower(static_cast<unsigned char>(op)) == 'z') {
        result.commands.push_back(absolute(op, nullptr, state));
        continue;
      }
      if (arity(static_cast<char>(std::tolower(static_cast<unsigned char>(op)))) == 0) break;
    } else if (op == 0 || std::tolower(static_cast<unsigned char>(op)) == 'z' || !scan.startsNumber()) {
      break;  // data without a command, or garbage
    }
    const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(op)));
    double a[7];
    bool ok = true;
    const qsizetype numbersStart = scan.pos();
    for (int i = 0; i < arity(lower) && ok; ++i)
      ok = (lower == 'a' && (i == 3 || i == 4)) ? scan.flag(a[i]) : scan.number(a[i]);
    if (!ok) {
      result.error = true;
      result.errorOffset = scan.pos();
      return result;
    }
    const PathCommand command = absolute(op, a, state);
    // Finite numbers whose absolute form overflows (a relative 1e308 after 1e308, a reflected
    // control point): bad data from here on, as an unparsable number is.
    if (!std::all_of(std::begin(command.v), std::end(command.v), [](double v) { return std::isfinite(v); })) {
      result.error = true;
      result.errorOffset = numbersStart;
      return result;
    }
    result.commands.push_back(command);
    if (op == 'm') op = 'l';  // implicit repeats of a moveto are linetos
    if (op == 'M') op = 'L';
  }
  if (!scan.atEnd()) {
    result.error = true;
    result.errorOffset = scan.pos();
  }
  return result;
}

void appendArcAsCubics(double x0, double y0, const PathCommand& arc, std::vector<PathCommand>& out) {
  const double x = arc.v[5], y = arc.v[6];
  if (x == x0 && y == y0) return;
  double rx = std::abs(arc.v[0]), ry = std::abs(arc.v[1]);
  if (rx == 0.0 || ry == 0.0) {
    out.push_back({'L', {x, y}});
    return;
  }
  const double phi = arc.v[2] * std::numbers::pi / 180.0;
  const double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
  const bool large = arc.v[3] != 0.0, sweep = arc.v[4] != 0.0;
  // F.6.5 step 1: the end points in the ellipse's axes, relative to their midpoint.
  const double dx2 = 0.5 * (x0 - x), dy2 = 0.5 * (y0 - y);
  const double x1p = cosPhi * dx2 + sinPhi * dy2;
  const double y1p = -sinPhi * dx2 + cosPhi * dy2;
  // F.6.6: radii too small to join the end points are scaled up.
  const double lambda = (x1p * x1p) / (rx * rx) + (y1p * y1p) / (ry * ry);
  if (lambda > 1.0) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  // Step 2: the centre in the ellipse's axes.
  const double rx2 = rx * rx, ry2 = ry * ry;
  const double den = rx2 * y1p * y1p + ry2 * x1p * x1p;
  const double num = rx2 * ry2 - den;
  double coef = den > 0.0 ? std::sqrt(std::max(0.0, num / den)) : 0.0;
  if (large == sweep) coef = -coef;
  const double cxp = coef * rx * y1p / ry, cyp = -coef * ry * x1p / rx;
  // Step 3: the centre; step 4: the start angle and the sweep.
  const double cx = cosPhi * cxp - sinPhi * cyp + 0.5 * (x0 + x);
  const double cy = sinPhi * cxp + cosPhi * cyp + 0.5 * (y0 + y);
  const double theta1 = std::atan2((y1p - cyp) / ry, (x1p - cxp) / rx);
  const double theta2 = std::atan2((-y1p - cyp) / ry, (-x1p - cxp) / rx);
  double delta = theta2 - theta1;
  if (!std::isfinite(delta) || !std::isfinite(cx) || !std::isfinite(cy) || !std::isfinite(rx * ry)) {
    // Numbers so large that the centre overflows (1e308): the chord, as for a zero radius; the
    // import refuses such coordinates anyway (ImportOptions::maxCoordinateMm).
    out.push_back({'L', {x, y}});
    return;
  }
  const double twoPi = 2.0 * std::numbers::pi;
  if (!sweep && delta > 0.0) delta -= twoPi;
  else if (sweep && delta < 0.0) delta += twoPi;
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(delta) / kArcPieceMaxRad - 1e-9)));
  const double step = delta / pieces;
  const double k = 4.0 / 3.0 * std::tan(step / 4.0);
  auto point = [&](double t, double& px, double& py) {
    const double c = std::cos(t), s = std::sin(t);
    px = cx + rx * cosPhi * c - ry * sinPhi * s;
    py = cy + rx * sinPhi * c + ry * cosPhi * s;
  };
  auto tangent = [&](double t, double& tx, double& ty) {  // d point / dt
    const double c = std::cos(t), s = std::sin(t);
    tx = -rx * cosPhi * s - ry * sinPhi * c;
    ty = -rx * sinPhi * s + ry * cosPhi * c;
  };
  // Computed piece ends differ from the given end points by rounding only: the first cubic
  // starts at the current point, the last one ends exactly at (x, y).
  for (int i = 0; i < pieces; ++i) {
    const double t0 = theta1 + step * i, t1 = theta1 + step * (i + 1);
    double sx, sy, ex, ey, tx0, ty0, tx1, ty1;
    point(t0, sx, sy);
    point(t1, ex, ey);
    tangent(t0, tx0, ty0);
    tangent(t1, tx1, ty1);
    const double bx = ex - k * tx1, by = ey - k * ty1;
    if (i + 1 == pieces) ex = x, ey = y;
    out.push_back({'C', {sx + k * tx0, sy + k * ty0, bx, by, ex, ey}});
  }
}

std::vector<PathCommand> arcsAsCubics(const std::vector<PathCommand>& commands) {
  std::vector<PathCommand> out;
  out.reserve(commands.size());
  double x = 0, y = 0, sx = 0, sy = 0;
  for (const PathCommand& c : commands) {
    if (c.op == 'A') appendArcAsCubics(x, y, c, out);
    else out.push_back(c);
    switch (c.op) {
      case 'M': sx = x = c.v[0]; sy = y = c.v[1]; break;
      case 'Z': x = sx; y = sy; break;
      case 'C': x = c.v[4]; y = c.v[5]; break;
      case 'Q': x = c.v[2]; y = c.v[3]; break;
      case 'A': x = c.v[5]; y = c.v[6]; break;
      default: x = c.v[0]; y = c.v[1]; break;
    }
  }
  return out;
}

int qtElementEstimate(const PathCommand& command) {
  switch (command.op) {
    case 'C': case 'Q': return 3;
    case 'A': return 12;
    default: return 1;
  }
}

std::vector<QString> splitPathData(const std::vector<PathCommand>& commands, int maxElements) {
  std::vector<QString> parts;
  std::string out;
  int elements = 0;
  double x = 0, y = 0, sx = 0, sy = 0;
  bool subpathStartedHere = false;
  for (const PathCommand& c : commands) {
    const int cost = qtElementEstimate(c);
    if (elements > 0 && elements + cost + 1 > maxElements) {
      parts.push_back(QString::fromLatin1(out.data(), static_cast<qsizetype>(out.size())));
      out.clear();
      elements = 0;
      subpathStartedHere = false;
      if (c.op != 'M') {
        out += "M";
        appendNumber(out, x);
        appendNumber(out, y);
        elements = 1;
      }
    }
    if (c.op == 'Z' && !subpathStartedHere) {
      out += " L";
      appendNumber(out, sx);
      appendNumber(out, sy);
    } else {
      if (!out.empty()) out.push_back(' ');
      out.push_back(c.op);
      for (int i = 0; i < numberCount(c.op); ++i) appendNumber(out, c.v[i]);
    }
    elements += cost;
    switch (c.op) {
      case 'M': sx = x = c.v[0]; sy = y = c.v[1]; subpathStartedHere = true; break;
      case 'Z': x = sx; y = sy; break;
      case 'C': x = c.v[4]; y = c.v[5]; break;
      case 'Q': x = c.v[2]; y = c.v[3]; break;
      case 'A': x = c.v[5]; y = c.v[6]; break;
      default: x = c.v[0]; y = c.v[1]; break;
    }
  }
  if (!out.empty()) parts.push_back(QString::fromLatin1(out.data(), static_cast<qsizetype>(out.size())));
  return parts;
}

}  // namespace fivebar::svg
