// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/studio/language_menu.hpp"

#include <QActionGroup>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

namespace fivebar::studio {
namespace {
const QString kKey = QStringLiteral("view/language");
}  // namespace

QString LanguageMenu::remembered() { return QSettings().value(kKey).toString(); }

void LanguageMenu::remember(const QString& code) { QSettings().setValue(kKey, code); }

LanguageMenu::LanguageMenu(QMenu* view, QWidget* window) : QObject(window), window_(window) {
  QMenu* menu = view->addMenu(tr("&Language"));
  menu->setObjectName(QStringLiteral("languageMenu"));
  auto* group = new QActionGroup(menu);
  // Each language in its own name, so that anyone finds theirs in any language.
  const std::pair<QString, QString> choices[] = {
      {QString(), tr("System default")},
      {QStringLiteral("de"), QStringLiteral("Deutsch")},
      {QStringLiteral("en"), QStringLiteral("English")},
      {QStringLiteral("es"), QStringLiteral("Español")},
      {QStringLiteral("fr"), QStringLiteral("Français")},
  };
  const QString current = remembered();
  for (const auto& [code, name] : choices) {
    QAction* action = menu->addAction(name);
    action->setCheckable(true);
    action->setChecked(code == current);
    action->setData(code);
    group->addAction(action);
    connect(action, &QAction::triggered, this, [this, code] {
      if (code == remembered()) return;
      remember(code);
      QMessageBox::information(window_, tr("Language"),
                               tr("The new language applies when FiveBar Studio starts again."));
    });
  }
}

}  // namespace fivebar::studio
