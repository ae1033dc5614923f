#include "workbench/HelpMenu.h"

#include "shared/Help.h"
#include "shared/RenderService.h"
#include "workbench/WorkbenchGuide.h"
#include "workbench/WorkbenchWindow.h"

#include "marbler/ImageFormats.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace marbler::ui {

HelpMenu::HelpMenu(WorkbenchWindow* window, RenderService* renderer)
    : QObject(window)
    , mWindow(window)
    , mRenderer(renderer) {
    QMenu* helpMenu = mWindow->menuBar()->addMenu(tr("&Help"));
    helpMenu->setObjectName(QStringLiteral("helpMenu"));
    mGuideAction = helpMenu->addAction(tr("Marbler &guide"), this, &HelpMenu::showGuide);
    mGuideAction->setShortcut(QKeySequence::HelpContents);
    mGuideAction->setStatusTip(tr("What the operators do, how to breed, and every keyboard shortcut"));
    helpMenu->addSeparator();
    mAboutAction = helpMenu->addAction(tr("&About Marbler"), this, &HelpMenu::showAbout);
    mAboutAction->setStatusTip(tr("Marbler's version, the libraries it runs with and the renderer in use"));
    mAboutQtAction = helpMenu->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
    mAboutQtAction->setStatusTip(tr("The Qt toolkit Marbler is built with"));
}

namespace {

/// A text window with a Close button: the guide and the About box.
QDialog* makeTextDialog(QWidget* parent, const QString& name, const QString& title, QWidget* body,
                        QSize size) {
    auto* dialog = new QDialog(parent);
    dialog->setObjectName(name);
    dialog->setWindowTitle(title);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    body->setParent(dialog);
    layout->addWidget(body, 1);
    layout->addWidget(buttons);
    dialog->resize(size);
    return dialog;
}

} // namespace

QDialog* HelpMenu::showGuide() {
    if (!mGuide) {
        auto* browser = new QTextBrowser;
        browser->setObjectName(QStringLiteral("guideBrowser"));
        browser->setOpenLinks(false);
        mGuide = makeTextDialog(mWindow, QStringLiteral("guideDialog"), tr("Marbler guide"), browser,
                                QSize(640, 720));
    }
    // Built each time it is shown, from the actions as they are now.
    mGuide->findChild<QTextBrowser*>(QStringLiteral("guideBrowser"))->setHtml(guideHtml(*mWindow));
    mGuide->show();
    mGuide->raise();
    mGuide->activateWindow();
    return mGuide;
}

QString HelpMenu::aboutText() const {
    AboutFacts facts;
    facts.version = marblerVersion();
    facts.qt = QString::fromLatin1(qVersion());
    if (facts.qt != QStringLiteral(QT_VERSION_STR))
        facts.qt = tr("%1 (built with %2)").arg(facts.qt, QStringLiteral(QT_VERSION_STR));
    if (const auto imageIo = loadedOpenImageIoVersion()) facts.imageIo = QString::fromStdString(*imageIo);
    facts.renderer = mWindow->rendererDescription();
    return aboutHtml(facts);
}

QDialog* HelpMenu::showAbout() {
    if (!mAbout) {
        auto* text = new QLabel;
        text->setObjectName(QStringLiteral("aboutText"));
        text->setWordWrap(true);
        text->setTextInteractionFlags(Qt::TextSelectableByMouse);
        text->setAlignment(Qt::AlignTop | Qt::AlignLeft);
        mAbout = makeTextDialog(mWindow, QStringLiteral("aboutDialog"), tr("About Marbler"), text,
                                QSize(520, 340));
        // The renderer may still be choosing, or change while the box is open.
        connect(mRenderer, &RenderService::backendReady, text, [this, text] { text->setText(aboutText()); });
    }
    // Filled each time it is shown: OpenImageIO may have loaded since.
    mAbout->findChild<QLabel*>(QStringLiteral("aboutText"))->setText(aboutText());
    mAbout->show();
    mAbout->raise();
    mAbout->activateWindow();
    return mAbout;
}

} // namespace marbler::ui
