// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar-studio --timings: how long the studio takes from opening a drawing to its planned
// preview, and each stage's wall and CPU time, printed to stderr in the form of
// `fivebar plan --timings`, so that the two can be compared on the same file
// (docs/performance.md, "Studio planning").
#pragma once

namespace fivebar::studio {

class MainWindow;

// Call just before the drawing is opened. Prints once the first plan after that import has
// finished ("opened and planned in N ms", the import, then the planner's stages and the
// studio's own), and after every later plan ("planned in N ms", from its start).
void printPlanTimings(MainWindow& window);

}  // namespace fivebar::studio
