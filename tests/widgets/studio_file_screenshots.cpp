// fivebar_studio_file_screenshots OUTDIR: screenshots for the docs of the placement panel (a
// drawing imported at true size, width and height in mm) and of the File menu (save, export),
// taken from the real main window (not a test; run it under
// xvfb-run -a -s "-screen 0 1600x1000x24"):
//   studio-placement.png   the placement panel beside the drawing placed at 100 %
//   studio-file-menu.png   the File menu open: open, save, save as, export G-code
#include <QAction>
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

#include "app/studio/main_window.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/document/preview_controller.hpp"

namespace {

bool waitUntil(const std::function<bool()>& pred, int timeoutMs) {
  QElapsedTimer clock;
  clock.start();
  while (!pred()) {
    if (clock.elapsed() > timeoutMs) return false;
    QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    QThread::msleep(2);
  }
  return true;
}

void settle(int ms) { waitUntil([] { return false; }, ms); }

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
  return status;
}
