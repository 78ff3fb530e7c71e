// SPDX-License-Identifier: GPL-3.0-or-later
// Shared pieces of the machine commands (stream, send, setup, reference, home): the Qt event
// loop, --baud parsing, and the warning --unchecked prints.
#pragma once

#include <QCoreApplication>
#include <clocale>
#include <string>

#include "options.hpp"

namespace fivebar::cli {

// QCoreApplication for a command that needs Qt's event loop.
struct QtApp {
  int argc = 1;
  char name[8] = "fivebar";
  char* argv[2] = {name, nullptr};
  QCoreApplication app{argc, argv};
  // QCoreApplication sets the C library's locale from the environment; CLI output and files
  // keep the decimal point.
  QtApp() { std::setlocale(LC_NUMERIC, "C"); }
};

inline int baudFrom(const Options& o) {
  const std::string b = o.value("--baud").value_or("115200");
  try {
    const int v = std::stoi(b);
    if (v > 0) return v;
  } catch (...) {
  }
  throw UsageError("--baud needs a positive integer, got '" + b + "'");
}

inline constexpr const char* kUncheckedWarning =
    "warning: --unchecked: motion lines go to the machine WITHOUT the safety check (workspace, "
    "joint limits, singularities); a wrong line can drive the arms into each other or the frame\n";

}  // namespace fivebar::cli
