// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar_studio_file_screenshots OUTDIR: screenshots for the docs of the placement panel (a
// drawing imported at true size, width and height in mm) and of the File menu (save, export),
// taken from the real main window (not a test; run it under
// xvfb-run -a -s "-screen 0 1600x1000x24"):
//   studio-placement.png   the placement panel beside the drawing placed at 100 %
//   studio-file-menu.png   the File menu open: open, save, save as, export G-code
//   studio-layer-fill.png  the layers panel: a layer of filled shapes hatched (crosshatch)
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QListWidget>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QPainter>
#include <QSettings>
#include <QTemporaryDir>
#include <QThread>
#include <cstdio>
#include <functional>

#include "tests/widgets/event_wait.hpp"

#include "app/studio/main_window.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/document/preview_controller.hpp"

namespace {

using fivebar::test::settle;
using fivebar::test::waitUntil;

bool save(const QPixmap& pixmap, const QString& path) {
  const bool ok = pixmap.save(path);
  std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  if (argc < 2) {
    std::fprintf(stderr, "usage: fivebar_studio_file_screenshots OUTDIR\n");
    return 2;
  }
  const QString outDir = QString::fromLocal8Bit(argv[1]);
  QTemporaryDir settingsDir;  // a fresh dock layout, not the user's
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
  QApplication::setOrganizationName(QStringLiteral("FiveBarScreenshots"));
  QApplication::setApplicationName(QStringLiteral("FiveBar Studio"));

  using namespace fivebar;
  studio::MainWindow window(*preset("maker-plotter"));
  window.resize(1600, 1000);
  window.show();
  QFile demo(QStringLiteral(FIVEBAR_DEMO_SVG));
  if (!demo.open(QIODevice::ReadOnly)) return 1;
  window.importer().setInteractive(false);
  window.importer().openData(demo.readAll(), QStringLiteral("fivebar-demo.svg"));
  if (!waitUntil([&] {
        return window.preview().result().status == widgets::PreviewStatus::Planned &&
               !window.preview().busy() && !window.importer().busy();
      }, 60000)) {
    std::fprintf(stderr, "the demo job did not plan\n");
    return 1;
  }
  if (auto* dock = window.findChild<QDockWidget*>(QStringLiteral("dockPlacement"))) dock->raise();
  window.fitView();
  settle(400);
  int status = save(window.grab(), outDir + QStringLiteral("/studio-placement.png")) ? 0 : 1;

  // The File menu, opened under its title, painted over the window.
  QMenu* file = window.menuBar()->actions().front()->menu();
  const QRect title = window.menuBar()->actionGeometry(window.menuBar()->actions().front());
  file->popup(window.menuBar()->mapToGlobal(title.bottomLeft()));
  settle(400);
  QPixmap shot = window.grab();
  {
    QPainter painter(&shot);
    painter.drawPixmap(window.mapFromGlobal(file->pos()), file->grab());
  }
  file->hide();
  if (!save(shot.copy(0, 0, 760, 420), outDir + QStringLiteral("/studio-file-menu.png"))) status = 1;

  // Filled shapes in two colours; the black layer hatched from the layers panel.
  window.importer().openData(QByteArray(R"(<svg xmlns="http://www.w3.org/2000/svg" width="120mm" height="80mm" viewBox="0 0 120 80">
  <path d="M 10 10 H 70 V 70 H 10 Z M 25 25 H 55 V 55 H 25 Z" fill="#000" fill-rule="evenodd"/>
  <circle cx="95" cy="30" r="18" fill="#000"/>
  <path d="M 80 60 L 115 60 L 97 78 Z" fill="none" stroke="#d62728"/>
</svg>)"), QStringLiteral("filled-shapes.svg"));
  if (!waitUntil([&] {
        return !window.importer().busy() &&
               window.document().fileName() == QStringLiteral("filled-shapes.svg");
      }, 60000))
    return 1;
  if (auto* dock = window.findChild<QDockWidget*>(QStringLiteral("dockLayers"))) dock->raise();
  auto* list = window.findChild<QListWidget*>(QStringLiteral("layersList"));
  auto* mode = window.findChild<QComboBox*>(QStringLiteral("layerFill"));
  auto* spacing = window.findChild<QDoubleSpinBox*>(QStringLiteral("layerHatchSpacing"));
  auto* angle = window.findChild<QDoubleSpinBox*>(QStringLiteral("layerHatchAngle"));
  auto* cross = window.findChild<QCheckBox*>(QStringLiteral("layerCrosshatch"));
  if (!list || !mode || !spacing || !angle || !cross) return 1;
  for (int row = 0; row < list->count(); ++row)
    if (window.document().drawing().layers[static_cast<std::size_t>(row)].rgb == 0) list->setCurrentRow(row);
  mode->setCurrentIndex(mode->findData(static_cast<int>(FillMode::Hatch)));
  spacing->setValue(1.5);
  angle->setValue(45.0);
  cross->setChecked(true);
  window.preview().replanNow();
  if (!waitUntil([&] {
        return window.preview().result().status == widgets::PreviewStatus::Planned && !window.preview().busy();
      }, 60000)) {
    std::fprintf(stderr, "the hatched job did not plan\n");
    return 1;
  }
  window.fitView();
  settle(400);
  if (!save(window.grab(), outDir + QStringLiteral("/studio-layer-fill.png"))) status = 1;
  return status;
}
