// SPDX-License-Identifier: GPL-3.0-or-later
// PathScene and SceneRenderer: level of detail, culling, colour classes, drawing-order limits
// and the offscreen cache, checked on pixels and counters.
#include <gtest/gtest.h>

#include <QImage>
#include <QPainter>
#include <cmath>
#include <random>

#include "test_support.hpp"
#include "widgets/canvas/path_scene.hpp"
#include "widgets/canvas/scene_renderer.hpp"
#include "paint/studio_palette.hpp"

namespace fivebar::widgets {
namespace {

QImage transparentImage(QSize size) {
  QImage image(size, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::transparent);
  return image;
}

int paintedPixels(const QImage& image, const QRect& area) {
  int n = 0;
  for (int y = area.top(); y <= area.bottom(); ++y)
    for (int x = area.left(); x <= area.right(); ++x) n += qAlpha(image.pixel(x, y)) > 0;
  return n;
}

// A dense spiral: many short segments, as a planned job has.
ScenePath spiral(int points, double radiusMm) {
  ScenePath p;
  for (int i = 0; i < points; ++i) {
    const double t = 60.0 * M_PI * i / points;
    const double r = radiusMm * (0.1 + 0.9 * i / points);
    p.pointsMm.emplace_back(r * std::cos(t), 150.0 + r * std::sin(t));
    if (i > 0) p.speedsMmPerS.push_back(static_cast<float>(10.0 + 30.0 * i / points));
  }
  return p;
}

TEST(PathScene, LevelsOfDetailShrinkAndAreChosenByZoom) {
  const PathScene scene({spiral(200000, 80.0)});
  ASSERT_GE(scene.levelCount(), 3);
  EXPECT_EQ(scene.segmentCount(0), 199999u);
  for (int l = 1; l < scene.levelCount(); ++l) {
    EXPECT_LT(scene.segmentCount(l), scene.segmentCount(l - 1));
  }
  EXPECT_EQ(scene.levelFor(1000.0), 0);          // zoomed far in: every segment
  EXPECT_GT(scene.levelFor(1.0), 0);             // 1 px per mm: merged below half a pixel
  EXPECT_GE(scene.levelFor(0.1), scene.levelFor(1.0));
  EXPECT_NEAR(scene.maxSpeedMmPerS(), 40.0, 1e-3);
}

// The flat list the planning pipeline fills (no allocation per path) makes the same scene as
// one ScenePath per path; a scene of two-point paths has nothing to simplify: one level.
TEST(PathScene, FlatListMakesTheSameScene) {
  std::mt19937_64 rng(test::seed());
  std::uniform_real_distribution<double> x(-80.0, 80.0), y(100.0, 220.0), v(5.0, 60.0);
  std::vector<ScenePath> paths;
  ScenePathList list;
  for (int i = 0; i < 3000; ++i) {
    ScenePath p;
    p.kind = i % 3 == 0 ? PathKind::Travel : PathKind::Draw;
    p.flagged = i % 7 == 0;
    p.firstOrder = 2 * i;
    p.pointsMm = {QPointF(x(rng), y(rng)), QPointF(x(rng), y(rng)), QPointF(x(rng), y(rng))};
    p.speedsMmPerS = {static_cast<float>(v(rng)), static_cast<float>(v(rng))};
    list.beginPath(p.kind, p.flagged, p.firstOrder);
    for (int k = 0; k < 3; ++k) list.addPoint(p.pointsMm[k], k < 2 ? p.speedsMmPerS[k] : 0.0f);
    paths.push_back(p);
  }
  const PathScene fromPaths(paths), fromList(list);
  ASSERT_EQ(fromList.levelCount(), fromPaths.levelCount());
  for (int l = 0; l < fromList.levelCount(); ++l)
    EXPECT_EQ(fromList.segmentCount(l), fromPaths.segmentCount(l));
  EXPECT_EQ(fromList.maxSpeedMmPerS(), fromPaths.maxSpeedMmPerS());
  const paint::ViewTransform view(QPointF(0.0, 160.0), 2.5, QSizeF(400.0, 300.0));
  QImage a = transparentImage(QSize(400, 300)), b = transparentImage(QSize(400, 300));
  ScenePaintOptions o;
  o.colourBySpeed = true;
  {
    QPainter pa(&a), pb(&b);
    fromPaths.paint(pa, view, o);
    fromList.paint(pb, view, o);
  }
  EXPECT_EQ(a, b);
  EXPECT_GT(paintedPixels(a, a.rect()), 1000);
  ScenePathList lines;
  for (int i = 0; i < 100; ++i) {
    lines.beginPath(PathKind::Draw, false, i);
    lines.addPoint(QPointF(i, 100.0));
    lines.addPoint(QPointF(i + 0.5, 110.0));
  }
  EXPECT_EQ(PathScene(lines).levelCount(), 1);
}

TEST(PathScene, PaintsWhereThePathIsAndNowhereElse) {
  ScenePath line;
  line.pointsMm = {QPointF(-50.0, 100.0), QPointF(50.0, 100.0)};
  const PathScene scene({line});
  const paint::ViewTransform view(QPointF(0.0, 100.0), 2.0, QSizeF(400.0, 300.0));
  QImage image = transparentImage(QSize(400, 300));
  {
    QPainter painter(&image);
    scene.paint(painter, view, ScenePaintOptions{});
  }
  // The line y = 100 mm is the widget row 150, x from 100 to 300 px.
  EXPECT_GT(paintedPixels(image, QRect(110, 149, 180, 3)), 170);
  EXPECT_EQ(paintedPixels(image, QRect(0, 0, 400, 140)), 0);
  EXPECT_EQ(paintedPixels(image, QRect(310, 140, 90, 20)), 0);
}

TEST(PathScene, OrderLimitAndClassesSelectSegments) {
  ScenePath draw;
  // An L: along y = 100 mm, then down x = 0 (a corner no level of detail merges away).
  draw.pointsMm = {QPointF(-50.0, 100.0), QPointF(0.0, 100.0), QPointF(0.0, 60.0)};
  draw.firstOrder = 0;
  ScenePath travel;
  travel.kind = PathKind::Travel;
  travel.pointsMm = {QPointF(50.0, 100.0), QPointF(50.0, 130.0)};
  travel.firstOrder = 2;
  ScenePath flagged;
  flagged.flagged = true;
  flagged.pointsMm = {QPointF(-50.0, 80.0), QPointF(50.0, 80.0)};
  flagged.firstOrder = 3;
  const PathScene scene({draw, travel, flagged});
  EXPECT_EQ(scene.orderCount(), 4);
  const paint::ViewTransform view(QPointF(0.0, 100.0), 2.0, QSizeF(400.0, 300.0));
  const auto render = [&](const ScenePaintOptions& o) {
    QImage image = transparentImage(QSize(400, 300));
    QPainter painter(&image);
    scene.paint(painter, view, o);
    painter.end();
    return image;
  };
  ScenePaintOptions first;
  first.orderLimit = 1;  // only the first segment (x from -50 to 0 mm)
  QImage a = render(first);
  EXPECT_GT(paintedPixels(a, QRect(105, 149, 90, 3)), 80);
  EXPECT_EQ(paintedPixels(a, QRect(195, 160, 10, 60)), 0);
  QImage all = render(ScenePaintOptions{});
  EXPECT_GT(paintedPixels(all, QRect(195, 160, 10, 60)), 50);
  ScenePaintOptions noTravel;
  noTravel.showTravel = false;
  QImage b = render(noTravel);
  EXPECT_EQ(paintedPixels(b, QRect(299, 95, 3, 50)), 0);  // travel at x = 50 mm hidden
  QImage c = render(ScenePaintOptions{});
  EXPECT_GT(paintedPixels(c, QRect(299, 95, 3, 50)), 40);
  // The flagged path is red.
  const QColor red = c.pixelColor(150, 190);
  EXPECT_EQ(red.rgb(), paint::palette::problem().rgb());
}

TEST(SceneRenderer, PanReusesTheImageAndTheTraceGrowsIncrementally) {
  auto scene = std::make_shared<const PathScene>(std::vector<ScenePath>{spiral(50000, 60.0)});
  SceneRenderer renderer;
  paint::ViewTransform view(QPointF(0.0, 150.0), 3.0, QSizeF(320.0, 240.0));
  QImage frame = transparentImage(QSize(320, 240));
  QPainter painter(&frame);
  ScenePaintOptions o;
  renderer.paint(painter, view, scene, o, 1);
  EXPECT_EQ(renderer.fullRenders(), 1);  // a first (new zoom) render covers the viewport only
  view.panByPx(QPointF(40.0, -25.0));
  renderer.paint(painter, view, scene, o, 1);
  EXPECT_EQ(renderer.fullRenders(), 2);  // panning: rendered again, now with margins
  for (int i = 0; i < 3; ++i) {
    view.panByPx(QPointF(-20.0, 15.0));
    renderer.paint(painter, view, scene, o, 1);
  }
  EXPECT_EQ(renderer.fullRenders(), 2);  // within the margin: blits only
  view.zoomAround(QPointF(160.0, 120.0), 2.0);
  renderer.paint(painter, view, scene, o, 1);
  EXPECT_EQ(renderer.fullRenders(), 3);  // a new zoom renders again
  o.orderLimit = 1000;
  renderer.paint(painter, view, scene, o, 2);
  EXPECT_EQ(renderer.fullRenders(), 4);
  o.orderLimit = 2000;
  renderer.paint(painter, view, scene, o, 2);
  o.orderLimit = 3000;
  renderer.paint(painter, view, scene, o, 2);
  EXPECT_EQ(renderer.fullRenders(), 4);
  EXPECT_EQ(renderer.incrementalRenders(), 2);
  o.orderLimit = 500;  // going back in time re-renders
  renderer.paint(painter, view, scene, o, 2);
  EXPECT_EQ(renderer.fullRenders(), 5);
}

TEST(SceneRenderer, CachedFrameEqualsDirectPaint) {
  auto scene = std::make_shared<const PathScene>(std::vector<ScenePath>{spiral(20000, 60.0)});
  paint::ViewTransform view(QPointF(3.0, 147.0), 2.5, QSizeF(300.0, 200.0));
  SceneRenderer renderer;
  ScenePaintOptions o;
  o.colourBySpeed = true;
  QImage warm = transparentImage(QSize(300, 200));
  {
    QPainter p(&warm);
    renderer.paint(p, view, scene, o, 7);
  }
  view.panByPx(QPointF(10.0, 5.0));  // renders with margins
  {
    QPainter p(&warm);
    renderer.paint(p, view, scene, o, 7);
  }
  view.panByPx(QPointF(30.0, 20.0));  // integer pan: the blit must match a direct paint
  QImage cached = transparentImage(QSize(300, 200));
  QImage direct = transparentImage(QSize(300, 200));
  {
    QPainter p(&cached);
    renderer.paint(p, view, scene, o, 7);
  }
  {
    QPainter p(&direct);
    scene->paint(p, view, o);
  }
  int differing = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 300; ++x) differing += cached.pixel(x, y) != direct.pixel(x, y);
  EXPECT_EQ(renderer.fullRenders(), 2);
  EXPECT_LT(differing, 300 * 200 / 200);  // rasterisation may differ by a few edge pixels
}

}  // namespace
}  // namespace fivebar::widgets

