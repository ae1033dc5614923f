// The vectorised tile kernel against the scalar reference maps (genome/src/Tools.cpp), in
// every variant this CPU runs; and the choice of variant (MARBLER_KERNEL).

#include "Kernel.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Growth.h"
#include "marbler/Params.h"
#include "marbler/Random.h"
#include "marbler/Tools.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <thread>

namespace marbler {
namespace {

TEST(KernelMath, SinCosWithinAnUlpOrTwoOfTheLibrary) {
    Pcg32 rng(7);
    double worst = 0;
    for (int k = 0; k < 200000; ++k) {
        double scale = std::pow(10.0, rng.uniform(-3.0, 6.0));
        double x = rng.uniform(-scale, scale);
        double s, c;
        kernel::sinCosForTest(x, s, c);
        worst = std::max({worst, std::abs(s - std::sin(x)), std::abs(c - std::cos(x))});
        ASSERT_NEAR(s, std::sin(x), 1e-15) << x;
        ASSERT_NEAR(c, std::cos(x), 1e-15) << x;
    }
    std::printf("  largest sin/cos difference: %.3g\n", worst);
    for (double x : {0.0, -0.0, std::numbers::pi / 4, std::numbers::pi / 2, std::numbers::pi, 1e6, -1e6}) {
        double s, c;
        kernel::sinCosForTest(x, s, c);
        EXPECT_NEAR(s, std::sin(x), 1e-15) << x;
        EXPECT_NEAR(c, std::cos(x), 1e-15) << x;
    }
    // Beyond the fast reduction: the library's own answer.
    for (double x : {1.5e6, -3e9, 1e300}) {
        double s, c;
        kernel::sinCosForTest(x, s, c);
        EXPECT_EQ(s, std::sin(x)) << x;
        EXPECT_EQ(c, std::cos(x)) << x;
    }
}

TEST(KernelMath, CubeRootOnTheUnitInterval) {
    Pcg32 rng(8);
    EXPECT_EQ(kernel::cbrtForTest(0.0), 0.0);
    EXPECT_NEAR(kernel::cbrtForTest(1.0), 1.0, 2e-16);
    for (int k = 0; k < 100000; ++k) {
        double x = std::pow(10.0, rng.uniform(-17.0, 0.0));
        ASSERT_NEAR(kernel::cbrtForTest(x), std::cbrt(x), 1e-15 * std::cbrt(x)) << x; // a few ulps
    }
}

/// A random operation of any tool allowed in `dimension`, with parameters drawn around the
/// parameter tables' defaults.
Operation randomOperation(Pcg32& rng, Tool tool, int dimension) {
    glm::dvec3 center(rng.uniform(0, 1000), rng.uniform(0, 1000),
                      dimension == 3 ? rng.uniform(0, 1000) : 0.0);
    Operation op = defaultOperation(tool, dimension, center);
    auto unit = [&] {
        glm::dvec3 v(rng.normal(), rng.normal(), rng.normal());
        return v / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    };
    op.radius = rng.uniform(20, 200);
    op.alpha = rng.uniform(-150, 150);
    op.lambda = rng.uniform(5, 80);
    op.spacing = rng.uniform(30, 200);
    op.angle = rng.uniform(-180, 180);
    op.amplitude = {rng.uniform(-60, 60), rng.uniform(-60, 60)};
    op.wavelength = {rng.uniform(50, 500), rng.uniform(50, 500)};
    op.phase = {rng.uniform(-180, 180), rng.uniform(-180, 180)};
    op.shape = rng.chance(0.5) ? WaveShape::Ripple : WaveShape::Eggcrate;
    op.axis = unit();
    op.direction = unit();
    glm::dvec3 n = unit();
    n -= (n.x * op.direction.x + n.y * op.direction.y + n.z * op.direction.z) * op.direction;
    op.normal = n / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    op.color = static_cast<int>(rng.below(4));
    // Version 2: a core on half the swirls; a stretch's teeth, shift and power (the three
    // powers the kernel takes exactly and one it takes through pow); a flow of either field,
    // with at least the steps that make its iteration contract.
    op.core = rng.chance(0.5) ? rng.uniform(1, 60) : 0.0;
    if (tool == Tool::Stretch) {
        op.teeth = {rng.uniform(-300, 300)};
        const int teeth = 2 + static_cast<int>(rng.below(12));
        while (int(op.teeth.size()) < teeth)
            op.teeth.push_back(op.teeth.back() + rng.uniform(20, 200));
        op.shift = rng.uniform(-80, 80);
        const double powers[] = {1.0, 2.0, 0.5, rng.uniform(0.2, 3.0)};
        op.power = powers[rng.below(4)];
    }
    if (tool == Tool::Flow) {
        op.field = rng.chance(0.5) ? FlowField::Cells : FlowField::Cavity;
        op.extent = {rng.uniform(150, 600), rng.uniform(150, 600)};
        op.speed = rng.uniform(-120, 120);
        op.time = rng.uniform(0.3, 2.0);
        op.steps = std::max(minimumFlowSteps(op), 1 + static_cast<int>(rng.below(4)));
    }
    if (tool == Tool::Stylus) {
        op.path = {{rng.uniform(0, 1000), rng.uniform(0, 1000)},
                   {rng.uniform(0, 1000), rng.uniform(0, 1000)},
                   {rng.uniform(0, 1000), rng.uniform(0, 1000)}};
        op.alpha = rng.uniform(-60, 60);
        op.lambda = rng.uniform(4, 20);
        op.reach = rng.uniform(40, 120);
        op.tines = 1 + static_cast<int>(rng.below(3));
        op.spacing = rng.uniform(10, 40);
        op.steps = minimumStylusSteps(op);
    }
    return op;
}

std::vector<Tool> toolsOf(int dimension) {
    std::vector<Tool> tools;
    for (const ToolSpec& spec : allTools())
        if (spec.available(dimension)) tools.push_back(spec.tool);
    return tools;
}

/// Tools whose inverse map the exact variants (avx2, baseline) compute bit for bit like the
/// reference: no sine, cosine or cube root of the kernel's own.
bool exactTool(Tool tool, int dimension) {
    switch (tool) {
    case Tool::Spray:
    case Tool::Line:
    case Tool::Comb:
    case Tool::Cylinder:
    case Tool::Stylus: // the kernel runs the reference's steps (stylusStep) per point
        return true;
    case Tool::Drop:
        return dimension == 2;
    case Tool::Wave:
    case Tool::Circle:
    case Tool::Sphere:
    case Tool::Vortex:
    case Tool::Stretch:
    case Tool::Flow:
        return false;
    }
    return false;
}

/// Runs each test with one kernel variant forced, and puts back the environment's choice.
class KernelVsReference : public ::testing::TestWithParam<std::tuple<std::string, int>> {
protected:
    void SetUp() override { setCpuKernelForTesting(variant()); }
    void TearDown() override { setCpuKernelForTesting(""); }
    const std::string& variant() const { return std::get<0>(GetParam()); }
    int dimension() const { return std::get<1>(GetParam()); }
};

TEST_P(KernelVsReference, EveryToolMovesPointsLikeTheReference) {
    const int dim = dimension();
    const bool exactVariant = variant() != "avx512";
    Pcg32 rng(100 + dim);
    auto tile = std::make_unique<kernel::Tile>();
    std::vector<int> colors(kernel::TileSize);
    for (Tool tool : toolsOf(dim)) {
        const bool exact = exactVariant && exactTool(tool, dim);
        for (int trial = 0; trial < 20; ++trial) {
            PreparedOp op = prepare(randomOperation(rng, tool, dim), dim);
            const int n = 300 + trial; // not a multiple of the vector width
            std::vector<glm::dvec3> points;
            for (int i = 0; i < n; ++i) {
                glm::dvec3 p(rng.uniform(-200, 1200), rng.uniform(-200, 1200),
                             dim == 3 ? rng.uniform(-200, 1200) : 0.0);
                if (i == 0) p = op.c; // the centre itself stays
                points.push_back(p);
                tile->x[i] = p.x;
                tile->y[i] = p.y;
                tile->z[i] = p.z;
                tile->id[i] = i;
            }
            kernel::traceTile(&op, 1, dim, *tile, n, colors.data(), nullptr, nullptr);
            ASSERT_EQ(kernel::variantName(kernel::lastVariantRunForTest()), variant());
            // Points that found ink were swapped out; the others keep their order.
            int k = 0;
            for (int i = 0; i < n; ++i) {
                const glm::dvec3& p = points[i];
                bool ink = op.color >= 0 && insideInk(op, p);
                ASSERT_EQ(colors[i], ink ? op.color : -1) << toolSpec(tool).name << " point " << i;
                if (ink) continue;
                ASSERT_EQ(tile->id[k], i);
                glm::dvec3 want = inverseMap(op, p);
                glm::dvec3 got(tile->x[k], tile->y[k], dim == 3 ? tile->z[k] : 0.0);
                double tolerance =
                    exact ? 0.0 : 1e-9 * (1.0 + std::abs(want.x) + std::abs(want.y) + std::abs(want.z));
                ASSERT_NEAR(got.x, want.x, tolerance) << toolSpec(tool).name << " point " << i;
                ASSERT_NEAR(got.y, want.y, tolerance) << toolSpec(tool).name << " point " << i;
                ASSERT_NEAR(got.z, want.z, tolerance) << toolSpec(tool).name << " point " << i;
                ++k;
            }
        }
    }
}

TEST_P(KernelVsReference, RandomGenomesGiveTheReferenceColours) {
    const int dim = dimension();
    Pcg32 rng(200 + dim);
    std::vector<Tool> tools = toolsOf(dim);
    int mismatches = 0, total = 0;
    for (int genomeIndex = 0; genomeIndex < 12; ++genomeIndex) {
        Genome g;
        g.dimension = dim;
        g.palette = {{10, 20, 30}, {200, 10, 10}, {10, 200, 10}, {10, 10, 200}};
        for (int i = 0; i < 25; ++i) {
            Tool tool = dim == 3 && rng.chance(0.2) ? Tool::Cylinder
                        : rng.chance(0.8)           ? Tool::Drop
                                                    : Tool::Spray;
            g.initial.push_back(randomOperation(rng, tool, dim));
        }
        for (int i = 0; i < 10; ++i)
            g.operations.push_back(randomOperation(rng, tools[rng.below(std::uint32_t(tools.size()))], dim));
        CpuRenderer renderer(g);
        std::vector<PreparedOp> ops = prepare(g);
        for (int k = 0; k < 2000; ++k) {
            glm::dvec3 p(rng.uniform(0, 1000), rng.uniform(0, 1000), dim == 3 ? rng.uniform(0, 1000) : 0.0);
            int want = traceColor(ops, p), got = renderer.colorIndexAt(p);
            if (want != got) {
                ++mismatches;
                std::printf("  genome %d point (%.17g, %.17g, %.17g): kernel %d, reference %d\n", genomeIndex,
                            p.x, p.y, p.z, got, want);
            }
            ++total;
        }
    }
    // Only a point within an ulp-sized hair of an ink boundary could differ.
    EXPECT_LE(mismatches, 1) << "of " << total;
}

/// A stylus stroke for the kernel's own tests: a path of `points` points (a zigzag when more
/// than two), `tines` tines, pressure varying along the path when asked.
Operation stylusStroke(Pcg32& rng, int points, int tines, bool pressure) {
    Operation op = defaultOperation(Tool::Stylus, 2, {500, 500, 0});
    op.path.clear();
    glm::dvec2 at(rng.uniform(100, 300), rng.uniform(100, 900));
    for (int i = 0; i < points; ++i) {
        op.path.push_back(at);
        at += glm::dvec2(rng.uniform(5, 900.0 / points + 20), rng.uniform(-120, 120));
    }
    op.alpha = rng.uniform(-80, 80);
    op.lambda = rng.uniform(4, 25);
    op.reach = rng.uniform(20, 90);
    op.tines = tines;
    op.spacing = rng.uniform(6, 30);
    op.pressure.clear();
    if (pressure)
        for (int i = 0; i < points; ++i)
            op.pressure.push_back(i == 0 ? 0.0 : rng.uniform(0, 1));
    // A wide rake is gentle and short, so that the reference checks it in a moment.
    if (tines > 8) {
        op.alpha = rng.uniform(-4, 4);
        op.path.resize(std::min<std::size_t>(op.path.size(), 4));
        if (!op.pressure.empty()) op.pressure.resize(op.path.size());
    }
    op.steps = minimumStylusSteps(op) + static_cast<int>(rng.below(50));
    return op;
}

/// Points where a stylus is hardest to skip: on every path point, at the stylus's reach ahead
/// of and behind each step's station (where |m| = l, give or take an ulp), beside the track,
/// and scattered.
/// As many as the reference (which visits every step of every tine) does in a moment.
std::vector<glm::dvec2> stylusProbePoints(Pcg32& rng, const PreparedOp& op) {
    const std::size_t target =
        std::clamp<std::size_t>(static_cast<std::size_t>(5e6 / (double(op.steps) * op.tines)), 64, 1400);
    const std::size_t stations = std::max<std::size_t>(4, target / 30);
    std::vector<glm::dvec2> points(op.path.begin(), op.path.end());
    for (std::size_t k = 0; k < op.stations.size(); k += 1 + op.stations.size() / stations) {
        const StylusStation& station = op.stations[k];
        const glm::dvec2 t = op.along[station.segment], n(-t.y, t.x);
        for (double side : {0.0, 3.0, -40.0})
            for (double ahead : {op.reach, -op.reach}) {
                glm::dvec2 p = station.s + ahead * t + side * n;
                points.push_back(p);
                points.push_back({std::nextafter(p.x, 1e9), p.y});
                points.push_back({std::nextafter(p.x, -1e9), std::nextafter(p.y, -1e9)});
            }
    }
    while (points.size() < target)
        points.push_back({rng.uniform(-200, 1200), rng.uniform(-200, 1200)});
    return points;
}

/// The kernel moves every point of `op` exactly as the reference (inverseMap) does.
void expectStylusExact(const PreparedOp& op, const std::vector<glm::dvec2>& points, const std::string& what) {
    auto tile = std::make_unique<kernel::Tile>();
    std::vector<int> colors(kernel::TileSize);
    for (std::size_t from = 0; from < points.size(); from += kernel::TileSize) {
        const int n = static_cast<int>(std::min<std::size_t>(kernel::TileSize, points.size() - from));
        for (int i = 0; i < n; ++i) {
            tile->x[i] = points[from + i].x;
            tile->y[i] = points[from + i].y;
            tile->z[i] = 0.0;
            tile->id[i] = i;
        }
        kernel::traceTile(&op, 1, 2, *tile, n, colors.data(), nullptr, nullptr);
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 p = points[from + i];
            const glm::dvec3 want = inverseMap(op, {p.x, p.y, 0.0});
            ASSERT_EQ(std::bit_cast<std::uint64_t>(tile->x[i]), std::bit_cast<std::uint64_t>(want.x))
                << what << ": point (" << p.x << ", " << p.y << ") x " << tile->x[i] << " vs " << want.x;
            ASSERT_EQ(std::bit_cast<std::uint64_t>(tile->y[i]), std::bit_cast<std::uint64_t>(want.y))
                << what << ": point (" << p.x << ", " << p.y << ") y " << tile->y[i] << " vs " << want.y;
        }
    }
}

/// The stylus (2D only) with one kernel variant forced, as KernelVsReference does.
class KernelStylusVsReference : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override { setCpuKernelForTesting(GetParam()); }
    void TearDown() override { setCpuKernelForTesting(""); }
};

