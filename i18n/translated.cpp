// SPDX-License-Identifier: GPL-3.0-or-later
// Core messages in the user's language. Contract: translated.hpp.
#include "i18n/translated.hpp"

#include <QCoreApplication>

namespace fivebar {

QString translated(const Message& message, const QLocale& locale) {
  if (const Message* studio = message.studioWording()) return translated(*studio, locale);
  if (!message.translatable()) return QString::fromStdString(message.templ());
  const QString templ =
      QCoreApplication::translate(message.context().c_str(), message.templ().c_str());
  if (message.args().empty()) return templ;
  std::vector<std::string> args;
  args.reserve(message.args().size());
  for (const MessageArg& a : message.args()) {
    switch (a.kind) {
      case MessageArg::Kind::Text: args.push_back(a.text); break;
      case MessageArg::Kind::Number:
        args.push_back(locale.toString(a.value, a.significant ? 'g' : 'f', a.decimals).toStdString());
        break;
      case MessageArg::Kind::Nested: args.push_back(translated(*a.message, locale).toStdString()); break;
    }
  }
  return QString::fromStdString(substituteArgs(templ.toStdString(), args));
}

QStringList translated(const std::vector<Message>& messages, const QLocale& locale) {
  QStringList out;
  out.reserve(static_cast<qsizetype>(messages.size()));
  for (const Message& m : messages) out << translated(m, locale);
  return out;
}

}  // namespace fivebar
