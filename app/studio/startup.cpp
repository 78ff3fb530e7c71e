// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/studio/startup.hpp"

#include <QApplication>
#include <QElapsedTimer>
#include <QPixmap>
#include <QTimer>
#include <cstdio>
#include <memory>

#include "app/studio/file_actions.hpp"
#include "app/studio/main_window.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/machine_panels.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/document/studio_document.hpp"
#include "widgets/document/simulation_controller.hpp"
#include "widgets/canvas/workspace_cache.hpp"
#include "widgets/canvas/workspace_layer.hpp"

namespace fivebar::studio {
namespace {
constexpr int kPollMs = 100;
constexpr int kSettleMs = 400;       // let the last repaint land after the plan arrives
constexpr qint64 kGiveUpMs = 120000;
}  // namespace

std::optional<MachineProfile> resolveProfile(const std::string& presetOrPath, std::string& error) {
  ProfileLoad load = resolveMachine(presetOrPath);
  if (load.profile) return load.profile;
  error.clear();
  for (const ValidationIssue& issue : load.issues) {
    if (!error.empty()) error += "\n";
    error += presetOrPath + ": " + issue.field + ": " + issue.message.text();
  }
  if (error.empty()) error = presetOrPath + ": cannot load the machine profile";
  return std::nullopt;
}

std::optional<MachineProfile> startupProfile(const std::optional<QString>& machineArg,
                                             std::string& error) {
  if (machineArg) return resolveProfile(machineArg->toStdString(), error);
  const QString remembered = FileActions::rememberedProfileJson();
  if (!remembered.isEmpty()) {
    if (auto p = profileFromJson(remembered.toStdString(), "remembered profile").profile) return p;
  }
  return resolveProfile("maker-plotter", error);
}

QString connectAtStart(MainWindow& window, const QString& port, const QString& baud) {
  std::optional<int> rate;
  if (!baud.isEmpty()) {
    bool ok = false;
    const int value = baud.toInt(&ok);
    if (!ok || value <= 0)
      return QStringLiteral("--baud: expected a positive whole number of bits per second, got '%1'").arg(baud);
    rate = value;
  }
  if (port.isEmpty()) return rate ? QStringLiteral("--baud needs --port") : QString();
  widgets::MachinePanel* panel = window.machinePanels().machinePanel();
  QTimer::singleShot(0, panel, [panel, port, rate] { panel->connectTo(port, rate); });
  return {};
}

void screenshotWhenReady(MainWindow& window, const QString& path, bool expectDrawing,
                         std::function<void()> beforeGrab) {
  auto* poll = new QTimer(&window);
  auto clock = std::make_shared<QElapsedTimer>();
  clock->start();
  auto planned = std::make_shared<bool>(!expectDrawing);
  QObject::connect(&window.preview(), &widgets::PreviewController::resultChanged, &window,
                   [&window, planned] {
                     if (window.document().hasDrawing()) *planned = true;
                   });
  QObject::connect(poll, &QTimer::timeout, &window, [&window, poll, clock, planned, path,
                                                     beforeGrab] {
    const bool ready = window.workspace().current() != nullptr && !window.importer().busy() &&
                       *planned && !window.preview().busy();
    if (!ready && clock->elapsed() < kGiveUpMs) return;
    poll->stop();
    if (beforeGrab) beforeGrab();
    QTimer::singleShot(kSettleMs, &window, [&window, path, ready] {
      const bool saved = window.grab().save(path, "PNG");
      if (!saved) std::fprintf(stderr, "fivebar-studio: cannot write %s\n", qPrintable(path));
      if (!ready) std::fprintf(stderr, "fivebar-studio: gave up waiting for the plan\n");
      QApplication::exit(saved && ready ? 0 : 1);
    });
  });
  poll->start(kPollMs);
}

QString applyViewOptions(MainWindow& window, const QStringList& overlays, const QString& atTime) {
  for (const QString& overlay : overlays) {
    widgets::WorkspaceOverlays o = window.workspaceLayer().overlays();
    if (overlay == QLatin1String("legend")) o.legend = true;
    else if (overlay == QLatin1String("transmission")) o.map = paint::MapKind::Transmission;
    else if (overlay == QLatin1String("conditioning")) o.map = paint::MapKind::Conditioning;
    else if (overlay == QLatin1String("resolution")) o.map = paint::MapKind::Resolution;
    else return QStringLiteral("--overlay: expected legend, transmission, conditioning or resolution, got '%1'").arg(overlay);
    window.workspaceLayer().setOverlays(o);
  }
  if (!atTime.isEmpty()) {
    bool ok = false;
    const double f = atTime.toDouble(&ok);
    if (!ok || f < 0.0 || f > 1.0) {
      return QStringLiteral("--at-time: expected a fraction from 0 to 1, got '%1'").arg(atTime);
    }
    widgets::SimulationController& sim = window.simulation();
    sim.setTimeS(f * sim.durationS());
  }
  return {};
}

}  // namespace fivebar::studio
