// The GL back end against the CPU renderer: same genome, same settings, the same pixels up to
// float rounding. Pixels may differ by more than 2 levels only where an ink boundary passes
// (float and double disagree on which side a sample lies), and at most 0.5% of them.

#include "GlTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Growth.h"
#include "marbler/Paper.h"
#include "marbler/Params.h"
#include "marbler/Tools.h"
#include "marbler/gl/Backend.h"

#include <OpenImageIO/imageio.h>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

namespace marbler {
namespace {

struct NamedGenome {
    std::string name;
    Genome genome;
};

/// A 2D genome of four drops on a 1200 x 800 bath, the start of the version-2 samples.
Genome dropsOnABath() {
    Genome genome;
    genome.dimension = 2;
    genome.size = {1200, 800, 1000};
    genome.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}, {0xe0, 0xb4, 0x4c}, {0x2e, 0x6e, 0x5e}};
    const double drops[4][3] = {{300, 400, 180}, {800, 350, 160}, {600, 600, 120}, {620, 210, 100}};
    for (int k = 0; k < 4; ++k) {
        Operation drop;
        drop.tool = Tool::Drop;
        drop.center = {drops[k][0], drops[k][1], 0.0};
        drop.radius = drops[k][2];
        drop.color = k;
        genome.initial.push_back(drop);
    }
    return genome;
}

Operation swirl(Tool tool, glm::dvec3 centre, double radius, double alpha, double lambda, double core) {
    Operation op;
    op.tool = tool;
    op.center = centre;
    op.radius = radius;
    op.alpha = alpha;
    op.lambda = lambda;
    op.core = core;
    return op;
}

Operation stretch(glm::dvec2 origin, double angle, std::vector<double> teeth, double shift, double power) {
    Operation op;
    op.tool = Tool::Stretch;
    op.center = {origin, 0.0};
    op.angle = angle;
    op.teeth = std::move(teeth);
    op.shift = shift;
    op.power = power;
    return op;
}

Operation flow(FlowField field, glm::dvec2 origin, double angle, glm::dvec2 size, double speed, double time) {
    Operation op;
    op.tool = Tool::Flow;
    op.field = field;
    op.center = {origin, 0.0};
    op.angle = angle;
    op.extent = size;
    op.speed = speed;
    op.time = time;
    op.steps = 1;
    op.steps = minimumFlowSteps(op) + 3;
    return op;
}

/// The version-2 samples: stretch (a few teeth, and hundreds for the shader's search), flow
/// through cells and a cavity, swirls with finite cores (and one without, which must keep the
/// version-1 turn where the version-2 forms are compiled in), 2D and 3D.
std::vector<NamedGenome> version2Genomes() {
    std::vector<NamedGenome> out;
    Genome stretched = dropsOnABath();
    stretched.operations.push_back(stretch({0, 800}, 180, {0, 90, 250, 400, 530, 700, 800}, 70, 2.0));
    std::vector<double> many;
    for (int k = 0; k <= 300; ++k)
        many.push_back(-50.0 + 4.3 * k + 1.1 * std::sin(k));
    stretched.operations.push_back(stretch({1200, 0}, 90, many, -9, 0.5));
    stretched.operations.push_back(swirl(Tool::Vortex, {420, 380, 0}, 0, 400, 50, 0));
    out.push_back({"v2-stretch-2d", stretched});

    Genome cells = dropsOnABath();
    cells.operations.push_back(flow(FlowField::Cells, {40, -30}, 20, {300, 250}, 40, 3));
    cells.operations.push_back(swirl(Tool::Circle, {600, 400, 0}, 250, 150, 30, 40));
    out.push_back({"v2-flow-cells-2d", cells});

    Genome cavity = dropsOnABath();
    cavity.operations.push_back(flow(FlowField::Cavity, {200, 150}, -10, {700, 500}, -100, 4));
    cavity.operations.push_back(swirl(Tool::Vortex, {350, 420, 0}, 0, 500, 60, 25));
    out.push_back({"v2-flow-cavity-2d", cavity});

    Genome solid;
    solid.dimension = 3;
    solid.size = {800, 800, 800};
    solid.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}, {0xe0, 0xb4, 0x4c}};
    const double drops[4][4] = {
        {330, 400, 400, 250}, {480, 380, 420, 170}, {420, 470, 380, 110}, {400, 300, 400, 80}};
    for (int k = 0; k < 4; ++k) {
        Operation drop;
        drop.tool = Tool::Drop;
        drop.center = {drops[k][0], drops[k][1], drops[k][2]};
        drop.radius = drops[k][3];
        drop.color = k % 3;
        solid.initial.push_back(drop);
    }
    Operation tilted = swirl(Tool::Circle, {400, 400, 400}, 150, 200, 40, 60);
    tilted.axis = glm::normalize(glm::dvec3(1, 2, 2));
    solid.operations.push_back(tilted);
    solid.operations.push_back(swirl(Tool::Sphere, {420, 380, 400}, 150, 150, 30, 50));
    Operation vortex = swirl(Tool::Vortex, {380, 420, 410}, 0, 900, 50, 70);
    vortex.axis = {0, 1, 0};
    solid.operations.push_back(vortex);
    out.push_back({"v2-cored-3d", solid});
    return out;
}

