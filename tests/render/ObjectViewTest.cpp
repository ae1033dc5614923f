// The CPU's own object path (ObjectView.h): the object rasterised on the CPU and coloured by
// the kernel, so `render --mesh` works with no display and no GL. The geometry is checked
// against what the camera must give (a framed sphere's disc, the visible hemisphere, the cut's
// cap on its plane); tests/gl/ObjectRasterTest.cpp compares it with the GL pass.

#include "marbler/ObjectView.h"
#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/Bake.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
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
    settings.fovY = 0.0;
    EXPECT_THROW(rasterizeObject(slateBlock(), builtinMesh("sphere"), settings), InputError);
    settings.fovY = 50.0;
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

/// A flat design with two halves of different inks: the background left of x = w/2, a drop
/// covering the right half (its radius reaches past the corners).
Genome halves() {
    Genome genome = loadGenome(test::dataDir() / "examples" / "five-stones.marble.json");
    genome.initial.clear();
    genome.operations.clear();
    Operation drop;
    drop.tool = Tool::Drop;
    drop.center = glm::dvec3(genome.size.x * 1.5, genome.size.y / 2.0, 0.0);
    drop.radius = genome.size.x;
    drop.color = 0;
    genome.initial.push_back(drop);
    return genome;
}

TEST(ObjectView, AFlatDesignLiesOnTheTextureCoordinates) {
    // A square flat design on the cube seen head-on and unlit: the front face shows the design's
    // texture square, so at each sample the colour is the design's at that sample's UV point.
    Genome genome = halves();
    genome.size = glm::dvec3(800.0, 800.0, 0.0);
    genome.initial[0].center = glm::dvec3(1200.0, 400.0, 0.0);
    genome.initial[0].radius = 800.0;
    MeshSettings settings;
    settings.width = settings.height = 64;
    settings.supersample = 1;
    settings.yaw = 0.0;
    settings.pitch = 0.0;
    settings.lighting = false;
    const MeshData cube = builtinMesh("cube");
    const MeshGBuffer g = rasterizeObject(genome, cube, settings);
    ASSERT_EQ(g.uvs.size(), std::size_t(64) * 64 * 2);
    const Image image = shadeMeshOnCpu(genome, g, settings);
    const FlatOnUvs flat(genome);
    const CpuRenderer renderer(genome);
    std::size_t checked = 0, inkSeen = 0, bathSeen = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const std::size_t s = std::size_t(63 - y) * 64 + std::size_t(x); // GL rows run upwards
            if (g.positions[s * 4 + 3] == 0.0f) continue;
            const glm::dvec3 q = flat.designPoint({g.uvs[s * 2], g.uvs[s * 2 + 1]});
            const int ink = renderer.colorIndexAt(q);
            const Color expected = ink >= 0 ? genome.palette[std::size_t(ink)] : genome.background;
            const std::uint8_t* got = image.row(y) + x * 3;
            EXPECT_EQ(got[0], expected.r);
            EXPECT_EQ(got[1], expected.g);
            EXPECT_EQ(got[2], expected.b);
            ++checked;
            (ink >= 0 ? inkSeen : bathSeen) += 1;
        }
    EXPECT_GT(checked, 64u * 64u / 4);
    // Both halves show: the design is laid across the face, not one colour.
    EXPECT_GT(inkSeen, checked / 5);
    EXPECT_GT(bathSeen, checked / 5);
}

TEST(ObjectView, AFlatDesignNeedsTheObjectsOwnUvs) {
    const Genome genome = halves();
    MeshSettings settings;
    MeshData bare = builtinMesh("sphere");
    bare.uvs.clear();
    EXPECT_THROW(rasterizeObject(genome, bare, settings), InputError);
    MeshData patches = builtinMesh("sphere");
    patches.uvsArePatches = true;
    EXPECT_THROW(rasterizeObject(genome, patches, settings), InputError);
}

TEST(ObjectView, RenderMeshLaysAFlatDesignOnTheVase) {
    const auto dir = test::outputDir("object-view-flat");
    const std::string genome = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    const std::filesystem::path out = dir / "vase.png";
    test::RunResult run = test::runMarbler(
        {"render", genome, "--mesh", "vase", "--view", "30,20", "--width", "64", "-o", out.string()},
        {{"DISPLAY", std::nullopt}, {"WAYLAND_DISPLAY", std::nullopt}});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    MeshSettings settings;
    settings.width = settings.height = 64;
    settings.yaw = 30.0;
    settings.pitch = 20.0;
    EXPECT_EQ(test::readImage8(out).rgb,
              renderObjectOnCpu(loadGenome(genome), builtinMesh("vase"), settings).rgb);
    EXPECT_EQ(serializeGenome(loadDesign(out)), serializeGenome(loadGenome(genome)));
}

