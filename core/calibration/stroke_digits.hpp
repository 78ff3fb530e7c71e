// SPDX-License-Identifier: GPL-3.0-or-later
// Simple stroke digits for the numbers a calibration pattern draws beside its marks: seven-segment
// shapes a pen draws in one to three strokes each, readable at 3 mm.
#pragma once

#include <string_view>
#include <vector>

#include "core/kinematics/geometry.hpp"

namespace fivebar {

// The strokes of `text` (digits only; other characters are skipped but advance) with the lower
// left corner of the first digit at `originMm`, digits `heightMm` tall and 2/3 as wide, upright
// in the frame of originMm, one digit advancing heightMm.
std::vector<std::vector<Vec2>> digitStrokes(std::string_view text, const Vec2& originMm,
                                            double heightMm);

// Width (mm) of the text digitStrokes draws.
double digitTextWidthMm(std::string_view text, double heightMm);

}  // namespace fivebar
