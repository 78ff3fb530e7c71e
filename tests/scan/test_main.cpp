// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <QGuiApplication>
#include <cstdlib>
#include <iostream>

#include "test_support.hpp"

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);  // fonts and image plugins
  ::testing::InitGoogleTest(&argc, argv);
  std::cout << "random seed " << fivebar::test::seed() << " (set FIVEBAR_TEST_SEED to change)\n";
  return RUN_ALL_TESTS();
}
