// SPDX-License-Identifier: GPL-3.0-or-later
// SVG path data ("d" attribute) parsing into absolute commands, and splitting of very long paths
// into several shorter "d" strings that draw the same geometry. Needed because Qt SVG 6.4 silently
// truncates a path after 32,767 QPainterPath elements.
#pragma once

#include <QString>
#include <QStringView>

#include <string>
#include <vector>

namespace fivebar::svg {

// An absolute command. op is one of M L C Q A Z; v holds its numbers in SVG order
// (M/L: x y; C: x1 y1 x2 y2 x y; Q: x1 y1 x y; A: rx ry angle large sweep x y).
struct PathCommand {
  char op = 'M';
  double v[7] = {};
};

struct ParsedPath {
  std::vector<PathCommand> commands;  // S/T/H/V and relative forms already made absolute
  bool error = false;                 // true when parsing stopped at bad data (a first command
                                      // that is not a moveto: error at its offset, no commands)
  qsizetype errorOffset = 0;          // character offset of the bad data
};

ParsedPath parsePathData(QStringView d);

// Largest sweep of one cubic our arc conversion makes (11.25 deg). Qt SVG 6.4 turns an arc into
// cubics of up to 90 deg (error 2.7e-4 x radius: 0.027 mm on r = 100 mm); the sanitiser hands Qt
// our cubics instead, whose error (<= 1.1e-9 x radius) the flattening takes from its tolerance
// (flatten.hpp arcPieceErrorBound).
inline constexpr double kArcPieceMaxRad = 0.19634954084936207;  // pi / 16

// Appends the cubics (op 'C') of the elliptical arc `arc` (op 'A', absolute) from (x0, y0): the
// SVG endpoint parametrisation (implementation notes F.6.5/F.6.6: radii scaled up when too small,
// a zero radius is a line, equal endpoints draw nothing), in equal pieces of at most
// kArcPieceMaxRad, each the standard cubic of its piece (control length 4/3 tan(sweep / 4)); the
// last one ends exactly at the arc's end point.
void appendArcAsCubics(double x0, double y0, const PathCommand& arc, std::vector<PathCommand>& out);

// The commands with every arc replaced by appendArcAsCubics.
std::vector<PathCommand> arcsAsCubics(const std::vector<PathCommand>& commands);

// Upper bound of the QPainterPath elements Qt SVG makes for a command (an arc becomes up to
// four cubics of three elements each).
int qtElementEstimate(const PathCommand& command);

// Splits the commands into "d" strings of at most maxElements estimated elements each. Each part
// starts with an absolute moveto at the current point; a closepath whose subpath began in an
// earlier part becomes a lineto to the subpath start.
std::vector<QString> splitPathData(const std::vector<PathCommand>& commands, int maxElements);

}  // namespace fivebar::svg
