// SPDX-License-Identifier: GPL-3.0-or-later
#include "grbl_codes.hpp"

#include <algorithm>
#include <array>

namespace fivebar::grbl {
namespace {

constexpr std::array<CodeInfo, 36> kErrors{{
    {1, "Expected command letter", "A word in the line did not start with a letter.",
     "Check the line for stray characters; G-code words are a letter followed by a number."},
    {2, "Bad number format", "A value was missing or not a valid number.",
     "Check the number after each letter of the line."},
    {3, "Invalid statement", "A '$' system command was not recognised or is not supported.",
     "Check the spelling of the $ command; send $ for the list GRBL knows."},
    {4, "Negative value", "A value that must be positive was negative.",
     "Use a positive value for this setting or word."},
    {5, "Setting disabled", "Homing was requested but homing is not enabled ($22).",
     "Enable homing with $22=1 on a machine with switches, or set the reference pose instead."},
    {6, "Step pulse too short", "The step pulse time must be at least 3 microseconds ($0).",
     "Set $0 to 3 or more."},
    {7, "EEPROM read fail", "Settings could not be read from EEPROM; defaults were restored.",
     "Re-write the machine settings (fivebar machine setup) and check the board."},
    {8, "Not idle", "This $ command needs the machine to be Idle.",
     "Wait until the machine is Idle (job finished or stopped), then send it again."},
    {9, "G-code lock", "G-code is locked out while the machine is in alarm or jog state.",
     "Unlock with '$X' (or home with '$H') after checking the machine, then resend."},
    {10, "Soft limits need homing", "Soft limits cannot be enabled without homing enabled.",
     "Enable homing ($22=1) before soft limits ($20=1), or leave soft limits off."},
    {11, "Line overflow", "The line was longer than GRBL's 80-character line buffer.",
     "Shorten the line: fewer decimals, no comments or spaces."},
    {12, "Step rate too high", "The value would make the step rate exceed 30 kHz.",
     "Lower the max speed or the steps per degree setting."},
    {13, "Safety door", "The safety door is open.", "Close the door, then resume with ~."},
    {14, "Line length exceeded", "A build-info or startup line exceeds the EEPROM line length.",
     "Use a shorter string."},
    {15, "Travel exceeded", "The jog target is outside the machine's soft limits.",
     "Jog a shorter distance, away from the joint limit."},
    {16, "Invalid jog command", "The $J= line lacked '=' or contained forbidden G-code.",
     "Jog lines carry only G20/G21, G90/G91, G53, axis words and F."},
    {17, "Laser mode needs PWM", "Laser mode requires PWM output on the spindle pin.",
     "Disable laser mode ($32=0) or use a build with variable spindle."},
    {20, "Unsupported command", "The line contains a G-code or M-code GRBL does not support.",
     "Remove the command; the studio never needs it."},
    {21, "Modal group violation", "Two commands from the same modal group are on one line.",
     "Split the line so each modal group appears once."},
    {22, "Undefined feed rate", "A feed move (G1) came before any feed rate F was set.",
     "Give the first G1 an F word."},
    {23, "Command value not integer", "A G or M command needs an integer value.",
     "Check the command number, e.g. G1 rather than G1.5."},
    {24, "Two axis commands", "Two commands that both use axis words are on one line.",
     "Split the line in two."},
    {25, "Repeated word", "A G-code word was repeated in the line.",
     "Remove the duplicate word."},
    {26, "No axis words", "The command needs axis words but the line has none.",
     "Add the X/Y target or remove the command."},
    {27, "Invalid line number", "The N line number is out of range.",
     "Use N numbers between 1 and 9999999 or leave them out."},
    {28, "Missing value word", "The command needs a P or L value that is missing.",
     "Add the missing word, e.g. G4 P0.15."},
    {29, "Work offset not supported", "G59.1, G59.2 and G59.3 are not supported.",
     "Use G54-G59."},
    {30, "G53 needs G0 or G1", "G53 is only allowed with G0 or G1 motion.",
     "Put G0 or G1 on the G53 line."},
    {31, "Unused axis words", "Axis words were given with a command that does not use them.",
     "Remove the axis words from this line."},
    {32, "Arc without in-plane axis", "G2/G3 arcs need at least one in-plane axis word.",
     "The studio never sends arcs to a joint-space machine; regenerate the job."},
    {33, "Invalid motion target", "The motion target is invalid (e.g. arc with equal ends).",
     "Regenerate the job; check the target of this line."},
    {34, "Arc radius error", "The arc radius computation failed.",
     "Regenerate the job without arcs."},
    {35, "Arc without offset", "G2/G3 in offset mode needs at least one in-plane offset word.",
     "Regenerate the job without arcs."},
    {36, "Unused value words", "The line has value words that no command used.",
     "Remove the unused words."},
    {37, "Tool offset axis", "G43.1 dynamic tool length offset is not on the tool axis.",
     "Remove G43.1 from the job."},
    {38, "Tool number too high", "The tool number is larger than GRBL supports.",
     "Use a tool number up to 255, or remove the T word."},
}};

constexpr std::array<CodeInfo, 9> kAlarms{{
    {1, "Hard limit", "A limit switch triggered; the position is lost.",
     "Check the machine for collisions, then re-home ('$H') or set the reference pose."},
    {2, "Soft limit", "A motion target was beyond the joint limits; the machine stopped.",
     "Soft-reset (Ctrl-X), unlock with '$X', then resume from the last drawn point."},
    {3, "Reset while in motion", "The board was reset during motion; the position may be lost.",
     "Unlock with '$X' and re-home or set the reference pose before resuming."},
    {4, "Probe fail", "The probe was not in the expected initial state.",
     "Check the probe wiring, then unlock with '$X'."},
    {5, "Probe fail", "The probe did not make contact within the search distance.",
     "Move closer or check the probe, then unlock with '$X'."},
    {6, "Homing fail: reset", "The board was reset during homing.",
     "Run homing ('$H') again."},
    {7, "Homing fail: door", "The safety door opened during homing.",
     "Close the door and run homing ('$H') again."},
    {8, "Homing fail: pull-off", "Pulling off did not clear the limit switch.",
     "Increase the pull-off ($27) or check the switch wiring, then home again."},
    {9, "Homing fail: no switch", "A limit switch was not found within the search distance.",
     "Check the switches and the homing direction ($23), then home again."},
}};

const CodeInfo* find(std::span<const CodeInfo> table, int code) {
  auto it = std::find_if(table.begin(), table.end(),
                         [code](const CodeInfo& c) { return c.code == code; });
  return it == table.end() ? nullptr : &*it;
}

std::string describe(const char* kind, const CodeInfo* info, int code) {
  std::string s = std::string(kind) + ":" + std::to_string(code);
  if (!info) return s + " (not a GRBL 1.1 code): see the board's documentation.";
  s += " (" + std::string(info->name) + "): " + std::string(info->meaning) + " " +
       std::string(info->action);
  return s;
}

}  // namespace

std::span<const CodeInfo> errorCodes() { return kErrors; }
std::span<const CodeInfo> alarmCodes() { return kAlarms; }
const CodeInfo* findError(int code) { return find(kErrors, code); }
const CodeInfo* findAlarm(int code) { return find(kAlarms, code); }
std::string describeError(int code) { return describe("error", findError(code), code); }
std::string describeAlarm(int code) { return describe("ALARM", findAlarm(code), code); }

}  // namespace fivebar::grbl
