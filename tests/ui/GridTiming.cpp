// ui_grid_timing: how long the window takes to show a new generation of nine 2D designs of 100
// operations each, first as previews, then sharp (the final rgss pass). A measuring tool, not
// a test: run it under a display (xvfb-run -a -s "-screen 0 1280x1024x24") and compare back
// ends with MARBLER_RENDERER=cpu or gpu.
//
//   ui_grid_timing [generations] [window width] [window height] [solid]
//
// With "solid", the nine designs are solid ones of 100 operations shown on the vase.

#include "marbler/Generator.h"
#include "marbler/Random.h"
#include "ui/DesignCell.h"
#include "ui/PopulationModel.h"
#include "ui/RenderService.h"
#include "ui/WorkbenchWindow.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

using namespace marbler;
using namespace marbler::ui;

namespace {

/// A random design with exactly `count` operations: its strokes, and initial drops topped up
/// (or cut) to the rest.
Genome designWithOperations(std::uint64_t seed, std::size_t count, int dimension) {
    Genome genome = randomGenome(seed, dimension);
    for (std::uint64_t extra = 1; genome.initial.size() + genome.operations.size() < count; ++extra) {
        Pcg32 rng(seed * 7919 + extra, 11);
        std::vector<Operation> more = randomInitial(rng, dimension, genome.size, int(genome.palette.size()));
        genome.initial.insert(genome.initial.begin(), more.begin(), more.end());
    }
    genome.operations.resize(std::min(genome.operations.size(), count));
    genome.initial.erase(genome.initial.begin(),
                         genome.initial.begin() +
                             std::ptrdiff_t(genome.initial.size() + genome.operations.size() - count));
    return genome;
}

} // namespace

int main(int argc, char** argv) {
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(
        QStringLiteral("MarblerTiming-%1").arg(QCoreApplication::applicationPid()));
    QApplication::setApplicationName(QStringLiteral("MarblerTiming"));
    const int generations = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    const int width = argc > 2 ? std::atoi(argv[2]) : 1180;
    const int height = argc > 3 ? std::atoi(argv[3]) : 860;
    const int dimension = argc > 4 && std::string(argv[4]) == "solid" ? 3 : 2;
    QTemporaryDir favourites;
    qputenv("MARBLER_FAVOURITES_DIR", favourites.path().toLocal8Bit());

    RenderService service;
    WorkbenchWindow window(&service);
    window.resize(width, height);
    window.show();
    QSignalSpy ready(&service, &RenderService::backendReady);
    if (service.backendName().isEmpty() && !ready.wait(60000)) return 1;
    // Let the layout and the resize debounce settle before timing.
    QElapsedTimer settle;
    settle.start();
    while (settle.elapsed() < 600)
        QApplication::processEvents(QEventLoop::AllEvents, 50);

    std::printf("back end: %s: %s\n", qPrintable(service.backendName()), qPrintable(service.backendReason()));
    std::printf("cell %dx%d, window %dx%d\n", window.cell(0)->width(), window.cell(0)->height(), width,
                height);
    std::vector<double> previews, finals;
    for (int g = 0; g < generations; ++g) {
        std::vector<Genome> designs;
        for (int i = 0; i < CellCount; ++i)
            designs.push_back(designWithOperations(std::uint64_t(1000 * g + i + 1), 100, dimension));
        int previewed = 0;
        double allPreviews = -1.0;
        QElapsedTimer clock;
        auto connection = QObject::connect(
            &service, &RenderService::rendered, [&](std::uint64_t key, const QImage&, bool final) {
                if (key < std::uint64_t(CellCount) && !final && ++previewed == CellCount)
                    allPreviews = double(clock.nsecsElapsed()) / 1e6;
            });
        QSignalSpy finished(&window, &WorkbenchWindow::renderingFinished);
        clock.start();
        window.model()->placeDesigns(designs, QStringLiteral("timing"));
        while (!window.renderingDone()) {
            if (!finished.wait(60000)) return 1;
        }
        const double done = double(clock.nsecsElapsed()) / 1e6;
        QObject::disconnect(connection);
        previews.push_back(allPreviews);
        finals.push_back(done);
        std::printf("generation %d: 9 previews %.1f ms, 9 sharp %.1f ms\n", g + 1, allPreviews, done);
    }
    std::sort(finals.begin(), finals.end());
    std::sort(previews.begin(), previews.end());
    std::printf("median: previews %.1f ms, sharp %.1f ms\n", previews[previews.size() / 2],
                finals[finals.size() / 2]);
    QSettings settings;
    settings.clear();
    return 0;
}
