// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/machine_settings_dialog.hpp"

#include <QColor>
#include <QCoreApplication>
#include <QDateTime>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cstdio>
#include <set>

#include "core/output/grbl_setting_table.hpp"
#include "session/machine_ports.hpp"
#include "session/machine_view.hpp"

namespace fivebar::widgets {
namespace {

constexpr int kColumns = 6;        // setting, meaning, board, profile, unit, differs
constexpr int kMeaningColumn = 1;

QString valueText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return QString::fromLatin1(buf);
}

}  // namespace

MachineSettingsDialog::MachineSettingsDialog(session::MachineView& view, session::BoardSettingsPort& settings,
                                             QString backupDir, QWidget* parent)
    : QDialog(parent), view_(view), settings_(settings), backupDir_(std::move(backupDir)) {
  setObjectName(QStringLiteral("machineSettingsDialog"));
  setWindowTitle(tr("Machine settings"));
  auto* layout = new QVBoxLayout(this);
  auto* intro = new QLabel(tr("The board's GRBL settings next to the values the machine profile "
                              "needs. Writing saves a backup of the board's settings first."),
                           this);
  intro->setWordWrap(true);
  layout->addWidget(intro);
  // Each setting with its meaning and unit (core/output/grbl_setting_table.hpp: X and Y are
  // the motor angles, in degrees).
  table_ = new QTableWidget(0, kColumns, this);
  table_->setHorizontalHeaderLabels({tr("Setting"), tr("Meaning"), tr("Board"), tr("Profile"), tr("Unit"), tr("Differs")});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(kMeaningColumn, QHeaderView::Stretch);
  table_->verticalHeader()->setVisible(false);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  layout->addWidget(table_, 1);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(status_);
  auto* buttons = new QDialogButtonBox(this);
  readButton_ = buttons->addButton(tr("Read from board"), QDialogButtonBox::ActionRole);
  writeButton_ = buttons->addButton(tr("Write differences..."), QDialogButtonBox::ActionRole);
  buttons->addButton(QDialogButtonBox::Close);
  buttons->button(QDialogButtonBox::Close)->setText(tr("Close"));
  layout->addWidget(buttons);
  connect(readButton_, &QPushButton::clicked, this, [this] { readBoard(); });
  connect(writeButton_, &QPushButton::clicked, this, &MachineSettingsDialog::confirmAndWrite);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  // The sync listens on the link's protocol: drop it before the link goes away.
  connect(&view_, &session::MachineView::aboutToDisconnect, this, [this] {
    sync_.reset();
    writing_ = false;
    status_->setText(tr("The machine was disconnected."));
    onSyncChanged();
  });
  wanted_ = setup::expectedSettings(view_.profile());
  fillTable();
  onSyncChanged();
  resize(720, 560);
}

MachineSettingsDialog::~MachineSettingsDialog() = default;

setup::SetupState MachineSettingsDialog::state() const {
  return sync_ ? sync_->state() : setup::SetupState::Idle;
}

bool MachineSettingsDialog::boardBusy(QString* why) const {
  if (!view_.isConnected()) {
    *why = tr("Connect the machine first.");
  } else if (view_.jobActive()) {
    *why = tr("A job is running.");
  } else if (state() == setup::SetupState::Reading || state() == setup::SetupState::Writing) {
    *why = tr("Still talking to the board.");
  } else {
    const grbl::MachineState s = view_.state();
    if (s == grbl::MachineState::Idle || s == grbl::MachineState::Alarm) return false;
    *why = tr("The machine must be idle (or in alarm) to change settings.");
  }
  return true;
}

bool MachineSettingsDialog::readBoard() {
  QString why;
  if (boardBusy(&why)) {
    status_->setText(why);
    return false;
  }
  if (!sync_) {
    sync_ = settings_.makeSettingsSync();
    if (!sync_) {
      status_->setText(tr("Connect the machine first."));
      return false;
    }
    sync_->changed = [this] { onSyncChanged(); };
  }
  wanted_ = setup::expectedSettings(view_.profile());
  writing_ = false;
  diffs_.clear();
  sync_->read();
  status_->setText(tr("Reading the board's settings..."));
  onSyncChanged();
  return true;
}

