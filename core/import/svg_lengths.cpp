// SPDX-License-Identifier: GPL-3.0-or-later
#include "svg_lengths.hpp"

#include <QSet>

#include <cmath>

#include "svg_units.hpp"

namespace fivebar::svg {

std::optional<double> resolveLength(QStringView text, LengthAxis axis, const LengthContext& context) {
  const std::optional<Length> length = parseLength(text);
  if (!length) return std::nullopt;
  const double w = context.viewport.width, h = context.viewport.height;
  switch (length->unit) {
    case LengthUnit::Percent: {
      const double reference = axis == LengthAxis::Width    ? w
                               : axis == LengthAxis::Height ? h
                                                            : std::sqrt(0.5 * (w * w + h * h));
      if (!(reference > 0.0)) return std::nullopt;
      return length->value / 100.0 * reference;
    }
    case LengthUnit::Em: return length->value * context.fontSizeUser;
    case LengthUnit::Ex: return length->value * context.fontSizeUser * 0.5;
    default: return *lengthToMm(*length, context.dpi) * context.dpi / 25.4;
  }
}

std::optional<LengthAxis> lengthAttributeAxis(QStringView tag, QStringView attribute) {
  static const QSet<QStringView> widthLike{u"x", u"cx", u"x1", u"x2", u"width", u"rx", u"refX",
                                           u"markerWidth", u"fx"};
  static const QSet<QStringView> heightLike{u"y", u"cy", u"y1", u"y2", u"height", u"ry", u"refY",
                                            u"markerHeight", u"fy"};
  static const QSet<QStringView> tags{u"rect", u"circle", u"ellipse", u"line", u"use", u"image",
                                      u"svg", u"symbol", u"marker", u"pattern"};
  if (!tags.contains(tag)) return std::nullopt;
  if (widthLike.contains(attribute)) return LengthAxis::Width;
  if (heightLike.contains(attribute)) return LengthAxis::Height;
  if (attribute == u"r") return LengthAxis::Diagonal;
  return std::nullopt;
}

bool hasLengthUnit(QStringView value) {
  const QStringView v = value.trimmed();
  return !v.isEmpty() && !v.back().isDigit() && v.back() != u'.';
}

// The value of a property in a style attribute ("a: b; c: d"), empty when absent.
QString styleValue(QStringView style, QStringView property) {
  QString found;
  for (QStringView decl : style.split(u';')) {
    const qsizetype colon = decl.indexOf(u':');
    if (colon < 0) continue;
    if (decl.left(colon).trimmed() == property) found = decl.mid(colon + 1).trimmed().toString();
  }
  return found;
}

}  // namespace fivebar::svg
