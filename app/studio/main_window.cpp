// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/studio/main_window.hpp"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>

#include "app/studio/file_actions.hpp"
#include "app/studio/help_menu.hpp"
#include "app/studio/language_menu.hpp"
#include "core/workspace/view_box.hpp"
#include "widgets/calibration/calibration_install.hpp"
#include "widgets/calibration/calibration_wizard.hpp"
#include "widgets/calibration/simulated_machine.hpp"
#include "widgets/canvas/canvas_view.hpp"
#include "widgets/design/design_dialog.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/panels/fill_options_box.hpp"
#include "widgets/panels/import_warnings_panel.hpp"
#include "widgets/canvas/job_layer.hpp"
#include "widgets/panels/layers_panel.hpp"
#include "widgets/canvas/machine_layer.hpp"
#include "session/machine_side.hpp"
#include "widgets/machine/document_inputs.hpp"
#include "widgets/machine/machine_panels.hpp"
#include "widgets/panels/mode_panel.hpp"
#include "widgets/panels/placement_panel.hpp"
#include "widgets/canvas/placement_tool.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/panels/preview_panel.hpp"
#include "widgets/document/simulation_controller.hpp"
#include "widgets/panels/simulation_panel.hpp"
#include "widgets/document/studio_document.hpp"
#include "widgets/canvas/workspace_cache.hpp"
#include "widgets/canvas/workspace_layer.hpp"

