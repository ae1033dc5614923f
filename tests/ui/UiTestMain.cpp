// The main of the window tests: a QApplication around gtest, headless where there is no display,
// with settings and data of its own (see below).
#include "UiTestSupport.h"

#include "editor/EditorWindow.h"
#include "shared/ErrorReport.h"

#include <QApplication>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileInfo>
#include <QMimeData>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <QUrl>
#include <QWidget>

#include <gtest/gtest.h>

namespace marbler::test {

void WindowTest::SetUp() {
    ASSERT_TRUE(mFavourites.isValid());
    qputenv("MARBLER_FAVOURITES_DIR", mFavourites.path().toLocal8Bit());
    mService = std::make_unique<ui::RenderService>(ui::RenderService::Backend::Cpu);
    mWindow = std::make_unique<ui::WorkbenchWindow>(mService.get());
    mWindow->model()->setSessionSeed(42);
    if (mPopulate) mWindow->newRandomPopulation(2);
}

ui::EditorWindow* EditorTest::open(const Genome& design, const QString& file) {
    auto* editor = new ui::EditorWindow(design, mService.get(), file, mWindow.get(), mRecovery.path());
    editor->setWindowFlag(Qt::Window);
    editor->setUnsavedAnswer(ui::EditorWindow::UnsavedAnswer::Discard);
    editor->resize(1200, 850);
    editor->show();
    EXPECT_TRUE(QTest::qWaitForWindowExposed(editor));
    return editor;
}

bool activate(QWidget* window) {
    for (int attempt = 0; attempt < 3; ++attempt) {
        window->raise();
        window->activateWindow();
        if (QTest::qWaitForWindowActive(window, 3000)) return true;
    }
    return false;
}

void WindowTest::TearDown() {
    mWindow.reset();
    mService.reset();
    qunsetenv("MARBLER_FAVOURITES_DIR");
}

ErrorCapture::ErrorCapture() {
    ui::setErrorHandler([this](QWidget*, const QString& title, const QString& message) {
        messages << title + QStringLiteral(": ") + message;
    });
}

ErrorCapture::~ErrorCapture() {
    ui::setErrorHandler({});
}

void dropFiles(QWidget* target, const QStringList& files) {
    QMimeData mime;
    QList<QUrl> urls;
    for (const QString& f : files)
        urls << QUrl::fromLocalFile(f);
    mime.setUrls(urls);
    const QPoint pos = target->rect().center();
    QDragEnterEvent enter(pos, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(target, &enter);
    ASSERT_TRUE(enter.isAccepted());
    QDropEvent drop(pos, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(target, &drop);
}

} // namespace marbler::test

int main(int argc, char** argv) {
    // Headless by default: with no display, Qt's offscreen platform (the CPU fallback renders).
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") &&
        qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    // Keep the user's settings and data out of the tests.
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    // ctest runs test cases as parallel processes: each process gets settings of its own, so
    // one test's remembered choices never leak into another running beside it.
    QApplication::setOrganizationName(
        QStringLiteral("MarblerTest-%1").arg(QCoreApplication::applicationPid()));
    QApplication::setApplicationName(QStringLiteral("MarblerTest"));
    ::testing::InitGoogleTest(&argc, argv);
    int status = RUN_ALL_TESTS();
    QSettings settings;
    settings.clear();
    settings.sync();
    QFile::remove(settings.fileName());
    QDir().rmdir(QFileInfo(settings.fileName()).absolutePath());
    return status;
}
