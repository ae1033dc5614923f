// Throughput of the CPU renderer. The figure of merit is sample-operations per second: every
// sample visits operations backward until it finds ink, so samples x operations traversed is
// the work done, independent of how much of the design happens to be ink.

#include "Kernel.h"
#include "SoaProbe.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/Tools.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
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

Case makeCase(const char* file, int side, std::optional<Slice> slice = std::nullopt) {
    Case k;
    k.genome = loadGenome(std::string(MARBLER_TEST_DATA) + file);
    k.settings.width = k.settings.height = side;
    k.settings.slice = slice;
    k.sampleOps = countSampleOps(k.genome, k.settings);
    return k;
}

const Case& flameCase() {
    static const Case c = makeCase("/examples/flame-comb-vortex.marble.json", 512);
    return c;
}

const Case& slateSliceCase() {
    static const Case c = makeCase("/examples/slate-block.marble.json", 256, Slice{2, 500.0});
    return c;
}

/// 50 stone drops then 50 combs: the operation mix of the SoA probe.
const Case& dropCombCase() {
    static const Case c = makeCase("/bench/drop-comb-50x50.marble.json", 512);
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

int allThreads() {
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void BM_Flame2D_OneThread(benchmark::State& state) {
    runRenderer(state, flameCase(), 1);
}
void BM_Flame2D_AllThreads(benchmark::State& state) {
    runRenderer(state, flameCase(), allThreads());
}
void BM_DropComb2D_OneThread(benchmark::State& state) {
    runRenderer(state, dropCombCase(), 1);
}
void BM_DropComb2D_TwoThreads(benchmark::State& state) {
    runRenderer(state, dropCombCase(), 2);
}
void BM_SlateSlice3D_OneThread(benchmark::State& state) {
    runRenderer(state, slateSliceCase(), 1);
}
void BM_SlateSlice3D_AllThreads(benchmark::State& state) {
    runRenderer(state, slateSliceCase(), allThreads());
}

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
            for (int k = 0; k < width; ++k)
                tile->id[k] = k;
            traversed += kernel::traceTile(ops.data(), ops.size(), c.genome.dimension, *tile, width,
                                           colors.data(), nullptr, nullptr);
        }
        benchmark::DoNotOptimize(colors.data());
    }
    state.counters["sample_ops_per_s"] = benchmark::Counter(double(traversed), benchmark::Counter::kIsRate);
}
void BM_Flame2D_KernelOnly(benchmark::State& state) {
    kernelOnly(state, flameCase());
}
void BM_SlateSlice3D_KernelOnly(benchmark::State& state) {
    kernelOnly(state, slateSliceCase());
}

/// The samples of a render (pixel centres, no antialiasing) as arrays, in blocks of the SoA
/// probe's size, shared out to `threads` workers block by block, as the renderer shares rows.
struct SampleBlocks {
    std::vector<double> x, y;
    std::size_t blocks = 0;

    explicit SampleBlocks(const Case& c) {
        SampleFrame frame = sampleFrame(c.genome, c.settings);
        for (int j = 0; j < c.settings.height; ++j)
            for (int i = 0; i < c.settings.width; ++i) {
                glm::dvec3 p = frame.at(i, j, 0.0, 0.0);
                x.push_back(p.x);
                y.push_back(p.y);
            }
        blocks = (x.size() + probe::BlockSize - 1) / probe::BlockSize;
    }
    std::size_t size() const { return x.size(); }
    std::size_t begin(std::size_t block) const { return block * probe::BlockSize; }
    std::size_t count(std::size_t block) const { return std::min(probe::BlockSize, size() - begin(block)); }

    /// Calls work(block) for every block, on `threads` threads; returns the sum of its results.
    template <typename Work> std::uint64_t forEachBlock(int threads, const Work& work) const {
        std::atomic<std::size_t> next{0};
        std::atomic<std::uint64_t> total{0};
        auto worker = [&] {
            std::uint64_t sum = 0;
            for (std::size_t b; (b = next.fetch_add(1)) < blocks;)
                sum += work(b);
            total += sum;
        };
        std::vector<std::thread> pool;
        for (int t = 1; t < threads; ++t)
            pool.emplace_back(worker);
        worker();
        for (std::thread& t : pool)
            t.join();
        return total;
    }
};

/// The SoA probe and the tile kernel on the same samples, blocks and threads. The probe
/// (SoaProbe.h) runs every sample through every operation, so its sample-ops are samples x
/// operations, all of which it computes; the kernel's are the operations each sample traverses
/// before it finds its ink, as in every other figure here.
struct ProbeAndKernel {
    std::vector<PreparedOp> ops; ///< in reverse time order
    SampleBlocks samples;
    std::vector<double> x, y;
    std::vector<int> probeColors, kernelColors;