Operation stylusStroke(std::vector<glm::dvec2> path, double alpha, double lambda, double reach, int tines = 1,
                       double spacing = 0.0, std::vector<double> pressure = {}) {
    Operation op;
    op.tool = Tool::Stylus;
    op.path = std::move(path);
    op.alpha = alpha;
    op.lambda = lambda;
    op.reach = reach;
    op.tines = tines;
    op.spacing = spacing;
    op.pressure = std::move(pressure);
    op.steps = minimumStylusSteps(op) + 7; // not a round number: segments start between steps
    return op;
}

std::vector<glm::dvec2> spiral() {
    std::vector<glm::dvec2> points;
    for (int k = 0; k < 240; ++k) {
        const double turn = 0.045 * k, radius = 40.0 + 1.4 * k;
        points.push_back({600 + radius * std::cos(turn), 420 + radius * std::sin(turn)});
    }
    return points;
}

/// The version-3 samples: a stylus gentle and strong (ink dragged to the end of the path), a
/// rake with bleed, pressure rising and falling to 0, a curved path of many segments, and a
/// stylus between other version-2 forms (the shader's runs stop at each).
std::vector<NamedGenome> stylusGenomes() {
    std::vector<NamedGenome> out;
    Genome single = dropsOnABath();
    single.operations.push_back(stylusStroke({{60, 120}, {1150, 700}}, 35, 15, 90));
    out.push_back({"v3-stylus-single-2d", single});

    Genome rake = dropsOnABath();
    rake.bleed = 4.0;
    rake.operations.push_back(stylusStroke({{40, 420}, {600, 300}, {1160, 460}}, 40, 12, 60, 5, 70));
    out.push_back({"v3-stylus-rake-bleed-2d", rake});

    Genome pressed = dropsOnABath();
    pressed.operations.push_back(stylusStroke({{80, 600}, {420, 380}, {700, 520}, {1120, 200}}, 110, 10, 50,
                                              1, 0, {0.1, 1.0, 0.4, 0.0}));
    out.push_back({"v3-stylus-pressure-2d", pressed});

    // A spiral of 240 points about the drops (segments of 3 to 17 units, each a few steps),
    // strong enough to drag ink along.
    Genome curve = dropsOnABath();
    curve.operations.push_back(stylusStroke(spiral(), 45, 9, 40));
    out.push_back({"v3-stylus-curve-2d", curve});

    Genome mixed = dropsOnABath();
    mixed.operations.push_back(stretch({0, 800}, 180, {0, 250, 530, 800}, 50, 2.0));
    mixed.operations.push_back(stylusStroke({{1100, 100}, {150, 650}}, 80, 20, 70));
    mixed.operations.push_back(swirl(Tool::Vortex, {620, 380, 0}, 0, 300, 40, 30));
    mixed.operations.push_back(stylusStroke({{200, 200}, {900, 260}}, -40, 8, 45, 3, 40));
    out.push_back({"v3-stylus-among-others-2d", mixed});
    return out;
}

