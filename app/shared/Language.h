#pragma once
/// The window's language (issue 25). The window's words are English in the source, wrapped in
/// tr(); translations/marbler_LANG.ts hold the Turkish and German ones, compiled by lrelease
/// into the module's resources (:/i18n/marbler_LANG.qm). The command line stays English.
///
/// Which language: MARBLER_LANGUAGE (tr, de, en; for screenshots and tests), else the choice
/// remembered from View ▸ Language, else the system locale's. A choice in the menu applies
/// when Marbler starts again: the windows build their words once.

#include <QList>
#include <QString>

#include <string>
#include <string_view>

class QMenu;
class QWidget;

namespace marbler::ui {

/// A language the window speaks: its code ("tr") and its own name ("Türkçe").
struct Language {
    QString code;
    QString name;
};
/// The languages offered besides the system's: English (the source), Türkçe, Deutsch.
QList<Language> languages();

/// The language remembered from View ▸ Language: a code from languages(), or empty for the
/// system's.
QString languageSetting();
void setLanguageSetting(const QString& code);

/// The language the window speaks now: MARBLER_LANGUAGE, else languageSetting(), else the
/// system locale's when Marbler has a translation for it, else "en".
QString chosenLanguage();

/// Installs the translation of `code` into the application ("en" removes any), replacing one
/// installed before, and makes its locale the default one for numbers and dates (unless the
/// system's language is the one chosen). Windows made afterwards speak it. Returns false when
/// Marbler has no translation for `code`.
bool installLanguage(const QString& code);

/// A word of the registry (genome/, breed/: a parameter's label, unit or help, a tool's or a
/// family's name) in the window's language (context "Registry"; translations/registry_words.py
/// lists them for lupdate).
QString registryText(std::string_view text);

/// Adds "Language" to a window's View menu: System, English, Türkçe, Deutsch, the remembered
/// one checked; choosing one remembers it and says (in the status bar of `window` when it has
/// one) that it applies on the next start.
QMenu* addLanguageMenu(QMenu* view, QWidget* window);

} // namespace marbler::ui
