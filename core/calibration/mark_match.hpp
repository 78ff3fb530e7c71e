// SPDX-License-Identifier: GPL-3.0-or-later
// Numbering found marks by matching them to the pattern: the sheet may be turned, shifted and
// mirrored (a rigid placement, no scale: the scan's dpi is known), and the drawn marks lie up to a
// few mm from their nominal places (that is what calibration measures). Hypotheses from pairs of
// far-apart marks, scored by how many marks land near a found one, refined by least squares.
// Qt-free; the image part is core/calibration/scan. docs/calibration-pattern.md "Scan".
#pragma once

#include "core/support/message.hpp"

#include <optional>
#include <string>
#include <vector>

#include "core/calibration/rigid_fit.hpp"
#include "core/kinematics/geometry.hpp"

namespace fivebar {

struct MatchOptions {
  double assignToleranceMm = 5.0;  // a found mark farther than this from a mark's place is not it
  double minFoundShare = 0.8;      // fewer matched marks than this share of the pattern: no match
};

struct MarkMatch {
  std::vector<int> foundOfMark;  // per nominal mark: index into `found`, or -1 when missing
  RigidFit machineFromPaper;     // the refined placement of the sheet
  int matched = 0;
  Message error;                 // no or an ambiguous match: why (translatable, CalibrationScan)
  bool ok() const { return error.empty(); }
};

// `found`: mark centres in the paper frame (mm); `nominal`: the pattern's marks (machine frame).
MarkMatch matchMarks(const std::vector<Vec2>& found, const std::vector<Vec2>& nominal,
                     const MatchOptions& options = {});

}  // namespace fivebar