std::vector<NamedGenome> sampleGenomes() {
    std::vector<NamedGenome> out = version2Genomes();
    for (NamedGenome& g : stylusGenomes())
        out.push_back(std::move(g));
    for (const auto& entry : std::filesystem::directory_iterator(test::dataDir() / "examples"))
        if (entry.path().string().ends_with(".marble.json"))
            out.push_back({entry.path().filename().string(), loadGenome(entry.path())});
    for (int k = 0; k < 5; ++k) {
        std::filesystem::path file =
            test::dataDir() / "conformance" / ("probes-" + std::to_string(k) + ".json");
        if (!std::filesystem::exists(file)) continue;
        auto json = nlohmann::json::parse(test::readFile(file));
        out.push_back({file.filename().string(), parseGenome(json.at("genome").dump(), file.string())});
    }
    std::filesystem::path renderData = test::dataDir() / "render";
    if (std::filesystem::exists(renderData))
        for (const auto& entry : std::filesystem::recursive_directory_iterator(renderData))
            if (entry.path().string().ends_with(".marble.json"))
                out.push_back({entry.path().filename().string(), loadGenome(entry.path())});
    for (std::uint64_t seed : {1u, 2u, 3u})
        for (int dimension : {2, 3})
            out.push_back({"random-" + std::to_string(seed) + "-" + std::to_string(dimension) + "d",
                           randomGenome(seed, dimension)});
    std::sort(out.begin(), out.end(),
              [](const NamedGenome& a, const NamedGenome& b) { return a.name < b.name; });
    return out;
}

int maxChannelDiff(const Image& a, const Image& b, std::size_t pixel) {
    int worst = 0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(int(a.rgb[pixel * 3 + c]) - int(b.rgb[pixel * 3 + c])));
    return worst;
}

/// Whether pixel (x, y) touches an ink boundary: a neighbour of another CPU colour, or samples
/// of different inks.
bool atInkBoundary(const Genome& genome, const CpuRenderer& cpu, const RenderSettings& settings,
                   const Image& ref, int x, int y) {
    const std::uint8_t* centre = ref.rgb.data() + (std::size_t(y) * ref.width + x) * 3;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= ref.width || ny >= ref.height) continue;
            if (!std::equal(centre, centre + 3, ref.rgb.data() + (std::size_t(ny) * ref.width + nx) * 3))
                return true;
        }
    SampleFrame frame = sampleFrame(genome, settings);
    AaPattern aa = aaPattern(settings.aa);
    std::set<int> inks;
    for (const glm::dvec2& o : aa.offsets)
        inks.insert(cpu.colorIndexAt(frame.at(x, y, o.x, o.y)));
    return inks.size() > 1;
}

/// Renders on both and holds GL to the CPU; saves both images when they disagree.
void expectMatchesCpu(const Genome& genome, const RenderSettings& settings, const std::string& label) {
    Image actual;
    try {
        actual = test::glRenderer()->render(genome, settings);
    } catch (const RuntimeFailure& e) {
        FAIL() << label << ": " << e.what();
    }
    CpuRenderer cpu(genome);
    Image expected = cpu.render(settings);
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);
    std::size_t pixels = std::size_t(expected.width) * std::size_t(expected.height);
    std::size_t off = 0, unexplained = 0;
    std::string firstUnexplained;
    for (int y = 0; y < expected.height; ++y) {
        for (int x = 0; x < expected.width; ++x) {
            if (maxChannelDiff(expected, actual, std::size_t(y) * expected.width + x) <= 2) continue;
            ++off;
            if (!atInkBoundary(genome, cpu, settings, expected, x, y)) {
                if (unexplained++ == 0)
                    firstUnexplained = "(" + std::to_string(x) + ", " + std::to_string(y) + ")";
            }
        }
    }
    bool ok = double(off) <= 0.005 * double(pixels) && unexplained == 0;
    EXPECT_LE(double(off), 0.005 * double(pixels))
        << label << ": " << off << " of " << pixels << " pixels differ by > 2";
    EXPECT_EQ(unexplained, 0u) << label << ": pixels differ away from ink boundaries, first at "
                               << firstUnexplained;
    if (!ok) {
        std::filesystem::path dir = test::outputDir("gl-vs-cpu");
        std::string stem = label;
        std::replace_if(
            stem.begin(), stem.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
            '_');
        test::savePng(expected, dir / (stem + "-cpu.png"));
        test::savePng(actual, dir / (stem + "-gl.png"));
        ADD_FAILURE() << "images saved in " << dir;
    }
}