    explicit ProbeAndKernel(const Case& c)
        : ops(prepare(c.genome))
        , samples(c)
        , x(samples.size())
        , y(samples.size())
        , probeColors(samples.size())
        , kernelColors(samples.size()) {
        std::reverse(ops.begin(), ops.end());
    }
    bool probeHandles() const { return probe::handles(ops.data(), ops.size()); }
    double probeSampleOps() const { return double(samples.size()) * double(ops.size()); }

    void probePass(int threads) {
        samples.forEachBlock(threads, [&](std::size_t b) {
            const std::size_t at = samples.begin(b), n = samples.count(b);
            std::memcpy(x.data() + at, samples.x.data() + at, n * sizeof(double));
            std::memcpy(y.data() + at, samples.y.data() + at, n * sizeof(double));
            probe::trace(ops.data(), ops.size(), x.data() + at, y.data() + at, probeColors.data() + at, n);
            return std::uint64_t(0);
        });
        benchmark::DoNotOptimize(probeColors.data());
    }

    /// Returns the sample-operations traversed.
    std::uint64_t kernelPass(int threads) {
        std::uint64_t traversed = samples.forEachBlock(threads, [&](std::size_t b) {
            thread_local std::unique_ptr<kernel::Tile> tile = std::make_unique<kernel::Tile>();
            std::uint64_t sum = 0;
            for (std::size_t at = samples.begin(b), end = at + samples.count(b); at < end;
                 at += kernel::TileSize) {
                const int n = static_cast<int>(std::min<std::size_t>(kernel::TileSize, end - at));
                std::memcpy(tile->x, samples.x.data() + at, sizeof(double) * std::size_t(n));
                std::memcpy(tile->y, samples.y.data() + at, sizeof(double) * std::size_t(n));
                for (int k = 0; k < n; ++k)
                    tile->id[k] = k;
                sum += kernel::traceTile(ops.data(), ops.size(), 2, *tile, n, kernelColors.data() + at,
                                         nullptr, nullptr);
            }
            return sum;
        });
        benchmark::DoNotOptimize(kernelColors.data());
        return traversed;
    }

    /// Samples whose colour differs from the kernel's (0, or a hair-line few: the probe's drop
    /// rounds as genome-format.md writes it, not as the reference does).
    int colourMismatches() const {
        int mismatches = 0;
        for (std::size_t k = 0; k < samples.size(); ++k)
            mismatches += probeColors[k] != kernelColors[k];
        return mismatches;
    }
};

