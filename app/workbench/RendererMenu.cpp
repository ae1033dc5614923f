#include "workbench/RendererMenu.h"

#include "shared/RenderService.h"

#include <QAction>
#include <QActionGroup>
#include <QMainWindow>
#include <QMenu>
#include <QSettings>
#include <QStatusBar>

namespace marbler::ui {

RendererMenu::RendererMenu(QMainWindow* window, RenderService* renderer, QMenu* viewMenu)
    : QObject(window)
    , mWindow(window)
    , mRenderer(renderer) {
    viewMenu->addSeparator();
    QMenu* rendererMenu = viewMenu->addMenu(tr("&Renderer"));
    rendererMenu->setObjectName(QStringLiteral("rendererMenu"));
    rendererMenu->setToolTipsVisible(true);
    auto* group = new QActionGroup(rendererMenu);
    const auto addChoice = [&](gl::BackendPreference preference, const QString& text, const QString& tip) {
        QAction* action = rendererMenu->addAction(text);
        action->setCheckable(true);
        action->setChecked(mRenderer->preference() == preference);
        action->setToolTip(tip);
        action->setStatusTip(tip);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, preference] { setPreference(preference); });
        mActions[std::size_t(preference)] = action;
    };
    addChoice(
        gl::BackendPreference::Auto, tr("Renderer: &Automatic"),
        tr("OpenGL on a graphics card; the CPU where OpenGL is a software rasteriser (such as llvmpipe) or "
           "missing, since the CPU renderer is faster there"));
    addChoice(
        gl::BackendPreference::Gpu, tr("Renderer: &GPU"),
        tr("Always render with OpenGL shaders, even on a software rasteriser (the CPU where there is no "
           "OpenGL at all)"));
    addChoice(gl::BackendPreference::Cpu, tr("Renderer: &CPU"),
              tr("Always render with the CPU renderer on every core; solid objects are still rasterised by "
                 "OpenGL where it exists, and coloured by the CPU"));
    std::string problem;
    if (!gl::environmentBackendPreference(&problem) && !problem.empty())
        mWindow->statusBar()->showMessage(QString::fromStdString(problem), 10000);
    if (const auto forced = RenderService::environmentPreference()) {
        // The environment wins over the setting, so the menu only shows what it forces.
        const QString why = tr("%1=%2 is set, which overrides this setting")
                                .arg(QString::fromLatin1(gl::BackendEnvironmentVariable),
                                     QString::fromLatin1(gl::backendPreferenceName(*forced).data()));
        for (QAction* action : group->actions()) {
            action->setEnabled(false);
            action->setToolTip(why);
        }
        mActions[std::size_t(*forced)]->setChecked(true);
    }
    connect(mRenderer, &RenderService::backendReady, this, [this] {
        if (mAnnounce) {
            mAnnounce = false;
            mWindow->statusBar()->showMessage(description(), 8000);
        }
    });
}

void RendererMenu::setPreference(gl::BackendPreference preference) {
    QSettings().setValue(QStringLiteral("view/renderer"),
                         QString::fromLatin1(gl::backendPreferenceName(preference).data()));
    mActions[std::size_t(preference)]->setChecked(true);
    if (preference != mRenderer->preference()) {
        mAnnounce = true;
        mRenderer->setPreference(preference);
    }
}

QAction* RendererMenu::action(gl::BackendPreference preference) const {
    return mActions[std::size_t(preference)];
}

QString RendererMenu::description() const {
    if (mRenderer->backendName().isEmpty()) return {};
    const QString where = mRenderer->usesGl() ? tr("Rendering with %1").arg(mRenderer->backendName())
                                              : tr("Rendering on the %1").arg(mRenderer->backendName());
    const QString why = mRenderer->backendReason();
    return why.isEmpty() ? where : tr("%1: %2").arg(where, why);
}

} // namespace marbler::ui
