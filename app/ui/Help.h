#pragma once
/// The Help menu's texts: the Marbler guide (what the operators do, how to pick parents, step
/// through generations, keep favourites and see a design large, and every keyboard shortcut)
/// and the About box (versions and the renderer in use). The shortcut table is built from the
/// window's own actions, so it cannot drift from what the keys do.

#include <QList>
#include <QString>

class QAction;
class QWidget;

namespace marbler::ui {

class WorkbenchWindow;

/// Every action of a window (its menus, toolbars and docks) that has a keyboard shortcut, in the
/// order the window made them.
QList<QAction*> shortcutActions(const QWidget* window);
/// An action's words as the guide shows them: "&Open designs…" -> "Open designs".
QString plainActionText(const QAction* action);
/// The guide's table of shortcuts: keys (as the platform writes them), what they do, and the
/// menu that holds the action.
QString shortcutTableHtml(const QList<QAction*>& actions);
/// The whole guide, in the words of the window's own actions.
QString guideHtml(const WorkbenchWindow& window);

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
