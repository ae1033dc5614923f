// Flat (2D) designs on objects drawn by GL (issue 23): the G-buffer carries the texture
// coordinates, and each sample is coloured at its texture point of the design through the
// inverse maps, as the CPU's object path colours it. GL against the CPU on several built-ins,
// `render --mesh X --gpu` on a flat design, and user meshes with and without UVs.

#include "GlTestUtil.h"
#include "TestUtil.h"
#include "marbler/Bake.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/ObjectView.h"
#include "marbler/gl/HybridMesh.h"
#include "marbler/gl/Meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace marbler {
namespace {

Genome flatExample(const char* name) {
    return loadGenome(test::dataDir() / "examples" / name);
}

struct FlatCase {
    const char* mesh;
    double yaw, pitch;
};

const FlatCase FlatCases[] = {{"book", 30, 20}, {"cushion", -25, 15}, {"cloth", 10, 5},
                              {"vase", 40, 25}, {"cube", 45, 35},     {"sphere", -60, 30}};

MeshSettings flatSettingsOf(const FlatCase& c) {
    MeshSettings settings;
    settings.width = 120;
    settings.height = 90;
    settings.supersample = 3;
    settings.mesh = c.mesh;
    settings.yaw = c.yaw;
    settings.pitch = c.pitch;
    return settings;
}

/// The share of pixels whose channels differ by more than `tolerance`.
double shareOff(const Image& a, const Image& b, int tolerance) {
    EXPECT_EQ(a.rgb.size(), b.rgb.size());
    std::size_t off = 0, pixels = std::min(a.rgb.size(), b.rgb.size()) / 3;
    for (std::size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (int k = 0; k < 3; ++k)
            worst = std::max(worst, std::abs(int(a.rgb[p * 3 + k]) - int(b.rgb[p * 3 + k])));
        off += worst > tolerance;
    }
    return pixels ? double(off) / double(pixels) : 1.0;
}

/// How many distinct colours an image shows.
std::size_t coloursIn(const Image& image) {
    std::vector<std::uint32_t> colours;
    for (std::size_t k = 0; k + 2 < image.rgb.size(); k += 3)
        colours.push_back(std::uint32_t(image.rgb[k]) << 16 | std::uint32_t(image.rgb[k + 1]) << 8 |
                          image.rgb[k + 2]);
    std::sort(colours.begin(), colours.end());
    return std::size_t(std::unique(colours.begin(), colours.end()) - colours.begin());
}

void saveOnFailure(const Image& gl, const Image& cpu, const std::string& name) {
    if (!::testing::Test::HasFailure()) return;
    const std::filesystem::path dir = test::outputDir("gl-flat-object-" + name);
    test::savePng(gl, dir / "gl.png");
    test::savePng(cpu, dir / "cpu.png");
    ADD_FAILURE() << "images saved in " << dir;
}

TEST(GlFlatObject, TheGBufferCarriesTheCpusTextureCoordinates) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    const Genome genome = flatExample("five-stones.marble.json");
    for (const FlatCase& c : FlatCases) {
        SCOPED_TRACE(c.mesh);
        const MeshSettings settings = flatSettingsOf(c);
        const MeshGBuffer gl = test::glRenderer()->renderMeshGBuffer(genome, settings);
        const MeshGBuffer cpu = rasterizeObject(genome, builtinMesh(c.mesh), settings);
        ASSERT_EQ(gl.uvs.size(), cpu.uvs.size());
        ASSERT_EQ(gl.uvs.size() * 2, gl.positions.size());
        std::size_t samples = gl.positions.size() / 4, covered = 0, disagree = 0, far = 0;
        for (std::size_t s = 0; s < samples; ++s) {
            const bool a = gl.positions[s * 4 + 3] > 0.0f, b = cpu.positions[s * 4 + 3] > 0.0f;
            covered += a;
            if (a != b) {
                ++disagree;
                continue;
            }
            if (!a) continue;
            // GL interpolates in float, the CPU in double; a seam's duplicated vertices may fall
            // either way on the seam itself.
            far += std::max(std::abs(gl.uvs[s * 2] - cpu.uvs[s * 2]),
                            std::abs(gl.uvs[s * 2 + 1] - cpu.uvs[s * 2 + 1])) > 1e-3f;
        }
        ASSERT_GT(covered, samples / 10);
        EXPECT_LT(double(disagree) / double(covered), 0.002);
        EXPECT_LT(double(far) / double(covered), 0.002);
    }
}