TEST_P(KernelStylusVsReference, StylusStrokesMoveEveryPointExactlyAsTheReference) {
    Pcg32 rng(300);
    struct Case {
        int points, tines;
        bool pressure;
    };
    const Case cases[] = {{2, 1, false},  {2, 4, false}, {3, 1, true},   {2, 7, true},
                          {40, 1, false}, {60, 3, true}, {12, 64, false}};
    for (const Case& c : cases) {
        Operation stroke = stylusStroke(rng, c.points, c.tines, c.pressure);
        const std::string what = std::to_string(c.points) + " points, " + std::to_string(c.tines) + " tines" +
                                 (c.pressure ? ", pressure" : "");
        PreparedOp op = prepare(stroke, 2);
        expectStylusExact(op, stylusProbePoints(rng, op), what);
        // Growing: the stroke's first floor(s n) steps, on a path cut between its points.
        for (double s : {0.13, 0.5, 0.77}) {
            std::optional<Operation> grown = grownOperation(stroke, 2, s);
            ASSERT_TRUE(grown);
            PreparedOp part = prepare(*grown, 2);
            expectStylusExact(part, stylusProbePoints(rng, part), what + ", grown to " + std::to_string(s));
        }
    }
}

TEST_P(KernelStylusVsReference, AStylusLeavesFarAndStrangePointsAsTheReferenceDoes) {
    Pcg32 rng(301);
    PreparedOp op = prepare(stylusStroke(rng, 5, 2, true), 2);
    std::vector<glm::dvec2> points = {{1e12, 500},       {-1e200, 3},    {500, 1e160},
                                      {INFINITY, 0},     {0, -INFINITY}, {NAN, 500},
                                      {1e-300, -1e-300}, {-0.0, -0.0},   {op.path[0].x, 1e9}};
    // Every point of a tile that moves little, and one that holds a far point.
    expectStylusExact(op, points, "far points");
    points.push_back(op.path[2]);
    expectStylusExact(op, points, "far points and one on the path");
}

