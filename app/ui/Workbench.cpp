#include "ui/Workbench.h"

#include "ui/RenderService.h"
#include "ui/WorkbenchWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>
#include <QTimer>

#include <iostream>

namespace marbler::ui {

namespace {

/// `--screenshot FILE`: breed one generation from the middle design, wait for every final
/// image, save the window and quit. Used to make docs/screenshot.png reproducibly.
void takeScreenshot(WorkbenchWindow& window, RenderService& service, const QString& file, int* status) {
    auto grab = [&window, file, status] {
        if (!window.grab().save(file)) {
            std::cerr << "marbler: cannot write " << file.toStdString() << "\n";
            *status = 1;
        }
        QApplication::quit();
    };
    auto breedThenGrab = [&window, grab] {
        if (window.model()->cell(4)) {
            window.model()->clearSelection();
            window.model()->setSelected(4, true);
            window.applyOperator(GeneticOperator::Alter);
        }
        // Rendering restarts with the new generation; grab when it all has its final image.
        QObject::connect(&window, &WorkbenchWindow::renderingFinished, &window, grab, Qt::SingleShotConnection);
    };
    // Let the window settle at its size (the resize debounce) before breeding.
    QObject::connect(&service, &RenderService::backendReady, &window,
                     [breedThenGrab] { QTimer::singleShot(500, breedThenGrab); }, Qt::SingleShotConnection);
}

} // namespace

int runWorkbench(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Marbler"));
    QApplication::setApplicationName(QStringLiteral("Marbler"));
    QApplication::setApplicationVersion(QStringLiteral("0.1.0"));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Marbler evolution workbench"));
    QCommandLineOption screenshot(QStringLiteral("screenshot"), QStringLiteral("save a picture of the window and quit"),
                                  QStringLiteral("FILE"));
    screenshot.setFlags(QCommandLineOption::HiddenFromHelp);
    QCommandLineOption seed(QStringLiteral("seed"), QStringLiteral("the session seed"), QStringLiteral("N"));
    seed.setFlags(QCommandLineOption::HiddenFromHelp);
    QCommandLineOption solid(QStringLiteral("solid"), QStringLiteral("start with a solid population"));
    solid.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOptions({screenshot, seed, solid});
    parser.addPositionalArgument(QStringLiteral("genome"), QStringLiteral("designs to open"), QStringLiteral("[GENOME...]"));
    parser.process(app);

    RenderService service;
    WorkbenchWindow window(&service);
    if (parser.isSet(seed)) window.model()->setSessionSeed(parser.value(seed).toULongLong());
    const QStringList files = parser.positionalArguments();
    if (!files.isEmpty()) window.openFiles(files);
    if (!window.model()->cell(0) && window.model()->history().size() <= 1) {
        const int dimension = parser.isSet(solid) ? 3 : QSettings().value(QStringLiteral("population/dimension"), 2).toInt();
        window.newRandomPopulation(dimension);
    }
    int status = 0;
    if (parser.isSet(screenshot)) {
        window.resize(1280, 900);
        takeScreenshot(window, service, parser.value(screenshot), &status);
    }
    window.show();
    const int result = QApplication::exec();
    return status != 0 ? status : result;
}

} // namespace marbler::ui