TEST(GlFlatObject, GlDrawsAFlatDesignOnEachObjectAsTheCpuDoes) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    // A square design, a landscape one whose background bands show above and below it on the
    // texture, a version-2 design with bleed (soft edges, linear colours) and one on a source
    // image (its pixels filtered in linear light).
    Genome landscape = flatExample("flame-comb-vortex.marble.json");
    landscape.size.y = 0.5 * landscape.size.x;
    const std::pair<const char*, Genome> designs[] = {
        {"five-stones", flatExample("five-stones.marble.json")},
        {"landscape", landscape},
        {"marbled-paper", flatExample("marbled-paper.marble.json")},
        {"source-image", loadGenome(test::dataDir() / "render" / "source-dataurl-2d.marble.json")}};
    for (const auto& [name, genome] : designs)
        for (const FlatCase& c : FlatCases) {
            SCOPED_TRACE(std::string(name) + " on " + c.mesh);
            const MeshSettings settings = flatSettingsOf(c);
            const Image gl = test::glRenderer()->renderMesh(genome, settings);
            const Image cpu = renderObjectOnCpu(genome, builtinMesh(c.mesh), settings);
            ASSERT_EQ(gl.width, 120);
            ASSERT_EQ(gl.height, 90);
            // The design itself shows, not one colour over the object.
            EXPECT_GT(coloursIn(gl), 20u);
            // Edges of ink and of the silhouette may round either way, nothing else.
            EXPECT_LT(shareOff(gl, cpu, 8), 0.01);
            // The hybrid path (GL's G-buffer, the CPU's colours) agrees too.
            EXPECT_LT(shareOff(gl::renderMeshHybrid(*test::glRenderer(), genome, settings), cpu, 8), 0.01);
            saveOnFailure(gl, cpu, std::string(name) + "-" + c.mesh);
        }
}

TEST(GlFlatObject, SolidsKeepTheirGBufferWithoutTextureCoordinates) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    MeshSettings settings;
    settings.width = settings.height = 32;
    const MeshGBuffer g =
        test::glRenderer()->renderMeshGBuffer(flatExample("slate-block.marble.json"), settings);
    EXPECT_TRUE(g.uvs.empty());
    EXPECT_EQ(g.positions.size(), std::size_t(96) * 96 * 4);
}

TEST(GlFlatObject, RenderMeshGpuDrawsAFlatDesign) {
    // `render --mesh book --gpu` on a flat design was refused; now GL draws it, the image on
    // disk is the CPU's but for edges, and it carries the design.
    MARBLER_REQUIRE_GL_OR_SKIP();
    const std::filesystem::path dir = test::outputDir("gl-flat-object-cli");
    const std::string design = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    const std::string gpu = (dir / "gpu.png").string(), cpu = (dir / "cpu.png").string();
    const std::vector<std::string> common = {"render", design,  "--mesh",  "book",
                                             "--view", "30,20", "--width", "96"};
    std::vector<std::string> words = common;
    words.insert(words.end(), {"--gpu", "-o", gpu});
    test::RunResult run = test::runMarbler(words);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    words = common;
    words.insert(words.end(), {"-o", cpu});
    run = test::runMarbler(words);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Image a = test::loadPng(gpu), b = test::loadPng(cpu);
    ASSERT_EQ(a.width, 96);
    EXPECT_GT(coloursIn(a), 20u);
    EXPECT_LT(shareOff(a, b, 8), 0.01);
    EXPECT_EQ(serializeGenome(loadDesign(gpu)), serializeGenome(loadGenome(design)));
}

/// A square of two triangles facing +z, its UVs covering [0, 1]^2 upright (v up in OBJ).
std::string squareObj(bool withUvs) {
    std::string obj = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n";
    if (withUvs)
        obj += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";
    else
        obj += "vn 0 0 1\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1\n";
    return obj;
}