namespace fivebar::studio {

using namespace fivebar::widgets;

namespace {
const char* const kGeometryKey = "window/geometry";
const char* const kStateKey = "window/state";
constexpr int kStateVersion = 1;
constexpr int kBottomDockHeightPx = 160;
constexpr int kSideDockWidthPx = 340;
}  // namespace

MainWindow::MainWindow(const MachineProfile& profile, QWidget* parent) : QMainWindow(parent) {
  setObjectName(QStringLiteral("FiveBarStudioMainWindow"));
  setWindowTitle(tr("FiveBar Studio"));
  setAcceptDrops(true);
  doc_ = new StudioDocument(profile, this);
  workspace_ = new WorkspaceCache(*doc_, this);
  preview_ = new PreviewController(*doc_, this);
  simulation_ = new SimulationController(this);
  importer_ = new ImportController(*doc_, this, this);
  importer_->setBudgetQuestion([this](const QString& title, const QString& question) {
    return askBeyondPointBudget(this, title, question);
  });
  files_ = new FileActions(*doc_, *preview_, *importer_, this);
  connect(preview_, &PreviewController::resultChanged, this,
          [this] { simulation_->setTrajectory(preview_->result().trajectory); });
  createCanvas();
  createDocks();
  createMenus();
  // Every feature installs itself through the one shell (widgets/shell/studio_shell.hpp).
  const StudioShell shell = makeShell();
  // The machine side: the session layer (session/machine_side.hpp) over the document and its
  // plan, and its panels (widgets/machine/machine_panels.hpp).
  inputs_ = new DocumentInputs(*doc_, preview_, this);
  machine_ = new session::MachineSide(*inputs_, this);
  machinePanels_ = new MachinePanels(*machine_, *doc_, *canvas_, *machineLayer_, this);
  machinePanels_->install(shell);
  // The board's soft limits in the pre-flight list while connected to a board with $20=1.
  connect(&machine_->boardPreflight(), &session::BoardPreflight::changed, previewPanel_,
          &PreviewPanel::setMachineProblem);
  DesignDialog::install(shell);
  const auto calibration = widgets::calibration::installCalibration(shell, machine_->session(), calibrationWizard_);
  simulatedTruth_ = calibration.simulatedTruth;
  calibrateAction_ = calibration.calibrateAction;
  cursorLabel_ = new QLabel(this);
  statusBar()->addPermanentWidget(cursorLabel_);
  connect(canvas_, &CanvasView::cursorMoved, this, [this](QPointF mm) {
    cursorLabel_->setText(tr("x %1 mm, y %2 mm").arg(QLocale().toString(mm.x(), 'f', 1)).arg(QLocale().toString(mm.y(), 'f', 1)));
  });
  connect(preview_, &PreviewController::planningStarted, this,
          [this] { statusBar()->showMessage(tr("Planning...")); });
  connect(preview_, &PreviewController::resultChanged, this,
          [this] { statusBar()->showMessage(preview_->result().message, 8000); });
  connect(importer_, &ImportController::finished, this, [this](bool ok, const QString& message) {
    if (ok) {
      updateTitle();
      fitView();
      preview_->replanNow();
      placementPanel_->setNote(message);
      if (!message.isEmpty()) statusBar()->showMessage(message, 10000);
    } else {
      statusBar()->showMessage(message, 10000);
    }
  });
  connect(files_, &FileActions::message, this, [this](const QString& m) { statusBar()->showMessage(m, 8000); });
  connect(doc_, &StudioDocument::modifiedChanged, this, &MainWindow::updateTitle);
  connect(doc_, &StudioDocument::projectPathChanged, this, &MainWindow::updateTitle);
  updateTitle();
  connect(workspace_, &WorkspaceCache::ready, this, [this] {
    if (!doc_->hasDrawing()) fitView();
  });
  restoreLayout();
}

MainWindow::~MainWindow() {
  // The canvas keeps raw pointers to the layers and the tool: detach them before they go.
  canvas_->setTool(nullptr);
}

QDockWidget* MainWindow::dock(const QString& objectName) const {
  for (QDockWidget* d : docks_)
    if (d->objectName() == objectName) return d;
  return nullptr;
}

widgets::calibration::CalibrationWizard* MainWindow::calibrationWizard() const {
  // Created by the Calibrate action on first use (widgets/calibration/calibration_wizard.cpp).
  return calibrationWizard_.data();
}

void MainWindow::createCanvas() {
  canvas_ = new CanvasView(this);
  canvas_->setObjectName(QStringLiteral("canvas"));
  setCentralWidget(canvas_);
  workspaceLayer_ = new WorkspaceLayer(*doc_, *workspace_, this);
  jobLayer_ = new JobLayer(*doc_, *preview_, *simulation_, this);
  machineLayer_ = new MachineLayer(*doc_, *simulation_, this);
  placementTool_ = new PlacementTool(*doc_, this);
  canvas_->addLayer(workspaceLayer_);
  canvas_->addLayer(jobLayer_);
  canvas_->addLayer(machineLayer_);
  legendLayer_ = std::make_unique<WorkspaceLegendLayer>(*workspaceLayer_);
  canvas_->addLayer(legendLayer_.get());
  canvas_->setTool(placementTool_);
  const auto repaint = [this] { canvas_->update(); };
  connect(workspaceLayer_, &WorkspaceLayer::changed, this, repaint);
  connect(jobLayer_, &JobLayer::changed, this, repaint);
  connect(machineLayer_, &MachineLayer::changed, this, repaint);
  connect(doc_, &StudioDocument::placementChanged, this, repaint);
}

QDockWidget* MainWindow::addDock(QWidget* panel, const QString& title, const QString& objectName,
                                 Qt::DockWidgetArea area) {
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(objectName);
  auto* scroll = new QScrollArea(dock);
  scroll->setWidget(panel);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setMinimumWidth(std::min(panel->sizeHint().width(), kSideDockWidthPx) + 16);
  dock->setWidget(scroll);
  addDockWidget(area, dock);
  docks_.push_back(dock);
  return dock;
}

QDockWidget* MainWindow::addPanel(QWidget* panel, const QString& title, const QString& objectName,
                                  Qt::DockWidgetArea area, QMenu* toggleMenu) {
  QDockWidget* dock = addDock(panel, title, objectName, area);
  if (toggleMenu != nullptr) toggleMenu->addAction(dock->toggleViewAction());
  // Default layout: a feature's side panels join the studio's tab groups on their side (the
  // remembered layout, restored at the end of construction, overrides this).
  if (area == Qt::RightDockWidgetArea && rightTabs_ != nullptr) tabifyDockWidget(rightTabs_, dock);
  if (area == Qt::LeftDockWidgetArea && leftTabs_ != nullptr) tabifyDockWidget(leftTabs_, dock);
  if (area == Qt::BottomDockWidgetArea) resizeDocks({dock}, {kBottomDockHeightPx}, Qt::Vertical);
  return dock;
}

StudioShell MainWindow::makeShell() {
  StudioShell shell;
  shell.window = this;
  shell.doc = doc_;
  shell.canvas = canvas_;
  shell.statusBar = statusBar();
  shell.fileMenu = fileMenu_;
  shell.editMenu = editMenu_;
  shell.viewMenu = viewMenu_;
  shell.machineMenu = machineMenu_;
  shell.helpMenu = helpMenu_;
  shell.addPanel = [this](QWidget* panel, const QString& title, const QString& objectName,
                          Qt::DockWidgetArea area, QMenu* toggleMenu) {
    return addPanel(panel, title, objectName, area, toggleMenu);
  };
  return shell;
}

void MainWindow::createDocks() {
  // The side docks take the full height; the bottom dock (the console) spans the canvas only.
  setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
  setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
  auto* mode = addDock(new ModePanel(*doc_, *workspaceLayer_, *preview_, this),
                       tr("Workspace"), QStringLiteral("dockWorkspace"), Qt::LeftDockWidgetArea);
  placementPanel_ = new PlacementPanel(*doc_, this);
  auto* placement = addDock(placementPanel_, tr("Placement"),
                            QStringLiteral("dockPlacement"), Qt::LeftDockWidgetArea);
  auto* layers = addDock(new LayersPanel(*doc_, this), tr("Layers"), QStringLiteral("dockLayers"),
                         Qt::LeftDockWidgetArea);
  previewPanel_ = new PreviewPanel(*preview_, *jobLayer_, this);
  connect(previewPanel_, &PreviewPanel::showLocation, canvas_, &CanvasView::centerOn);
  auto* preview = addDock(previewPanel_, tr("Job preview"), QStringLiteral("dockPreview"),
                          Qt::RightDockWidgetArea);
  auto* sim = addDock(new SimulationPanel(*simulation_, *doc_, this), tr("Simulation"),
                      QStringLiteral("dockSimulation"), Qt::RightDockWidgetArea);
  tabifyDockWidget(placement, layers);
  resizeDocks({mode, placement, preview, sim}, {330, 420, 515, 325}, Qt::Vertical);
  leftTabs_ = layers;
  rightTabs_ = sim;
  // Fills of the next import (widgets/panels/fill_options_box.hpp) next to the layers; the import
  // warnings (widgets/panels/import_warnings_panel.hpp) at the bottom, raised when an import brings some.
  fillOptions_ = new FillOptionsBox(*importer_, *doc_, this);
  tabifyDockWidget(layers, addDock(fillOptions_, tr("Fills"),
                                   QStringLiteral("dockFills"), Qt::LeftDockWidgetArea));
  auto* warnings = new ImportWarningsPanel(this);
  auto* warningsDock = addDock(warnings, tr("Import warnings"), QStringLiteral("dockImportWarnings"),
                               Qt::BottomDockWidgetArea);
  connect(importer_, &ImportController::warningsReported, warnings, &ImportWarningsPanel::showWarnings);
  // The panel takes room only while the last import has warnings to read.
  warningsDock->hide();
  connect(importer_, &ImportController::warningsReported, warningsDock,
          [warningsDock](const QString&, const QStringList& list) { warningsDock->setVisible(!list.isEmpty()); });
  connect(warnings, &ImportWarningsPanel::attentionWanted, warningsDock, &QDockWidget::raise);
}

void MainWindow::createMenus() {
  QMenu* file = fileMenu_ = menuBar()->addMenu(tr("&File"));
  QAction* open = file->addAction(tr("&Open drawing or project..."), files_, &FileActions::open);
  open->setShortcut(QKeySequence::Open);
  recentMenu_ = file->addMenu(tr("Open &recent"));
  connect(importer_, &ImportController::recentFilesChanged, this, &MainWindow::rebuildRecentMenu);
  rebuildRecentMenu();
  file->addSeparator();
  QAction* save = file->addAction(tr("&Save project"), files_, &FileActions::save);
  save->setShortcut(QKeySequence::Save);
  save->setObjectName(QStringLiteral("actionSave"));
  QAction* saveAs = file->addAction(tr("Save project &as..."), files_, &FileActions::saveAs);
  saveAs->setShortcut(QKeySequence::SaveAs);
  saveAs->setObjectName(QStringLiteral("actionSaveAs"));
  file->addSeparator();
  QAction* exportGcode = file->addAction(tr("&Export G-code..."), files_, &FileActions::exportGcode);
  exportGcode->setShortcut(QKeySequence(tr("Ctrl+E")));
  exportGcode->setObjectName(QStringLiteral("actionExportGcode"));
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  QMenu* edit = editMenu_ = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = doc_->undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  undo->setObjectName(QStringLiteral("actionUndo"));
  QAction* redo = doc_->undoStack()->createRedoAction(this, tr("&Redo"));
  // Both usual redo keys on every platform (the platform's own first, for the menu's label).
  QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
  for (const QKeySequence& k : {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)})
    if (!redoKeys.contains(k)) redoKeys << k;
  redo->setShortcuts(redoKeys);
  redo->setObjectName(QStringLiteral("actionRedo"));
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  QAction* fit = edit->addAction(tr("&Fit drawing to workspace"), placementPanel_, &PlacementPanel::fitToWorkspace);
  fit->setShortcut(QKeySequence(tr("Ctrl+F")));
  edit->addAction(tr("&Actual size (100 %)"), placementPanel_, &PlacementPanel::actualSize)->setShortcut(QKeySequence(tr("Ctrl+1")));