TEST(GlVsCpuCoverage, SampleGenomesHoldEveryToolOfTheRegistry) {
    // The shaders are held to the CPU renderer on the sample genomes, so a tool they lack
    // would go unchecked: a new tool without a sample fails here, with or without GL.
    std::set<std::string> seen;
    for (const NamedGenome& g : sampleGenomes())
        test::addToolsUsed(g.genome, seen);
    test::expectEveryRegistryTool(seen, "no sample genome holds");
}

class GlVsCpu : public ::testing::Test {
protected:
    void SetUp() override { MARBLER_REQUIRE_GL_OR_SKIP(); }
};

TEST_F(GlVsCpu, EverySampleGenomeWithAndWithoutAntialiasing) {
    for (const NamedGenome& g : sampleGenomes()) {
        for (const char* aa : {"none", "rgss"}) {
            RenderSettings settings;
            settings.width = 120;
            settings.height = 96;
            settings.aa = aa;
            if (g.genome.dimension == 2) {
                expectMatchesCpu(g.genome, settings, g.name + " " + aa);
                continue;
            }
            for (int axis = 0; axis < 3; ++axis) {
                settings.slice = Slice{axis, g.genome.size[axis] * (axis == 1 ? 0.37 : 0.5)};
                expectMatchesCpu(g.genome, settings, g.name + " axis " + std::to_string(axis) + " " + aa);
            }
        }
    }
}

TEST_F(GlVsCpu, SolidsOnATurnedSection) {
    // A section turned to any normal (issue 23) is sampled through the same frame on both.
    for (const NamedGenome& g : sampleGenomes()) {
        if (g.genome.dimension != 3) continue;
        RenderSettings settings;
        settings.width = 120;
        settings.height = 96;
        settings.aa = "rgss";
        const glm::dvec3 n = glm::normalize(glm::dvec3(1.0, -2.0, 3.0));
        const glm::dvec2 range = sliceOffsetRange(n, g.genome.size);
        settings.slice = Slice{2, 0.5 * (range.x + range.y), n};
        expectMatchesCpu(g.genome, settings, g.name + " turned");
    }
}

TEST_F(GlVsCpu, StylusDesignsAtALargerSize) {
    // The version-3 samples at 240 x 160, where a pixel is 5 units: the stylus's fine curls
    // (lambda 8 to 20) span a few pixels each.
    for (const NamedGenome& g : stylusGenomes()) {
        RenderSettings settings;
        settings.width = 240;
        settings.height = 160;
        settings.aa = "none";
        expectMatchesCpu(g.genome, settings, g.name + " 240");
    }
}

TEST_F(GlVsCpu, AWrappingBathAndItsNeighbouringTiles) {
    // A wrapping bath (docs/genome-format.md): marbler paper's default recipe, over the tile and
    // half of each neighbour, hard and soft-edged.
    PaperOptions options;
    options.width = 80.0;
    options.height = 60.0;
    for (double bleed : {0.0, 0.8}) {
        Genome g = paperGenome(4, options);
        ASSERT_TRUE(g.wrap);
        g.bleed = bleed;
        RenderSettings settings;
        settings.width = 160;
        settings.height = 120;
        settings.region = Region{-40.0, -30.0, 120.0, 90.0};
        expectMatchesCpu(g, settings, "wrapping paper, bleed " + std::to_string(bleed));
    }
}

