// SPDX-License-Identifier: GPL-3.0-or-later
// The Design dialog (widgets/design): a search from the brief on worker threads, the table and
// trade-off plot, the canvas preview of a clicked design, "Use as profile" (undoable), export,
// cancel, and the atlas painter.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QImage>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "core/machine/profile.hpp"
#include "widgets/canvas/canvas_view.hpp"
#include "widgets/design/design_dialog.hpp"
#include "widgets/design/pareto_plot.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {
namespace {

design::SearchOptions quick() {
  design::SearchOptions o;
  o.startsPerMode = 1;
  o.globalEvaluations = 500;
  o.localEvaluations = 300;
  return o;
}

struct Fixture {
  StudioDocument doc{*preset("maker-plotter")};
  CanvasView canvas;
  DesignDialog dialog{doc, canvas};
  Fixture() {
    canvas.resize(800, 600);
    dialog.setSearchOptions(quick());
  }
  bool runSearch() {
    QSignalSpy done(&dialog, &DesignDialog::searchFinished);
    dialog.startSearch();
    EXPECT_TRUE(dialog.searching());
    return done.wait(60000);
  }
};

TEST(DesignDialog, BriefFollowsPaperOrientationAndMargin) {
  Fixture f;
  const auto combos = f.dialog.findChildren<QComboBox*>();
  ASSERT_GE(combos.size(), 2);
  combos[0]->setCurrentIndex(0);  // A4
  combos[1]->setCurrentIndex(1);  // portrait
  const design::DesignBrief b = f.dialog.brief();
  EXPECT_DOUBLE_EQ(b.widthMm, 210.0 - 20.0);  // 10 mm margin on each side
  EXPECT_DOUBLE_EQ(b.heightMm, 297.0 - 20.0);
  EXPECT_DOUBLE_EQ(b.bounds.maxLinkMm, 200.0);
  EXPECT_NEAR(degFromRad(b.rules.workspace.typeIIMarginRad), 15.0, 1e-9);
}

TEST(DesignDialog, SearchFillsTableAndPlotAndPreviewsOnTheCanvas) {
  Fixture f;
  const auto combos = f.dialog.findChildren<QComboBox*>();
  combos[0]->setCurrentIndex(2);  // A6: 128 x 85 mm after the margin
  ASSERT_TRUE(f.runSearch());
  ASSERT_GT(f.dialog.designCount(), 0) << f.dialog.statusText().toStdString();
  auto* table = f.dialog.findChild<QTableWidget*>();
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(table->rowCount(), f.dialog.designCount());
  ASSERT_NE(f.dialog.selectedDesign(), nullptr);  // the best design is shown at once
  EXPECT_TRUE(f.dialog.layer().showing());
  // Clicking a dot of the trade-off plot selects that design.
  auto* plot = f.dialog.findChild<ParetoPlot*>();
  ASSERT_NE(plot, nullptr);
  plot->resize(360, 220);
  const int last = f.dialog.designCount() - 1;
  QTest::mouseClick(plot, Qt::LeftButton, {}, plot->positionOf(last).toPoint());
  EXPECT_EQ(plot->selected(), last);
  EXPECT_EQ(table->currentRow(), last);
  EXPECT_EQ(table->item(last, 3)->text(), QString::number(f.dialog.selectedDesign()->geometry.a1, 'f', 1));
  // The canvas shows the design's rectangle: paint it and look for the rectangle's amber.
  QImage image(800, 600, QImage::Format_ARGB32_Premultiplied);
  {
    QPainter p(&image);
    f.canvas.render(p);
  }
  int amber = 0;
  for (int y = 0; y < image.height(); y += 2)
    for (int x = 0; x < image.width(); x += 2) {
      const QColor c = image.pixelColor(x, y);
      if (c.red() > 220 && c.green() > 130 && c.green() < 180 && c.blue() < 60) ++amber;
    }
  EXPECT_GT(amber, 50);
  f.dialog.show();
  f.dialog.hide();
  EXPECT_FALSE(f.dialog.layer().showing());
}

TEST(DesignDialog, UseAsProfileIsUndoableAndExportWritesAValidProfile) {
  Fixture f;
  const Geometry before = f.doc.profile().geometry;
  ASSERT_TRUE(f.runSearch());
  const design::Design* d = f.dialog.selectedDesign();
  ASSERT_NE(d, nullptr);
  f.dialog.useAsProfile();
  EXPECT_EQ(f.doc.profile().geometry, d->geometry);
  EXPECT_EQ(f.doc.profile().defaultMode, d->mode);
  f.doc.undoStack()->undo();
  EXPECT_EQ(f.doc.profile().geometry, before);
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("designed.json"));
  EXPECT_TRUE(f.dialog.exportProfile(path).isEmpty());
  const ProfileLoad load = loadProfile(path.toStdString());
  ASSERT_TRUE(load.profile);
  EXPECT_EQ(load.profile->geometry, d->geometry);
}

TEST(DesignDialog, ImpossibleBriefSaysWhatBinds) {
  Fixture f;
  const auto combos = f.dialog.findChildren<QComboBox*>();
  combos[0]->setCurrentIndex(0);  // A4 with links <= 200 mm cannot be reached
  design::SearchOptions o = quick();
  o.startsPerMode = 2;
  o.globalEvaluations = 1500;
  f.dialog.setSearchOptions(o);
  ASSERT_TRUE(f.runSearch());
  EXPECT_EQ(f.dialog.designCount(), 0);
  EXPECT_TRUE(f.dialog.statusText().contains(QStringLiteral("reach binds"))) << f.dialog.statusText().toStdString();
}

TEST(DesignDialog, CancelEndsTheSearch) {
  Fixture f;
  f.dialog.setSearchOptions({});  // the full budget: several seconds
  QSignalSpy done(&f.dialog, &DesignDialog::searchFinished);
  f.dialog.startSearch();
  f.dialog.cancelSearch();
  ASSERT_TRUE(done.wait(20000));
  EXPECT_TRUE(f.dialog.statusText().contains(QStringLiteral("cancelled"))) << f.dialog.statusText().toStdString();
}

TEST(DesignPainter, AtlasShowsFourPanels) {
  design::Design d;
  d.geometry = {70, 200, 70, 200, 250};
  d.rect = {-55, 110.7, 55, 200.7};
  d.evaluation = design::evaluateDesign(d.geometry, d.mode, d.rect, {}, design::Sampling{5});
  const paint::DesignMaps maps = paint::computeDesignMaps(d, {}, 160);
  EXPECT_GT(maps.analysis.reachableAreaMm2, 10000.0);
  const QImage atlas = paint::designAtlas(d, maps, QStringLiteral("hoang2015"), QSize(900, 700));
  ASSERT_EQ(atlas.size(), QSize(900, 700));
  // Each quadrant holds painted content (not just the white page).
  for (int q = 0; q < 4; ++q) {
    const int x0 = (q % 2) * 450, y0 = 120 + (q / 2) * 290;
    int coloured = 0;
    for (int y = y0 + 40; y < y0 + 250; y += 4)
      for (int x = x0 + 20; x < x0 + 430; x += 4) {
        const QColor c = atlas.pixelColor(x, y);
        if (std::abs(c.red() - c.green()) > 30 || std::abs(c.green() - c.blue()) > 30) ++coloured;
      }
    EXPECT_GT(coloured, 100) << "panel " << q;
  }
}

}  // namespace
}  // namespace fivebar::widgets
