// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's main window: a composition root only. It creates the document, the controllers,
// the canvas with its layers and tool, and the panels in dock widgets, wires them together, and
// offers the menus and shortcuts. Dock layout and window geometry are remembered (QSettings).
// The machine side is two parts composed here: session::MachineSide (session, run and jog
// controllers; Qt Core only) and widgets::MachinePanels (its panels). Every feature (machine
// panels, design explorer, calibration, path editor) installs itself through one StudioShell.
// Everything a test or a screenshot needs has an accessor: nothing is looked up by findChild.
#pragma once

#include "widgets/shell/studio_shell.hpp"
#include <QMainWindow>
#include <QPointer>
#include <QString>
#include <vector>
#include <memory>

#include "core/machine/profile.hpp"

class QAction;
class QDockWidget;
class QLabel;
class QMenu;

namespace fivebar::session {
class MachineSide;
}

namespace fivebar::widgets {
class CanvasView;
class ImportController;
class JobLayer;
class DocumentInputs;
class MachineLayer;
class MachinePanels;
class PlacementPanel;
class PreviewPanel;
class FillOptionsBox;
class PlacementTool;
class PreviewController;
class SimulationController;
class StudioDocument;
class WorkspaceCache;
class WorkspaceLayer;
class WorkspaceLegendLayer;
namespace calibration {
class CalibrationWizard;
class SimulatedTruth;
}
}  // namespace fivebar::widgets

namespace fivebar::studio {

class FileActions;
class HelpMenu;

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
  HelpMenu& help() { return *help_; }  // Help > Documentation, First job guide
  // The machine side: session, run and jog controllers (Qt Core), and their panels.
  session::MachineSide& machine() { return *machine_; }
  widgets::MachinePanels& machinePanels() { return *machinePanels_; }
  widgets::PlacementPanel& placementPanel() { return *placementPanel_; }
  widgets::FillOptionsBox& fillOptions() { return *fillOptions_; }
  // A dock by its object name ("dockPlacement", "dockJog", ...); nullptr when there is none.
  QDockWidget* dock(const QString& objectName) const;
  // Machine > Calibrate..., and the wizard it opened (nullptr before the first use).
  QAction* calibrateAction() const { return calibrateAction_; }
  widgets::calibration::CalibrationWizard* calibrationWizard() const;
  // The simulated machine's true (imperfect) build, Machine > Simulated machine...
  widgets::calibration::SimulatedTruth& simulatedTruth() { return *simulatedTruth_; }

  // A feature's panel in the window (StudioShell::addPanel): a dock restored with the others,
  // its toggle in `toggleMenu`.
  QDockWidget* addPanel(QWidget* panel, const QString& title, const QString& objectName,
                        Qt::DockWidgetArea area = Qt::RightDockWidgetArea, QMenu* toggleMenu = nullptr);
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
  // The door every feature installs through (widgets/shell/studio_shell.hpp).
  widgets::StudioShell makeShell();

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
  HelpMenu* help_ = nullptr;
  widgets::PlacementPanel* placementPanel_ = nullptr;
  widgets::PreviewPanel* previewPanel_ = nullptr;
  widgets::FillOptionsBox* fillOptions_ = nullptr;
  QPointer<widgets::calibration::CalibrationWizard> calibrationWizard_;  // created on first use
  widgets::DocumentInputs* inputs_ = nullptr;
  session::MachineSide* machine_ = nullptr;
  widgets::MachinePanels* machinePanels_ = nullptr;
  QAction* calibrateAction_ = nullptr;
  widgets::calibration::SimulatedTruth* simulatedTruth_ = nullptr;  // the machine session's child
  std::vector<QDockWidget*> docks_;  // in the order they were created
  std::unique_ptr<widgets::WorkspaceLegendLayer> legendLayer_;
  QDockWidget* leftTabs_ = nullptr;   // tab group machine panels join on each side
  QDockWidget* rightTabs_ = nullptr;
  QMenu* viewMenu_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QMenu* machineMenu_ = nullptr;
  QMenu* fileMenu_ = nullptr;
  QMenu* editMenu_ = nullptr;
  QMenu* helpMenu_ = nullptr;
  QLabel* cursorLabel_ = nullptr;
};

}  // namespace fivebar::studio
