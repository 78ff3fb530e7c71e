// SPDX-License-Identifier: GPL-3.0-or-later
#include "pen_state.hpp"

namespace fivebar::grbl {

BoardPen penFromStatus(const ToolSettings& tool, const StatusReport& report, std::optional<double> workZ) {
  switch (tool.kind) {
    case ToolKind::ZAxis:
      if (!workZ) return BoardPen::Unknown;
      return *workZ <= 0.5 * (tool.zUpMm + tool.zDownMm) ? BoardPen::Down : BoardPen::Up;
    case ToolKind::Laser:
      if (!report.spindle) return BoardPen::Unknown;
      return *report.spindle > 0.0 ? BoardPen::Down : BoardPen::Up;
    case ToolKind::PenServo: {
      if (!report.spindle) return BoardPen::Unknown;
      const double s = *report.spindle;
      // M5 raises (penUpS 0), or M3 S<penUpS>: down when the speed is nearer penDownS.
      if (tool.penUpS <= 0.0) return s > 0.0 ? BoardPen::Down : BoardPen::Up;
      const bool downIsHigher = tool.penDownS > tool.penUpS;
      const double middle = 0.5 * (tool.penUpS + tool.penDownS);
      if (s <= 0.0) return BoardPen::Up;  // the servo holds no command: GRBL sends no PWM (M5)
      return (downIsHigher ? s >= middle : s <= middle) ? BoardPen::Down : BoardPen::Up;
    }
  }
  return BoardPen::Unknown;
}

}  // namespace fivebar::grbl
