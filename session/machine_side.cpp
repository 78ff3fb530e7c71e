// SPDX-License-Identifier: GPL-3.0-or-later
#include "session/machine_side.hpp"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QThread>

namespace fivebar::session {

MachineSide::MachineSide(const StudioInputs& inputs, QObject* parent)
    : QObject(parent), session_(inputs), view_(session_), run_(inputs, session_), jog_(session_), console_(session_),
      preflight_(inputs, session_) {
  setObjectName(QStringLiteral("machineSide"));
}

bool MachineSide::connectSimulated(double speedup, QString* error) {
  QString why;
  if (!session_.connectSimulated(speedup, sim::Fault{}, &why)) {
    if (error) *error = why;
    return false;
  }
  // The simulated board starts at MPos 0,0 like a real one after power-up: the demo declares
  // the pose it stands in the home pose (G10 L20, shown in the machine console).
  session_.setReferencePose();
  return true;
}

bool MachineSide::stopRunForQuit() {
  if (!run_.running()) return true;
  run_.hold();
  run_.stop();
  // The stop sequence (hold, reset, unlock) runs on the event loop; its end saves the progress.
  QElapsedTimer clock;
  clock.start();
  while (run_.running() && clock.elapsed() < kStopWaitMs) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    QThread::msleep(5);
  }
  return !run_.running();
}

}  // namespace fivebar::session
