// SPDX-License-Identifier: GPL-3.0-or-later
// Waiting on Qt's event loop in tests and screenshot tools: waitUntil runs events until a
// predicate holds or a timeout passes; settle runs them for a while; grab saves a settled widget's
// picture and says so on stdout. One copy for tests/widgets, tests/session and the screenshot tools.
#pragma once

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QString>
#include <QThread>
#ifdef QT_WIDGETS_LIB
#include <QWidget>
#endif
#include <cstdio>
#include <functional>

namespace fivebar::test {

inline bool waitUntil(const std::function<bool()>& pred, int timeoutMs) {
  QElapsedTimer clock;
  clock.start();
  while (!pred()) {
    if (clock.elapsed() > timeoutMs) return false;
    QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    QThread::msleep(1);
  }
  return true;
}

inline void settle(int ms) { waitUntil([] { return false; }, ms); }

#ifdef QT_WIDGETS_LIB  // tests/session links Qt Core only

// The widget's picture after `settleMs` of events, saved to path ("wrote PATH" or "FAILED PATH").
inline bool grab(QWidget& widget, const QString& path, int settleMs = 300) {
  settle(settleMs);
  const bool ok = widget.grab().save(path);
  std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
  return ok;
}
#endif

}  // namespace fivebar::test
