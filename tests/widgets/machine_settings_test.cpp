// SPDX-License-Identifier: GPL-3.0-or-later
// The machine settings dialog on the simulated machine: reading $$, the comparison with the
// profile, and writing the differences after a backup file.
#include <gtest/gtest.h>

#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <set>

#include "drivers/check/machine_setup.hpp"
#include "machine_test_support.hpp"
#include "widgets/machine/machine_settings_dialog.hpp"

namespace fivebar {
namespace {

using test::MachineRig;
using test::waitUntil;

bool settled(const widgets::MachineSettingsDialog& d) {
  return d.state() == setup::SetupState::Done || d.state() == setup::SetupState::Failed;
}

// The table row of setting `id` ("$id" in column 0), or -1.
int rowOf(const QTableWidget& table, int id) {
  for (int r = 0; r < table.rowCount(); ++r)
    if (table.item(r, 0)->text() == QStringLiteral("$%1").arg(id)) return r;
  return -1;
}

TEST(MachineSettingsDialog, RefusesWithoutAMachine) {
  MachineRig rig;
  QTemporaryDir dir;
  widgets::MachineSettingsDialog dialog(rig.view, rig.session, dir.path());
  EXPECT_FALSE(dialog.readBoard());
  EXPECT_TRUE(dialog.statusLabel()->text().contains(QStringLiteral("Connect")))
      << dialog.statusLabel()->text().toStdString();
  EXPECT_FALSE(dialog.writeDifferences());
  EXPECT_FALSE(dialog.writeButton()->isEnabled());
}

TEST(MachineSettingsDialog, FindsChangedSettingsAndWritesThemBackAfterABackup) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(20.0));
  ASSERT_TRUE(rig.waitIdle());
  const setup::Settings wanted = setup::expectedSettings(rig.session.profile());
  ASSERT_TRUE(wanted.count(100) && wanted.count(110));
  QTemporaryDir dir;
  widgets::MachineSettingsDialog dialog(rig.view, rig.session, dir.path() + QStringLiteral("/backups"));
  // What the fresh board already differs in (the simulator's defaults are GRBL's, not all the
  // profile's), compared on the board's own report.
  ASSERT_TRUE(dialog.readBoard());
  ASSERT_TRUE(waitUntil([&] { return settled(dialog); }, 5000));
  ASSERT_EQ(dialog.state(), setup::SetupState::Done) << dialog.statusLabel()->text().toStdString();
  std::set<int> expected;
  for (const auto& d : dialog.differences()) expected.insert(d.id);
  // Put two settings off the profile's values on the board.
  ASSERT_TRUE(rig.session.sendLine(QStringLiteral("$100=12.5")));
  ASSERT_TRUE(rig.session.sendLine(QStringLiteral("$110=%1").arg(wanted.at(110) * 0.5)));
  ASSERT_TRUE(waitUntil([&] { return rig.session.bytesInFlight() == 0; }, 5000));
  expected.insert({100, 110});

  ASSERT_TRUE(dialog.readBoard());
  ASSERT_TRUE(waitUntil([&] { return settled(dialog); }, 5000));
  ASSERT_EQ(dialog.state(), setup::SetupState::Done) << dialog.statusLabel()->text().toStdString();
  std::set<int> found;
  for (const auto& d : dialog.differences()) found.insert(d.id);
  EXPECT_EQ(found, expected);
  const int row = rowOf(*dialog.table(), 100);
  ASSERT_GE(row, 0);
  EXPECT_EQ(dialog.table()->item(row, 2)->text(), QStringLiteral("12.5"));
  EXPECT_FALSE(dialog.table()->item(row, 5)->text().isEmpty());  // marked as differing
  EXPECT_TRUE(dialog.table()->item(rowOf(*dialog.table(), 101), 5)->text().isEmpty());
  // Each setting says what it is and its unit: X and Y are the motor angles, in degrees.
  EXPECT_EQ(dialog.table()->item(row, 1)->text(), QStringLiteral("Motor 1 (X) steps per degree"));
  EXPECT_EQ(dialog.table()->item(row, 4)->text(), QStringLiteral("steps/deg"));
  EXPECT_EQ(dialog.table()->item(rowOf(*dialog.table(), 120), 4)->text(), QStringLiteral("deg/s^2"));
  EXPECT_TRUE(dialog.writeButton()->isEnabled());

  ASSERT_TRUE(dialog.writeDifferences());
  ASSERT_TRUE(waitUntil([&] { return settled(dialog); }, 5000));
  ASSERT_EQ(dialog.state(), setup::SetupState::Done) << dialog.statusLabel()->text().toStdString();
  // The backup holds the board's values before the write, and its path is shown.
  QFile backup(dialog.backupPath());
  ASSERT_TRUE(backup.open(QIODevice::ReadOnly)) << dialog.backupPath().toStdString();
  EXPECT_TRUE(backup.readAll().contains("$100=12.5"));
  EXPECT_TRUE(dialog.statusLabel()->text().contains(QFileInfo(dialog.backupPath()).fileName()));

  // Read again: the board now matches the profile.
  ASSERT_TRUE(dialog.readBoard());
  ASSERT_TRUE(waitUntil([&] { return settled(dialog); }, 5000));
  EXPECT_EQ(dialog.state(), setup::SetupState::Done);
  EXPECT_TRUE(dialog.differences().empty());
  EXPECT_FALSE(dialog.writeButton()->isEnabled());
}

}  // namespace
}  // namespace fivebar
