// ui_stroke_timing: how fast the editor's canvas follows a free-hand stylus stroke on the CPU.
// A measuring tool, not a test: run it under a display (xvfb-run -a -s "-screen 0 1280x1024x24").
//
//   ui_stroke_timing [drops] [canvas side] [seconds] [tines]
//
// A design of `drops` drops (200 by default) in a grid over a 1000-unit bath is shown on a
// square canvas (700 pixels by default) with the stylus tool; the pointer then draws a wavy
// stroke across it, one move every 16 ms (a 60 Hz mouse), for `seconds` (4 by default). It
// prints the live previews the canvas received a second while drawing (the frame rate), their
// size, the pointer moves the canvas handled a second, and the time from the release to the
// sharp image of the committed stroke.

#include "editor/EditorCanvas.h"
#include "marbler/Params.h"
#include "shared/RenderService.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace marbler;
using namespace marbler::ui;

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    const int drops = argc > 1 ? std::max(1, std::stoi(argv[1])) : 200;
    const int side = argc > 2 ? std::max(100, std::stoi(argv[2])) : 700;
    const double seconds = argc > 3 ? std::max(0.5, std::stod(argv[3])) : 4.0;
    const int tines = argc > 4 ? std::clamp(std::stoi(argv[4]), 1, int(MaxTines)) : 1;

    Genome design;
    design.palette = {{200, 30, 30}, {30, 30, 200}, {240, 200, 40}, {20, 140, 60}};
    const int across = int(std::ceil(std::sqrt(double(drops))));
    for (int i = 0; i < drops; ++i) {
        Operation drop = defaultOperation(
            Tool::Drop, 2, {1000.0 * (i % across + 0.5) / across, 1000.0 * (i / across + 0.5) / across, 0.0});
        drop.radius = 0.4 * 1000.0 / across;
        drop.color = i % int(design.palette.size());
        design.initial.push_back(drop);
    }

    RenderService service(RenderService::Backend::Cpu);
    EditorCanvas canvas(&service);
    canvas.resize(side, side);
    canvas.show();
    if (!QTest::qWaitForWindowExposed(&canvas)) {
        std::fprintf(stderr, "ui_stroke_timing: no window (run it under a display)\n");
        return 1;
    }
    canvas.setDesign(design);
    ToolSettings settings;
    settings.tines = tines;
    canvas.setToolSettings(settings);
    canvas.setTool(Tool::Stylus);
    QElapsedTimer settle;
    settle.start();
    while (!canvas.imageFinal() && settle.elapsed() < 60000)
        QTest::qWait(10);

    int frames = 0;
    double pixels = 0.0;
    QObject::connect(&service, &RenderService::rendered, [&](std::uint64_t, const QImage& image, bool) {
        ++frames;
        pixels += double(image.width()) * image.height();
    });
    auto at = [&](double t) { // a wave across the bath, t in [0, 1]
        const double x = 100.0 + 800.0 * t;
        return canvas.toWidget({x, 500.0 + 150.0 * std::sin(t * 4.0 * 3.14159265), 0.0}).toPoint();
    };
    QTest::mousePress(&canvas, Qt::LeftButton, {}, at(0.0));
    QElapsedTimer clock;
    clock.start();
    int moves = 0;
    while (clock.elapsed() < seconds * 1000.0) {
        const double t = std::min(1.0, clock.elapsed() / (seconds * 1000.0));
        QTest::mouseMove(&canvas, at(t));
        ++moves;
        QTest::qWait(16);
    }
    const double drawing = clock.elapsed() / 1000.0;
    const int drawnFrames = frames;
    const double meanPixels = drawnFrames > 0 ? pixels / drawnFrames : 0.0;
    const double scale = canvas.strokePreviewScale();
    QTest::mouseRelease(&canvas, Qt::LeftButton, {}, at(1.0));
    QElapsedTimer sharp;
    sharp.start();
    while (!canvas.imageFinal() && sharp.elapsed() < 600000)
        QTest::qWait(5);
    std::printf("design: %d drops, canvas %d x %d, stylus with %d tine(s), %.1f s of drawing\n", drops, side,
                side, tines, drawing);
    std::printf("live previews: %d in %.2f s = %.1f frames a second, mean %.0f pixels (about %.0f x %.0f), "
                "preview scale %.3f\n",
                drawnFrames, drawing, drawnFrames / drawing, meanPixels, std::sqrt(meanPixels),
                std::sqrt(meanPixels), scale);
    std::printf("pointer moves handled: %d = %.1f a second\n", moves, moves / drawing);
    std::printf("release to sharp image: %.2f s\n", sharp.elapsed() / 1000.0);
    return 0;
}
