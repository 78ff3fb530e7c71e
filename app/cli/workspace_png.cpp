// SPDX-License-Identifier: GPL-3.0-or-later
#include "workspace_png.hpp"

#include <QGuiApplication>
#include <clocale>
#include <QImage>
#include <QPainter>
#include <memory>
#include <optional>

#include "core/kinematics/kinematics.hpp"
#include "paint/machine_painter.hpp"
#include "paint/studio_palette.hpp"
#include "paint/view_transform.hpp"
#include "paint/workspace_painter.hpp"

namespace fivebar::cli {
namespace {

constexpr int kWidthPx = 1600;
constexpr int kHeightPx = 1000;
constexpr double kTitlePx = 56.0;   // title band at the top
constexpr double kPanelPx = 470.0;  // legend panel on the right
constexpr double kMarginPx = 40.0;

// Text needs fonts, and fonts need a QGuiApplication: make one (offscreen) if there is none.
std::unique_ptr<QGuiApplication> ensureGuiApplication() {
  if (QCoreApplication::instance()) return nullptr;
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  static int argc = 1;
  static char name[] = "fivebar";
  static char* argv[] = {name, nullptr};
  auto app = std::make_unique<QGuiApplication>(argc, argv);
  std::setlocale(LC_NUMERIC, "C");  // Qt took the environment's; CLI output keeps the point
  return app;
}

// A pose of the analysed mode to draw: at the rectangle's centre, else the profile's home.
std::optional<Pose> displayPose(const MachineProfile& p, const WorkspaceAnalysis& a) {
  if (a.largestRectangle) {
    const Rect& r = *a.largestRectangle;
    const Vec2 centre(0.5 * (r.xMin + r.xMax), 0.5 * (r.yMin + r.yMax));
    const IkResult ik = inverse(p.geometry, centre, a.mode);
    if (ik.ok()) return makePose(p.geometry, ik.angles, centre);
  }
  const FkResult fk = forward(p.geometry, p.homeAngles, p.assembly);
  if (fk.ok()) return makePose(p.geometry, p.homeAngles, fk.p);
  return std::nullopt;
}

// The machine-frame box to show: the reachable cells, the motors and the drawn pose.
QRectF contentBoxMm(const Geometry& g, const WorkspaceMap& map, const std::optional<Pose>& pose) {
  const GridSpec& grid = map.grid;
  double x0 = -0.5 * g.w, x1 = 0.5 * g.w, y0 = -0.1 * (g.a1 + g.a2), y1 = 0.0;
  if (pose) {
    for (const Vec2& q : {pose->R1, pose->R2, pose->P}) {
      x0 = std::min(x0, q.x() - 5.0);
      x1 = std::max(x1, q.x() + 5.0);
      y0 = std::min(y0, q.y() - 5.0);
      y1 = std::max(y1, q.y() + 5.0);
    }
  }
  for (int iy = 0; iy < grid.ny; ++iy)
    for (int ix = 0; ix < grid.nx; ++ix) {
      if (!map.reachable[grid.index(ix, iy)]) continue;
      x0 = std::min(x0, grid.x0 + ix * grid.cellMm);
      x1 = std::max(x1, grid.x0 + (ix + 1) * grid.cellMm);
      y1 = std::max(y1, grid.y0 + (iy + 1) * grid.cellMm);
    }
  return QRectF(QPointF(x0, y0), QPointF(x1, y1));
}

// The view placing `box` in the plot area (left of the legend panel, below the title).
paint::ViewTransform fitView(const QRectF& box) {
  const QRectF plot(kMarginPx, kTitlePx + kMarginPx, kWidthPx - kPanelPx - 2 * kMarginPx,
                    kHeightPx - kTitlePx - 2 * kMarginPx);
  const double s = std::min(plot.width() / box.width(), plot.height() / box.height());
  // The view centres on the image; shift its centre so that the box centres on the plot area.
  const QPointF shiftPx = QPointF(0.5 * kWidthPx, 0.5 * kHeightPx) - plot.center();
  const QPointF centreMm = box.center() + QPointF(shiftPx.x() / s, -shiftPx.y() / s);
  return paint::ViewTransform(centreMm, s, QSizeF(kWidthPx, kHeightPx));
}

void paintTitle(QPainter& painter, const MachineProfile& p, const WorkspaceAnalysis& a) {
  const Geometry& g = p.geometry;
  painter.fillRect(QRectF(0, 0, kWidthPx, kTitlePx), QColor(255, 255, 255, 230));
  QFont font = painter.font();
  font.setPointSizeF(15.0);
  font.setBold(true);
  painter.setFont(font);
  painter.setPen(paint::palette::machineBase());
  const QString title = QStringLiteral("%1  \u2014  working mode %2")
                            .arg(QString::fromStdString(p.name), QString::fromUtf8(toString(a.mode).data(), 2));
  painter.drawText(QRectF(20, 0, kWidthPx - 40, kTitlePx), Qt::AlignVCenter | Qt::AlignLeft, title);
  font.setPointSizeF(10.0);
  font.setBold(false);
  painter.setFont(font);
  const QString dims = QStringLiteral("a1 = %1, b1 = %2, a2 = %3, b2 = %4, w = %5 mm")
                           .arg(g.a1).arg(g.b1).arg(g.a2).arg(g.b2).arg(g.w);
  painter.drawText(QRectF(20, 0, kWidthPx - 40, kTitlePx), Qt::AlignVCenter | Qt::AlignRight, dims);
}

}  // namespace

std::string writeWorkspacePng(const std::string& path, const MachineProfile& profile,
                              const WorkspaceMap& map, const WorkspaceAnalysis& analysis) {
  const auto app = ensureGuiApplication();
  QImage image(kWidthPx, kHeightPx, QImage::Format_ARGB32_Premultiplied);
  const std::optional<Pose> pose = displayPose(profile, analysis);
  const paint::ViewTransform view = fitView(contentBoxMm(profile.geometry, map, pose));
  const QTransform widgetFromMachine = view.widgetFromMachine();
  {
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    paint::paintGrid(painter, view);
    paint::paintWorkspace(painter, widgetFromMachine, map, analysis);
    if (pose) paint::paintMachine(painter, widgetFromMachine, profile.geometry, *pose, 0.85);
    paintTitle(painter, profile, analysis);
    paint::paintWorkspaceLegend(painter, QPointF(kWidthPx - kPanelPx + 10.0, kTitlePx + kMarginPx),
                                  map, analysis);
    paint::paintScaleBar(painter, widgetFromMachine,
                           QPointF(kWidthPx - kPanelPx + 20.0, kHeightPx - kMarginPx));
  }
  if (!image.save(QString::fromStdString(path), "PNG")) return "cannot write PNG " + path;
  return {};
}

}  // namespace fivebar::cli
