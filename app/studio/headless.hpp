// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar-studio DRAWING.svg|PROJECT.fivebar [--machine PRESET|FILE] --export-gcode OUT.gcode:
// plans the input exactly as the studio window does (job/job_source.hpp, the document's
// default mode and tolerance, the placement chosen on import or saved in the project) and writes
// the G-code that Run would stream. Needs no display. Exit 0, 1 with the problems (stderr), 2 for
// bad arguments.
#pragma once

namespace fivebar::studio {

// True when the command line asks for the headless export (checked before any QApplication).
bool wantsHeadlessExport(int argc, char** argv);
int runHeadlessExport(int argc, char** argv);

}  // namespace fivebar::studio
