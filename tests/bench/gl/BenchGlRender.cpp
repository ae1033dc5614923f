// Frames per second of the GL back end: a 1024x1024 design and a 3x3 grid of 256x256
// thumbnails (the workbench's breeding view) at 10, 100 and 1000 entries, without and with
// antialiasing (rgss), a 1024x1024 design of format version 2 (stretches, a flow, finite cores;
// with and without bleed), a 512x512 design with stylus strokes of format version 3 (one with a
// rake), and a 512x512 marbled mesh. Every frame ends in glFinish and the
// read-back, so a frame is a finished image in memory.

#include "marbler/Error.h"
#include "marbler/Genome.h"
#include "marbler/Params.h"
#include "marbler/Random.h"
#include "marbler/gl/GlRenderer.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

namespace {

using namespace marbler;

/// A design of exactly `entries` tools: half drops, half strokes of every family.
Genome makeGenome(int entries, int dimension) {
    Genome genome;
    genome.dimension = dimension;
    genome.size = {1000, 1000, 1000};
    genome.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}, {0xe0, 0xb4, 0x4c}, {0x2e, 0x6e, 0x5e}};
    Pcg32 rng(2024);
    auto point = [&] {
        return glm::dvec3(rng.uniform(0, 1000), rng.uniform(0, 1000),
                          dimension == 3 ? rng.uniform(0, 1000) : 0.0);
    };
    for (int k = 0; k < entries / 2; ++k) {
        Operation drop;
        drop.tool = Tool::Drop;
        drop.center = point();
        drop.radius = rng.uniform(20, 120);
        drop.color = k % 4;
        genome.initial.push_back(drop);
    }
    const Tool strokes[] = {Tool::Comb, Tool::Wave, Tool::Line, Tool::Vortex, Tool::Circle};
    for (int k = entries / 2; k < entries; ++k) {
        Operation op;
        op.tool = strokes[k % 5];
        op.center = point();
        op.angle = rng.uniform(0, 360);
        op.alpha = rng.uniform(10, 60);
        op.lambda = rng.uniform(5, 40);
        op.spacing = rng.uniform(40, 150);
        op.radius = rng.uniform(50, 300);
        op.amplitude = {rng.uniform(5, 40), rng.uniform(5, 40)};
        op.wavelength = {rng.uniform(100, 400), rng.uniform(100, 400)};
        if (dimension == 3) {
            op.direction = {1, 0, 0};
            op.normal = {0, 1, 0};
            if (op.tool == Tool::Circle) op.tool = Tool::Sphere;
        }
        genome.operations.push_back(op);
    }
    return genome;
}

// Released in main, before exit: the driver's own exit handlers may already have torn the
// context down by the time static destructors run.
std::unique_ptr<gl::GlRenderer> instance;

gl::GlRenderer* renderer(benchmark::State& state) {
    std::string why;
    if (!instance && gl::GlRenderer::available(&why)) instance = std::make_unique<gl::GlRenderer>();
    if (!instance) state.SkipWithError(("no OpenGL context: " + why).c_str());
    return instance.get();
}

/// makeGenome's design with version 2's tools: every tenth stroke a stretch of 12 teeth, one
/// stroke a flow through cells (at its fewest steps), every swirl with a finite core.
Genome makeVersion2Genome(int entries, double bleed) {
    Genome genome = makeGenome(entries, 2);
    genome.bleed = bleed;
    Pcg32 rng(7);
    for (std::size_t k = 0; k < genome.operations.size(); ++k) {
        Operation& op = genome.operations[k];
        if (op.tool == Tool::Vortex || op.tool == Tool::Circle) op.core = rng.uniform(10, 60);
        if (k % 10 == 3) {
            op.tool = Tool::Stretch;
            op.teeth.clear();
            for (int t = 0; t < 12; ++t)
                op.teeth.push_back(-800.0 + t * 130.0 + rng.uniform(0, 40));
            op.shift = rng.uniform(-60, 60);
            op.power = rng.uniform(0.5, 3.0);
        }
    }
    Operation& flow = genome.operations[genome.operations.size() / 2];
    flow.tool = Tool::Flow;
    flow.field = FlowField::Cells;
    flow.extent = {260, 220};
    flow.speed = 30;
    flow.time = 3;
    flow.steps = minimumFlowSteps(flow);
    return genome;
}