namespace fivebar::widgets {
namespace {

TEST(SceneRenderer, QuickZoomScalesTheCacheUntilSettled) {
  auto scene = std::make_shared<const PathScene>(std::vector<ScenePath>{spiral(20000, 60.0)});
  paint::ViewTransform view(QPointF(0.0, 150.0), 2.0, QSizeF(300.0, 200.0));
  SceneRenderer renderer;
  renderer.setQuickZoom(true);
  QImage frame = transparentImage(QSize(300, 200));
  QPainter painter(&frame);
  const ScenePaintOptions o;
  renderer.paint(painter, view, scene, o, 1);
  EXPECT_EQ(renderer.fullRenders(), 1);
  EXPECT_FALSE(renderer.stale());
  for (int i = 0; i < 4; ++i) {
    view.zoomAround(QPointF(150.0, 100.0), 1.2);
    renderer.paint(painter, view, scene, o, 1);
  }
  EXPECT_EQ(renderer.fullRenders(), 1);  // zoom steps reuse the cached image, scaled
  EXPECT_EQ(renderer.previewFrames(), 4);
  EXPECT_TRUE(renderer.stale());
  renderer.setQuickZoom(false);  // the view rests: render sharp
  renderer.paint(painter, view, scene, o, 1);
  EXPECT_EQ(renderer.fullRenders(), 2);
  EXPECT_FALSE(renderer.stale());
}

}  // namespace
}  // namespace fivebar::widgets
