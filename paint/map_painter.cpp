// SPDX-License-Identifier: GPL-3.0-or-later
#include "paint/map_painter.hpp"

#include <QCoreApplication>
#include <QLinearGradient>
#include <QLocale>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "core/kinematics/units.hpp"
#include "paint/studio_palette.hpp"

namespace fivebar::paint {
namespace {

QString trMap(const char* text) { return QCoreApplication::translate("MapPainter", text); }

QColor lerp(const QColor& a, const QColor& b, double f) {
  return QColor::fromRgbF(static_cast<float>(a.redF() + (b.redF() - a.redF()) * f),
                          static_cast<float>(a.greenF() + (b.greenF() - a.greenF()) * f),
                          static_cast<float>(a.blueF() + (b.blueF() - a.blueF()) * f));
}

// Sequential ramp bad -> good: red, amber, yellow-green, green, teal.
QColor ramp(double t) {
  static const std::array<QColor, 5> stops{QColor(0xdc, 0x26, 0x26), QColor(0xf5, 0x9e, 0x0b),
                                           QColor(0xa3, 0xc9, 0x3a), QColor(0x16, 0xa3, 0x4a),
                                           QColor(0x0f, 0x76, 0x6e)};
  t = std::clamp(t, 0.0, 1.0) * (stops.size() - 1);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(t), stops.size() - 2);
  return lerp(stops[i], stops[i + 1], t - static_cast<double>(i));
}

// The value at a quantile of the finite values of a field.
double quantile(std::vector<float> values, double q) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

double mapValue(const WorkspaceMap& map, MapKind kind, std::size_t i) {
  if (!map.reachable[i]) return std::numeric_limits<double>::quiet_NaN();
  switch (kind) {
    case MapKind::Transmission: return degFromRad(map.muRad[i]);
    case MapKind::Conditioning: return map.inverseCondition[i];
    case MapKind::Resolution: return map.resolutionMm[i] * 1000.0;  // micrometres per step
    case MapKind::None: break;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

MapScale mapScale(const WorkspaceMap& map, MapKind kind) {
  MapScale s;
  switch (kind) {
    case MapKind::Transmission:
      s = {0.0, 180.0, true, false,
           trMap(QT_TRANSLATE_NOOP("MapPainter", "Transmission angle at the pen (deg)")), 0};
      break;
    case MapKind::Conditioning:
      s = {0.0, 1.0, false, false,
           trMap(QT_TRANSLATE_NOOP("MapPainter", "Conditioning (1 = isotropic)")), 2};
      break;
    case MapKind::Resolution: {
      std::vector<float> values;
      for (std::size_t i = 0; i < map.grid.size(); ++i) {
        const double v = mapValue(map, kind, i);
        if (std::isfinite(v)) values.push_back(static_cast<float>(v));
      }
      // Quantiles keep the near-singular extremes from flattening the useful range.
      s = {quantile(values, 0.02), quantile(values, 0.9), false, true,
           trMap(QT_TRANSLATE_NOOP("MapPainter", "Resolution (um per motor step)")), 1};
      if (s.high <= s.low) s.high = s.low + 1.0;
      break;
    }
    case MapKind::None: break;
  }
  return s;
}

QColor mapColour(const MapScale& scale, double value) {
  double t = (value - scale.low) / (scale.high - scale.low);
  t = std::clamp(t, 0.0, 1.0);
  if (scale.diverging) return ramp(1.0 - std::abs(2.0 * t - 1.0));
  return ramp(scale.reversed ? 1.0 - t : t);
}

QImage mapImage(const WorkspaceMap& map, MapKind kind, const MapScale& scale, int alpha) {
  const GridSpec& g = map.grid;
  QImage image(g.nx, g.ny, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::transparent);
  for (int iy = 0; iy < g.ny; ++iy) {
    auto* row = reinterpret_cast<QRgb*>(image.scanLine(g.ny - 1 - iy));
    for (int ix = 0; ix < g.nx; ++ix) {
      const double v = mapValue(map, kind, g.index(ix, iy));
      if (!std::isfinite(v)) continue;
      QColor c = mapColour(scale, v);
      c.setAlpha(alpha);
      row[ix] = qPremultiply(c.rgba());
    }
  }
  return image;
}

void paintMapImage(QPainter& painter, const QTransform& widgetFromMachine,
                   const WorkspaceMap& map, const QImage& image) {
  const GridSpec& g = map.grid;
  const QTransform machineFromImage(g.cellMm, 0.0, 0.0, -g.cellMm, g.x0, g.y0 + g.ny * g.cellMm);
  painter.save();
  painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
  painter.setTransform(machineFromImage * widgetFromMachine, true);
  painter.drawImage(QPointF(0.0, 0.0), image);
  painter.restore();
}

void paintColourBar(QPainter& painter, const QRectF& rectPx, const MapScale& scale) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setPen(QPen(palette::gridMajor(), 1.0));
  painter.setBrush(QColor(255, 255, 255, 235));
  painter.drawRoundedRect(rectPx, 6.0, 6.0);
  QFont font = painter.font();
  font.setPointSizeF(8.5);
  painter.setFont(font);
  const QRectF inner = rectPx.adjusted(10.0, 6.0, -10.0, -6.0);
  painter.setPen(palette::machineBase());
  painter.drawText(QRectF(inner.left(), inner.top(), inner.width(), 16.0),
                   Qt::AlignLeft | Qt::AlignVCenter, scale.title);
  const QRectF bar(inner.left(), inner.top() + 20.0, inner.width(), 12.0);
  QLinearGradient gradient(bar.topLeft(), bar.topRight());
  constexpr int kStops = 16;
  for (int k = 0; k <= kStops; ++k) {
    const double f = static_cast<double>(k) / kStops;
    gradient.setColorAt(f, mapColour(scale, scale.low + f * (scale.high - scale.low)));
  }
  painter.setPen(Qt::NoPen);
  painter.setBrush(gradient);
  painter.drawRect(bar);
  painter.setPen(palette::gridLabel());
  constexpr int kTicks = 4;
  for (int k = 0; k <= kTicks; ++k) {
    const double f = static_cast<double>(k) / kTicks;
    const double x = bar.left() + f * bar.width();
    painter.drawLine(QPointF(x, bar.bottom()), QPointF(x, bar.bottom() + 3.0));
    const QString label =
        QLocale().toString(scale.low + f * (scale.high - scale.low), 'f', scale.decimals);
    const Qt::Alignment align = k == 0 ? Qt::AlignLeft : (k == kTicks ? Qt::AlignRight
                                                                       : Qt::AlignHCenter);
    const double w = 60.0;
    const double left = k == 0 ? x : (k == kTicks ? x - w : x - w / 2.0);
    painter.drawText(QRectF(left, bar.bottom() + 3.0, w, 14.0), align | Qt::AlignTop, label);
  }
  painter.restore();
}

}  // namespace fivebar::paint
