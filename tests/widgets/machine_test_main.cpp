// SPDX-License-Identifier: GPL-3.0-or-later
// Test main of the machine panels' tests: offscreen Qt (so discovery works without a display),
// a QApplication for the widgets, settings apart from the user's, and the printed, settable
// random seed.
#include <gtest/gtest.h>

#include <QApplication>
#include <QTemporaryDir>
#include <cstdlib>
#include <iostream>
#include <string>

#include "test_support.hpp"

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  // Settings of its own (recent ports, remembered profile), as tests/widgets/test_main.cpp.
  QTemporaryDir configHome;
  if (configHome.isValid()) qputenv("XDG_CONFIG_HOME", configHome.path().toLocal8Bit());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("FiveBarTests"));
  QApplication::setApplicationName(QStringLiteral("fivebar_machine_ui_tests"));
  ::testing::InitGoogleTest(&argc, argv);
  std::cout << "random seed " << fivebar::test::seed() << " (set FIVEBAR_TEST_SEED to change)\n";
  return RUN_ALL_TESTS();
}
