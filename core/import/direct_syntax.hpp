// SPDX-License-Identifier: GPL-3.0-or-later
// Syntax pieces of the direct reader (fast_import.hpp), on 8-bit text: a strict scanner for the
// XML subset, and SVG numbers and path data read exactly as Qt SVG 6 reads them. Every function
// returns false when the text leaves the subset; the caller then declines the document.
#pragma once

#include <QPainterPath>

#include <cstddef>
#include <string_view>
#include <vector>

namespace fivebar::svg {

// True when every byte is printable ASCII, tab, CR or LF, and there is no '&' (no entity or
// character references to expand).
bool asciiWithoutReferences(std::string_view text);

struct XmlAttribute {
  std::string_view name;   // qualified name as written (prefix:local)
  std::string_view value;  // raw value: no references by the subset's rules, but tab/CR/LF are
                           // not yet normalised to spaces as an XML reader would
};

struct XmlTag {
  enum Kind { Start, End } kind = Start;
  std::string_view name;
  std::vector<XmlAttribute> attributes;  // start tags only; names are unique
  bool selfClosing = false;
};

// Walks the document tag by tag. Between tags only whitespace and comments are allowed.
class XmlCursor {
 public:
  explicit XmlCursor(std::string_view text) : text_(text) {}
  // An optional <?xml version="1.0" ...?> declaration, then whitespace and comments.
  bool skipProlog();
  // The next start or end tag (after whitespace and comments).
  bool readTag(XmlTag& tag);
  // Whitespace and comments up to the end of the text.
  bool skipEpilog();
  std::size_t position() const { return pos_; }
  long long lineOfTagStart() const;  // 1-based line of the last tag read

 private:
  bool skipMisc();
  bool readName(std::string_view& name);
  bool readAttributes(XmlTag& tag);

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t tagStart_ = 0;
};

// A plain number ("12", "-0.5", "1e-3"; no unit) with nothing around it.
bool parsePlainNumber(std::string_view text, double& value);

// A list of numbers separated by whitespace and/or one comma (polyline/polygon points).
bool parseNumberList(std::string_view text, std::vector<double>& numbers);

// Path data with commands M L H V C S Q T Z (either case): the QPainterPath Qt SVG builds for
// it. False for arcs, malformed data, or data long enough to be split by the sanitiser.
bool buildQtPath(std::string_view d, QPainterPath& path);

}  // namespace fivebar::svg
