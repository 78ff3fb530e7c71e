// Widget tests run without a display: the offscreen platform is chosen here, before the
// QApplication exists, so that test discovery works on a headless machine too.
#include <gtest/gtest.h>

#include <QApplication>
#include <QSettings>
#include <cstdlib>
#include <iostream>
#include <string>

#include "test_support.hpp"

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  // Keep the tests' recent files and window state away from the user's settings.
  QApplication::setOrganizationName(QStringLiteral("FiveBarTests"));
  QApplication::setApplicationName(QStringLiteral("fivebar_widgets_tests"));
  QSettings::setDefaultFormat(QSettings::IniFormat);
  ::testing::InitGoogleTest(&argc, argv);
  std::cout << "random seed " << fivebar::test::seed() << " (set FIVEBAR_TEST_SEED to change)\n";
  return RUN_ALL_TESTS();
}
