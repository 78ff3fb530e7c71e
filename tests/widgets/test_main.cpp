// SPDX-License-Identifier: GPL-3.0-or-later
// Widget tests run without a display: the offscreen platform is chosen here, before the
// QApplication exists, so that test discovery works on a headless machine too.
#include <gtest/gtest.h>

#include <QApplication>
#include <QSettings>
#include <QTemporaryDir>
#include <cstdlib>
#include <iostream>
#include <string>

#include "test_support.hpp"

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  // Each test process gets settings of its own (recent files, the remembered profile, window
  // state): runs of other builds or earlier runs on the same account cannot leak into a test.
  QTemporaryDir configHome;
  if (configHome.isValid()) qputenv("XDG_CONFIG_HOME", configHome.path().toLocal8Bit());
  QApplication app(argc, argv);
  // Keep the tests' recent files and window state away from the user's settings.
  QApplication::setOrganizationName(QStringLiteral("FiveBarTests"));
  QApplication::setApplicationName(QStringLiteral("fivebar_widgets_tests"));
  QSettings::setDefaultFormat(QSettings::IniFormat);
  ::testing::InitGoogleTest(&argc, argv);
  std::cout << "random seed " << fivebar::test::seed() << " (set FIVEBAR_TEST_SEED to change)\n";
  return RUN_ALL_TESTS();
}
