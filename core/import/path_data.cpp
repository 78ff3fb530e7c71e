#include "path_data.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

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

  bool number(double& out) {
    skipSeparators();
    char buffer[64];
    int n = 0;
    qsizetype p = pos_;
    auto take = [&](auto pred) {
      while (p < d_.size() && n < 63 && pred(d_[p])) buffer[n++] = static_cast<char>(d_[p++].unicode());
    };
    if (p < d_.size() && (d_[p] == u'+' || d_[p] == u'-')) buffer[n++] = static_cast<char>(d_[p++].unicode());
    const int digitsStart = n;
    take([](QChar c) { return c.isDigit(); });
    if (p < d_.size() && d_[p] == u'.') {
      buffer[n++] = '.';
      ++p;
      take([](QChar c) { return c.isDigit(); });
    }
    if (n == digitsStart || (n == digitsStart + 1 && buffer[digitsStart] == '.')) return false;
    if (p < d_.size() && (d_[p] == u'e' || d_[p] == u'E')) {
      qsizetype q = p + 1;
      if (q < d_.size() && (d_[q] == u'+' || d_[q] == u'-')) ++q;
      if (q < d_.size() && d_[q].isDigit()) {
        buffer[n++] = 'e';
        ++p;
        if (d_[p] == u'+' || d_[p] == u'-') buffer[n++] = static_cast<char>(d_[p++].unicode());
        take([](QChar c) { return c.isDigit(); });
      }
    }
    const char* begin = buffer[0] == '+' ? buffer + 1 : buffer;
    const auto [end, ec] = std::from_chars(begin, buffer + n, out);
    if (ec != std::errc() || !std::isfinite(out)) return false;
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
    for (int i = 0; i < arity(lower) && ok; ++i)
      ok = (lower == 'a' && (i == 3 || i == 4)) ? scan.flag(a[i]) : scan.number(a[i]);
    if (!ok) {
      result.error = true;
      result.errorOffset = scan.pos();
      return result;
    }
    result.commands.push_back(absolute(op, a, state));
    if (op == 'm') op = 'l';  // implicit repeats of a moveto are linetos
    if (op == 'M') op = 'L';
  }
  if (!scan.atEnd()) {
    result.error = true;
    result.errorOffset = scan.pos();
  }
  return result;
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
