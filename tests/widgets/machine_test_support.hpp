// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers for the machine panels' tests: a document on a preset profile, a session connected to
// the in-process simulated machine, and waiting on the event loop with a deadline.
#pragma once

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QThread>
#include <cmath>
#include <functional>
#include <memory>

#include "core/machine/profile.hpp"
#include "session/machine_session.hpp"
#include "session/machine_view.hpp"
#include "tests/widgets/event_wait.hpp"
#include "session/console_port.hpp"
#include "session/jog_controller.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/document/studio_document.hpp"
#include "widgets/machine/document_inputs.hpp"

namespace fivebar::test {

inline MachineProfile makerPlotter() { return *preset("maker-plotter"); }

// A document, its preview, the session layer's view of both, a session and a jog controller;
// connect() opens the simulated machine and waits for it to report.
struct MachineRig {
  explicit MachineRig(MachineProfile profile = makerPlotter())
      : doc(std::move(profile)), preview(doc), inputs(doc, &preview), session(inputs), view(session), jog(session),
        consolePort(session) {}
  bool connect(double speedup, sim::Fault fault = {}) {
    QString error;
    if (!session.connectSimulated(speedup, fault, &error)) return false;
    if (!waitUntil([this] { return session.lastStatus() != nullptr &&
                                   session.state() != grbl::MachineState::Unknown; }, 5000))
      return false;
    // The simulated board starts at MPos 0,0 like a real one after power-up: declare its pose
    // the home pose, as a user does, unless a fault test wants the raw board.
    if (fault.kind == sim::FaultKind::AlarmAfter) return true;  // the alarm test wants it raw
    return setReference();
  }
  bool setReference() {
    session.setReferencePose();
    return waitUntil([this] {
      const auto q = session.motorAngles();
      const MachineProfile& p = doc.profile();
      return q && std::abs(q->theta1 - p.homeAngles.theta1) < 1e-3 &&
             std::abs(q->theta2 - p.homeAngles.theta2) < 1e-3;
    }, 5000);
  }
  bool waitIdle(int timeoutMs = 10000) {
    return waitUntil([this] { return session.state() == grbl::MachineState::Idle && session.jogSettled(); },
                     timeoutMs);
  }
  widgets::StudioDocument doc;
  widgets::PreviewController preview;
  widgets::DocumentInputs inputs;
  session::MachineSession session;
  session::MachineView view;  // the panels' read-only view; the session itself is every port
  session::JogController jog;
  session::ConsolePort consolePort;
};

}  // namespace fivebar::test

#include <QAbstractButton>
#include <QApplication>
#include <QMessageBox>
#include <QTimer>

namespace fivebar::test {

// Answers the next modal message box with this object name by clicking the button with
// buttonName (object name), or the standard button `standard` when buttonName is empty.
// *seenText receives the box's text.
inline void answerBox(const QString& boxName, const QString& buttonName,
                      QMessageBox::StandardButton standard = QMessageBox::Cancel,
                      QString* seenText = nullptr, int tries = 400) {
  QTimer::singleShot(10, [=] {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (box == nullptr || box->objectName() != boxName) {
      if (tries > 0) answerBox(boxName, buttonName, standard, seenText, tries - 1);
      return;
    }
    if (seenText) *seenText = box->text();
    QAbstractButton* button = buttonName.isEmpty() ? box->button(standard)
                                                   : box->findChild<QAbstractButton*>(buttonName);
    if (button == nullptr) button = box->buttons().front();
    button->click();
  });
}

}  // namespace fivebar::test
