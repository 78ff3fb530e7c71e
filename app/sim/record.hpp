// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated machine's record file (JSON): what it drew and how the stream went, for tests
// and benchmarks. Format in docs/machine-protocol.md.
#pragma once

#include <string>

#include "drivers/sim/sim_machine.hpp"

namespace fivebar::simapp {

std::string recordJson(const sim::SimMachine& machine);
// Writes atomically; returns an error message or "".
std::string writeRecord(const sim::SimMachine& machine, const std::string& path);

// What the pen of the true machine drew (SimMachine::drawnTrace, machine frame, mm): an SVG
// when path ends in ".svg" (one <polyline> per pen-down stroke, 1 user unit = 1 mm, y up in the
// machine frame drawn up), otherwise CSV "stroke,x_mm,y_mm" (stroke numbered from 0). Written
// atomically; returns an error message or "".
std::string drawnText(const sim::SimMachine& machine, bool svg);
std::string writeDrawn(const sim::SimMachine& machine, const std::string& path);

}  // namespace fivebar::simapp
