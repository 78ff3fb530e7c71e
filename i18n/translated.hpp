// SPDX-License-Identifier: GPL-3.0-or-later
// One message mechanism for every Qt front end: the core's messages (core/support/message.hpp)
// in the user's language: the template
// translated with QCoreApplication::translate(context, template) from translations/*.ts, real
// numbers written by QLocale (1,5 in German, French and Spanish), nested messages translated
// on their own; verbatim messages are shown as they are. The markers are substituted as
// QString::arg(a1, a2, ...) does (core substituteArgs), so the CLI's English and the studio's
// text differ only by the translation and the number format. Qt Core only (library
// fivebar::i18n): the job library, the session layer and the widgets all word core's codes with it.
#pragma once

#include <QLocale>
#include <QString>
#include <QStringList>
#include <vector>

#include "core/support/message.hpp"

namespace fivebar {

QString translated(const Message& message, const QLocale& locale = QLocale());
QStringList translated(const std::vector<Message>& messages, const QLocale& locale = QLocale());

}  // namespace fivebar
