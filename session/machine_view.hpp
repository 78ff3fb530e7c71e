// SPDX-License-Identifier: GPL-3.0-or-later
// MachineView: the read-only view of the machine session every machine panel gets: connection,
// the board's reported state, the pen, the problem for the banner, the board's settings against
// the profile, with a signal for each change. It has no command: commands go through the ports
// a panel is handed (session/machine_ports.hpp).
#pragma once

#include <QObject>
#include <QString>
#include <optional>
#include <vector>

#include "session/machine_session.hpp"

namespace fivebar::session {

class MachineView : public QObject {
  Q_OBJECT
 public:
  // session must outlive the view.
  explicit MachineView(const MachineSession& session, QObject* parent = nullptr);

  bool isConnected() const { return session_.isConnected(); }
  bool isConnecting() const { return session_.isConnecting(); }
  QString linkName() const { return session_.linkName(); }
  grbl::MachineState state() const { return session_.state(); }
  const grbl::StatusReport* lastStatus() const { return session_.lastStatus(); }
  std::optional<JointAngles> motorAngles() const { return session_.motorAngles(); }
  std::optional<Vec2> penMm() const { return session_.penMm(); }
  PenState penState() const { return session_.penState(); }
  bool poseKnown() const { return session_.poseKnown(); }
  QString poseDoubtText() const { return session_.poseDoubtText(); }
  bool jobActive() const { return session_.jobActive(); }
  bool canFrame() const { return session_.canFrame(); }
  const MachineProblem& problem() const { return session_.problem(); }
  const MachineProfile& profile() const { return session_.profile(); }
  bool boardSettingsKnown() const { return session_.boardSettingsKnown(); }
  std::vector<setup::SettingDiff> settingDifferences() const { return session_.settingDifferences(); }

 signals:
  void connectionChanged(bool connected);
  void connectFailed(const QString& message);
  void aboutToDisconnect();
  void statusUpdated();
  void problemChanged();
  void jobActiveChanged(bool active);
  void penStateChanged();
  void boardSettingsChanged();
  void poseKnownChanged();
  void plannedJobChanged();

 private:
  const MachineSession& session_;
};

}  // namespace fivebar::session