TEST_F(GlVsCpu, HalfDropAndBrickBathsOverSeveralTiles) {
    // The wrap's lattices (docs/genome-format.md, "Half-drop and brick repeats"): the shader's
    // three-column nearest image and halved stretch periods draw what the CPU kernel draws,
    // over a region of 2 x 2 tiles and more, hard and soft-edged.
    for (Lattice lattice : {Lattice::HalfDrop, Lattice::Brick})
        for (double bleed : {0.0, 0.8}) {
            PaperOptions options;
            options.width = 80.0;
            options.height = 60.0;
            options.lattice = lattice;
            Genome g = paperGenome(4, options);
            ASSERT_EQ(g.lattice, lattice);
            g.bleed = bleed;
            RenderSettings settings;
            settings.width = 200;
            settings.height = 150;
            settings.region = Region{-50.0, -37.5, 150.0, 112.5};
            expectMatchesCpu(g, settings,
                             std::string(latticeName(lattice)) + " paper, bleed " + std::to_string(bleed));
        }
}

TEST_F(GlVsCpu, AStylusBeyondASoftwareRasterisersLoopLimitIsRefused) {
    // llvmpipe ends every loop of a shader invocation after 65535 iterations in all, silently;
    // a rake dragging ink along 240 points at four samples a pixel runs more. The GL back end
    // sees it (tools.glsl, loopsWereCut) and refuses with its reason, a RuntimeFailure, on which
    // the render service draws on the CPU; a hardware GPU has no such limit and draws it.
    Genome genome = dropsOnABath();
    genome.operations.push_back(stylusStroke(spiral(), 45, 9, 40, 4, 25));
    RenderSettings settings;
    settings.width = 150;
    settings.height = 100;
    settings.aa = "rgss";
    if (!gl::isSoftwareRenderer(test::glRenderer()->rendererName())) {
        expectMatchesCpu(genome, settings, "a long rake");
        return;
    }
    try {
        test::glRenderer()->render(genome, settings);
        ADD_FAILURE() << "a render whose loops were cut short was returned";
    } catch (const RuntimeFailure& e) {
        EXPECT_NE(std::string(e.what()).find("loop iterations"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("CPU renderer draws it"), std::string::npos) << e.what();
    }
    // And the same design within the limit (one sample a pixel) is drawn as the CPU draws it.
    settings.width = 90;
    settings.height = 60;
    settings.aa = "none";
    expectMatchesCpu(genome, settings, "a long rake, one sample");
}

TEST_F(GlVsCpu, AStylusPartWayAlongItsPath) {
    // Growth (genome-format.md, the making of a design): at progress s a stylus runs its first
    // floor(s n) steps, its path cut where it has travelled to; GL draws each part as the CPU.
    for (const NamedGenome& g : stylusGenomes()) {
        if (g.name != "v3-stylus-pressure-2d" && g.name != "v3-stylus-curve-2d") continue;
        const double last = double(stepCount(g.genome) - 1);
        for (double progress : {0.23, 0.5, 0.91}) {
            const Genome part = designAtGrowth(g.genome, last + progress);
            ASSERT_EQ(part.operations.size(), g.genome.operations.size()) << g.name;
            EXPECT_LT(part.operations.back().steps, g.genome.operations.back().steps);
            RenderSettings settings;
            settings.width = 120;
            settings.height = 80;
            settings.aa = "rgss";
            expectMatchesCpu(part, settings, g.name + " at " + std::to_string(progress));
        }
    }
}

TEST_F(GlVsCpu, EbruHeartsRenderAsTheirReference) {
    // The example of version 3 against the independent reference's render without
    // antialiasing, as the CPU renderer is held to it (Conformance.EbruHeartsRenderAsTheirReference):
    // pixel for pixel but for a hair's width of edges.
    const Genome genome = loadGenome(test::dataDir() / "examples" / "ebru-hearts.marble.json");
    const Image expected = test::loadPng(test::dataDir() / "reference" / "ebru-hearts-noaa.png");
    ASSERT_GT(expected.width, 0);
    RenderSettings settings;
    settings.width = expected.width;
    settings.height = expected.height;
    settings.aa = "none";
    const Image actual = test::glRenderer()->render(genome, settings);
    ASSERT_EQ(actual.rgb.size(), expected.rgb.size());
    std::size_t equal = 0;
    for (std::size_t i = 0; i < actual.rgb.size(); i += 3)
        equal += std::equal(actual.rgb.begin() + long(i), actual.rgb.begin() + long(i + 3),
                            expected.rgb.begin() + long(i));
    const double share = double(equal) / double(actual.rgb.size() / 3);
    if (!(share >= 0.995)) {
        const std::filesystem::path out = test::outputDir("gl-ebru-hearts") / "ebru-hearts.gl.png";
        test::savePng(actual, out);
        ADD_FAILURE() << (1.0 - share) * 100.0 << "% of pixels differ; the GL image is saved to " << out;
    }
}

TEST_F(GlVsCpu, VersionTwoFormsKeepTheVersionOneResult) {
    // A stretch that moves nothing compiles the version-2 forms in (tools.glsl): the circle and
    // vortex with core 0 must then turn exactly as the version-1 body turns them.
    Genome genome = loadGenome(test::dataDir() / "render" / "waves-swirls-2d.marble.json");
    RenderSettings settings;
    settings.width = 120;
    settings.height = 80;
    settings.aa = "rgss";
    const Image version1 = test::glRenderer()->render(genome, settings);
    Operation still;
    still.tool = Tool::Stretch;
    still.teeth = {-1000, 1000};
    still.shift = 0.0;
    genome.operations.push_back(still);
    const Image version2 = test::glRenderer()->render(genome, settings);
    EXPECT_TRUE(version1.rgb == version2.rgb);
}

TEST_F(GlVsCpu, EveryAntialiasingPattern) {
    Genome genome = randomGenome(7, 2);
    for (const std::string& aa : aaPatternNames()) {
        RenderSettings settings;
        settings.width = 48;
        settings.height = 40;
        settings.aa = aa;
        expectMatchesCpu(genome, settings, "pattern " + aa);
    }
}

TEST_F(GlVsCpu, DeepZoomKeepsPrecision) {
    // A 4-unit window at 128 pixels: 0.03 units a pixel, where float design coordinates alone
    // (ulp 6e-5 at 1000) would still do, and a 0.05-unit one, where only the tile-relative
    // packing keeps the samples apart.
    Genome genome = randomGenome(11, 2);
    for (double half : {2.0, 0.025}) {
        RenderSettings settings;
        settings.width = 128;
        settings.height = 128;
        settings.region = Region{612.3 - half, 401.7 - half, 612.3 + half, 401.7 + half};
        expectMatchesCpu(genome, settings, "zoom " + std::to_string(half));
    }
}

TEST_F(GlVsCpu, TilesJoinWithoutSeams) {
    // Wider than one 2048-pixel tile, so a tile edge crosses the image.
    Genome genome = randomGenome(5, 2);
    RenderSettings settings;
    settings.width = 2300;
    settings.height = 24;
    settings.region = Region{0, 480, 1000, 480 + 24.0 * 1000.0 / 2300.0};
    expectMatchesCpu(genome, settings, "tiles");
}

TEST_F(GlVsCpu, TenThousandEntriesRender) {
    Genome genome;
    genome.dimension = 2;
    genome.size = {1000, 1000, 1000};
    genome.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}, {0xe0, 0xb4, 0x4c}};
    Pcg32 rng(99);
    for (int k = 0; k < 5000; ++k) {
        Operation drop;
        drop.tool = Tool::Drop;
        drop.center = {rng.uniform() * 1000.0, rng.uniform() * 1000.0, 0.0};
        drop.radius = 5.0 + rng.uniform() * 20.0;
        drop.color = k % 3;
        genome.initial.push_back(drop);
    }
    for (int k = 0; k < 5000; ++k) {
        Operation line;
        line.tool = k % 2 ? Tool::Line : Tool::Comb;
        line.center = {rng.uniform() * 1000.0, rng.uniform() * 1000.0, 0.0};
        line.angle = rng.uniform() * 360.0;
        line.alpha = 2.0;
        line.lambda = 10.0;
        line.spacing = 90.0;
        genome.operations.push_back(line);
    }
    ASSERT_EQ(genome.initial.size() + genome.operations.size(), MaxEntries);
    RenderSettings settings;
    settings.width = 40;
    settings.height = 40;
    expectMatchesCpu(genome, settings, "10000 entries");
}

