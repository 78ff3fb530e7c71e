// SPDX-License-Identifier: GPL-3.0-or-later
// Painting functions into QImages: the view transform, the machine, the grid, map legends and
// the placement delta. Pixels are checked where the geometry says they must be.
#include <gtest/gtest.h>

#include <QImage>
#include <QPainter>
#include <cmath>
#include <random>

#include "core/planning/placement.hpp"
#include "test_support.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/trajectory.hpp"
#include "widgets/canvas/job_layer.hpp"
#include "widgets/canvas/machine_layer.hpp"
#include "widgets/document/simulation_controller.hpp"
#include "widgets/document/studio_document.hpp"
#include "paint/machine_painter.hpp"
#include "paint/map_painter.hpp"
#include "paint/studio_palette.hpp"
#include "paint/view_transform.hpp"

namespace fivebar::widgets {
namespace {

QImage blank(int w, int h) {
  QImage image(w, h, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  return image;
}

bool differsFrom(const QImage& image, QPoint p, QColor c, int tolerance = 12) {
  const QColor got = image.pixelColor(p);
  return std::abs(got.red() - c.red()) > tolerance || std::abs(got.green() - c.green()) > tolerance ||
         std::abs(got.blue() - c.blue()) > tolerance;
}

TEST(ViewTransform, RoundTripAndYFlip) {
  const paint::ViewTransform view(QPointF(10.0, 50.0), 3.0, QSizeF(400.0, 300.0));
  EXPECT_EQ(view.widgetFromMachine(QPointF(10.0, 50.0)), QPointF(200.0, 150.0));
  // y up in the machine frame is y down on screen.
  EXPECT_LT(view.widgetFromMachine(QPointF(10.0, 60.0)).y(), 150.0);
  auto rng = test::rng();
  std::uniform_real_distribution<double> u(-500.0, 500.0);
  for (int i = 0; i < 100; ++i) {
    const QPointF m(u(rng), u(rng));
    const QPointF back = view.machineFromWidget(view.widgetFromMachine(m));
    EXPECT_NEAR(back.x(), m.x(), 1e-9);
    EXPECT_NEAR(back.y(), m.y(), 1e-9);
  }
}

TEST(ViewTransform, ZoomKeepsTheAnchorAndFitContains) {
  paint::ViewTransform view(QPointF(0.0, 100.0), 2.0, QSizeF(800.0, 600.0));
  const QPointF anchor(613.0, 97.0);
  const QPointF before = view.machineFromWidget(anchor);
  view.zoomAround(anchor, 1.7);
  EXPECT_DOUBLE_EQ(view.pxPerMm(), 3.4);
  const QPointF after = view.machineFromWidget(anchor);
  EXPECT_NEAR(after.x(), before.x(), 1e-9);
  EXPECT_NEAR(after.y(), before.y(), 1e-9);
  const QRectF target(-120.0, 30.0, 240.0, 90.0);
  view.fit(target, 10.0);
  EXPECT_TRUE(view.visibleMachineRect().contains(target));
  view.panByPx(QPointF(100.0, 0.0));  // content follows the drag to the right
  EXPECT_LT(view.centerMm().x(), target.center().x());
}

TEST(MachinePainter, DrawsLinksAtThePose) {
  const auto profile = preset("maker-plotter");
  ASSERT_TRUE(profile);
  const Geometry& g = profile->geometry;
  const Vec2 p(0.0, 0.6 * (g.a1 + g.b1));
  const IkResult ik = inverse(g, p, WorkingMode::PlusPlus);
  ASSERT_TRUE(ik.ok());
  const Pose pose = makePose(g, ik.angles, p);
  QImage image = blank(600, 500);
  const paint::ViewTransform view(QPointF(0.0, p.y() / 2.0), 1.5, QSizeF(600.0, 500.0));
  {
    QPainter painter(&image);
    paint::paintMachine(painter, view.widgetFromMachine(), g, pose);
  }
  const auto at = [&](const Vec2& v) {
    return view.widgetFromMachine(QPointF(v.x(), v.y())).toPoint();
  };
  // Motors (their body around the white joint), the middle of each link and the pen are
  // painted; a far corner is not.
  const QPoint belowJoint(0, 10);
  EXPECT_TRUE(differsFrom(image, at(g.motor1()) + belowJoint, Qt::white));
  EXPECT_TRUE(differsFrom(image, at(g.motor2()) + belowJoint, Qt::white));
  EXPECT_TRUE(differsFrom(image, at(0.5 * (g.motor1() + pose.R1)), Qt::white));
  EXPECT_TRUE(differsFrom(image, at(0.5 * (pose.R2 + pose.P)), Qt::white));
  EXPECT_TRUE(differsFrom(image, at(pose.P), Qt::white));
  EXPECT_FALSE(differsFrom(image, QPoint(3, 3), Qt::white));
}

TEST(MachinePainter, GridFillsTheBackgroundAndDrawsAxes) {
  QImage image = blank(300, 200);
  const paint::ViewTransform view(QPointF(0.0, 0.0), 2.0, QSizeF(300.0, 200.0));
  {
    QPainter painter(&image);
    paint::paintGrid(painter, view);
  }
  // Origin is at the centre: the dashed axes cross there; elsewhere the background colour.
  EXPECT_TRUE(differsFrom(image, QPoint(150, 100), paint::palette::background(), 8));
  int background = 0;
  for (int x = 0; x < 300; ++x) background += !differsFrom(image, QPoint(x, 57), paint::palette::background(), 2);
  EXPECT_GT(background, 150);
}

TEST(MapPainter, ColourBarShowsTheScale) {
  paint::MapScale scale{0.0, 180.0, true, false, QStringLiteral("angle"), 0};
  // Diverging: both ends alike (bad), the middle different (good).
  const QColor low = paint::mapColour(scale, 0.0), high = paint::mapColour(scale, 180.0);
  const QColor mid = paint::mapColour(scale, 90.0);
  EXPECT_EQ(low, high);
  EXPECT_NE(low, mid);
  QImage image = blank(300, 80);
  {
    QPainter painter(&image);
    paint::paintColourBar(painter, QRectF(5, 5, 260, 60), scale);
  }
  // The bar's left end has the low colour.
  const QColor got = image.pixelColor(17, 5 + 6 + 20 + 6);
  EXPECT_LE(std::abs(got.red() - low.red()), 20);
  EXPECT_LE(std::abs(got.green() - low.green()), 20);
}

TEST(PlacementDelta, MatchesCoreTransforms) {
  Drawing d;
  Layer l;
  Polyline p;
  p.points = {Vec2(3.0, 4.0), Vec2(40.0, 9.0), Vec2(17.0, 33.0)};
  l.paths.push_back(p);
  d.layers.push_back(l);
  auto rng = test::rng();
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 20; ++i) {
    Placement a, b;
    a.centerMm = Vec2(100.0 * u(rng), 150.0 + 50.0 * u(rng));
    a.rotationRad = 3.0 * u(rng);
    a.scale = 1.5 + u(rng);
    b.centerMm = Vec2(100.0 * u(rng), 150.0 + 50.0 * u(rng));
    b.rotationRad = 3.0 * u(rng);
    b.scale = 1.5 + u(rng);
    const QTransform delta = placementDelta(a, b);
    const auto ta = machineFromWork(d, a), tb = machineFromWork(d, b);
    for (const Vec2& w : p.points) {
      const Vec2 ma = ta * w, mb = tb * w;
      const QPointF got = delta.map(QPointF(ma.x(), ma.y()));
      EXPECT_NEAR(got.x(), mb.x(), 1e-9);
      EXPECT_NEAR(got.y(), mb.y(), 1e-9);
    }
  }
}

}  // namespace
}  // namespace fivebar::widgets