TEST(KernelStylus, APointRunsOnlyTheStepsWhileTheStylusIsWithinReach) {
    // A straight stroke along x: a point runs the steps while |x - S(tau)| < reach (give or take
    // a step at each end), and none where the stylus never comes abreast of it.
    Operation stroke = defaultOperation(Tool::Stylus, 2, {500, 500, 0});
    stroke.path = {{100, 500}, {900, 500}};
    stroke.pressure.clear();
    stroke.tines = 1;
    stroke.alpha = 30;
    stroke.lambda = 10;
    stroke.reach = 40;
    stroke.steps = std::max(minimumStylusSteps(stroke), 800);
    const PreparedOp op = prepare(stroke, 2);
    const double h = op.step;
    const int within = static_cast<int>(std::ceil(2.0 * op.reach / h)) + 3;
    auto tile = std::make_unique<kernel::Tile>();
    std::vector<int> colors(kernel::TileSize);
    auto stepsRun = [&](const std::vector<glm::dvec2>& points) {
        for (std::size_t i = 0; i < points.size(); ++i) {
            tile->x[i] = points[i].x;
            tile->y[i] = points[i].y;
            tile->id[i] = static_cast<int>(i);
        }
        const std::uint64_t before = kernel::stylusStepsRunForTest();
        kernel::traceTile(&op, 1, 2, *tile, static_cast<int>(points.size()), colors.data(), nullptr, nullptr);
        return kernel::stylusStepsRunForTest() - before;
    };
    // Far behind the start and far beyond the end (along the track): no step at all.
    EXPECT_EQ(stepsRun({{0, 500}, {-300, 100}, {980, 900}, {2000, 500}}), 0u);
    // Beside the track (the atan term moves it while the stylus is abreast, but hardly along
    // it) and on it (dragged along, so the stylus stays within reach longer).
    for (glm::dvec2 p : {glm::dvec2(500, 500), glm::dvec2(300, 900), glm::dvec2(700, -4000)}) {
        const std::uint64_t run = stepsRun({p});
        const bool beside = p.y != 500.0;
        EXPECT_GT(run, 0u) << p.x << ", " << p.y;
        EXPECT_LE(run, static_cast<std::uint64_t>(beside ? within : op.steps / 3))
            << p.x << ", " << p.y << " of " << op.steps;
        const glm::dvec3 want = inverseMap(op, {p.x, p.y, 0.0});
        EXPECT_EQ(tile->x[0], want.x);
        EXPECT_EQ(tile->y[0], want.y);
    }
}

