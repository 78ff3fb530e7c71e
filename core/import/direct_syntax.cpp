// SPDX-License-Identifier: GPL-3.0-or-later
#include "direct_syntax.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "svg_sanitize.hpp"

namespace fivebar::svg {
namespace {

constexpr int kMaxNumberChars = 64;
constexpr std::size_t kMaxAttributes = 64;  // per element; plotter files use a handful
constexpr int kMaxExponent = 300;  // the sanitiser refuses larger ones: let it speak
constexpr double kSmallestNormal = 1e-300;

bool isSpace(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isNameStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isNameChar(char c) {
  return isNameStart(c) || isDigit(c) || c == '-' || c == '.' || c == ':';
}
bool startsNumber(char c) { return isDigit(c) || c == '-' || c == '+' || c == '.'; }

// Plain decimals with at most 15 digits and no exponent ("-12.345"): the digits as an integer m
// and k fraction digits give m / 10^k, both exact doubles, so the one division is the correctly
// rounded value, the same double as from_chars (and as Qt's integer/divisor conversion).
bool exactSmallDecimal(const char* p, const char* end, double& value) {
  static constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7,
                                      1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  const bool negative = *p == '-';
  if (*p == '-' || *p == '+') ++p;
  std::uint64_t m = 0;
  int digits = 0, fraction = -1;
  for (; p < end; ++p) {
    if (*p == '.') {
      fraction = 0;
      continue;
    }
    if (!isDigit(*p) || ++digits > 15) return false;  // exponent, or too many digits
    m = m * 10 + static_cast<std::uint64_t>(*p - '0');
    if (fraction >= 0) ++fraction;
  }
  const double v = static_cast<double>(m) / kPow10[std::max(fraction, 0)];
  value = negative ? -v : v;
  return true;
}

// One number in Qt SVG's syntax: [sign] digits [. digits] [e [sign] digits]; the value is the
// correctly rounded double (as Qt's integer/divisor or strtod-based conversion gives).
bool scanNumber(const char*& p, const char* end, double& value) {
  const char* start = p;
  if (p < end && (*p == '+' || *p == '-')) ++p;
  const char* digits = p;
  while (p < end && isDigit(*p)) ++p;
  std::ptrdiff_t mantissaDigits = p - digits;
  if (p < end && *p == '.') {
    const char* fraction = ++p;
    while (p < end && isDigit(*p)) ++p;
    mantissaDigits += p - fraction;
  }
  if (mantissaDigits == 0) return false;
  if (p < end && (*p == 'e' || *p == 'E')) {
    ++p;
    if (p < end && (*p == '+' || *p == '-')) ++p;
    int exponent = 0, exponentDigits = 0;
    while (p < end && isDigit(*p) && exponentDigits < 6) {
      exponent = exponent * 10 + (*p++ - '0');
      ++exponentDigits;
    }
    if (exponentDigits == 0 || exponent > kMaxExponent || (p < end && isDigit(*p))) return false;
  }
  if (p - start > kMaxNumberChars) return false;
  if (exactSmallDecimal(start, p, value)) return true;
  const char* first = *start == '+' ? start + 1 : start;
  const auto [stop, ec] = std::from_chars(first, p, value);
  if (ec != std::errc() || stop != p || !std::isfinite(value)) return false;
  const double magnitude = std::abs(value);
  return magnitude == 0.0 || (magnitude > kSmallestNormal && magnitude < 1.0 / kSmallestNormal);
}

void skipSpaces(const char*& p, const char* end) {
  while (p < end && isSpace(*p)) ++p;
}

// Qt SVG's parseNumbersArray: leading spaces, then numbers each followed by spaces, at most one
// comma, spaces. Stops at the first character that cannot start a number.
bool scanNumbers(const char*& p, const char* end, std::vector<double>& out) {
  skipSpaces(p, end);
  while (p < end && startsNumber(*p)) {
    double v = 0.0;
    if (!scanNumber(p, end, v)) return false;
    out.push_back(v);
    skipSpaces(p, end);
    if (p < end && *p == ',') ++p;
    skipSpaces(p, end);
  }
  return true;
}

int arity(char lower) {
  switch (lower) {
    case 'm': case 'l': case 't': return 2;
    case 'h': case 'v': return 1;
    case 's': case 'q': return 4;
    case 'c': return 6;
    default: return 0;  // z, and everything outside the subset
  }
}

// The state of Qt SVG's parsePathDataFast between commands.
struct PathState {
  double x0 = 0, y0 = 0;  // subpath start
  double x = 0, y = 0;    // current point
  QPointF control;        // last control point, for S and T
  char lastMode = 0;
};

// Applies one command group (arity numbers at `n`) the way Qt SVG does; returns the command
// that repeats after it (M becomes L).
char applyGroup(char op, const double* n, PathState& s, QPainterPath& path) {
  const bool relative = op >= 'a';
  const double ox = relative ? s.x : 0.0, oy = relative ? s.y : 0.0;
  char next = op;
  switch (op | 0x20) {
    case 'm':
      s.x = s.x0 = n[0] + ox;
      s.y = s.y0 = n[1] + oy;
      path.moveTo(s.x0, s.y0);
      next = relative ? 'l' : 'L';
      break;
    case 'l':
      s.x = n[0] + ox;
      s.y = n[1] + oy;
      path.lineTo(s.x, s.y);
      break;
    case 'h':
      s.x = n[0] + ox;
      path.lineTo(s.x, s.y);
      break;
    case 'v':
      s.y = n[0] + oy;
      path.lineTo(s.x, s.y);
      break;
    case 'c': case 's': {
      const char last = static_cast<char>(s.lastMode | 0x20);
      const int k = (op | 0x20) == 'c' ? 2 : 0;
      const QPointF c1 = k == 2 ? QPointF(n[0] + ox, n[1] + oy)
                         : (last == 'c' || last == 's')
                             ? QPointF(2 * s.x - s.control.x(), 2 * s.y - s.control.y())
                             : QPointF(s.x, s.y);
      const QPointF c2(n[k] + ox, n[k + 1] + oy), e(n[k + 2] + ox, n[k + 3] + oy);
      path.cubicTo(c1, c2, e);
      s.control = c2;
      s.x = e.x();
      s.y = e.y();
      break;
    }
    case 'q': case 't': {
      const char last = static_cast<char>(s.lastMode | 0x20);
      const bool quad = (op | 0x20) == 'q';
      const QPointF c = quad ? QPointF(n[0] + ox, n[1] + oy)
                        : (last == 'q' || last == 't')
                            ? QPointF(2 * s.x - s.control.x(), 2 * s.y - s.control.y())
                            : QPointF(s.x, s.y);
      const int k = quad ? 2 : 0;
      const QPointF e(n[k] + ox, n[k + 1] + oy);
      path.quadTo(c, e);
      s.control = c;
      s.x = e.x();
      s.y = e.y();
      break;
    }
    default: break;
  }
  s.lastMode = next;
  return next;
}

}  // namespace

bool asciiWithoutReferences(std::string_view text) {
  // Branch-free so that the compiler vectorises the pass over megabytes.
  unsigned bad = 0;
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    bad |= static_cast<unsigned>(c >= 0x7F) | static_cast<unsigned>(c == '&') |
           (static_cast<unsigned>(c < 0x20) & static_cast<unsigned>(c != '\n') &
            static_cast<unsigned>(c != '\t') & static_cast<unsigned>(c != '\r'));
  }
  return bad == 0;
}

bool XmlCursor::skipMisc() {
  for (;;) {
    while (pos_ < text_.size() && isSpace(text_[pos_])) ++pos_;
    if (text_.compare(pos_, 4, "<!--") != 0) return true;
    const std::size_t close = text_.find("--", pos_ + 4);
    if (close == std::string_view::npos || text_.compare(close, 3, "-->") != 0) return false;
    pos_ = close + 3;
  }
}

bool XmlCursor::skipProlog() {
  if (text_.compare(0, 5, "<?xml") == 0) {
    const std::size_t close = text_.find("?>");
    if (close == std::string_view::npos) return false;
    const std::string_view decl = text_.substr(5, close - 5);
    // version 1.0 first; encodings that read ASCII as ASCII; standalone.
    if (decl.empty() || !isSpace(decl[0])) return false;
    std::string_view rest = decl;
    auto take = [&](std::string_view key, std::initializer_list<std::string_view> values) {
      std::size_t i = 0;
      while (i < rest.size() && isSpace(rest[i])) ++i;
      if (rest.compare(i, key.size(), key) != 0) return false;
      i += key.size();
      if (i >= rest.size() || (rest[i] != '"' && rest[i] != '\'')) return false;
      const char quote = rest[i];
      for (std::string_view v : values) {
        if (rest.compare(i + 1, v.size(), v) == 0 && i + 1 + v.size() < rest.size() &&
            rest[i + 1 + v.size()] == quote) {
          rest.remove_prefix(i + v.size() + 2);
          return true;
        }
      }
      return false;
    };
    if (!take("version=", {"1.0"})) return false;
    take("encoding=", {"UTF-8", "utf-8", "US-ASCII", "us-ascii", "ISO-8859-1", "iso-8859-1"});
    take("standalone=", {"yes", "no"});
    if (!std::all_of(rest.begin(), rest.end(), isSpace)) return false;
    pos_ = close + 2;
  }
  return skipMisc();
}

bool XmlCursor::skipEpilog() { return skipMisc() && pos_ == text_.size(); }

bool XmlCursor::readName(std::string_view& name) {
  const std::size_t start = pos_;
  if (pos_ >= text_.size() || !isNameStart(text_[pos_])) return false;
  while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
  name = text_.substr(start, pos_ - start);
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ||
         (colon > 0 && colon + 1 < name.size() && name.find(':', colon + 1) == std::string_view::npos &&
          isNameStart(name[colon + 1]));
}

bool XmlCursor::readAttributes(XmlTag& tag) {
  for (;;) {
    const std::size_t before = pos_;
    while (pos_ < text_.size() && isSpace(text_[pos_])) ++pos_;
    if (pos_ >= text_.size()) return false;
    if (text_[pos_] == '>') {
      ++pos_;
      return true;
    }
    if (text_[pos_] == '/') {
      tag.selfClosing = true;
      return text_.compare(pos_, 2, "/>") == 0 && (pos_ += 2, true);
    }
    XmlAttribute a;
    if (pos_ == before || !readName(a.name)) return false;
    while (pos_ < text_.size() && isSpace(text_[pos_])) ++pos_;
    if (pos_ >= text_.size() || text_[pos_] != '=') return false;
    ++pos_;
    while (pos_ < text_.size() && isSpace(text_[pos_])) ++pos_;
    if (pos_ >= text_.size() || (text_[pos_] != '"' && text_[pos_] != '\'')) return false;
    const char quote = text_[pos_++];
    const std::size_t close = text_.find(quote, pos_);
    if (close == std::string_view::npos) return false;
    a.value = text_.substr(pos_, close - pos_);
    pos_ = close + 1;
    if (a.value.find('<') != std::string_view::npos) return false;  // not well-formed
    if (tag.attributes.size() >= kMaxAttributes) return false;  // keeps the check below cheap
    for (const XmlAttribute& other : tag.attributes)
      if (other.name == a.name) return false;
    tag.attributes.push_back(a);
  }
}

bool XmlCursor::readTag(XmlTag& tag) {
  if (!skipMisc() || pos_ >= text_.size() || text_[pos_] != '<') return false;
  tagStart_ = pos_++;
  tag.attributes.clear();
  tag.selfClosing = false;
  if (pos_ < text_.size() && text_[pos_] == '/') {
    ++pos_;
    tag.kind = XmlTag::End;
    if (!readName(tag.name)) return false;
    while (pos_ < text_.size() && isSpace(text_[pos_])) ++pos_;
    return pos_ < text_.size() && text_[pos_++] == '>';
  }
  tag.kind = XmlTag::Start;
  return readName(tag.name) && readAttributes(tag);
}

long long XmlCursor::lineOfTagStart() const {
  return 1 + std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(tagStart_), '\n');
}