/// Writes a `width` x `height` RGB image whose channels run through fine steps (so an 8-bit
/// copy would lose them): a 16-bit TIFF in sRGB, or a half-float EXR in linear light with
/// values up to 1.5.
void writeGradient(const std::filesystem::path& file, int width, int height) {
    const bool exr = file.extension() == ".exr";
    OIIO::ImageSpec spec(width, height, 3, exr ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT16);
    spec.attribute("oiio:ColorSpace", exr ? "Linear" : "sRGB");
    std::vector<float> pixels(std::size_t(width) * std::size_t(height) * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                const float t =
                    (float(x) + float(y) * float(width) + float(c) * 0.37f) / float(width * height);
                pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3 + std::size_t(c)] =
                    exr ? 0.003f + 1.5f * t * t : 0.1f + 0.8f * t;
            }
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out && out->open(file.string(), spec)) << OIIO::geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
}

TEST_F(GlVsCpu, SourceImagesOfEveryDepthShowTheSameColours) {
    // Both back ends take their pixels from one decoder: a 16-bit image keeps its fine steps
    // and a linear (EXR) one its light, on the GPU as on the CPU.
    const std::filesystem::path dir = test::outputDir("gl-sources");
    Genome genome = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
    genome.baseDirectory = dir.string();
    for (const char* name : {"deep.tif", "linear.exr"}) {
        writeGradient(dir / name, 37, 19);
        genome.source = SourceImage{name};
        for (const char* aa : {"none", "rgss"}) {
            RenderSettings settings;
            settings.width = 150;
            settings.height = 75;
            settings.aa = aa;
            expectMatchesCpu(genome, settings, std::string(name) + " " + aa);
            // Zoomed in between pixel centres, where the bilinear blend of the two decoders shows.
            settings.region = Region{10, 300, 90, 340};
            expectMatchesCpu(genome, settings, std::string(name) + " zoomed " + aa);
        }
    }
}