  viewMenu_ = menuBar()->addMenu(tr("&View"));
  QAction* zoomIn = viewMenu_->addAction(tr("Zoom &in"), canvas_, &CanvasView::zoomIn);
  zoomIn->setShortcuts({QKeySequence::ZoomIn, QKeySequence(tr("Ctrl+="))});
  QAction* zoomOut = viewMenu_->addAction(tr("Zoom &out"), canvas_, &CanvasView::zoomOut);
  zoomOut->setShortcut(QKeySequence::ZoomOut);
  QAction* zoomFit = viewMenu_->addAction(tr("Zoom to &fit"), this, &MainWindow::fitView);
  zoomFit->setShortcut(QKeySequence(tr("Ctrl+0")));
  new LanguageMenu(viewMenu_, this);
  viewMenu_->addSeparator();
  for (QDockWidget* d : docks_) viewMenu_->addAction(d->toggleViewAction());

  QMenu* simulate = menuBar()->addMenu(tr("&Simulation"));
  QAction* play = simulate->addAction(tr("&Play / pause"), simulation_,
                                      &SimulationController::togglePlay);
  play->setShortcut(QKeySequence(tr("F5")));
  simulate->addAction(tr("Step &forward"), simulation_, &SimulationController::stepForward)
      ->setShortcut(QKeySequence(tr("F6")));
  simulate->addAction(tr("Step &back"), simulation_, &SimulationController::stepBackward)
      ->setShortcut(QKeySequence(tr("Shift+F6")));