INSTANTIATE_TEST_SUITE_P(Variants, KernelVsReference,
                         ::testing::Combine(::testing::ValuesIn(cpuKernelsSupported()),
                                            ::testing::Values(2, 3)),
                         [](const auto& info) {
                             return std::get<0>(info.param) + "_" + std::to_string(std::get<1>(info.param)) +
                                    "D";
                         });
INSTANTIATE_TEST_SUITE_P(Variants, KernelStylusVsReference, ::testing::ValuesIn(cpuKernelsSupported()),
                         [](const auto& info) { return info.param; });

/// The variant a traceTile call of `renderer` runs on this thread.
kernel::Variant variantThatRuns(const CpuRenderer& renderer) {
    renderer.colorIndexAt({500.0, 500.0, 0.0});
    return kernel::lastVariantRunForTest();
}

/// Sets MARBLER_KERNEL for one test and puts back the value it had.
class KernelEnvironment : public ::testing::Test {
protected:
    void SetUp() override {
        if (const char* old = std::getenv("MARBLER_KERNEL")) mOld = old;
    }
    void TearDown() override {
        if (mOld)
            ::setenv("MARBLER_KERNEL", mOld->c_str(), 1);
        else
            ::unsetenv("MARBLER_KERNEL");
        setCpuKernelForTesting("");
    }
    /// Sets MARBLER_KERNEL (null: unset) and has the kernel read it again.
    static void use(const char* value) {
        if (value)
            ::setenv("MARBLER_KERNEL", value, 1);
        else
            ::unsetenv("MARBLER_KERNEL");
        setCpuKernelForTesting("");
    }

private:
    std::optional<std::string> mOld;
};