TEST_F(GlVsCpu, BadSourcesAreRefusedAlike) {
    // The GL back end once decoded with QImage, which skipped base64 it could not read and
    // showed what was left; now it refuses what the CPU refuses, with the same message.
    Genome genome = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
    RenderSettings settings;
    settings.width = 16;
    settings.height = 8;
    for (const std::string& image :
         {std::string("data:image/png;base64,iVBORw0KGgo!!AAAA"), std::string("data:image/png,plain"),
          std::string("data:image/png;base64,AAAA"), std::string("no-such.png"),
          // A Photoshop file's first bytes in a PNG's clothing: refused by what it is.
          std::string("data:image/png;base64,OEJQUwABAAAAAAAA"), std::string("../escape.png")}) {
        genome.source = SourceImage{image};
        std::string cpuError, glError;
        try {
            CpuRenderer cpu(genome);
        } catch (const GenomeError& e) {
            cpuError = e.what();
        }
        try {
            test::glRenderer()->render(genome, settings);
        } catch (const GenomeError& e) {
            glError = e.what();
        }
        EXPECT_FALSE(cpuError.empty()) << image;
        EXPECT_EQ(glError, cpuError) << image;
        EXPECT_NE(cpuError.find("source.image"), std::string::npos) << cpuError;
    }
}

TEST_F(GlVsCpu, BadSettingsAreInputErrors) {
    Genome genome = randomGenome(3, 3);
    RenderSettings settings;
    settings.width = 16;
    settings.height = 16; // a solid genome needs a slice
    EXPECT_THROW(test::glRenderer()->render(genome, settings), InputError);
    settings.slice = Slice{2, 500};
    settings.aa = "grid9";
    EXPECT_THROW(test::glRenderer()->render(genome, settings), InputError);
}

TEST(GlAvailability, ReportsAReasonOrARenderer) {
    std::string why;
    if (gl::GlRenderer::available(&why)) {
        EXPECT_FALSE(test::glRenderer()->rendererName().empty());
        std::string version = test::glRenderer()->glVersion();
        EXPECT_GE(std::stod(version), 4.3) << version;
    } else {
        EXPECT_FALSE(why.empty());
        if (test::glRequired()) ADD_FAILURE() << "MARBLER_REQUIRE_GL=1 but no GL: " << why;
    }
}

} // namespace
} // namespace marbler