bool parsePlainNumber(std::string_view text, double& value) {
  const char* p = text.data();
  const char* end = p + text.size();
  return !text.empty() && scanNumber(p, end, value) && p == end;
}

bool parseNumberList(std::string_view text, std::vector<double>& numbers) {
  const char* p = text.data();
  const char* end = p + text.size();
  return scanNumbers(p, end, numbers) && p == end;
}

bool buildQtPath(std::string_view d, QPainterPath& path) {
  thread_local std::vector<double> numbers;
  const char* p = d.data();
  const char* end = p + d.size();
  const bool countElements = static_cast<qsizetype>(d.size()) > kPathScanChars;
  long long elements = 0;  // the sanitiser's estimate; beyond kMaxPathElements it splits
  PathState s;
  bool first = true;
  for (;;) {
    skipSpaces(p, end);
    if (p == end) return true;
    const char op = *p++;
    const char lower = static_cast<char>(op | 0x20);
    if ((op < 'A' || op > 'Z') && (op < 'a' || op > 'z')) return false;
    if (first && lower != 'm') return false;
    first = false;
    numbers.clear();
    if (!scanNumbers(p, end, numbers)) return false;
    if (lower == 'z') {
      if (!numbers.empty()) return false;
      s.x = s.x0;
      s.y = s.y0;
      s.lastMode = op;
      path.closeSubpath();
      elements += 1;
      continue;
    }
    const int n = arity(lower);
    if (n == 0 || numbers.empty() || numbers.size() % static_cast<std::size_t>(n) != 0) return false;
    char command = op;
    for (std::size_t i = 0; i < numbers.size(); i += static_cast<std::size_t>(n)) {
      command = applyGroup(command, numbers.data() + i, s, path);
      elements += n >= 4 || lower == 't' ? 3 : 1;
    }
    if (countElements && elements > kMaxPathElements) return false;
  }
}

}  // namespace fivebar::svg