/// The G-buffer's coverage, depth-tested points and texture coordinates by the plainest
/// rasteriser: every triangle over the whole frame at once, in the mesh's order, with the
/// arithmetic of rasterizeObject (no cut, so no caps). What the bands and their bins of
/// triangles must give byte for byte.
MeshGBuffer wholeFrameRaster(const Genome& genome, const MeshData& mesh, const MeshSettings& settings) {
    const FittedMesh fitted = fitMesh(mesh);
    const ObjectCamera view = frameObject(objectBox(genome), fitted, settings);
    const int n = settings.supersample, gw = settings.width * n, gh = settings.height * n;
    MeshGBuffer g;
    const std::size_t samples = std::size_t(gw) * std::size_t(gh);
    g.positions.assign(samples * 4, 0.0f);
    g.normals.assign(samples * 4, 0.0f);
    g.uvs.assign(samples * 2, 0.0f);
    std::vector<double> depth(samples, std::numeric_limits<double>::infinity());
    std::vector<glm::dvec3> design(fitted.points.size()), normals(fitted.points.size());
    std::vector<glm::dvec4> screen(fitted.points.size()); // x, y, z, 1/w
    for (std::size_t v = 0; v < fitted.points.size(); ++v) {
        design[v] = fitted.points[v] * view.scale;
        const glm::dvec3 normal(mesh.normals[v]);
        normals[v] = normal / glm::length(normal);
        const glm::dvec4 clip = view.viewProjection * glm::dvec4(design[v], 1.0);
        const double invW = 1.0 / clip.w;
        screen[v] = {(clip.x * invW * 0.5 + 0.5) * gw, (clip.y * invW * 0.5 + 0.5) * gh, clip.z * invW, invW};
    }
    for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t) {
        const std::uint32_t i0 = mesh.indices[t * 3], i1 = mesh.indices[t * 3 + 1],
                            i2 = mesh.indices[t * 3 + 2];
        const glm::dvec4 &a = screen[i0], &b = screen[i1], &c = screen[i2];
        const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (!(std::abs(area) > 0.0)) continue;
        const bool front = area > 0.0;
        for (int j = 0; j < gh; ++j)
            for (int i = 0; i < gw; ++i) {
                const double sx = i + 0.5, sy = j + 0.5;
                double w0 = (c.x - b.x) * (sy - b.y) - (c.y - b.y) * (sx - b.x);
                double w1 = (a.x - c.x) * (sy - c.y) - (a.y - c.y) * (sx - c.x);
                double w2 = (b.x - a.x) * (sy - a.y) - (b.y - a.y) * (sx - a.x);
                if (front ? (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) : (w0 > 0.0 || w1 > 0.0 || w2 > 0.0)) continue;
                w0 /= area;
                w1 /= area;
                w2 /= area;
                const double z = w0 * a.z + w1 * b.z + w2 * c.z;
                const std::size_t s = std::size_t(j) * std::size_t(gw) + std::size_t(i);
                if (!(z < depth[s])) continue;
                depth[s] = z;
                const double p0 = w0 * a.w, p1 = w1 * b.w, p2 = w2 * c.w, sum = p0 + p1 + p2;
                const glm::dvec3 position = (p0 * design[i0] + p1 * design[i1] + p2 * design[i2]) / sum;
                glm::dvec3 normal = glm::normalize(p0 * normals[i0] + p1 * normals[i1] + p2 * normals[i2]);
                if (!front) normal = -normal;
                const glm::dvec2 uv = (p0 * glm::dvec2(mesh.uvs[i0]) + p1 * glm::dvec2(mesh.uvs[i1]) +
                                       p2 * glm::dvec2(mesh.uvs[i2])) /
                                      sum;
                for (int k = 0; k < 3; ++k) {
                    g.positions[s * 4 + std::size_t(k)] = float(position[k]);
                    g.normals[s * 4 + std::size_t(k)] = float(normal[k]);
                }
                g.positions[s * 4 + 3] = 1.0f;
                g.uvs[s * 2] = float(uv.x);
                g.uvs[s * 2 + 1] = float(uv.y);
            }
    }
    return g;
}

TEST(ObjectView, TheBandsGiveWhatTheWholeFrameGives) {
    // rasterizeObject bins each triangle once to the bands of rows it reaches; every sample must
    // still be exactly what one pass of every triangle over the whole frame gives, the depth
    // test's ties broken in the mesh's order. Sizes whose rows end inside a band, and objects of
    // many small triangles (teapot) and of a few large ones (book, cube).
    const Genome genome = loadGenome(test::dataDir() / "examples" / "five-stones.marble.json");
    for (const char* name : {"teapot", "book", "cube", "cloth"}) {
        SCOPED_TRACE(name);
        MeshSettings settings;
        settings.width = 53;
        settings.height = 37;
        settings.supersample = 3;
        settings.mesh = name;
        settings.yaw = 35.0;
        settings.pitch = 25.0;
        const MeshData mesh = builtinMesh(name);
        const MeshGBuffer reference = wholeFrameRaster(genome, mesh, settings);
        for (int threads : {1, 2}) {
            settings.threads = threads;
            const MeshGBuffer g = rasterizeObject(genome, mesh, settings);
            EXPECT_EQ(g.positions, reference.positions);
            EXPECT_EQ(g.normals, reference.normals);
            EXPECT_EQ(g.uvs, reference.uvs);
        }
        EXPECT_GT(coveredSamples(reference), reference.positions.size() / 4 / 10);
    }
}

} // namespace
} // namespace marbler
