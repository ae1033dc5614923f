#include "ui/Workbench.h"

#include "ui/RenderService.h"
#include "ui/WorkbenchWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>
#include <QTimer>

#include <iostream>
#include <memory>

namespace marbler::ui {

namespace {

/// `--screenshot FILE`: breed one generation from the middle design, wait for every final
/// image, save the window and quit. Used to make docs/screenshot.png reproducibly.
void takeScreenshot(WorkbenchWindow& window, RenderService& service, const QString& file, int* status) {
    auto done = std::make_shared<bool>(false);
    auto grab = [&window, &service, file, status, done] {
        // Wait for the shelf's thumbnails too, not only the grid.
        if (*done || !window.renderingDone() || !service.idle()) return;
        *done = true;
        if (!window.grab().save(file)) {
            std::cerr << "marbler: cannot write " << file.toStdString() << "\n";
            *status = 1;
        }
        QApplication::quit();
    };
    auto breedThenGrab = [&window, &service, grab] {
        if (window.model()->cell(4)) {
            window.model()->clearSelection();
            window.model()->setSelected(4, true);
            window.applyOperator(GeneticOperator::Alter);
            // Show a stocked shelf, but only into a folder chosen for the picture.
            if (!qEnvironmentVariableIsEmpty("MARBLER_FAVOURITES_DIR")) {
                window.keepFavourite(0);
                window.keepFavourite(8);
            }
        }
        // Rendering restarts with the new generation; grab when it all has its final image.
        QObject::connect(&service, &RenderService::becameIdle, &window, grab);
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

    // main() treats a leading option as an unknown verb, so the hidden options can also come
    // from the environment: MARBLER_SCREENSHOT=FILE, MARBLER_SEED=N, MARBLER_SOLID=1.
    QString screenshotFile = parser.value(screenshot);
    if (screenshotFile.isEmpty()) screenshotFile = qEnvironmentVariable("MARBLER_SCREENSHOT");
    QString seedText = parser.value(seed);
    if (seedText.isEmpty()) seedText = qEnvironmentVariable("MARBLER_SEED");
    const bool startSolid = parser.isSet(solid) || qEnvironmentVariableIntValue("MARBLER_SOLID") == 1;

    RenderService service;
    WorkbenchWindow window(&service);
    if (!seedText.isEmpty()) window.model()->setSessionSeed(seedText.toULongLong());
    const QStringList files = parser.positionalArguments();
    if (!files.isEmpty()) window.openFiles(files);
    if (!window.model()->cell(0) && window.model()->history().size() <= 1) {
        const int dimension = startSolid ? 3 : QSettings().value(QStringLiteral("population/dimension"), 2).toInt();
        window.newRandomPopulation(dimension);
    }
    int status = 0;
    if (!screenshotFile.isEmpty()) {
        window.resize(1280, 900);
        takeScreenshot(window, service, screenshotFile, &status);
    }
    window.show();
    const int result = QApplication::exec();
    return status != 0 ? status : result;
}

} // namespace marbler::ui
