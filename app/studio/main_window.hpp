// The studio's main window: a composition root only. It creates the document, the controllers,
// the canvas with its layers and tool, and the panels in dock widgets, wires them together, and
// offers the menus and shortcuts. Dock layout and window geometry are remembered (QSettings).
// Machine panels (connection, status, console, jog, run, profile editor) are added by
// addMachinePanel(); the machine side drives the canvas pose through machineLayer().
#pragma once

#include <QMainWindow>
#include <memory>

#include "core/machine/profile.hpp"

class QDockWidget;
class QLabel;
class QMenu;

namespace fivebar::widgets {
class CanvasView;
class ImportController;
class JobLayer;
class MachineLayer;
class MachineUi;
class PlacementTool;
class PreviewController;
class SimulationController;
class StudioDocument;
class WorkspaceCache;
class WorkspaceLayer;
class WorkspaceLegendLayer;
}  // namespace fivebar::widgets

namespace fivebar::studio {

class FileActions;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(const MachineProfile& profile, QWidget* parent = nullptr);
  ~MainWindow() override;

  widgets::StudioDocument& document() { return *doc_; }
  widgets::CanvasView& canvas() { return *canvas_; }
  widgets::PreviewController& preview() { return *preview_; }
  widgets::SimulationController& simulation() { return *simulation_; }
  widgets::ImportController& importer() { return *importer_; }
  widgets::WorkspaceCache& workspace() { return *workspace_; }
  widgets::MachineLayer& machineLayer() { return *machineLayer_; }
  widgets::JobLayer& jobLayer() { return *jobLayer_; }
  widgets::WorkspaceLayer& workspaceLayer() { return *workspaceLayer_; }
  FileActions& files() { return *files_; }
  // The machine side (session, run, panels).
  widgets::MachineUi& machine() { return *machineUi_; }

  // The machine side's place in the window: the panel goes into a dock (restored with the
  // others), its toggle into the Machine menu.
  QDockWidget* addMachinePanel(QWidget* panel, const QString& title, const QString& objectName,
                               Qt::DockWidgetArea area = Qt::RightDockWidgetArea);
  QMenu* machineMenu() const { return machineMenu_; }

  // Fits the view to the machine's reach, or to the drawing when there is one.
  void fitView();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createCanvas();
  void createDocks();
  void createMenus();
  void rebuildRecentMenu();
  void updateTitle();
  QDockWidget* addDock(QWidget* panel, const QString& title, const QString& objectName,
                       Qt::DockWidgetArea area);
  void restoreLayout();

  widgets::StudioDocument* doc_ = nullptr;
  widgets::WorkspaceCache* workspace_ = nullptr;
  widgets::PreviewController* preview_ = nullptr;
  widgets::SimulationController* simulation_ = nullptr;
  widgets::ImportController* importer_ = nullptr;
  widgets::CanvasView* canvas_ = nullptr;
  widgets::WorkspaceLayer* workspaceLayer_ = nullptr;
  widgets::JobLayer* jobLayer_ = nullptr;
  widgets::MachineLayer* machineLayer_ = nullptr;
  widgets::PlacementTool* placementTool_ = nullptr;
  FileActions* files_ = nullptr;
  widgets::MachineUi* machineUi_ = nullptr;
  std::unique_ptr<widgets::WorkspaceLegendLayer> legendLayer_;
  QDockWidget* leftTabs_ = nullptr;   // tab group machine panels join on each side
  QDockWidget* rightTabs_ = nullptr;
  QMenu* viewMenu_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QMenu* machineMenu_ = nullptr;
  QLabel* cursorLabel_ = nullptr;
};

}  // namespace fivebar::studio