bool MachineSettingsDialog::writeDifferences() {
  QString why;
  if (boardBusy(&why)) {
    status_->setText(why);
    return false;
  }
  if (!sync_ || sync_->state() != setup::SetupState::Done || writing_ || diffs_.empty()) {
    status_->setText(tr("Nothing to write: read the board's settings first."));
    return false;
  }
  writing_ = true;
  sync_->apply(diffs_, [this](const std::string& text) { return saveBackup(text); });
  onSyncChanged();
  return sync_->state() != setup::SetupState::Failed;
}

void MachineSettingsDialog::confirmAndWrite() {
  const auto answer = QMessageBox::question(
      this, tr("Write settings"),
      tr("Write %n setting(s) to the board? Its current settings are saved to a backup file "
         "first.", nullptr, int(diffs_.size())));
  if (answer == QMessageBox::Yes) writeDifferences();
}

// Writes the board's settings to a new file in backupDir_; returns "" or the error.
std::string MachineSettingsDialog::saveBackup(const std::string& text) {
  if (!QDir().mkpath(backupDir_)) return "cannot create folder " + backupDir_.toStdString();
  const QString name = QStringLiteral("grbl-settings-%1.txt")
                           .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz")));
  const QString path = QDir(backupDir_).filePath(name);
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
    return path.toStdString() + ": " + file.errorString().toStdString();
  const QByteArray bytes = QByteArray::fromStdString(text);
  if (file.write(bytes) != bytes.size() || !file.flush())
    return path.toStdString() + ": " + file.errorString().toStdString();
  backupPath_ = path;
  return {};
}

void MachineSettingsDialog::onSyncChanged() {
  const setup::SetupState s = state();
  if (s == setup::SetupState::Done && !writing_) {
    diffs_ = setup::compare(sync_->board(), wanted_);
    status_->setText(diffs_.empty()
                         ? tr("The board's settings match the profile.")
                         : tr("%n setting(s) differ from the profile.", nullptr, int(diffs_.size())));
  } else if (s == setup::SetupState::Done && writing_) {
    status_->setText(tr("%n setting(s) written. Backup of the previous settings: %1", nullptr,
                        int(diffs_.size()))
                         .arg(QDir::toNativeSeparators(backupPath_)));
  } else if (s == setup::SetupState::Writing) {
    status_->setText(tr("Writing settings one at a time... Backup: %1")
                         .arg(QDir::toNativeSeparators(backupPath_)));
  } else if (s == setup::SetupState::Failed) {
    status_->setText(tr("Failed: %1").arg(QString::fromStdString(sync_->problem())));
  }
  fillTable();
  const bool idle = s != setup::SetupState::Reading && s != setup::SetupState::Writing;
  readButton_->setEnabled(idle && view_.isConnected());
  writeButton_->setEnabled(idle && s == setup::SetupState::Done && !writing_ && !diffs_.empty());
  emit stateChanged();
}

// One row per setting the profile expects, plus any other setting the board reported.
void MachineSettingsDialog::fillTable() {
  const setup::Settings empty;
  const setup::Settings& board =
      sync_ && !sync_->board().empty() ? sync_->board() : empty;
  std::set<int> ids;
  for (const auto& [id, v] : wanted_) ids.insert(id);
  for (const auto& [id, v] : board) ids.insert(id);
  std::set<int> differing;
  for (const setup::SettingDiff& d : diffs_) differing.insert(d.id);
  table_->setRowCount(int(ids.size()));
  int row = 0;
  for (int id : ids) {
    const auto b = board.find(id);
    const auto w = wanted_.find(id);
    const GrblSettingInfo* info = grblSettingInfo(id);
    const QString cells[kColumns] = {
        QStringLiteral("$%1").arg(id),
        info ? QCoreApplication::translate("GrblSetting", info->meaning) : tr("(not a GRBL 1.1h setting)"),
        b == board.end() ? QStringLiteral("-") : valueText(b->second),
        w == wanted_.end() ? QStringLiteral("-") : valueText(w->second),
        info ? QString::fromUtf8(info->unit) : QString(),
        differing.count(id) ? tr("yes") : QString()};
    for (int c = 0; c < kColumns; ++c) {
      auto* item = new QTableWidgetItem(cells[c]);
      if (differing.count(id)) item->setForeground(QColor(0xdc, 0x26, 0x26));
      table_->setItem(row, c, item);
    }
    ++row;
  }
}

}  // namespace fivebar::widgets
