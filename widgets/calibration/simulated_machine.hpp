// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's simulated-machine settings (issue 13): the "true machine" the built-in simulated
// machine really is, when it differs from the profile (links longer or shorter, motor zeros off,
// play in the drives), so calibration can be tried without hardware.
//
// Lifetime, on purpose: the setting lives in SimulatedTruth, one per MachineSession. It is set in
// Machine > Simulated machine... (SimulatedMachineDialog) and saved in the studio's settings there;
// while it is imperfect the status bar says so (SimulatedTruthBadge) and the canvas shows what the
// simulated pen really drew (SimTraceLayer). A change applies at once, to the open simulated
// machine too (MachineSession::setSimulatedTrueMachine). The calibration wizard offers the same
// form; its changes are temporary and undone when the wizard closes, unless the maker keeps them.
#pragma once

#include <QDialog>
#include <QLabel>
#include <QObject>
#include <memory>
#include <vector>

#include "widgets/calibration/calibration_state.hpp"
#include "widgets/document/studio_document.hpp"

class QDoubleSpinBox;
class QMenu;
class QSettings;
class QStatusBar;

namespace fivebar::session {
class MachineSession;
}  // namespace fivebar::session

namespace fivebar::widgets {
class CanvasView;
}  // namespace fivebar::widgets

namespace fivebar::widgets::calibration {

class SimulatedTruth : public QObject {
  Q_OBJECT
 public:
  // Created by the composition root (one per machine session, as the session's child); starts
  // perfect, the saved setting is read by load().
  SimulatedTruth(const StudioDocument& doc, session::MachineSession& session);

  const TrueMachine& truth() const { return truth_; }
  bool active() const { return !truth_.perfect(); }
  // The profile's geometry the amounts are measured from (kept while the profile keeps its name,
  // e.g. when a calibration is applied: the real machine does not change with its profile).
  const Geometry& builtFrom() const { return truth_.builtFrom; }
  // Sets the true machine (its builtFrom is replaced by builtFrom()), applied to the session at
  // once. `persist`: also saved as the studio's setting (what load() reads next time).
  void setTruth(TrueMachine truth, bool persist);
  void makePerfect(bool persist) { setTruth(TrueMachine{}, persist); }
  // The saved setting (perfect when none), and applying it.
  TrueMachine saved() const;
  void load();
  // The amounts in words ("b1 +0.50 mm, motor 1 zero +1.00°, ..."); "" when perfect.
  QString describe() const;

  // Where the setting is saved: the studio's QSettings, or this INI file (tests).
  void setSettingsFile(const QString& path) { settingsFile_ = path; }

 signals:
  void changed();

 private:
  std::unique_ptr<QSettings> settings() const;
  void apply();
  void onProfileChanged();

  const StudioDocument& doc_;
  session::MachineSession& session_;
  TrueMachine truth_;
  std::string baseName_;  // the profile builtFrom belongs to
  QString settingsFile_;
};

// The form of a true machine: link lengths, motor distance, zero offsets and backlash, as amounts
// the real machine differs from the profile by.
class TrueMachineForm : public QWidget {
  Q_OBJECT
 public:
  explicit TrueMachineForm(QWidget* parent = nullptr);
  // Fields: da1, db1, da2, db2, dw (mm), zero offset 1, 2 (deg), backlash 1, 2 (deg).
  QDoubleSpinBox* field(int index) const { return fields_.at(static_cast<std::size_t>(index)); }
  static constexpr int kFields = 9;
  // The amounts (builtFrom left default) / shown without emitting edited().
  TrueMachine amounts() const;
  void setAmounts(const TrueMachine& truth);
  // An example of a maker's machine: links off by up to 0.5 mm, zeros by about 1 deg, some play.
  static TrueMachine example();

 signals:
  void edited();  // by the user (or a test) through a field

 private:
  std::vector<QDoubleSpinBox*> fields_;
  bool setting_ = false;
};

// Machine > Simulated machine...: the setting, applied at once and saved.
class SimulatedMachineDialog : public QDialog {
  Q_OBJECT
 public:
  SimulatedMachineDialog(SimulatedTruth& truth, QWidget* parent = nullptr);
  TrueMachineForm* form() const { return form_; }
  // Applies and saves the form (the OK button).
  void applyForm();

 private:
  SimulatedTruth& truth_;
  TrueMachineForm* form_ = nullptr;
};

// Shown in the status bar while the simulated machine is imperfect; a click opens the dialog.
class SimulatedTruthBadge : public QLabel {
  Q_OBJECT
 public:
  SimulatedTruthBadge(SimulatedTruth& truth, QWidget* parent = nullptr);
 signals:
  void clicked();

 protected:
  void mousePressEvent(QMouseEvent* event) override;

 private:
  void refresh();
  SimulatedTruth& truth_;
};

// The studio's composition of the above: the saved setting loaded, "Simulated machine..." in
// `menu`, the badge in `statusBar`, the pen's true trace on `canvas`.
void installSimulatedMachine(SimulatedTruth& truth, session::MachineSession& session, CanvasView& canvas,
                             QMenu& menu, QStatusBar& statusBar, QWidget* window);

}  // namespace fivebar::widgets::calibration
