// fivebar_import_tests: QGuiApplication on the offscreen platform (Qt SVG text needs fonts), so
// test discovery and runs work without a display.
#include <gtest/gtest.h>
#include <QGuiApplication>

#include <cstdlib>
#include <iostream>
#include <string>

#include "../core/test_support.hpp"

namespace fivebar::test {
std::uint64_t seed() {
  static const std::uint64_t s = [] {
    const char* env = std::getenv("FIVEBAR_TEST_SEED");
    return env ? std::stoull(env) : std::uint64_t{20261122};
  }();
  return s;
}
}  // namespace fivebar::test

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  std::cout << "random seed " << fivebar::test::seed() << " (set FIVEBAR_TEST_SEED to change)\n";
  return RUN_ALL_TESTS();
}
