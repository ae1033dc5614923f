#include "shared/Language.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QFile>
#include <QLibraryInfo>
#include <QLocale>
#include <QMainWindow>
#include <QMenu>
#include <QSettings>
#include <QStatusBar>
#include <QTranslator>

namespace marbler::ui {

namespace {

const QString SettingKey = QStringLiteral("ui/language");
const QString Folder = QStringLiteral(":/i18n");

QString languageText(const char* source) {
    return QCoreApplication::translate("Language", source);
}

/// The words Qt itself puts on the standard buttons of the window's dialogs and message boxes,
/// listed so that lupdate keeps them in Marbler's translations: Debian ships Qt's own
/// translations in another package (qt6-translations-l10n), which a machine may lack.
[[maybe_unused]] const char* const QtWords[][2] = {
    QT_TRANSLATE_NOOP("QPlatformTheme", "OK"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Save"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Save All"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Open"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "&Yes"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Yes to &All"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "&No"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "N&o to All"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Abort"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Retry"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Ignore"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Close"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Cancel"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Discard"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Help"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Apply"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Reset"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Restore Defaults"),
    QT_TRANSLATE_NOOP("QMessageBox", "Show Details..."),
    QT_TRANSLATE_NOOP("QMessageBox", "Hide Details..."),
};

/// Marbler's translation. Some files translate through a helper with a context of its own
/// (Help.cpp's "Help", ...), which lupdate cannot follow: it files their words under the
/// namespace's context, or QObject's, so a word missing under the context asked for is looked
/// for there too.
class MarblerTranslator : public QTranslator {
public:
    QString translate(const char* context, const char* source, const char* disambiguation,
                      int n) const override {
        QString found = QTranslator::translate(context, source, disambiguation, n);
        for (const char* fallback : {"marbler::ui", "QObject"})
            if (found.isNull()) found = QTranslator::translate(fallback, source, disambiguation, n);
        return found;
    }
};

QTranslator*& marblerTranslator() {
    static QTranslator* translator = nullptr;
    return translator;
}

QTranslator*& qtTranslator() {
    static QTranslator* translator = nullptr;
    return translator;
}

void removeTranslator(QTranslator*& translator) {
    if (!translator) return;
    QCoreApplication::removeTranslator(translator);
    delete translator;
    translator = nullptr;
}

bool haveTranslation(const QString& code) {
    return QFile::exists(Folder + QStringLiteral("/marbler_") + code + QStringLiteral(".qm"));
}

} // namespace

QList<Language> languages() {
    return {{QStringLiteral("en"), QStringLiteral("English")},
            {QStringLiteral("tr"), QStringLiteral("Türkçe")},
            {QStringLiteral("de"), QStringLiteral("Deutsch")}};
}

QString languageSetting() {
    return QSettings().value(SettingKey).toString();
}

void setLanguageSetting(const QString& code) {
    if (code.isEmpty())
        QSettings().remove(SettingKey);
    else
        QSettings().setValue(SettingKey, code);
}

QString chosenLanguage() {
    QString code = qEnvironmentVariable("MARBLER_LANGUAGE");
    if (code.isEmpty()) code = languageSetting();
    if (!code.isEmpty()) return code;
    // The first of the system's languages (LANGUAGE, then LC_ALL, LC_MESSAGES, LANG) that
    // Marbler speaks; English is the source, so it always does.
    for (const QString& name : QLocale::system().uiLanguages()) {
        const QString language = QLocale(name).name().section(QLatin1Char('_'), 0, 0);
        if (language == QLatin1String("en") || haveTranslation(language)) return language;
    }
    return QStringLiteral("en");
}

bool installLanguage(const QString& code) {
    removeTranslator(marblerTranslator());
    removeTranslator(qtTranslator());
    const bool system = QLocale::system().language() == QLocale(code).language();
    QLocale::setDefault(system || code == QLatin1String("en") ? QLocale::system() : QLocale(code));
    if (code == QLatin1String("en")) return true;
    auto* translator = new MarblerTranslator;
    if (!translator->load(QStringLiteral("marbler_") + code, Folder)) {
        delete translator;
        QLocale::setDefault(QLocale::system());
        return false;
    }
    marblerTranslator() = translator;
    // Qt's own words, where the machine has Qt's translations; installed first, so Marbler's
    // (which hold the standard buttons' words too) are asked before them.
    auto* qt = new QTranslator;
    if (qt->load(QStringLiteral("qtbase_") + code, QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        qtTranslator() = qt;
        QCoreApplication::installTranslator(qt);
    } else {
        delete qt;
    }
    QCoreApplication::installTranslator(translator);
    return true;
}

QString registryText(std::string_view text) {
    return QCoreApplication::translate("Registry", std::string(text).c_str());
}

QMenu* addLanguageMenu(QMenu* view, QWidget* window) {
    QMenu* menu = view->addMenu(languageText("&Language"));
    menu->setObjectName(QStringLiteral("languageMenu"));
    menu->setToolTipsVisible(true);
    auto* group = new QActionGroup(menu);
    const QString current = languageSetting();
    QList<Language> entries{{QString(), languageText("&System language")}};
    entries += languages();
    for (const Language& language : entries) {
        QAction* action = menu->addAction(language.name);
        action->setObjectName(QStringLiteral("language_") +
                              (language.code.isEmpty() ? QStringLiteral("system") : language.code));
        action->setCheckable(true);
        action->setChecked(language.code == current);
        action->setToolTip(languageText("The window's language from the next start of Marbler"));
        group->addAction(action);
        const QString code = language.code;
        QObject::connect(action, &QAction::triggered, window, [window, code] {
            setLanguageSetting(code);
            if (auto* main = qobject_cast<QMainWindow*>(window))
                main->statusBar()->showMessage(languageText("The language changes when Marbler starts again"),
                                               10000);
        });
    }
    return menu;
}

} // namespace marbler::ui