void soaProbe(benchmark::State& state, const Case& c, int threads) {
    ProbeAndKernel work(c);
    if (!work.probeHandles()) {
        state.SkipWithError("the probe handles 2D drops and combs only");
        return;
    }
    for (auto _ : state)
        work.probePass(threads);
    work.kernelPass(1);
    state.counters["sample_ops_per_s"] =
        benchmark::Counter(work.probeSampleOps() * double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["ops_per_sample"] = double(work.ops.size());
    state.counters["colour_mismatches"] = work.colourMismatches();
    state.counters["threads"] = threads;
}

void kernelOnBlocks(benchmark::State& state, const Case& c, int threads) {
    ProbeAndKernel work(c);
    std::uint64_t traversed = 0;
    for (auto _ : state)
        traversed += work.kernelPass(threads);
    state.counters["sample_ops_per_s"] = benchmark::Counter(double(traversed), benchmark::Counter::kIsRate);
    state.counters["ops_per_sample"] =
        double(traversed) /
        (double(work.samples.size()) * double(std::max<benchmark::IterationCount>(1, state.iterations())));
    state.counters["threads"] = threads;
    state.SetLabel(cpuKernel().name);
}

/// The probe and the kernel in turn within each iteration, each timed by the wall clock: on a
/// machine busy with other work both see the same load, so `kernel_over_probe` (the ratio of
/// their sample-op rates) holds up better than two separate benchmarks' figures.
void kernelVsProbe(benchmark::State& state, const Case& c, int threads) {
    ProbeAndKernel work(c);
    if (!work.probeHandles()) {
        state.SkipWithError("the probe handles 2D drops and combs only");
        return;
    }
    using Clock = std::chrono::steady_clock;
    double probeSeconds = 0, kernelSeconds = 0;
    std::uint64_t traversed = 0;
    for (auto _ : state) {
        const Clock::time_point t0 = Clock::now();
        work.probePass(threads);
        const Clock::time_point t1 = Clock::now();
        traversed += work.kernelPass(threads);
        const Clock::time_point t2 = Clock::now();
        probeSeconds += std::chrono::duration<double>(t1 - t0).count();
        kernelSeconds += std::chrono::duration<double>(t2 - t1).count();
    }
    const double probeRate = work.probeSampleOps() * double(state.iterations()) / probeSeconds;
    const double kernelRate = double(traversed) / kernelSeconds;
    state.counters["probe_sample_ops_per_s"] = probeRate;
    state.counters["kernel_sample_ops_per_s"] = kernelRate;
    state.counters["kernel_over_probe"] = kernelRate / probeRate;
    state.counters["colour_mismatches"] = work.colourMismatches();
    state.counters["threads"] = threads;
    state.SetLabel(cpuKernel().name);
}

void BM_DropComb2D_SoaProbe_OneThread(benchmark::State& state) {
    soaProbe(state, dropCombCase(), 1);
}
void BM_DropComb2D_SoaProbe_TwoThreads(benchmark::State& state) {
    soaProbe(state, dropCombCase(), 2);
}
void BM_DropComb2D_Kernel_OneThread(benchmark::State& state) {
    kernelOnBlocks(state, dropCombCase(), 1);
}
void BM_DropComb2D_Kernel_TwoThreads(benchmark::State& state) {
    kernelOnBlocks(state, dropCombCase(), 2);
}
void BM_DropComb2D_KernelVsProbe_OneThread(benchmark::State& state) {
    kernelVsProbe(state, dropCombCase(), 1);
}
void BM_DropComb2D_KernelVsProbe_TwoThreads(benchmark::State& state) {
    kernelVsProbe(state, dropCombCase(), 2);
}

/// The per-pixel scalar loop the tile kernel replaces: the reference traceColor per sample.
void scalarBaseline(benchmark::State& state, const Case& c) {
    std::vector<PreparedOp> ops = prepare(c.genome);
    SampleFrame frame = sampleFrame(c.genome, c.settings);
    for (auto _ : state) {
        long sum = 0;
        for (int j = 0; j < c.settings.height; ++j)
            for (int i = 0; i < c.settings.width; ++i)
                sum += traceColor(ops, frame.at(i, j, 0.0, 0.0));
        benchmark::DoNotOptimize(sum);
    }
    state.counters["sample_ops_per_s"] =
        benchmark::Counter(double(c.sampleOps) * double(state.iterations()), benchmark::Counter::kIsRate);
}
void BM_Flame2D_ScalarReference(benchmark::State& state) {
    scalarBaseline(state, flameCase());
}
void BM_SlateSlice3D_ScalarReference(benchmark::State& state) {
    scalarBaseline(state, slateSliceCase());
}

/// One flow (version 2) alone, on one thread: the cost of one implicit midpoint step per sample
/// (its fixed-point iterations included), for the tile kernel and for the scalar reference, on
/// a tile of points across the first cell (the cavity's box).
PreparedOp benchFlow(FlowField field) {
    Operation op;
    op.tool = Tool::Flow;
    op.field = field;
    op.center = {100.0, 80.0, 0.0};
    op.angle = 12.0;
    op.extent = {260.0, 210.0};
    op.speed = 80.0;
    op.time = 2.0;
    op.steps = 64; // at least minimumFlowSteps (32 U T Lmax / Lmin^2 = 38)
    return prepare(op, 2);
}

void flowKernel(benchmark::State& state, FlowField field) {
    const PreparedOp op = benchFlow(field);
    auto tile = std::make_unique<kernel::Tile>();
    std::vector<int> colors(kernel::TileSize);
    std::int64_t samples = 0;
    for (auto _ : state) {
        for (int k = 0; k < kernel::TileSize; ++k) {
            tile->x[k] = 110.0 + 0.45 * k;
            tile->y[k] = 90.0 + 0.35 * k;
            tile->id[k] = k;
        }
        kernel::traceTile(&op, 1, 2, *tile, kernel::TileSize, colors.data(), nullptr, nullptr);
        benchmark::DoNotOptimize(tile->x);
        samples += kernel::TileSize;
    }
    state.counters["sample_steps_per_s"] =
        benchmark::Counter(double(samples) * op.steps, benchmark::Counter::kIsRate);
    state.counters["ns_per_sample_step"] = benchmark::Counter(
        double(samples) * op.steps, benchmark::Counter::kIsRate | benchmark::Counter::kInvert,
        benchmark::Counter::OneK::kIs1000);
    state.SetLabel(cpuKernel().name);
}

void flowReference(benchmark::State& state, FlowField field) {
    const PreparedOp op = benchFlow(field);
    std::int64_t samples = 0;
    for (auto _ : state) {
        for (int k = 0; k < kernel::TileSize; ++k) {
            glm::dvec3 q = inverseMap(op, glm::dvec3(110.0 + 0.45 * k, 90.0 + 0.35 * k, 0.0));
            benchmark::DoNotOptimize(q);
        }
        samples += kernel::TileSize;
    }
    state.counters["sample_steps_per_s"] =
        benchmark::Counter(double(samples) * op.steps, benchmark::Counter::kIsRate);
    state.counters["ns_per_sample_step"] = benchmark::Counter(
        double(samples) * op.steps, benchmark::Counter::kIsRate | benchmark::Counter::kInvert,
        benchmark::Counter::OneK::kIs1000);
}
void BM_FlowCells_Kernel(benchmark::State& state) {
    flowKernel(state, FlowField::Cells);
}
void BM_FlowCells_ScalarReference(benchmark::State& state) {
    flowReference(state, FlowField::Cells);
}
void BM_FlowCavity_Kernel(benchmark::State& state) {
    flowKernel(state, FlowField::Cavity);
}
void BM_FlowCavity_ScalarReference(benchmark::State& state) {
    flowReference(state, FlowField::Cavity);
}

/// The bleed test design (tests/data/render/bleed-2d) rendered on one thread at 512 x 410 with
/// its bleed and with bleed 0: what soft edges cost (every ink met is composited, and a point
/// stops only where an ink covers it wholly).
const Case& bleedCase(bool soft) {
    static const Case hard = [] {
        Case c = makeCase("/render/bleed-2d.marble.json", 512);
        c.settings.height = 410;
        c.genome.bleed = 0.0;
        c.sampleOps = countSampleOps(c.genome, c.settings);
        return c;
    }();
    static const Case bled = [] {
        Case c = hard;
        c.genome.bleed = loadGenome(std::string(MARBLER_TEST_DATA) + "/render/bleed-2d.marble.json").bleed;
        return c;
    }();
    return soft ? bled : hard;
}
void BM_Bleed2D_Hard_OneThread(benchmark::State& state) {
    runRenderer(state, bleedCase(false), 1);
}
void BM_Bleed2D_Soft_OneThread(benchmark::State& state) {
    runRenderer(state, bleedCase(true), 1);
}

// ---- Version 3: the stylus (issue 24) ---------------------------------------------------------

/// 200 drops then 10 stylus strokes (single and rakes, 300 to 2,000 steps), or the same design
/// with each stroke a line, at 1024 x 1024 on every core. The goal: the strokes in at most 1 s
/// on two cores, and at most 4 times the lines. The scalar reference is far too slow to count
/// the sample-operations here, so these report times only (and the kernel's own count).
const Case& stylusCase(bool lines) {
    auto make = [](const char* file) {
        Case c;
        c.genome = loadGenome(std::string(MARBLER_TEST_DATA) + file);
        c.settings.width = c.settings.height = 1024;
        return c;
    };
    static const Case strokes = make("/bench/stylus-10x200.marble.json");
    static const Case asLines = make("/bench/stylus-as-lines-10x200.marble.json");
    return lines ? asLines : strokes;
}
void stylusRender(benchmark::State& state, bool lines) {
    const Case& c = stylusCase(lines);
    CpuRenderer renderer(c.genome);
    RenderSettings settings = c.settings;
    settings.threads = allThreads();
    for (auto _ : state) {
        Image image = renderer.render(settings);
        benchmark::DoNotOptimize(image.rgb.data());
    }
    state.counters["threads"] = settings.threads;
}
void BM_Stylus10x200_1024_AllThreads(benchmark::State& state) {
    stylusRender(state, false);
}
void BM_StylusAsLines10x200_1024_AllThreads(benchmark::State& state) {
    stylusRender(state, true);
}

// Real time: the renderer's own threads do the work, so the calling thread's CPU time would
// overstate the rate.
BENCHMARK(BM_Flame2D_OneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Flame2D_AllThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Flame2D_KernelOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Flame2D_ScalarReference)->Unit(benchmark::kMillisecond)->UseRealTime();
// The drop+comb mix: the SoA probe, the kernel alone on the same samples, the whole renderer.
BENCHMARK(BM_DropComb2D_SoaProbe_OneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DropComb2D_Kernel_OneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DropComb2D_SoaProbe_TwoThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DropComb2D_Kernel_TwoThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DropComb2D_KernelVsProbe_OneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DropComb2D_KernelVsProbe_TwoThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DropComb2D_OneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DropComb2D_TwoThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SlateSlice3D_OneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SlateSlice3D_AllThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SlateSlice3D_KernelOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SlateSlice3D_ScalarReference)->Unit(benchmark::kMillisecond)->UseRealTime();
// Version 2: a flow step per sample; soft edges against hard ones (sample_ops_per_s of both
// counts the hard rule's traversal, so the ratio of the times is the cost of bleed).
BENCHMARK(BM_FlowCells_Kernel)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FlowCells_ScalarReference)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FlowCavity_Kernel)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FlowCavity_ScalarReference)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Bleed2D_Hard_OneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Bleed2D_Soft_OneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
// Version 3: ten stylus strokes against ten lines (the strokes take tens of seconds here: one
// render is enough to time them).
BENCHMARK(BM_Stylus10x200_1024_AllThreads)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_StylusAsLines10x200_1024_AllThreads)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
