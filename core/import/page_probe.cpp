// SPDX-License-Identifier: GPL-3.0-or-later
#include "page_probe.hpp"

#include <QPaintDevice>
#include <QPaintEngine>
#include <QPainter>
#include <QSvgRenderer>

namespace fivebar::svg {
namespace {

// Records the combined transform of the first path Qt SVG draws (the viewport probe).
class ProbeEngine final : public QPaintEngine {
 public:
  ProbeEngine() : QPaintEngine(QPaintEngine::AllFeatures) {}
  bool begin(QPaintDevice*) override { return true; }
  bool end() override { return true; }
  void updateState(const QPaintEngineState&) override {}
  Type type() const override { return QPaintEngine::User; }
  void drawPath(const QPainterPath&) override {
    if (!seen) transform = painter()->combinedTransform();
    seen = true;
  }
  void drawPolygon(const QPointF*, int, PolygonDrawMode) override {}
  void drawPixmap(const QRectF&, const QPixmap&, const QRectF&) override {}
  bool seen = false;
  QTransform transform;
};

class ProbeDevice final : public QPaintDevice {
 public:
  QPaintEngine* paintEngine() const override { return &engine; }
  int metric(PaintDeviceMetric m) const override {
    switch (m) {
      case PdmDpiX: case PdmDpiY: case PdmPhysicalDpiX: case PdmPhysicalDpiY: return 96;
      case PdmDevicePixelRatio: return 1;
      case PdmDevicePixelRatioScaled: return static_cast<int>(devicePixelRatioFScale());
      case PdmDepth: return 32;
      default: return 1000;
    }
  }
  mutable ProbeEngine engine;
};

}  // namespace

bool probePageTransform(const RootAttributes& root, const PageSetup& page, QTransform& out) {
  QByteArray doc = "<svg xmlns=\"http://www.w3.org/2000/svg\"";
  auto attribute = [&](bool present, const char* name, const QString& value) {
    if (present) doc += QByteArray(" ") + name + "=\"" + value.toLatin1() + "\"";
  };
  attribute(root.hasWidth, "width", root.width);
  attribute(root.hasHeight, "height", root.height);
  attribute(root.hasViewBox, "viewBox", root.viewBox);
  attribute(!root.preserveAspectRatio.isEmpty(), "preserveAspectRatio", root.preserveAspectRatio);
  doc += "><path d=\"M0 0L1 1\" stroke=\"#000000\"/></svg>";
  QSvgRenderer renderer;
  if (!renderer.load(doc)) return false;
  renderer.setViewBox(page.viewBoxUser);
  ProbeDevice device;
  QPainter painter(&device);
  renderer.render(&painter, page.targetMm);
  painter.end();
  out = device.engine.transform;
  return device.engine.seen;
}

}  // namespace fivebar::svg