namespace fivebar {
namespace {

// With a calibrated pen offset the canvas draws the linkage from the motor angles and the pen
// where penForward puts it, for the home pose and along the simulation (whose samples carry the
// pen, not P).
TEST(MachineLayerPen, ThePenIsDrawnWhereTheOffsetPutsIt) {
  MachineProfile p = *preset("maker-plotter");
  p.calibration.emplace();
  p.calibration->penOffset = PenOffset{6.0, -4.0};
  widgets::StudioDocument doc(p);
  widgets::SimulationController sim;
  widgets::MachineLayer layer(doc, sim);
  ASSERT_TRUE(layer.pose() && layer.penMm());
  const JointAngles home = kinematicFromCommanded(p.calibration, p.homeAngles);
  const FkResult atP = forward(p.geometry, home, p.assembly);
  EXPECT_LT((layer.pose()->P - atP.p).norm(), 1e-9);
  EXPECT_LT((*layer.penMm() - penForward(p, home).p).norm(), 1e-9);
  EXPECT_GT((*layer.penMm() - atP.p).norm(), 7.0);  // |(6, -4)| = 7.2 mm off P
  // Along a planned square: P from the angles, the pen where the sample says it is.
  Drawing d;
  d.layers.resize(1);
  Polyline pl;
  for (const Vec2& c : {Vec2(0, 0), Vec2(30, 0), Vec2(30, 30), Vec2(0, 30), Vec2(0, 0)}) pl.points.push_back(c);
  d.layers[0].paths.push_back(pl);
  PlanOptions o;
  o.atMm = Vec2(-15, 150);
  const PlanResult plan = planJob(d, p, o);
  ASSERT_TRUE(plan.ok()) << plan.message.text();
  sim.setTrajectory(std::make_shared<Trajectory>(plan.job, p));
  sim.setTimeS(0.5 * sim.durationS());
  const TrajectorySample s = sim.sample();
  ASSERT_TRUE(layer.pose() && layer.penMm());
  EXPECT_LT((layer.pose()->P - forward(p.geometry, s.q, p.assembly).p).norm(), 1e-9);
  EXPECT_LT((*layer.penMm() - s.p).norm(), 1e-6);
  // The painter puts the pen's dot there: its colour at the pen, not at P.
  QImage img(600, 600, QImage::Format_RGB32);
  img.fill(Qt::white);
  QPainter painter(&img);
  QTransform t;
  t.translate(300, 300);
  t.scale(8, -8);
  t.translate(-layer.penMm()->x(), -layer.penMm()->y());
  paint::paintMachine(painter, t, p.geometry, *layer.pose(), 1.0, layer.penMm());
  painter.end();
  EXPECT_EQ(img.pixelColor(300, 300), paint::palette::pen());
}

}  // namespace
}  // namespace fivebar
