// The GL back end's bleed (genome-format.md, version 2, `bleed`) against the scalar rule: the
// inks traceCovers meets, composited over the bath in linear light and encoded as the renderers
// encode, pixel by pixel. Soft edges have no jumps, so every pixel is held to 2 levels.

#include "GlTestUtil.h"
#include "TestUtil.h"
#include "marbler/GenomeIO.h"
#include "marbler/Tools.h"
#include "marbler/gl/HybridMesh.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace marbler {
namespace {

glm::dvec3 linear(Color c) {
    return {srgbToLinear(c.r / 255.0), srgbToLinear(c.g / 255.0), srgbToLinear(c.b / 255.0)};
}

/// The bleed colour rule at p, in linear light: c0 ink0 + (1 - c0)(c1 ink1 + ... (bath)).
glm::dvec3 bleedColour(const Genome& genome, const std::vector<PreparedOp>& ops, const glm::dvec3& p,
                       double* partial) {
    std::vector<InkCover> covers;
    traceCovers(ops, genome.bleed, p, covers);
    glm::dvec3 colour = linear(genome.background); // a full cover, last, replaces it
    for (auto it = covers.rbegin(); it != covers.rend(); ++it) {
        colour =
            it->coverage * linear(genome.palette[std::size_t(it->color)]) + (1.0 - it->coverage) * colour;
        if (it->coverage < 1.0) *partial += 1.0;
    }
    return colour;
}

/// Renders on GL (one sample a pixel, at its centre) and holds every pixel to the scalar rule.
/// Returns the share of pixels where some ink covers only partly, so a caller can check that
/// the soft edges were really met.
double expectMatchesScalarBleed(const Genome& genome, RenderSettings settings, const std::string& label) {
    settings.aa = "none";
    const Image actual = test::glRenderer()->render(genome, settings);
    const SampleFrame frame = sampleFrame(genome, settings);
    const std::vector<PreparedOp> ops = prepare(genome);
    int off = 0;
    double partial = 0.0;
    std::string first;
    for (int y = 0; y < settings.height; ++y) {
        for (int x = 0; x < settings.width; ++x) {
            double partlyCovered = 0.0;
            const glm::dvec3 colour = bleedColour(genome, ops, frame.at(x, y, 0.0, 0.0), &partlyCovered);
            partial += partlyCovered > 0.0 ? 1.0 : 0.0;
            const std::uint8_t* got = actual.row(y) + std::size_t(x) * 3;
            for (int c = 0; c < 3; ++c) {
                if (std::abs(int(got[c]) - int(encodeSrgb8(colour[c]))) <= 2) continue;
                if (off++ == 0)
                    first = "(" + std::to_string(x) + ", " + std::to_string(y) + ") channel " +
                            std::to_string(c) + ": " + std::to_string(got[c]) + " for " +
                            std::to_string(encodeSrgb8(colour[c]));
                break;
            }
        }
    }
    EXPECT_EQ(off, 0) << label << ": " << off << " pixels differ by more than 2 levels, first at " << first;
    return partial / double(settings.width * settings.height);
}

Operation drop(glm::dvec3 centre, double radius, int color) {
    Operation op;
    op.tool = Tool::Drop;
    op.center = centre;
    op.radius = radius;
    op.color = color;
    return op;
}

class GlBleed : public ::testing::Test {
protected:
    void SetUp() override { MARBLER_REQUIRE_GL_OR_SKIP(); }
};

TEST_F(GlBleed, FlatDesignMatchesTheScalarRule) {
    // Overlapping drops (a soft ink seen through the soft edge of a newer one), then a comb and
    // a cored vortex that draw the soft edges out; the bleed is wide enough to span many pixels.
    Genome genome;
    genome.size = {1000, 700, 1000};
    genome.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}, {0xe0, 0xb4, 0x4c}};
    genome.initial = {drop({350, 350, 0}, 220, 0), drop({560, 330, 0}, 170, 1), drop({470, 420, 0}, 90, 2),
                      drop({480, 400, 0}, 40, 0)};
    Operation comb;
    comb.tool = Tool::Comb;
    comb.center = {0, 30, 0};
    comb.alpha = 40;
    comb.lambda = 20;
    comb.spacing = 120;
    genome.operations.push_back(comb);
    Operation vortex;
    vortex.tool = Tool::Vortex;
    vortex.center = {480, 380, 0};
    vortex.alpha = 300;
    vortex.lambda = 60;
    vortex.core = 30;
    genome.operations.push_back(vortex);
    RenderSettings settings;
    settings.width = 100;
    settings.height = 70;
    for (double bleed : {6.0, 40.0}) {
        genome.bleed = bleed;
        double partial = expectMatchesScalarBleed(genome, settings, "bleed " + std::to_string(bleed));
        EXPECT_GT(partial, bleed > 10.0 ? 0.1 : 0.02) << "too few soft-edged pixels to test the rule";
    }
}

