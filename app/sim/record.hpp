// The simulated machine's record file (JSON): what it drew and how the stream went, for tests
// and benchmarks. Format in docs/machine-protocol.md.
#pragma once

#include <string>

#include "drivers/sim_machine.hpp"

namespace fivebar::simapp {

std::string recordJson(const sim::SimMachine& machine);
// Writes atomically; returns an error message or "".
std::string writeRecord(const sim::SimMachine& machine, const std::string& path);

}  // namespace fivebar::simapp
