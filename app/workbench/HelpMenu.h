#pragma once
/// The workbench's Help menu: Marbler guide (F1), About Marbler, About Qt. Owns the actions and
/// the two text windows (not modal, one of each at a time, deleted on close); the guide's text
/// is built from the window's actions each time it is shown (Help.h).

#include <QObject>
#include <QPointer>

class QAction;
class QDialog;

namespace marbler::ui {

class RenderService;
class WorkbenchWindow;

class HelpMenu : public QObject {
    Q_OBJECT
public:
    /// Adds the Help menu to `window`'s menu bar. The render service must outlive it.
    HelpMenu(WorkbenchWindow* window, RenderService* renderer);

    QAction* guideAction() const { return mGuideAction; }
    QAction* aboutQtAction() const { return mAboutQtAction; }
    /// Shows the guide and returns it.
    QDialog* showGuide();
    /// Shows the About box and returns it.
    QDialog* showAbout();

private:
    /// The About box's text as things are now.
    QString aboutText() const;

    WorkbenchWindow* mWindow;
    RenderService* mRenderer;
    QAction* mGuideAction = nullptr;
    QAction* mAboutAction = nullptr;
    QAction* mAboutQtAction = nullptr;
    QPointer<QDialog> mGuide;
    QPointer<QDialog> mAbout;
};

} // namespace marbler::ui
