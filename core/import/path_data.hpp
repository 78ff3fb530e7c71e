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
  bool error = false;                 // true when parsing stopped at bad data
  qsizetype errorOffset = 0;          // character offset of the bad data
};

ParsedPath parsePathData(QStringView d);

// Upper bound of the QPainterPath elements Qt SVG makes for a command (an arc becomes up to
// four cubics of three elements each).
int qtElementEstimate(const PathCommand& command);

// Splits the commands into "d" strings of at most maxElements estimated elements each. Each part
// starts with an absolute moveto at the current point; a closepath whose subpath began in an
// earlier part becomes a lineto to the subpath start.
std::vector<QString> splitPathData(const std::vector<PathCommand>& commands, int maxElements);

}  // namespace fivebar::svg