TEST(KernelSelection, TheSupportedVariantsAreKnownBestFirstAndEndWithBaseline) {
    std::vector<std::string> names = cpuKernelsSupported();
    ASSERT_FALSE(names.empty());
    EXPECT_EQ(names.back(), "baseline");
    int last = -1;
    for (const std::string& name : names) {
        std::optional<kernel::Variant> v = kernel::variantNamed(name);
        ASSERT_TRUE(v) << name;
        EXPECT_GT(static_cast<int>(*v), last) << name << " is out of order";
        last = static_cast<int>(*v);
    }
    std::printf("  this CPU runs:");
    for (const std::string& name : names)
        std::printf(" %s", name.c_str());
    std::printf("\n");
}

TEST(KernelSelection, ForcingAVariantRunsItsCode) {
    CpuRenderer renderer(loadGenome(test::dataDir() / "examples" / "five-stones.marble.json"));
    std::vector<std::string> names = cpuKernelsSupported();
    // Each in turn, after a different one, so a stale choice cannot pass.
    for (std::size_t k = 0; k < names.size(); ++k) {
        setCpuKernelForTesting(names[(k + 1) % names.size()]);
        variantThatRuns(renderer);
        setCpuKernelForTesting(names[k]);
        EXPECT_EQ(cpuKernel().name, names[k]);
        EXPECT_EQ(cpuKernel().reason, "set for testing");
        EXPECT_EQ(kernel::variantName(variantThatRuns(renderer)), names[k]);
    }
    // Other threads (the renderer's workers) follow the choice too.
    setCpuKernelForTesting("baseline");
    kernel::Variant seen = kernel::Variant::Avx512;
    std::thread([&] { seen = variantThatRuns(renderer); }).join();
    EXPECT_EQ(seen, kernel::Variant::Baseline);
    setCpuKernelForTesting("");
}

