// SPDX-License-Identifier: GPL-3.0-or-later
#include "session/settings_advice.hpp"

#include <QCoreApplication>
#include <QStringList>

namespace fivebar::session {
namespace {


QString number(double v) { return QString::number(v, 'g', 8); }

// What the difference does on the machine, and whether it stops (or spoils) the job.
std::pair<QString, bool> meaningOf(const setup::SettingDiff& d) {
  const double board = d.board.value_or(0.0);
  switch (d.id) {
    case 20:
      if (board != 0.0)
        return {QCoreApplication::translate("fivebar::session::SettingsAdvice", "soft limits are on, but this machine has no homing switches: the board measures "
                   "its travel from where it was switched on, not from the reference pose, and "
                   "stops the job with ALARM:2 when a move leaves that range."),
                true};
      return {QCoreApplication::translate("fivebar::session::SettingsAdvice", "soft limits are off although the profile expects them."), false};
    case 21:
      return {board != 0.0 ? QCoreApplication::translate("fivebar::session::SettingsAdvice", "hard limits are on: without limit switches wired, noise on the "
                                "pins stops the machine with ALARM:1.")
                           : QCoreApplication::translate("fivebar::session::SettingsAdvice", "hard limits are off although the profile expects them."),
              board != 0.0};
    case 22:
      return {board != 0.0 ? QCoreApplication::translate("fivebar::session::SettingsAdvice", "the homing cycle is on: the board starts locked and wants $H, "
                                "which needs homing switches.")
                           : QCoreApplication::translate("fivebar::session::SettingsAdvice", "the homing cycle is off although the profile has switches."),
              board != 0.0};
    case 100:
    case 101:
      return {QCoreApplication::translate("fivebar::session::SettingsAdvice", "steps per degree differ: every motor angle would be wrong by the ratio, so the "
                 "arms would leave the checked, safe poses."),
              true};
    case 110:
    case 111:
    case 112:
      return {board < d.wanted ? QCoreApplication::translate("fivebar::session::SettingsAdvice", "the board's maximum rate is lower: the job runs slower than "
                                    "planned and the time estimate is off.")
                               : QCoreApplication::translate("fivebar::session::SettingsAdvice", "the board's maximum rate is higher than the profile allows: "
                                    "the motors may lose steps."),
              false};
    case 120:
    case 121:
    case 122:
      return {board < d.wanted ? QCoreApplication::translate("fivebar::session::SettingsAdvice", "the board accelerates more gently: the job takes longer "
                                    "than planned.")
                               : QCoreApplication::translate("fivebar::session::SettingsAdvice", "the board accelerates harder than the profile allows: the "
                                    "motors may lose steps."),
              false};
    case 130:
    case 131:
      return {QCoreApplication::translate("fivebar::session::SettingsAdvice", "the motor's travel for soft limits differs: with soft limits on, a move beyond "
                 "it stops the job with ALARM:2."),
              false};
    case 30:
    case 31:
    case 32:
      return {QCoreApplication::translate("fivebar::session::SettingsAdvice", "the spindle (pen servo / laser) range differs: the pen may not lift or lower as "
                 "planned."),
              false};
    case 11:
      return {QCoreApplication::translate("fivebar::session::SettingsAdvice", "the junction deviation differs: corners run at other speeds than planned."), false};
    default:
      return {QCoreApplication::translate("fivebar::session::SettingsAdvice", "differs from what the profile expects."), false};
  }
}

}  // namespace

std::vector<SettingAdvice> adviseOnSettings(const std::vector<setup::SettingDiff>& diffs) {
  std::vector<SettingAdvice> out;
  for (const setup::SettingDiff& d : diffs) {
    auto [meaning, stops] = meaningOf(d);
    const QString board = d.board ? number(*d.board) : QCoreApplication::translate("fivebar::session::SettingsAdvice", "not reported");
    out.push_back({d.id,
                   QCoreApplication::translate("fivebar::session::SettingsAdvice", "$%1 is %2 on the board, the profile wants %3: %4")
                       .arg(d.id)
                       .arg(board, number(d.wanted), meaning),
                   stops});
  }
  return out;
}

bool anyStopsJob(const std::vector<SettingAdvice>& advice) {
  for (const SettingAdvice& a : advice)
    if (a.stopsJob) return true;
  return false;
}

QString settingsWarningText(const std::vector<setup::SettingDiff>& diffs) {
  QStringList ids;
  for (const setup::SettingDiff& d : diffs) ids << QStringLiteral("$%1").arg(d.id);
  const auto advice = adviseOnSettings(diffs);
  QString text = QCoreApplication::translate("fivebar::session::SettingsAdvice", "The board's settings differ from the profile in %n place(s): %1.", nullptr, int(diffs.size()))
                     .arg(ids.join(QStringLiteral(", ")));
  if (anyStopsJob(advice)) text += QLatin1Char(' ') + QCoreApplication::translate("fivebar::session::SettingsAdvice", "A job would stop or move wrongly with them.");
  return text;
}

QString settingsMismatchText(const std::vector<setup::SettingDiff>& diffs) {
  const auto advice = adviseOnSettings(diffs);
  QString html = QStringLiteral("<p>") +
                 (anyStopsJob(advice)
                      ? QCoreApplication::translate("fivebar::session::SettingsAdvice", "The board's GRBL settings differ from the machine profile, and the job "
                           "would not run as planned:")
                      : QCoreApplication::translate("fivebar::session::SettingsAdvice", "The board's GRBL settings differ from the machine profile:")) +
                 QStringLiteral("</p><ul>");
  for (const SettingAdvice& a : advice)
    html += QStringLiteral("<li>%1%2%3</li>")
                .arg(a.stopsJob ? QStringLiteral("<b>") : QString(), a.text.toHtmlEscaped(),
                     a.stopsJob ? QStringLiteral("</b>") : QString());
  html += QStringLiteral("</ul><p>") +
          QCoreApplication::translate("fivebar::session::SettingsAdvice", "Write the profile's settings to the board (its current ones are saved to a backup "
             "file first), or start anyway.") +
          QStringLiteral("</p>");
  return html;
}

}  // namespace fivebar::session
