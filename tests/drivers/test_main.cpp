// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QTemporaryDir>
#include <cstdlib>
#include <iostream>
#include <string>

#include "test_support.hpp"

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QCoreApplication app(argc, argv);
  // Where the host remembers each board's position (drivers/protocol/pose_trust.hpp): this run's own.
  QTemporaryDir state;
  qputenv("FIVEBAR_STATE_DIR", state.path().toUtf8());
  ::testing::InitGoogleTest(&argc, argv);
  std::cout << "random seed " << fivebar::test::seed() << " (set FIVEBAR_TEST_SEED to change)\n";
  return RUN_ALL_TESTS();
}
