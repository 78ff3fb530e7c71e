// SPDX-License-Identifier: GPL-3.0-or-later
#include "svg_units.hpp"

#include <QList>
#include <QRegularExpression>

#include <cmath>

namespace fivebar::svg {
namespace {

constexpr double kMmPerInch = 25.4;
constexpr double kPxPerEm = 16.0;  // CSS initial font-size
constexpr double kPxPerEx = 8.0;

std::optional<LengthUnit> unitFromSuffix(QStringView suffix) {
  const QString s = suffix.toString().trimmed().toLower();
  if (s.isEmpty()) return LengthUnit::None;
  if (s == u"px") return LengthUnit::Px;
  if (s == u"mm") return LengthUnit::Mm;
  if (s == u"cm") return LengthUnit::Cm;
  if (s == u"q") return LengthUnit::Q;
  if (s == u"in") return LengthUnit::In;
  if (s == u"pt") return LengthUnit::Pt;
  if (s == u"pc") return LengthUnit::Pc;
  if (s == u"em") return LengthUnit::Em;
  if (s == u"ex") return LengthUnit::Ex;
  if (s == u"%") return LengthUnit::Percent;
  return std::nullopt;
}

double alignOffset(Align align, double free) {
  switch (align) {
    case Align::Min: return 0.0;
    case Align::Mid: return 0.5 * free;
    case Align::Max: return free;
    case Align::None: return 0.0;
  }
  return 0.0;
}

}  // namespace

std::optional<Length> parseLength(QStringView text) {
  const QString t = text.toString().trimmed();
  static const QRegularExpression number(
      QStringLiteral("^([+-]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][+-]?\\d+)?)\\s*(.*)$"));
  const QRegularExpressionMatch m = number.match(t);
  if (!m.hasMatch()) return std::nullopt;
  bool ok = false;
  const double value = m.captured(1).toDouble(&ok);
  if (!ok || !std::isfinite(value)) return std::nullopt;
  const std::optional<LengthUnit> unit = unitFromSuffix(m.capturedView(2));
  if (!unit) return std::nullopt;
  return Length{value, *unit};
}

std::optional<double> lengthToMm(const Length& length, double dpi) {
  const double mmPerPx = kMmPerInch / dpi;
  switch (length.unit) {
    case LengthUnit::None:
    case LengthUnit::Px: return length.value * mmPerPx;
    case LengthUnit::Mm: return length.value;
    case LengthUnit::Cm: return length.value * 10.0;
    case LengthUnit::Q: return length.value * 0.25;
    case LengthUnit::In: return length.value * kMmPerInch;
    case LengthUnit::Pt: return length.value * kMmPerInch / 72.0;
    case LengthUnit::Pc: return length.value * kMmPerInch / 6.0;
    case LengthUnit::Em: return length.value * kPxPerEm * mmPerPx;
    case LengthUnit::Ex: return length.value * kPxPerEx * mmPerPx;
    case LengthUnit::Percent: return std::nullopt;
  }
  return std::nullopt;
}

NumberList scanNumberList(QStringView text) {
  NumberList out;
  const qsizetype n = text.size();
  qsizetype i = 0;
  auto digits = [&](qsizetype& k) {
    const qsizetype start = k;
    while (k < n && text[k].isDigit()) ++k;
    return k > start;
  };
  bool comma = false;  // one comma between numbers at most
  for (;;) {
    while (i < n && text[i].isSpace()) ++i;
    if (i < n && text[i] == u',' && !comma && !out.tokens.isEmpty()) {
      comma = true;
      ++i;
      continue;
    }
    if (i >= n) {
      if (comma) out.badAt = i;  // a trailing comma
      return out;
    }
    qsizetype k = i;
    if (text[k] == u'+' || text[k] == u'-') ++k;
    const bool whole = digits(k);
    bool fraction = false;
    if (k < n && text[k] == u'.') {
      qsizetype f = k + 1;
      fraction = digits(f);
      if (fraction || whole) k = f;
    }
    if (!whole && !fraction) {
      out.badAt = i;
      return out;
    }
    if (k < n && (text[k] == u'e' || text[k] == u'E')) {
      qsizetype e = k + 1;
      if (e < n && (text[e] == u'+' || text[e] == u'-')) ++e;
      if (digits(e)) k = e;
    }
    out.tokens.push_back(text.mid(i, k - i).toString());
    comma = false;
    i = k;
  }
}

std::optional<QRectF> parseViewBox(QStringView text) {
  const NumberList list = scanNumberList(text);
  if (list.badAt >= 0 || list.tokens.size() != 4) return std::nullopt;
  double v[4];
  for (int i = 0; i < 4; ++i) {
    bool ok = false;
    v[i] = list.tokens[i].toDouble(&ok);
    if (!ok || !std::isfinite(v[i])) return std::nullopt;
  }
  return QRectF(v[0], v[1], v[2], v[3]);
}

std::string viewBoxProblem(QStringView text) {
  const NumberList list = scanNumberList(text);
  if (list.badAt >= 0)
    return QStringLiteral("\"%1\" is not a number (after %2 numbers)")
        .arg(text.mid(list.badAt, 16).toString().simplified())
        .arg(list.tokens.size())
        .toStdString();
  if (list.tokens.size() != 4)
    return "not four numbers (" + std::to_string(list.tokens.size()) + " numbers)";
  double v[4];
  for (int i = 0; i < 4; ++i) {
    bool ok = false;
    v[i] = list.tokens[i].toDouble(&ok);
    if (!ok || !std::isfinite(v[i])) return "a number beyond 1e300 (" + list.tokens[i].toStdString() + ")";
    if (std::abs(v[i]) > kMaxViewBoxNumber)
      return "a number too large (" + list.tokens[i].toStdString() + "; at most 1e12)";
  }
  if (v[2] <= 0.0 || v[3] <= 0.0) return "width and height must be positive";
  return {};
}

AspectRatio parsePreserveAspectRatio(QStringView text) {
  AspectRatio ratio;
  const QStringList parts = text.toString().simplified().split(u' ', Qt::SkipEmptyParts);
  for (const QString& part : parts) {
    if (part == u"defer") continue;
    if (part == u"none") {
      ratio.alignX = ratio.alignY = Align::None;
    } else if (part == u"meet") {
      ratio.slice = false;
    } else if (part == u"slice") {
      ratio.slice = true;
    } else if (part.size() == 8 && part.startsWith(u'x')) {
      auto axis = [](QStringView s) {
        if (s == u"Min") return Align::Min;
        if (s == u"Max") return Align::Max;
        return Align::Mid;
      };
      ratio.alignX = axis(QStringView(part).mid(1, 3));
      ratio.alignY = axis(QStringView(part).mid(5, 3));
    }
  }
  return ratio;
}

QRectF placeViewBox(const QRectF& viewBox, const QRectF& viewport, const AspectRatio& ratio) {
  if (ratio.alignX == Align::None || ratio.alignY == Align::None) return viewport;
  const double sx = viewport.width() / viewBox.width();
  const double sy = viewport.height() / viewBox.height();
  const double s = ratio.slice ? std::max(sx, sy) : std::min(sx, sy);
  const double w = viewBox.width() * s;
  const double h = viewBox.height() * s;
  return QRectF(viewport.x() + alignOffset(ratio.alignX, viewport.width() - w),
                viewport.y() + alignOffset(ratio.alignY, viewport.height() - h), w, h);
}

namespace {

// One side of the viewport: mm when given in absolute units, nullopt when missing or percent.
// Sets error for unparsable, zero or negative values.
std::optional<double> sideMm(bool present, const QString& text, const char* name, double dpi,
                             Message& error) {
  if (!present) return std::nullopt;
  const std::optional<Length> length = parseLength(text);
  if (!length) {
    error = FB_TR("ImportError", "root <svg> %1=\"%2\" is not a length").arg(name).arg(text.toStdString());
    return std::nullopt;
  }
  if (length->value <= 0.0) {
    error = FB_TR("ImportError", "root <svg> %1=\"%2\" is zero or negative: nothing to draw")
                .arg(name)
                .arg(text.toStdString());
    return std::nullopt;
  }
  return lengthToMm(*length, dpi);
}

}  // namespace

Message computePage(const RootAttributes& root, double dpi, PageSetup& page) {
  Message error;
  std::optional<double> w = sideMm(root.hasWidth, root.width, "width", dpi, error);
  if (!error.empty()) return error;
  std::optional<double> h = sideMm(root.hasHeight, root.height, "height", dpi, error);
  if (!error.empty()) return error;
  std::optional<QRectF> vb;
  if (root.hasViewBox) {
    const std::string problem = viewBoxProblem(root.viewBox);
    if (!problem.empty())
      return FB_TR("ImportError", "root <svg> viewBox=\"%1\": %2").arg(root.viewBox.toStdString()).arg(problem);
    vb = parseViewBox(root.viewBox);
  }
  const double mmPerUser = 25.4 / dpi;
  if (vb) {
    const double aspect = vb->height() / vb->width();
    if (w && !h) h = *w * aspect;
    if (h && !w) w = *h / aspect;
    if (!w) w = vb->width() * mmPerUser;
    if (!h) h = vb->height() * mmPerUser;
    page.sizeKnown = true;
    page.widthMm = *w;
    page.heightMm = *h;
    page.viewBoxUser = *vb;
    page.targetMm = placeViewBox(*vb, QRectF(0, 0, *w, *h),
                                 parsePreserveAspectRatio(root.preserveAspectRatio));
    return {};
  }
  // No viewBox: one user unit is one px (1/dpi inch), user (0,0) at the page's top-left.
  page.sizeKnown = w && h;
  page.widthMm = w.value_or(0.0);
  page.heightMm = h.value_or(0.0);
  const double refWidthMm = w.value_or(1000.0);  // any scale-preserving rectangle will do
  const double refHeightMm = h.value_or(1000.0);
  page.viewBoxUser = QRectF(0, 0, refWidthMm / mmPerUser, refHeightMm / mmPerUser);
  page.targetMm = QRectF(0, 0, refWidthMm, refHeightMm);
  return {};
}

namespace {

// A nested viewport length in the parent's user units; percent of `reference` (user units).
std::optional<double> userLength(const QString& text, double reference, double dpi) {
  const std::optional<Length> length = parseLength(text);
  if (!length) return std::nullopt;
  if (length->unit == LengthUnit::Percent)
    return reference > 0.0 ? std::optional<double>(length->value / 100.0 * reference) : std::nullopt;
  return lengthToMm(*length, dpi).value() * dpi / 25.4;
}

}  // namespace

QString nestedViewportTransform(const NestedViewport& nested, double parentWidth, double parentHeight,
                                double dpi, QSizeF* viewport) {
  const double refW = parentWidth, refH = parentHeight;
  const double x = userLength(nested.x, refW, dpi).value_or(0.0);
  const double y = userLength(nested.y, refH, dpi).value_or(0.0);
  const std::optional<QRectF> box = parseViewBox(nested.viewBox);
  auto num = [](double v) { return QString::number(v, 'g', 17); };
  const double w = userLength(nested.width.isEmpty() ? QStringLiteral("100%") : nested.width, refW, dpi)
                       .value_or(box ? box->width() : refW);
  const double h = userLength(nested.height.isEmpty() ? QStringLiteral("100%") : nested.height, refH, dpi)
                       .value_or(box ? box->height() : refH);
  if (!box || box->width() <= 0.0 || box->height() <= 0.0) {
    if (viewport) *viewport = QSizeF(w, h);
    return QStringLiteral("translate(%1,%2)").arg(num(x), num(y));
  }
  if (viewport) *viewport = box->size();
  const QRectF place = placeViewBox(*box, QRectF(0, 0, w, h),
                                    parsePreserveAspectRatio(nested.preserveAspectRatio));
  return QStringLiteral("translate(%1,%2) scale(%3,%4) translate(%5,%6)")
      .arg(num(x + place.x()), num(y + place.y()), num(place.width() / box->width()),
           num(place.height() / box->height()), num(-box->x()), num(-box->y()));
}

QTransform nestedViewportMatrix(const NestedViewport& nested, double parentWidth, double parentHeight,
                                double dpi) {
  const double x = userLength(nested.x, parentWidth, dpi).value_or(0.0);
  const double y = userLength(nested.y, parentHeight, dpi).value_or(0.0);
  const std::optional<QRectF> box = parseViewBox(nested.viewBox);
  if (!box || box->width() <= 0.0 || box->height() <= 0.0) return QTransform::fromTranslate(x, y);
  const double w = userLength(nested.width.isEmpty() ? QStringLiteral("100%") : nested.width, parentWidth, dpi)
                       .value_or(box->width());
  const double h = userLength(nested.height.isEmpty() ? QStringLiteral("100%") : nested.height, parentHeight, dpi)
                       .value_or(box->height());
  const QRectF place = placeViewBox(*box, QRectF(0, 0, w, h), parsePreserveAspectRatio(nested.preserveAspectRatio));
  const double sx = place.width() / box->width(), sy = place.height() / box->height();
  return QTransform(sx, 0, 0, sy, x + place.x() - box->x() * sx, y + place.y() - box->y() * sy);
}

}  // namespace fivebar::svg
