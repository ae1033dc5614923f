// The CPU's own object path (ObjectView.h): the object rasterised on the CPU and coloured by
// the kernel, so `render --mesh` works with no display and no GL. The geometry is checked
// against what the camera must give (a framed sphere's disc, the visible hemisphere, the cut's
// cap on its plane); tests/gl/ObjectRasterTest.cpp compares it with the GL pass.

#include "marbler/ObjectView.h"
#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

namespace marbler {
namespace {

Genome slateBlock() {
    return loadGenome(test::dataDir() / "examples" / "slate-block.marble.json");
}

std::size_t coveredSamples(const MeshGBuffer& g) {
    std::size_t covered = 0;
    for (std::size_t s = 3; s < g.positions.size(); s += 4)
        covered += g.positions[s] > 0.0f;
    return covered;
}

TEST(ObjectView, AFramedSphereFillsItsShareOfTheView) {
    const Genome genome = slateBlock();
    MeshSettings settings;
    settings.width = settings.height = 120;
    settings.supersample = 3;
    settings.yaw = 0.0;
    settings.pitch = 0.0;
    const MeshGBuffer g = rasterizeObject(genome, builtinMesh("sphere"), settings);
    ASSERT_EQ(g.positions.size(), std::size_t(360) * 360 * 4);
    // Framing makes the sphere's outline span 92 % of the view: a disc of radius 0.46 views.
    const double share = double(coveredSamples(g)) / (360.0 * 360.0);
    const double disc = std::numbers::pi * 0.46 * 0.46;
    EXPECT_NEAR(share, disc, 0.01);
    // Only the near side is seen (the depth test), its normals facing the camera: all but a few
    // samples on the silhouette, where a facet's interpolated normal may turn just past it.
    std::size_t facing = 0, covered = 0;
    for (std::size_t s = 0; s < g.positions.size(); s += 4) {
        if (g.positions[s + 3] == 0.0f) continue;
        ++covered;
        const glm::dvec3 p(g.positions[s], g.positions[s + 1], g.positions[s + 2]);
        const glm::dvec3 n(g.normals[s], g.normals[s + 1], g.normals[s + 2]);
        facing +=
            glm::dot(p, g.eye) > -1e-6 * glm::length(g.eye) * glm::length(p) && glm::dot(n, g.eye - p) > 0.0;
    }
    EXPECT_GT(double(facing) / double(covered), 0.999);
}

TEST(ObjectView, ACutShowsItsCapOnThePlane) {
    const Genome genome = slateBlock();
    MeshSettings settings;
    settings.width = settings.height = 96;
    settings.supersample = 1;
    settings.yaw = 0.0;
    settings.pitch = 0.0;
    // Cut away the half towards the camera (+z) through the box centre: the cap faces the eye.
    settings.cut = CutPlane{{0.0, 0.0, 1.0}, genome.size.z / 2.0};
    const MeshGBuffer g = rasterizeObject(genome, builtinMesh("sphere"), settings);
    std::size_t onPlane = 0, covered = 0;
    for (std::size_t s = 0; s < g.positions.size(); s += 4) {
        if (g.positions[s + 3] == 0.0f) continue;
        ++covered;
        // Relative to the box centre, the cap lies at z = 0 with the plane's normal.
        if (std::abs(g.positions[s + 2]) < 1e-3 * genome.size.z && g.normals[s + 2] > 0.999f) ++onPlane;
    }
    ASSERT_GT(covered, 0u);
    // Seen head-on, the whole disc is the cap.
    EXPECT_GT(double(onPlane) / double(covered), 0.97);
}

TEST(ObjectView, BadInputIsRefused) {
    MeshSettings settings;
    Genome flat = loadGenome(test::dataDir() / "examples" / "five-stones.marble.json");
    EXPECT_THROW(rasterizeObject(flat, builtinMesh("sphere"), settings), InputError);
    MeshData empty;
    EXPECT_THROW(rasterizeObject(slateBlock(), empty, settings), InputError);
    MeshData broken = builtinMesh("cube");
    broken.indices.push_back(std::uint32_t(broken.positions.size()));
    broken.indices.push_back(0);
    broken.indices.push_back(1);
    EXPECT_THROW(rasterizeObject(slateBlock(), broken, settings), InputError);
    settings.supersample = 2;
    EXPECT_THROW(rasterizeObject(slateBlock(), builtinMesh("sphere"), settings), InputError);
}

TEST(ObjectView, RenderMeshNeedsNoDisplay) {
    const auto dir = test::outputDir("object-view-cli");
    const std::string genome = (test::dataDir() / "examples" / "slate-block.marble.json").string();
    const std::filesystem::path out = dir / "vase.png";
    // No display at all, and Qt's offscreen platform (which makes no GL context) if Qt is asked.
    test::RunResult run = test::runMarbler(
        {"render", genome, "--mesh", "vase", "--view", "30,20", "--width", "80", "--supersample", "3", "-o",
         out.string()},
        {{"DISPLAY", std::nullopt}, {"WAYLAND_DISPLAY", std::nullopt}, {"QT_QPA_PLATFORM", "offscreen"}});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const Image image = test::readImage8(out);
    ASSERT_EQ(image.width, 80);
    ASSERT_EQ(image.height, 80);
    // The object covers a good part of the frame, the rest is the clear colour.
    std::size_t clear = 0;
    for (std::size_t p = 0; p < image.rgb.size(); p += 3)
        clear += image.rgb[p] == 0x2b && image.rgb[p + 1] == 0x2b && image.rgb[p + 2] == 0x2b;
    const double objectShare = 1.0 - double(clear) / (80.0 * 80.0);
    EXPECT_GT(objectShare, 0.2);
    EXPECT_LT(objectShare, 0.9);
    // The file carries its design, as every render does.
    EXPECT_EQ(serializeGenome(loadDesign(out)), serializeGenome(loadGenome(genome)));
    // And the same object as the library draws it.
    MeshSettings settings;
    settings.width = settings.height = 80;
    settings.yaw = 30.0;
    settings.pitch = 20.0;
    EXPECT_EQ(renderObjectOnCpu(loadGenome(genome), builtinMesh("vase"), settings).rgb, image.rgb);
}

} // namespace
} // namespace marbler