TEST(KernelSelection, ForcingAnUnknownOrUnsupportedVariantThrows) {
    EXPECT_THROW(setCpuKernelForTesting("sse9"), InputError);
    EXPECT_THROW(setCpuKernelForTesting("AVX2"), InputError);
    for (kernel::Variant v : kernel::AllVariants) {
        if (!kernel::cpuRuns(v)) {
            EXPECT_THROW(setCpuKernelForTesting(kernel::variantName(v)), InputError);
        }
    }
    setCpuKernelForTesting("");
}

TEST_F(KernelEnvironment, MarblerKernelPicksTheVariant) {
    CpuRenderer renderer(loadGenome(test::dataDir() / "examples" / "five-stones.marble.json"));
    const std::string best = cpuKernelsSupported().front();
    use(nullptr);
    EXPECT_EQ(cpuKernel().name, best);
    EXPECT_EQ(cpuKernel().reason, "best this CPU runs");
    use("auto");
    EXPECT_EQ(cpuKernel().name, best);
    EXPECT_EQ(cpuKernel().reason, "best this CPU runs");
    for (const std::string& name : cpuKernelsSupported()) {
        use(name.c_str());
        EXPECT_EQ(cpuKernel().name, name);
        EXPECT_EQ(cpuKernel().reason, "MARBLER_KERNEL=" + name);
        EXPECT_EQ(kernel::variantName(variantThatRuns(renderer)), name);
    }
}

