// Frames per second of the editor's canvas while a parameter is dragged: the time from
// setDesign with one parameter changed to the coarse (dragging) image delivered, through the
// real RenderService on the CPU back end, for a 100-step flat design on a 900 x 700 canvas.
// Also the sharp (antialiased) final image after a release, for comparison. Qt's offscreen
// platform is used when no display is set.

#include "editor/EditorCanvas.h"
#include "marbler/Genome.h"
#include "marbler/Params.h"
#include "marbler/Random.h"
#include "shared/RenderService.h"

#include <QApplication>
#include <QEventLoop>

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace marbler;
using namespace marbler::ui;

/// A flat design of exactly `entries` steps: half drops, half strokes of every family.
Genome makeDesign(int entries) {
    Genome genome;
    genome.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}, {0xe0, 0xb4, 0x4c}, {0x2e, 0x6e, 0x5e}};
    Pcg32 rng(2024);
    auto point = [&] { return glm::dvec3(rng.uniform(0, 1000), rng.uniform(0, 1000), 0.0); };
    for (int k = 0; k < entries / 2; ++k) {
        Operation drop = defaultOperation(Tool::Drop, 2, point());
        drop.radius = rng.uniform(20, 120);
        drop.color = k % 4;
        genome.initial.push_back(drop);
    }
    const Tool strokes[] = {Tool::Comb, Tool::Wave, Tool::Line, Tool::Vortex, Tool::Circle};
    for (int k = entries / 2; k < entries; ++k) {
        Operation op = defaultOperation(strokes[k % 5], 2, point());
        op.angle = rng.uniform(0, 360);
        op.alpha = rng.uniform(10, 60);
        op.lambda = rng.uniform(5, 40);
        op.spacing = rng.uniform(40, 150);
        op.radius = rng.uniform(50, 300);
        op.amplitude = {rng.uniform(5, 40), 0.0};
        op.wavelength = {rng.uniform(100, 400), 1.0};
        genome.operations.push_back(op);
    }
    return genome;
}

/// Handles events until the canvas shows a new image (coarse or final as `final` asks).
void waitForImage(EditorCanvas& canvas, qint64 before, bool final) {
    while (canvas.image().cacheKey() == before || canvas.image().isNull() || (final && !canvas.imageFinal()))
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
}

/// One drag step: a stroke's shift moved, set while dragging, until its coarse image arrives.
void BM_EditorDragFrame(benchmark::State& state, bool dragging) {
    RenderService service(RenderService::Backend::Cpu);
    EditorCanvas canvas(&service);
    canvas.resize(900, 700);
    canvas.show();
    Genome design = makeDesign(100);
    canvas.setDesign(design);
    waitForImage(canvas, 0, true);
    canvas.setDragging(dragging);
    Operation& dragged = design.operations[25];
    int frame = 0;
    for (auto _ : state) {
        dragged.alpha = 20.0 + (frame++ % 40);
        const qint64 before = canvas.image().cacheKey();
        canvas.setDesign(design);
        waitForImage(canvas, before, !dragging);
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["width"] = canvas.image().width();
    state.counters["height"] = canvas.image().height();
}

BENCHMARK_CAPTURE(BM_EditorDragFrame, coarse_while_dragging, true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_EditorDragFrame, sharp_after_release, false)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
