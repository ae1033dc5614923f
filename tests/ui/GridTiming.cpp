// ui_grid_timing: how long the window takes to show a new generation of nine 2D designs of 100
// operations each, first as previews, then sharp (the final rgss pass). A measuring tool, not
// a test: run it under a display (xvfb-run -a -s "-screen 0 1280x1024x24") and compare back
// ends with MARBLER_RENDERER=cpu or gpu.
//
//   ui_grid_timing [generations] [window width] [window height] [solid]
//   ui_grid_timing zoom [steps] [view side]
//
// With "solid", the nine designs are solid ones of 100 operations shown on the vase. With
// "zoom", a design of 100 operations is opened large (a square view of the given side, 900 by
// default) and zoomed in a step (√2) at a time about a point off its centre: each step's time
// from the wheel to the sharp image of the new view (the scaled stand-in shows at once, then the
// quick pass, then the final one).

#include "marbler/Generator.h"
#include "marbler/Random.h"
#include "shared/DesignDialog.h"
#include "shared/RenderService.h"
#include "workbench/DesignCell.h"
#include "workbench/PopulationModel.h"
#include "workbench/WorkbenchWindow.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
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

/// The "zoom" mode (see the top of the file); returns the exit status.
int timeZoom(int steps, int side) {
    RenderService service;
    WorkbenchWindow window(&service);
    const std::vector<int> cells =
        window.model()->placeDesigns({designWithOperations(7, 100, 2)}, QStringLiteral("timing"));
    DesignDialog* dialog = cells.empty() ? nullptr : window.openDesign(cells.front());
    if (!dialog) return 1;
    dialog->canvas()->setFixedSize(side, side);
    dialog->adjustSize();
    QElapsedTimer clock;
    clock.start();
    const auto waitFinal = [&] {
        while (!dialog->imageIsFinal())
            if (clock.elapsed() > 120000)
                return false;
            else
                QApplication::processEvents(QEventLoop::AllEvents, 5);
        return true;
    };
    if (!waitFinal()) return 1;
    std::printf("back end: %s; view %dx%d\n", qPrintable(service.backendName()), side, side);
    std::vector<double> times;
    for (int k = 0; k < steps; ++k) {
        clock.restart();
        dialog->zoomAt(std::sqrt(2.0), QPointF(side * 0.3, side * 0.4));
        const double standIn = double(clock.nsecsElapsed()) / 1e6;
        if (!waitFinal()) return 1;
        times.push_back(double(clock.nsecsElapsed()) / 1e6);
        std::printf("zoom %s: stand-in %.1f ms, sharp %.1f ms\n", qPrintable(dialog->zoomText()), standIn,
                    times.back());
    }
    std::sort(times.begin(), times.end());
    std::printf("median: sharp %.1f ms after a zoom step\n", times[times.size() / 2]);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(
        QStringLiteral("MarblerTiming-%1").arg(QCoreApplication::applicationPid()));
    QApplication::setApplicationName(QStringLiteral("MarblerTiming"));
    if (argc > 1 && std::string(argv[1]) == "zoom") {
        const int status =
            timeZoom(argc > 2 ? std::max(1, std::atoi(argv[2])) : 8, argc > 3 ? std::atoi(argv[3]) : 900);
        QSettings().clear();
        return status;
    }
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