TEST_F(KernelEnvironment, AnUnknownNameFallsBackToTheBestWithAReason) {
    CpuRenderer renderer(loadGenome(test::dataDir() / "examples" / "five-stones.marble.json"));
    const std::string best = cpuKernelsSupported().front();
    use("baseline"); // so that the fallback visibly changes the code that runs
    use("avx1024");
    EXPECT_EQ(cpuKernel().name, best);
    EXPECT_NE(cpuKernel().reason.find("MARBLER_KERNEL=avx1024 is not a kernel"), std::string::npos)
        << cpuKernel().reason;
    EXPECT_EQ(kernel::variantName(variantThatRuns(renderer)), best);
}

TEST(KernelSelection, AVariantTheCpuCannotRunFallsBackToTheBestItRuns) {
    // The choice for a CPU without AVX-512, whatever this one has.
    kernel::Choice c = kernel::chooseVariant("avx512", {kernel::Variant::Avx2, kernel::Variant::Baseline});
    EXPECT_EQ(c.variant, kernel::Variant::Avx2);
    EXPECT_NE(c.reason.find("MARBLER_KERNEL=avx512"), std::string::npos) << c.reason;
    EXPECT_NE(c.reason.find("lacks"), std::string::npos) << c.reason;
    c = kernel::chooseVariant("avx2", {kernel::Variant::Baseline});
    EXPECT_EQ(c.variant, kernel::Variant::Baseline);
    EXPECT_NE(c.reason.find("lacks"), std::string::npos) << c.reason;
    c = kernel::chooseVariant("baseline", {kernel::Variant::Avx2, kernel::Variant::Baseline});
    EXPECT_EQ(c.variant, kernel::Variant::Baseline);
    EXPECT_EQ(c.reason, "MARBLER_KERNEL=baseline");
    // And on this CPU, for real, where it lacks one.
    for (kernel::Variant v : kernel::AllVariants)
        if (!kernel::cpuRuns(v)) {
            kernel::Choice real = kernel::chooseVariant(kernel::variantName(v));
            EXPECT_TRUE(kernel::cpuRuns(real.variant));
            EXPECT_NE(real.reason.find("lacks"), std::string::npos) << real.reason;
        }
}

TEST(KernelSelection, EveryVariantRendersTheSameImage) {
    Genome g = loadGenome(test::dataDir() / "examples" / "flame-comb-vortex.marble.json");
    CpuRenderer renderer(g);
    RenderSettings settings;
    settings.width = settings.height = 160;
    settings.aa = "rgss";
    setCpuKernelForTesting("baseline");
    const Image want = renderer.render(settings);
    for (const std::string& name : cpuKernelsSupported()) {
        setCpuKernelForTesting(name);
        const Image got = renderer.render(settings);
        int differ = 0;
        for (std::size_t k = 0; k < got.rgb.size(); ++k)
            differ += got.rgb[k] != want.rgb[k];
        // The kernels' own sine and cube root and the AVX-512 drops differ from the exact forms
        // by ulps: only a sample on an ink boundary could change, moving a channel by a level
        // or so through the average.
        EXPECT_LE(differ, 6) << name;
    }
    setCpuKernelForTesting("");
}

} // namespace
} // namespace marbler