  machineMenu_ = menuBar()->addMenu(tr("&Machine"));

  QMenu* help = helpMenu_ = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&About FiveBar Studio"), this, [this] {
    QMessageBox::about(this, tr("About FiveBar Studio"),
                       tr("<b>FiveBar Studio %1</b><p>Plans and simulates drawings for five-bar "
                          "linkage robots: workspace and singularity analysis, safe job "
                          "planning, GRBL output.</p>")
                           .arg(QApplication::applicationVersion()));
  });
  help_ = new HelpMenu(help, this);

  QToolBar* bar = addToolBar(tr("Main"));
  bar->setObjectName(QStringLiteral("toolbarMain"));
  bar->addAction(open);
  bar->addAction(save);
  bar->addAction(undo);
  bar->addAction(redo);
  bar->addSeparator();
  bar->addAction(zoomIn);
  bar->addAction(zoomOut);
  bar->addAction(zoomFit);
  bar->addSeparator();
  bar->addAction(play);
  bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
}

void MainWindow::rebuildRecentMenu() { files_->fillRecentMenu(recentMenu_); }

// The title names what Save writes: the project file, or, for a drawing not saved as a project
// yet, an untitled project (Save asks for a name) made from that drawing.
void MainWindow::updateTitle() {
  const QString project = doc_->projectPath();
  setWindowFilePath(project);
  if (!project.isEmpty())
    setWindowTitle(tr("%1[*] - FiveBar Studio").arg(QFileInfo(project).fileName()));
  else if (doc_->hasDrawing())
    setWindowTitle(tr("Untitled project (%1)[*] - FiveBar Studio").arg(QFileInfo(doc_->fileName()).fileName()));
  else
    setWindowTitle(tr("FiveBar Studio"));
  setWindowModified(doc_->isModified() && doc_->hasDrawing());
}

