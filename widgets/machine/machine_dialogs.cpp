// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/machine_dialogs.hpp"

#include <QCoreApplication>
#include <QMessageBox>
#include <QPushButton>

#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"
#include "session/machine_ports.hpp"

namespace fivebar::widgets {
namespace {


}  // namespace

QString referencePoseQuestion(const MachineProfile& profile) {
  return QCoreApplication::translate("fivebar::widgets::MachineDialogs", "Set the reference pose?\n\n"
            "The studio will take the machine's current position to be the home pose of "
            "\"%1\": motor 1 at %2°, motor 2 at %3°. Every later move is computed from it.\n\n"
            "Confirm only if the arms stand exactly in that pose now. If they stand elsewhere, "
            "moves will land in the wrong place and can drive the arms into each other or into "
            "the base.")
      .arg(QString::fromStdString(profile.name))
      .arg(degFromRad(profile.homeAngles.theta1), 0, 'f', 1)
      .arg(degFromRad(profile.homeAngles.theta2), 0, 'f', 1);
}

bool confirmReferencePose(QWidget* parent, const MachineProfile& profile) {
  QMessageBox box(QMessageBox::Warning, QCoreApplication::translate("fivebar::widgets::MachineDialogs", "Set reference pose"), referencePoseQuestion(profile),
                  QMessageBox::NoButton, parent);
  box.setObjectName(QStringLiteral("referencePoseQuestion"));
  QPushButton* yes = box.addButton(QCoreApplication::translate("fivebar::widgets::MachineDialogs", "The arms stand in the home pose: set it"), QMessageBox::AcceptRole);
  yes->setObjectName(QStringLiteral("confirmReference"));
  QPushButton* no = box.addButton(QMessageBox::Cancel);
  no->setText(QCoreApplication::translate("fivebar::widgets::MachineDialogs", "Cancel"));
  box.setDefaultButton(no);
  box.exec();
  return box.clickedButton() == yes;
}

void requestReferencePose(QWidget* parent, const MachineProfile& profile, session::RecoveryPort& recovery) {
  if (confirmReferencePose(parent, profile)) recovery.setReferencePose();
}

void requestHome(QWidget* parent, const MachineProfile& profile, session::RecoveryPort& recovery) {
  if (profile.hasHomingSwitches) {
    recovery.home();
    return;
  }
  if (confirmReferencePose(parent, profile)) recovery.home();
}

}  // namespace fivebar::widgets
