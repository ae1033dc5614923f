#pragma once
/// The Help menus' texts that both windows share: the table of keyboard shortcuts, built from a
/// window's own actions so it cannot drift from what the keys do, and the About box (versions
/// and the renderer in use). Each window's guide is its own (WorkbenchGuide.h, the editor's).

#include <QList>
#include <QString>

class QAction;
class QWidget;

namespace marbler::ui {

/// Every action of a window (its menus, toolbars and docks) that has a keyboard shortcut, in the
/// order the window made them.
QList<QAction*> shortcutActions(const QWidget* window);
/// An action's keys as the platform writes them ("Ctrl+S, F2"); empty for none.
QString shortcutKeys(const QAction* action);
/// An action's words as the guide shows them: "&Open designs…" -> "Open designs".
QString plainActionText(const QAction* action);
/// A user's words (a session's or a file's name) made fit for a button's or an action's label:
/// each '&' doubled, so "Tom & Jerry" shows as written and makes no keyboard mnemonic.
inline QString labelSafe(const QString& userText) {
    QString text = userText;
    return text.replace(QLatin1Char('&'), QStringLiteral("&&"));
}
/// The guide's table of shortcuts: keys (as the platform writes them), what they do, and the
/// menu that holds the action.
QString shortcutTableHtml(const QList<QAction*>& actions);

/// What the About box says.
struct AboutFacts {
    QString version;  ///< Marbler's
    QString qt;       ///< the Qt running, and the one built against when they differ
    QString imageIo;  ///< OpenImageIO's version, empty when its module is not loaded
    QString renderer; ///< the renderer in use and why; empty while it is being chosen
};
/// The About box's text.
QString aboutHtml(const AboutFacts& facts);
/// Marbler's version (the project's, from CMake).
QString marblerVersion();

} // namespace marbler::ui
