// SPDX-License-Identifier: GPL-3.0-or-later
// The `fivebar design --png` atlas, painted with widgets/design/design_painter when the CLI is
// built with Qt. Separate so that the command itself needs only the core.
#pragma once

#include <string>

#include "core/design/search.hpp"

namespace fivebar::cli {

// Writes the design's atlas (workspace, conditioning, transmission and resolution maps with the
// placed rectangle). Returns an error message, or an empty string on success.
std::string writeDesignPng(const std::string& path, const design::Design& d,
                           const design::DesignBrief& brief);

}  // namespace fivebar::cli
