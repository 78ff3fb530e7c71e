// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar_import_tests: QGuiApplication on the offscreen platform (Qt SVG text needs fonts), so
// test discovery and runs work without a display.
#include <gtest/gtest.h>
#include <QGuiApplication>

#include <cstdlib>
#include <iostream>
#include <string>

#include "../core/test_support.hpp"

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  std::cout << "random seed " << fivebar::test::seed() << " (set FIVEBAR_TEST_SEED to change)\n";
  return RUN_ALL_TESTS();
}
