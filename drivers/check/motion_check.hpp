// SPDX-License-Identifier: GPL-3.0-or-later
// The one motion check of the machine link: every line that can move the machine (G0/G1 with X
// or Y, $J=, G28/G30, G53 moves) is read the way GRBL 1.1h reads it and its joint-linear moves
// are checked from the machine's current pose with core's checkJointMove / checkJointPath
// (workspace, joint limits, type II margin: exactly as jog and job moves are checked). Lines
// that cannot be checked are refused: G2/G3 (an arc in joint space is no arc on paper), G38
// probing, G20 (inches would scale the angles), coordinate changes G10/G92/G55-G59 (only the
// reference action, `fivebar reference`, sets coordinates). Non-motion lines and "$" commands
// pass. With the board's soft limits on ($20=1, travel $130/$131 known), every target is also
// checked in MACHINE coordinates (work + WCO) against the board's travel, as GRBL 1.1h does
// (soft_limits.hpp): a line the board would answer with ALARM:2 (or a jog with error:15) is
// refused before a byte is sent. Used by `fivebar send`, `fivebar stream` (the whole file before
// the first byte), the reference / home commands and the studio (console, jog, go-to, go to home,
// frame). Pure; X/Y are theta1/theta2 in degrees (work coordinates), Z in mm. Reasons are
// translatable Messages (context "MotionCheck"; the CLI prints their English text()).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/support/message.hpp"
#include "drivers/protocol/grbl_protocol.hpp"

namespace fivebar::motion {

using Axes3 = std::array<double, 3>;  // X, Y deg; Z mm

// What the check knows about the board: its work position, work offset (MPos = WPos + WCO),
// distance mode, the stored G28 / G30 positions (machine coordinates, from `$#`) and, when the
// board's soft limits are on ($20=1), their travel ($130, $131 in deg: targets must lie within
// -travel..0 in machine coordinates).
struct BoardPose {
  Axes3 workDeg{0.0, 0.0, 0.0};
  Axes3 wco{0.0, 0.0, 0.0};
  bool absolute = true;  // G90 (true) or G91
  std::optional<Axes3> g28Machine;
  std::optional<Axes3> g30Machine;
  std::optional<std::array<double, 2>> softTravelDeg;  // nullopt: soft limits off or not known
};

enum class Verdict {
  Pass,     // no motion of the joints (settings, spindle, Z only, ...): send it
  Motion,   // joint motion that passed the check: send it
  Refused,  // do not send; reason says why and what to do
};

struct LineCheck {
  Verdict verdict = Verdict::Pass;
  Message reason;                     // Refused: why, and what to do instead
  std::vector<Axes3> targetsWork;     // Motion: successive targets in work coordinates
  bool jog = false;                   // a $J= line
  bool systemCommand = false;         // a "$" line other than $J= (the pose may change: re-read it)
  bool ok() const { return verdict != Verdict::Refused; }
};

// The board's pose as the protocol knows it (work position, offset, stored G28/G30 from `$#`);
// nullopt while the work position is not known (no report yet, or MPos without a known WCO).
// The soft-limit travel comes from the board's settings as the protocol last saw them ($$).
std::optional<BoardPose> boardPoseOf(const grbl::GrblProtocol& protocol);

// Reads one line (comments and spaces allowed) against `pose` without checking the joints:
// which targets it moves to, or why it is refused. Does not change `pose`.
LineCheck interpretLine(std::string_view line, const BoardPose& pose);

// The pose after a line that interpretLine accepted (modal distance mode, final target).
void applyLine(std::string_view line, const LineCheck& check, BoardPose& pose);

// interpretLine plus the joint check of every move from pose.workDeg (checkJointMove in the
// profile's assembly mode). A current pose that does not pass checkPose is reported as such
// (the reference is probably not set).
LineCheck checkLine(const MachineProfile& profile, std::string_view line, const BoardPose& pose);

// The lines of a move planned on the host (jog, go-to, go to home pose, frame: the planner has
// checked every sub-move against the workspace, joint limits and singularity margin with the same
// core checks) read from `pose` one after another and checked against the board: the soft-limit
// travel and the lines the link refuses (arcs, coordinate changes...). `passing` leading lines
// may be sent; `reason` says why the next one may not.
struct LinesCheck {
  std::size_t passing = 0;
  Message reason;
  bool ok(std::size_t lineCount) const { return passing == lineCount; }
};
LinesCheck checkBoardLines(const std::vector<std::string>& lines, BoardPose pose);

// The advice in the reasons, in the CLI's words (nested messages, so that the studio can say
// them with its buttons): set the reference / home; choose a target inside the workspace.
Message referenceHint();
Message workspaceHint();

// "(12.345, -6.789) deg"
std::string anglesText(double theta1Deg, double theta2Deg);
Message anglesMessage(double theta1Deg, double theta2Deg);

// A whole G-code file checked before the first byte is sent: every line read from `start`
// (work coordinates, the job's start pose), every joint move checked along the path. The first
// problem names its file line.
struct FileCheck {
  bool ok = true;
  int fileLine = 0;       // 1-based line of the first problem
  std::string reason;     // "line 12 'G2X1Y1I1': ..."
  std::size_t motionLines = 0;
  std::optional<Axes3> firstTargetWork;  // where the first joint motion goes
};
// startWork nullopt: the job starts where its first joint motion goes (that move is the approach,
// checked by the caller from the machine's real pose).
FileCheck checkFile(const MachineProfile& profile, std::string_view text,
                    std::optional<Axes3> startWork);

// The header facts of a FiveBar job ("; profile: NAME", "; start pose X.. Y..") when present.
struct JobHeader {
  std::optional<std::string> profileName;
  std::optional<std::array<double, 2>> startDeg;
};
JobHeader readJobHeader(std::string_view text);

}  // namespace fivebar::motion