TEST_F(GlBleed, SolidSliceMatchesTheScalarRule) {
    Genome genome;
    genome.dimension = 3;
    genome.size = {800, 800, 800};
    genome.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}, {0xe0, 0xb4, 0x4c}};
    genome.bleed = 30;
    genome.initial = {drop({400, 400, 400}, 280, 0), drop({450, 380, 410}, 170, 1)};
    Operation column;
    column.tool = Tool::Cylinder;
    column.center = {330, 420, 400};
    column.axis = glm::normalize(glm::dvec3(0, 1, 1));
    column.radius = 60;
    column.color = 2;
    genome.initial.push_back(column);
    Operation sphere;
    sphere.tool = Tool::Sphere;
    sphere.center = {400, 400, 400};
    sphere.radius = 200;
    sphere.alpha = 90;
    sphere.lambda = 30;
    sphere.core = 25;
    genome.operations.push_back(sphere);
    RenderSettings settings;
    settings.width = 80;
    settings.height = 80;
    for (int axis = 0; axis < 3; ++axis) {
        settings.slice = Slice{axis, 405.0};
        double partial = expectMatchesScalarBleed(genome, settings, "axis " + std::to_string(axis));
        EXPECT_GT(partial, 0.05) << "too few soft-edged pixels to test the rule";
    }
}

TEST_F(GlBleed, MeshShadingMatchesTheScalarRule) {
    // The mesh's shading pass runs the same colour rule at the G-buffer's positions: unlit, one
    // sample a pixel, each pixel is the scalar rule at its position (cored swirl included).
    Genome genome;
    genome.dimension = 3;
    genome.size = {800, 800, 800};
    genome.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}, {0xe0, 0xb4, 0x4c}};
    genome.bleed = 40;
    genome.initial = {drop({300, 420, 500}, 260, 0), drop({520, 380, 560}, 200, 1),
                      drop({430, 520, 620}, 110, 2)};
    Operation vortex;
    vortex.tool = Tool::Vortex;
    vortex.center = {400, 400, 400};
    vortex.axis = {0, 1, 0};
    vortex.alpha = 500;
    vortex.lambda = 60;
    vortex.core = 50;
    genome.operations.push_back(vortex);
    gl::MeshSettings settings;
    settings.width = 64;
    settings.height = 64;
    settings.mesh = "sphere";
    settings.lighting = false;
    settings.supersample = 1;
    const Image actual = test::glRenderer()->renderMesh(genome, settings);
    const gl::MeshGBuffer buffer = test::glRenderer()->renderMeshGBuffer(genome, settings);
    const std::vector<PreparedOp> ops = prepare(genome);
    int off = 0, covered = 0;
    double partial = 0.0;
    for (int y = 0; y < settings.height; ++y) {
        for (int x = 0; x < settings.width; ++x) {
            // The G-buffer's rows run bottom to top.
            const float* position =
                buffer.positions.data() + (std::size_t(settings.height - 1 - y) * settings.width + x) * 4;
            glm::dvec3 colour = linear(settings.clearColor);
            if (position[3] > 0.0f) {
                ++covered;
                double partlyCovered = 0.0;
                colour = bleedColour(genome, ops,
                                     buffer.reference + glm::dvec3(position[0], position[1], position[2]),
                                     &partlyCovered);
                partial += partlyCovered > 0.0 ? 1.0 : 0.0;
            }
            const std::uint8_t* got = actual.row(y) + std::size_t(x) * 3;
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(got[c]) - int(encodeSrgb8(colour[c]))) > 2) {
                    ++off;
                    break;
                }
        }
    }
    EXPECT_EQ(off, 0) << off << " pixels differ by more than 2 levels";
    EXPECT_GT(covered, 64 * 64 / 3);
    EXPECT_GT(partial, 0.05 * covered) << "too few soft-edged pixels to test the rule";
    // The CPU back end's meshes (GL rasterises, the kernel marbles) draw the same soft edges.
    const Image hybrid = gl::renderMeshHybrid(*test::glRenderer(), genome, settings);
    int hybridOff = 0;
    for (int y = 0; y < settings.height; ++y)
        for (int x = 0; x < settings.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(hybrid.row(y)[x * 3 + c]) - int(actual.row(y)[x * 3 + c])) > 2) {
                    ++hybridOff;
                    break;
                }
    EXPECT_EQ(hybridOff, 0) << hybridOff << " pixels of the CPU back end's mesh differ by more than 2 levels";
}

TEST_F(GlBleed, SourceDesignsTakeEveryVariant) {
    // A source image under the version-2 body and the bleed rule: a stretch that moves nothing
    // and a bleed far below a pixel change no pixel but those an ink edge passes through.
    Genome genome = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
    RenderSettings settings;
    settings.width = 120;
    settings.height = 60;
    const Image hard = test::glRenderer()->render(genome, settings);
    Operation still;
    still.tool = Tool::Stretch;
    still.teeth = {-5000, 5000};
    genome.operations.push_back(still);
    genome.bleed = 1e-6;
    const Image soft = test::glRenderer()->render(genome, settings);
    ASSERT_EQ(soft.rgb.size(), hard.rgb.size());
    std::size_t off = 0;
    for (std::size_t i = 0; i < hard.rgb.size(); ++i)
        off += std::abs(int(hard.rgb[i]) - int(soft.rgb[i])) > 2;
    EXPECT_LE(off, hard.rgb.size() / 500) << off << " channels differ";
}

TEST_F(GlBleed, NoBleedIsTheHardRule) {
    // bleed 0 is version 1's hard edge: the same pixels as the scalar rule's single full cover.
    Genome genome;
    genome.size = {600, 600, 1000};
    genome.palette = {{0x1f, 0x3b, 0x5a}, {0xb8, 0x41, 0x2c}};
    genome.initial = {drop({300, 300, 0}, 200, 0), drop({360, 280, 0}, 90, 1)};
    RenderSettings settings;
    settings.width = 60;
    settings.height = 60;
    double partial = expectMatchesScalarBleed(genome, settings, "bleed 0");
    EXPECT_EQ(partial, 0.0);
}

} // namespace
} // namespace marbler
