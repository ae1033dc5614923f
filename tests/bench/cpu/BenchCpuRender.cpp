// Throughput of the CPU renderer. The figure of merit is sample-operations per second: every
// sample visits operations backward until it finds ink, so samples x operations traversed is
// the work done, independent of how much of the design happens to be ink.

#include "Kernel.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/Tools.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <thread>

namespace {

using namespace marbler;

struct Case {
    Genome genome;
    RenderSettings settings;
    std::uint64_t sampleOps = 0; ///< per render
};

/// Counts the operations the colour rule visits for every sample of a render, with the scalar
/// reference (once, outside the timings).
std::uint64_t countSampleOps(const Genome& genome, const RenderSettings& settings) {
    std::vector<PreparedOp> ops = prepare(genome);
    SampleFrame frame = sampleFrame(genome, settings);
    AaPattern pattern = aaPattern(settings.aa);
    std::uint64_t total = 0;
    for (int j = 0; j < settings.height; ++j)
        for (int i = 0; i < settings.width; ++i)
            for (const glm::dvec2& o : pattern.offsets) {
                glm::dvec3 p = frame.at(i, j, o.x, o.y);
                for (auto it = ops.rbegin(); it != ops.rend(); ++it) {
                    ++total;
                    if (it->color >= 0 && insideInk(*it, p)) break;
                    p = inverseMap(*it, p);
                }
            }
    return total;
}

const Case& flameCase() {
    static const Case c = [] {
        Case k;
        k.genome = loadGenome(MARBLER_TEST_DATA "/examples/flame-comb-vortex.marble.json");
        k.settings.width = k.settings.height = 512;
        k.sampleOps = countSampleOps(k.genome, k.settings);
        return k;
    }();
    return c;
}

const Case& slateSliceCase() {
    static const Case c = [] {
        Case k;
        k.genome = loadGenome(MARBLER_TEST_DATA "/examples/slate-block.marble.json");
        k.settings.width = k.settings.height = 256;
        k.settings.slice = Slice{2, 500.0};
        k.sampleOps = countSampleOps(k.genome, k.settings);
        return k;
    }();
    return c;
}

void runRenderer(benchmark::State& state, const Case& c, int threads) {
    CpuRenderer renderer(c.genome);
    RenderSettings settings = c.settings;
    settings.threads = threads;
    for (auto _ : state) {
        Image image = renderer.render(settings);
        benchmark::DoNotOptimize(image.rgb.data());
    }
    state.counters["sample_ops_per_s"] =
        benchmark::Counter(double(c.sampleOps) * double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["threads"] = settings.threads;
}

int allThreads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

void BM_Flame2D_OneThread(benchmark::State& state) { runRenderer(state, flameCase(), 1); }
void BM_Flame2D_AllThreads(benchmark::State& state) { runRenderer(state, flameCase(), allThreads()); }
void BM_SlateSlice3D_OneThread(benchmark::State& state) { runRenderer(state, slateSliceCase(), 1); }
void BM_SlateSlice3D_AllThreads(benchmark::State& state) { runRenderer(state, slateSliceCase(), allThreads()); }

/// The tile kernel alone, on one thread: the samples of the render (one row per tile, as the
/// renderer fills them) traced with no sampling set-up, no colour averaging and no sRGB
/// encoding around it. Its rate against the full renderer's shows what those cost.
void kernelOnly(benchmark::State& state, const Case& c) {
    std::vector<PreparedOp> ops = prepare(c.genome);
    std::reverse(ops.begin(), ops.end());
    SampleFrame frame = sampleFrame(c.genome, c.settings);
    const int width = std::min(c.settings.width, kernel::TileSize);
    std::vector<double> xs, ys, zs;
    for (int j = 0; j < c.settings.height; ++j)
        for (int i = 0; i < width; ++i) {
            glm::dvec3 p = frame.at(i, j, 0.0, 0.0);
            xs.push_back(p.x);
            ys.push_back(p.y);
            zs.push_back(p.z);
        }
    auto tile = std::make_unique<kernel::Tile>();
    std::vector<int> colors(kernel::TileSize);
    std::uint64_t traversed = 0;
    for (auto _ : state) {
        for (int j = 0; j < c.settings.height; ++j) {
            const std::size_t at = std::size_t(j) * std::size_t(width);
            std::memcpy(tile->x, xs.data() + at, sizeof(double) * std::size_t(width));
            std::memcpy(tile->y, ys.data() + at, sizeof(double) * std::size_t(width));
            std::memcpy(tile->z, zs.data() + at, sizeof(double) * std::size_t(width));
            for (int k = 0; k < width; ++k) tile->id[k] = k;
            traversed += kernel::traceTile(ops.data(), ops.size(), c.genome.dimension, *tile, width, colors.data(),
                                           nullptr, nullptr);
        }
        benchmark::DoNotOptimize(colors.data());
    }
    state.counters["sample_ops_per_s"] = benchmark::Counter(double(traversed), benchmark::Counter::kIsRate);
}
void BM_Flame2D_KernelOnly(benchmark::State& state) { kernelOnly(state, flameCase()); }
void BM_SlateSlice3D_KernelOnly(benchmark::State& state) { kernelOnly(state, slateSliceCase()); }

/// The per-pixel scalar loop the tile kernel replaces: the reference traceColor per sample.
void scalarBaseline(benchmark::State& state, const Case& c) {
    std::vector<PreparedOp> ops = prepare(c.genome);
    SampleFrame frame = sampleFrame(c.genome, c.settings);
    for (auto _ : state) {
        long sum = 0;
        for (int j = 0; j < c.settings.height; ++j)
            for (int i = 0; i < c.settings.width; ++i) sum += traceColor(ops, frame.at(i, j, 0.0, 0.0));
        benchmark::DoNotOptimize(sum);
    }
    state.counters["sample_ops_per_s"] =
        benchmark::Counter(double(c.sampleOps) * double(state.iterations()), benchmark::Counter::kIsRate);
}
void BM_Flame2D_ScalarReference(benchmark::State& state) { scalarBaseline(state, flameCase()); }
void BM_SlateSlice3D_ScalarReference(benchmark::State& state) { scalarBaseline(state, slateSliceCase()); }

// Real time: the renderer's own threads do the work, so the calling thread's CPU time would
// overstate the rate.
BENCHMARK(BM_Flame2D_OneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Flame2D_AllThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Flame2D_KernelOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Flame2D_ScalarReference)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SlateSlice3D_OneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SlateSlice3D_AllThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SlateSlice3D_KernelOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SlateSlice3D_ScalarReference)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
