#pragma once
/// View ▸ Renderer: Automatic, GPU or CPU, remembered in the settings (an environment variable
/// overrides it, and the menu then says so), and which renderer took over said on the status bar
/// once the service has chosen again. Owns the three entries.

#include "marbler/gl/Backend.h"

#include <QObject>
#include <QString>

#include <array>

class QAction;
class QMainWindow;
class QMenu;

namespace marbler::ui {

class RenderService;

class RendererMenu : public QObject {
    Q_OBJECT
public:
    /// Adds the Renderer menu to `viewMenu`. The render service must outlive it.
    RendererMenu(QMainWindow* window, RenderService* renderer, QMenu* viewMenu);

    /// See WorkbenchWindow::setRendererPreference.
    void setPreference(gl::BackendPreference preference);
    QAction* action(gl::BackendPreference preference) const;
    /// See WorkbenchWindow::rendererDescription.
    QString description() const;

private:
    QMainWindow* mWindow;
    RenderService* mRenderer;
    std::array<QAction*, 3> mActions{}; ///< by gl::BackendPreference
    bool mAnnounce = false;             ///< the user switched renderer: say which one took over
};

} // namespace marbler::ui
