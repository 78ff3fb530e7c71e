// SPDX-License-Identifier: GPL-3.0-or-later
#include "session/machine_view.hpp"

namespace fivebar::session {

MachineView::MachineView(const MachineSession& session, QObject* parent) : QObject(parent), session_(session) {
  connect(&session_, &MachineSession::connectionChanged, this, &MachineView::connectionChanged);
  connect(&session_, &MachineSession::connectFailed, this, &MachineView::connectFailed);
  connect(&session_, &MachineSession::aboutToDisconnect, this, &MachineView::aboutToDisconnect);
  connect(&session_, &MachineSession::statusUpdated, this, &MachineView::statusUpdated);
  connect(&session_, &MachineSession::problemChanged, this, &MachineView::problemChanged);
  connect(&session_, &MachineSession::jobActiveChanged, this, &MachineView::jobActiveChanged);
  connect(&session_, &MachineSession::penStateChanged, this, &MachineView::penStateChanged);
  connect(&session_, &MachineSession::poseKnownChanged, this, &MachineView::poseKnownChanged);
  connect(&session_, &MachineSession::plannedJobChanged, this, &MachineView::plannedJobChanged);
  connect(&session_, &MachineSession::boardSettingsChanged, this, &MachineView::boardSettingsChanged);
}

}  // namespace fivebar::session