TEST(GlFlatObject, AUserMeshLaysAFlatDesignOnItsOwnUvs) {
    // A square with UVs, seen head-on and framed: its texture is the design, upright (the OBJ's
    // v counts up, the design's y down), so the render is the design's own render, scaled.
    const std::filesystem::path dir = test::outputDir("gl-flat-object-user-mesh");
    test::writeFile(dir / "square.obj", squareObj(true));
    const std::string design = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    const std::string out = (dir / "cpu.png").string();
    const std::vector<std::string> common = {
        "render", design,          "--mesh", (dir / "square.obj").string(), "--view", "0,0", "--width",
        "100",    "--supersample", "1"};
    std::vector<std::string> words = common;
    words.insert(words.end(), {"-o", out});
    test::RunResult run = test::runMarbler(words);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const Image cpu = test::loadPng(out);
    ASSERT_EQ(cpu.width, 100);

    // The file's UVs are the ones used: the same picture as the square built here with them.
    const Genome genome = loadGenome(design);
    MeshData square;
    square.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    square.normals.assign(4, glm::vec3(0, 0, 1));
    square.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    square.indices = {0, 1, 2, 0, 2, 3};
    MeshSettings settings;
    settings.width = settings.height = 100;
    settings.supersample = 1;
    settings.yaw = settings.pitch = 0.0;
    EXPECT_EQ(cpu.rgb, renderObjectOnCpu(genome, square, settings).rgb);

    // And the design lies upright on it: unlit, the middle pixel of each quarter of the framed
    // square (92 % of the view) shows the design's colour at the same place of the design.
    settings.lighting = false;
    const Image unlit = renderObjectOnCpu(genome, gl::loadMesh((dir / "square.obj").string()), settings);
    const CpuRenderer reference(genome);
    const FlatOnUvs flat(genome);
    int agree = 0, checked = 0;
    for (int y = 20; y < 80; y += 3)
        for (int x = 20; x < 80; x += 3) {
            const double u = 0.5 + (x + 0.5 - 50.0) / 92.0, v = 0.5 + (y + 0.5 - 50.0) / 92.0;
            const glm::dvec3 q = flat.designPoint({u, v});
            const int ink = flat.inside(q) ? reference.colorIndexAt(q) : -1;
            const Color c = ink >= 0 ? genome.palette[std::size_t(ink)] : genome.background;
            const std::uint8_t* got = unlit.row(y) + x * 3;
            agree += got[0] == c.r && got[1] == c.g && got[2] == c.b;
            ++checked;
        }
    EXPECT_GT(agree, checked * 9 / 10) << agree << " of " << checked;
    EXPECT_GT(coloursIn(unlit), 2u);

    // GL draws the file's UVs too.
    MARBLER_REQUIRE_GL_OR_SKIP();
    const std::string gpu = (dir / "gpu.png").string();
    words = common;
    words.insert(words.end(), {"--gpu", "-o", gpu});
    run = test::runMarbler(words);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_LT(shareOff(test::loadPng(gpu), cpu, 8), 0.01);
}

TEST(GlFlatObject, AUserMeshWithoutUvsIsRefusedSayingWhatToDo) {
    const std::filesystem::path dir = test::outputDir("gl-flat-object-no-uvs");
    const std::string mesh = (dir / "bare.obj").string();
    test::writeFile(mesh, squareObj(false));
    const std::string design = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    std::vector<std::vector<std::string>> runs = {
        {"render", design, "--mesh", mesh, "--view", "0,0", "--width", "32", "-o", (dir / "x.png").string()}};
    std::string glWhy;
    if (gl::GlRenderer::available(&glWhy)) {
        runs.push_back(runs[0]);
        runs.back().push_back("--gpu");
    }
    for (const std::vector<std::string>& words : runs) {
        SCOPED_TRACE(words.back());
        const test::RunResult run = test::runMarbler(words);
        EXPECT_EQ(run.exitCode, 2) << run.err;
        // One line naming the file, what is missing and what to do.
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_NE(run.err.find(mesh), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("no texture coordinates"), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("export the mesh with UVs"), std::string::npos) << run.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
    }
    // The same mesh takes a solid design.
    const test::RunResult solid = test::runMarbler(
        {"render", (test::dataDir() / "examples" / "slate-block.marble.json").string(), "--mesh", mesh,
         "--view", "0,0", "--width", "32", "-o", (dir / "solid.png").string()});
    EXPECT_EQ(solid.exitCode, 0) << solid.err;
}

} // namespace
} // namespace marbler
