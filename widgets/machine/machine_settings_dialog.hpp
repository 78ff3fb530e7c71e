// SPDX-License-Identifier: GPL-3.0-or-later
// Machine settings dialog: reads the board's GRBL settings ($$), shows them next to what the
// machine profile expects (drivers/check/machine_setup.hpp: steps/deg, rates, accelerations, soft
// limits...), and on confirmation saves a backup of the board's values to a file and writes the
// differences one at a time. All machine traffic goes through a SettingsSync the session hands
// out (BoardSettingsPort); the dialog sees the rest of the session only through MachineView.
#pragma once

#include <QDialog>
#include <QString>
#include <memory>
#include <vector>

#include "session/machine_ports.hpp"

class QLabel;
class QPushButton;
class QTableWidget;

namespace fivebar::session {
class BoardSettingsPort;
class MachineView;
}

namespace fivebar::widgets {


class MachineSettingsDialog : public QDialog {
  Q_OBJECT
 public:
  // backupDir: folder of the backup files written before any change (created when missing).
  MachineSettingsDialog(session::MachineView& view, session::BoardSettingsPort& settings, QString backupDir,
                        QWidget* parent = nullptr);
  ~MachineSettingsDialog() override;

  // Sends $$; false (with the reason in statusLabel) when the machine is not connected, a job
  // runs or a read/write is under way.
  bool readBoard();
  // Saves the backup, then writes the differences found by the last read; false when there is
  // nothing read, nothing to write, or the board is busy. No confirmation asked here.
  bool writeDifferences();

  setup::SetupState state() const;
  const std::vector<setup::SettingDiff>& differences() const { return diffs_; }
  QString backupPath() const { return backupPath_; }  // "" until a backup was written
  QTableWidget* table() const { return table_; }
  QLabel* statusLabel() const { return status_; }
  QPushButton* readButton() const { return readButton_; }
  QPushButton* writeButton() const { return writeButton_; }

 signals:
  void stateChanged();

 private:
  bool boardBusy(QString* why) const;
  void onSyncChanged();
  void fillTable();
  void confirmAndWrite();
  std::string saveBackup(const std::string& text);

  session::MachineView& view_;
  session::BoardSettingsPort& settings_;
  QString backupDir_;
  std::unique_ptr<setup::SettingsSync> sync_;
  setup::Settings wanted_;
  std::vector<setup::SettingDiff> diffs_;
  QString backupPath_;
  bool writing_ = false;
  QTableWidget* table_ = nullptr;
  QLabel* status_ = nullptr;
  QPushButton* readButton_ = nullptr;
  QPushButton* writeButton_ = nullptr;
};

}  // namespace fivebar::widgets