void BM_Version2Design1024(benchmark::State& state) {
    gl::GlRenderer* gl = renderer(state);
    if (!gl) return;
    Genome genome = makeVersion2Genome(int(state.range(0)), double(state.range(2)));
    if (!state.range(1)) {
        // The version-1 design under the version-2 body: one stretch that moves nothing.
        genome = makeGenome(int(state.range(0)), 2);
        genome.bleed = double(state.range(2));
        Operation still;
        still.tool = Tool::Stretch;
        still.teeth = {0.0, 1.0};
        genome.operations.push_back(still);
    }
    RenderSettings settings;
    settings.width = settings.height = 1024;
    for (auto _ : state) {
        Image image = gl->render(genome, settings);
        gl->finish();
        benchmark::DoNotOptimize(image.rgb.data());
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

/// makeGenome's design of 100 entries with three stylus strokes after it: one straight across
/// as the ebru example draws it (ink dragged to its end; with `rake`, a gentler rake of 5 tines
/// instead), one zigzag of 40 points with a pen's pressure, one spiral of 200 points; each at its
/// fewest steps.
Genome makeStylusGenome(bool rake) {
    Genome genome = makeGenome(100, 2);
    auto stroke = [&](std::vector<glm::dvec2> path, double alpha, double lambda, double reach,
                      std::vector<double> pressure, int tines = 1) {
        Operation op;
        op.tool = Tool::Stylus;
        op.path = std::move(path);
        op.alpha = alpha;
        op.lambda = lambda;
        op.reach = reach;
        op.tines = tines;
        op.spacing = 60;
        op.pressure = std::move(pressure);
        op.steps = minimumStylusSteps(op);
        genome.operations.push_back(op);
    };
    if (rake)
        stroke({{20, 500}, {980, 500}}, 30, 10, 50, {}, 5);
    else
        stroke({{20, 500}, {980, 500}}, 70, 10, 50, {});
    std::vector<glm::dvec2> zigzag, spiral;
    std::vector<double> pressure;
    for (int k = 0; k < 40; ++k) {
        zigzag.push_back({60 + 22.0 * k, k % 2 ? 150.0 : 300.0});
        pressure.push_back(0.3 + 0.7 * std::abs(std::sin(0.2 * k)));
    }
    stroke(zigzag, 50, 12, 60, pressure);
    for (int k = 0; k < 200; ++k)
        spiral.push_back(
            {500 + (30 + 1.6 * k) * std::cos(0.06 * k), 650 + (30 + 1.6 * k) * std::sin(0.06 * k)});
    stroke(spiral, 40, 8, 40, {});
    return genome;
}

void BM_StylusDesign512(benchmark::State& state) {
    gl::GlRenderer* gl = renderer(state);
    if (!gl) return;
    const Genome genome = makeStylusGenome(state.range(0) != 0);
    RenderSettings settings;
    settings.width = settings.height = 512;
    for (auto _ : state) {
        try {
            Image image = gl->render(genome, settings);
            gl->finish();
            benchmark::DoNotOptimize(image.rgb.data());
        } catch (const RuntimeFailure& e) {
            // A software rasteriser's loop limit (tools.glsl, loopsWereCut).
            state.SkipWithError(e.what());
            break;
        }
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

const char* aaName(int64_t index) {
    return index ? "rgss" : "none";
}

void BM_Design1024(benchmark::State& state) {
    gl::GlRenderer* gl = renderer(state);
    if (!gl) return;
    Genome genome = makeGenome(int(state.range(0)), 2);
    RenderSettings settings;
    settings.width = settings.height = 1024;
    settings.aa = aaName(state.range(1));
    for (auto _ : state) {
        Image image = gl->render(genome, settings);
        gl->finish();
        benchmark::DoNotOptimize(image.rgb.data());
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.SetLabel(gl->rendererName());
}

void BM_Thumbnails3x3(benchmark::State& state) {
    gl::GlRenderer* gl = renderer(state);
    if (!gl) return;
    std::vector<Genome> genomes;
    for (int k = 0; k < 9; ++k)
        genomes.push_back(makeGenome(int(state.range(0)), 2));
    RenderSettings settings;
    settings.width = settings.height = 256;
    settings.aa = aaName(state.range(1));
    for (auto _ : state) {
        for (const Genome& genome : genomes)
            benchmark::DoNotOptimize(gl->render(genome, settings).rgb.data());
        gl->finish();
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_Mesh512(benchmark::State& state) {
    gl::GlRenderer* gl = renderer(state);
    if (!gl) return;
    Genome genome = makeGenome(int(state.range(0)), 3);
    gl::MeshSettings settings;
    settings.width = settings.height = 512;
    settings.mesh = "vase";
    settings.supersample = 3;
    for (auto _ : state) {
        Image image = gl->renderMesh(genome, settings);
        gl->finish();
        benchmark::DoNotOptimize(image.rgb.data());
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_Design1024)
    ->ArgsProduct({{10, 100, 1000}, {0, 1}})
    ->ArgNames({"ops", "rgss"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Thumbnails3x3)
    ->ArgsProduct({{10, 100, 1000}, {0, 1}})
    ->ArgNames({"ops", "rgss"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Version2Design1024)
    ->ArgsProduct({{100}, {0, 1}, {0, 10}})
    ->ArgNames({"ops", "v2tools", "bleed"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_StylusDesign512)->Arg(0)->Arg(1)->ArgName("rake")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Mesh512)->Arg(100)->ArgName("ops")->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    instance.reset();
    return 0;
}
