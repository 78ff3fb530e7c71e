// SPDX-License-Identifier: GPL-3.0-or-later
// The one door a feature of the studio installs itself through: its panels (docks), its menu
// entries, its canvas layers and status widgets. The composition root (app/studio/MainWindow)
// builds one StudioShell and hands it to each feature's install function (the machine panels,
// the design explorer, the calibration wizard and the simulated machine, the path editor); no
// feature reaches into the window, and the window knows a feature only by its install call.
#pragma once

#include <QString>
#include <Qt>
#include <functional>

class QDockWidget;
class QMenu;
class QStatusBar;
class QWidget;

namespace fivebar::widgets {

class CanvasView;
class StudioDocument;

struct StudioShell {
  QWidget* window = nullptr;  // parent of the feature's dialogs and objects
  StudioDocument* doc = nullptr;
  CanvasView* canvas = nullptr;
  QStatusBar* statusBar = nullptr;
  QMenu* fileMenu = nullptr;
  QMenu* editMenu = nullptr;
  QMenu* viewMenu = nullptr;
  QMenu* machineMenu = nullptr;
  QMenu* helpMenu = nullptr;
  // Docks `panel` under `title` (objectName names it in the remembered layout) on `area`; its
  // show/hide toggle goes into `toggleMenu` (none when null). Side docks join the studio's tab
  // group on their side. Returns the dock.
  std::function<QDockWidget*(QWidget* panel, const QString& title, const QString& objectName,
                             Qt::DockWidgetArea area, QMenu* toggleMenu)>
      addPanel;
};

}  // namespace fivebar::widgets