void MainWindow::fitView() {
  const Geometry& g = doc_->profile().geometry;
  const auto toRect = [](const BoxMm& b) {
    return QRectF(QPointF(b.min.x(), b.min.y()), QPointF(b.max.x(), b.max.y()));
  };
  const auto corners = doc_->hasDrawing() ? placementTool_->cornersMm() : std::nullopt;
  if (corners) {
    std::array<Vec2, 4> cornersMm;
    for (int i = 0; i < 4; ++i) cornersMm[i] = Vec2((*corners)[i].x(), (*corners)[i].y());
    canvas_->fitRect(toRect(drawingViewBoxMm(g, doc_->effectiveMode(), cornersMm)));
  } else {
    canvas_->fitRect(toRect(machineViewBoxMm(g)));
  }
}

void MainWindow::restoreLayout() {
  QSettings settings;
  if (!restoreGeometry(settings.value(kGeometryKey).toByteArray())) resize(1560, 960);
  if (!restoreState(settings.value(kStateKey).toByteArray(), kStateVersion)) {
    // First start: the studio's own panels in front of their tab groups, docks wide enough
    // for their forms.
    for (const char* name : {"dockPlacement", "dockSimulation"}) {
      if (auto* d = dock(QLatin1String(name))) d->raise();
    }
    auto* left = dock(QStringLiteral("dockWorkspace"));
    auto* right = dock(QStringLiteral("dockPreview"));
    if (left != nullptr && right != nullptr) {
      resizeDocks({left, right}, {kSideDockWidthPx, kSideDockWidthPx}, Qt::Horizontal);
    }
  }
}

void MainWindow::closeEvent(QCloseEvent* event) {
  // A running job first: quitting would cut the machine's stream mid-drawing.
  if (!machinePanels_->confirmClose() || !files_->maybeSave()) {
    event->ignore();
    return;
  }
  QSettings settings;
  settings.setValue(kGeometryKey, saveGeometry());
  settings.setValue(kStateKey, saveState(kStateVersion));
  event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const auto urls = event->mimeData()->urls();
  if (!urls.isEmpty() && urls.front().isLocalFile()) {
    files_->openPath(urls.front().toLocalFile());
    event->acceptProposedAction();
  }
}

}  // namespace fivebar::studio
