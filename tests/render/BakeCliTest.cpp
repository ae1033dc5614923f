// `marbler bake` through the executable: the files it writes, the stack of cross-sections, exit
// codes, one-line errors and no partial output.

#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/Bake.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Mesh.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <set>
#include <sstream>

namespace marbler {
namespace {

using test::runMarbler;
namespace fs = std::filesystem;

long entries(const fs::path& dir) {
    return std::distance(fs::directory_iterator(dir), {});
}

TEST(BakeCli, WritesEachFormatWithItsCompanions) {
    const auto dir = test::outputDir("bake-cli-formats");
    const std::string solid = test::examplePath("slate-block.marble.json");
    auto r = runMarbler(
        {"bake", solid, "--mesh", "vase", "-o", (dir / "vase.glb").string(), "--texture", "1024", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_EQ(test::readFile(dir / "vase.glb").substr(0, 4), "glTF");

    r = runMarbler({"bake", solid, "--mesh", "cube", "-o", (dir / "cube.gltf").string(), "--texture", "256"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json doc = nlohmann::json::parse(test::readFile(dir / "cube.gltf"));
    EXPECT_EQ(doc["asset"]["version"], "2.0");
    EXPECT_EQ(test::readImage8(dir / "cube.png").width, 256);
    EXPECT_EQ(fs::file_size(dir / "cube.bin"), doc["buffers"][0]["byteLength"].get<std::uintmax_t>());

    // A flat design is projected onto the object.
    r = runMarbler({"bake", test::examplePath("flame-comb-vortex.marble.json"), "--mesh", "cube", "-o",
                    (dir / "flat.obj").string(), "--texture", "128"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(test::readFile(dir / "flat.mtl").find("map_Kd flat.png"), std::string::npos);
    EXPECT_EQ(test::readImage8(dir / "flat.png").height, 128);
    EXPECT_EQ(entries(dir), 7) << "vase.glb, cube.gltf/.bin/.png, flat.obj/.mtl/.png and nothing else";
}

void expectFailure(const std::vector<std::string>& args, int exitCode, const std::string& mention,
                   const fs::path& dir) {
    auto r = runMarbler(args);
    EXPECT_EQ(r.exitCode, exitCode) << r.err;
    EXPECT_EQ(test::lineCount(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    for (const auto& entry : fs::directory_iterator(dir))
        ADD_FAILURE() << "left behind: " << entry.path();
}

TEST(BakeCli, BadInputExitsTwoWithOneLineAndNoOutput) {
    const auto dir = test::outputDir("bake-cli-bad");
    const std::string out = (dir / "out.glb").string();
    const std::string solid = test::examplePath("slate-block.marble.json");
    expectFailure({"bake", solid, "--mesh", "dodecahedron", "-o", out}, 2, "dodecahedron", dir);
    expectFailure({"bake", solid, "--mesh", "vase", "-o", (dir / "out.fbx").string()}, 2, "out.fbx", dir);
    expectFailure({"bake", solid, "--mesh", "vase", "-o", out, "--texture", "16385"}, 2, "--texture", dir);
    expectFailure({"bake", solid, "--mesh", "vase", "-o", out, "--texture", "0"}, 2, "--texture", dir);
    expectFailure({"bake", solid, "--mesh", "vase", "-o", out, "--texture", "big"}, 2, "--texture", dir);
    expectFailure({"bake", solid, "--mesh", "vase", "-o", out, "--aa", "fxaa"}, 2, "fxaa", dir);
    expectFailure({"bake", solid, "-o", out}, 2, "--mesh", dir);
    expectFailure({"bake", solid, "--mesh", "vase"}, 2, "-o", dir);
    expectFailure({"bake", (dir.parent_path() / "absent.marble.json").string(), "--mesh", "vase", "-o", out},
                  2, "absent.marble.json", dir);
    expectFailure({"bake", solid, "--mesh", "vase", "--slices", "z", "-o", out}, 2, "--slices", dir);
    expectFailure({"bake", solid, "--slices", "w", "-o", (dir / "s").string()}, 2, "'w'", dir);
    expectFailure({"bake", solid, "--slices", "z", "--count", "0", "-o", (dir / "s").string()}, 2, "--count",
                  dir);
    expectFailure(
        {"bake", test::examplePath("five-stones.marble.json"), "--slices", "z", "-o", (dir / "s").string()},
        2, "five-stones", dir);
    // Not the input's fault: exit 1, the file named.
    expectFailure(
        {"bake", solid, "--mesh", "cube", "-o", (dir / "no" / "cube.glb").string(), "--texture", "64"}, 1,
        "cube.glb", dir);
}

TEST(BakeCli, MessagesAndHelpNameEveryBuiltInObject) {
    // The objects come from one list (Mesh.h); what a person reads names each of them.
    const auto dir = test::outputDir("bake-cli-objects");
    auto r = runMarbler({"bake", test::examplePath("slate-block.marble.json"), "--mesh", "dodecahedron", "-o",
                         (dir / "out.glb").string()});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(r.err,
              "marbler bake: --mesh: 'dodecahedron' is neither a built-in object (vase, sphere, cube, torus, "
              "teapot, book, cushion, cloth, wall) nor a mesh file\n");
    EXPECT_EQ(builtinMeshList(), "vase, sphere, cube, torus, teapot, book, cushion, cloth, wall");
    try {
        builtinMesh("dodecahedron");
        ADD_FAILURE() << "an unknown object was made";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("(" + builtinMeshList() + ", or a mesh file)"),
                  std::string::npos)
            << e.what();
    }
    for (const char* verb : {"bake", "render"}) {
        const std::string help = runMarbler({verb, "--help"}).out;
        for (const std::string& name : builtinMeshNames())
            EXPECT_NE(help.find(name), std::string::npos) << verb << " --help does not name " << name;
    }
}

TEST(BakeCli, SlicesAreTheCentresOfEqualLayers) {
    const auto dir = test::outputDir("bake-cli-slices");
    const std::string solid = test::examplePath("slate-block.marble.json");
    auto r = runMarbler(
        {"bake", solid, "--slices", "y", "--count", "5", "--width", "64", "-o", (dir / "stack").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(entries(dir / "stack"), 5);
    // Layer 3 of 5 across a 1000-unit box: its centre is y = 700.
    r = runMarbler({"render", solid, "--slice", "y=700", "--width", "64", "-o", (dir / "y700.png").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Image slice = test::readImage8(dir / "stack" / "slice-0003.png");
    EXPECT_EQ(slice.width, 64);
    EXPECT_EQ(slice.rgb, test::readImage8(dir / "y700.png").rgb);
    EXPECT_NE(slice.rgb, test::readImage8(dir / "stack" / "slice-0002.png").rgb);
}

TEST(BakeCli, EveryBuiltInObjectBakesAt256AndKeepsItsUvs) {
    // Issue 23: `bake --mesh vase --texture 256` was refused (too many triangles for generated
    // UVs); the objects' own UVs serve any size, and the OBJ written carries them (vt counts v
    // upwards), one per vertex, in the object's order.
    const auto dir = test::outputDir("bake-cli-own-uvs");
    for (const std::string& name : builtinMeshNames()) {
        SCOPED_TRACE(name);
        const fs::path obj = dir / (name + ".obj");
        auto r = runMarbler({"bake", test::examplePath("slate-block.marble.json"), "--mesh", name, "-o",
                             obj.string(), "--texture", "256", "--quiet"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(r.err.empty()) << r.err;
        const Image texture = test::readImage8(dir / (name + ".png"));
        EXPECT_EQ(texture.width, 256);
        std::set<std::array<std::uint8_t, 3>> colours;
        for (std::size_t k = 0; k + 2 < texture.rgb.size(); k += 3)
            colours.insert({texture.rgb[k], texture.rgb[k + 1], texture.rgb[k + 2]});
        EXPECT_GT(colours.size(), 3u) << "the texture should show the design";

        const MeshData mesh = builtinMesh(name);
        std::istringstream lines(test::readFile(obj));
        std::size_t count = 0;
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("vt ", 0) != 0) continue;
            float u = 0.0f, v = 0.0f;
            ASSERT_EQ(std::sscanf(line.c_str(), "vt %f %f", &u, &v), 2) << line;
            ASSERT_LT(count, mesh.uvs.size());
            EXPECT_EQ(u, mesh.uvs[count].x);
            EXPECT_NEAR(1.0f - v, mesh.uvs[count].y, 1e-6f);
            ++count;
        }
        EXPECT_EQ(count, mesh.uvs.size());
    }
}

TEST(BakeCli, EveryBuiltInObjectTakesAFlatDesignAt256OnItsOwnUvs) {
    // Issue 23: a flat design baked onto an object lies on the object's own UVs, the design
    // itself rather than a projection along z. At 256 texels every built-in bakes; the OBJ
    // written has the object's UVs, and a texel whose centre lies inside a triangle shows the
    // design at that texture point (FlatOnUvs: fitted by its longer side, centred).
    const auto dir = test::outputDir("bake-cli-flat-own-uvs");
    const std::string design = test::examplePath("flame-comb-vortex.marble.json");
    const Genome genome = loadGenome(design);
    const CpuRenderer reference(genome);
    const FlatOnUvs flat(genome);
    constexpr int n = 256;
    for (const std::string& name : builtinMeshNames()) {
        SCOPED_TRACE(name);
        const fs::path obj = dir / (name + ".obj");
        auto r = runMarbler({"bake", design, "--mesh", name, "-o", obj.string(), "--texture",
                             std::to_string(n), "--aa", "none", "--quiet"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(r.err.empty()) << r.err;

        // The UVs read back from the file are the object's (vt counts v upwards).
        const MeshData mesh = builtinMesh(name);
        std::vector<glm::dvec2> uvs;
        std::istringstream lines(test::readFile(obj));
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("vt ", 0) != 0) continue;
            float u = 0.0f, v = 0.0f;
            ASSERT_EQ(std::sscanf(line.c_str(), "vt %f %f", &u, &v), 2) << line;
            uvs.emplace_back(u, 1.0 - double(v));
        }
        ASSERT_EQ(uvs.size(), mesh.uvs.size());
        for (std::size_t k = 0; k < uvs.size(); ++k) {
            EXPECT_NEAR(uvs[k].x, mesh.uvs[k].x, 1e-6);
            EXPECT_NEAR(uvs[k].y, mesh.uvs[k].y, 1e-6);
        }

        // Texels inside a triangle, by the file's UVs, show the design at their texture point.
        const Image texture = test::readImage8(dir / (name + ".png"));
        ASSERT_EQ(texture.width, n);
        int checked = 0, differing = 0;
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            const glm::dvec2 a = uvs[mesh.indices[t]], b = uvs[mesh.indices[t + 1]],
                             c = uvs[mesh.indices[t + 2]];
            const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
            const glm::dvec2 lo = glm::min(a, glm::min(b, c)) * double(n),
                             hi = glm::max(a, glm::max(b, c)) * double(n);
            for (int j = std::max(0, int(lo.y)); j < std::min(n, int(hi.y) + 1); ++j)
                for (int i = std::max(0, int(lo.x)); i < std::min(n, int(hi.x) + 1); ++i) {
                    const glm::dvec2 q((i + 0.5) / n, (j + 0.5) / n);
                    // Inside by a margin, so the texel belongs to this triangle alone.
                    const double w0 = ((c.x - b.x) * (q.y - b.y) - (c.y - b.y) * (q.x - b.x)) / area;
                    const double w1 = ((a.x - c.x) * (q.y - c.y) - (a.y - c.y) * (q.x - c.x)) / area;
                    const double w2 = 1.0 - w0 - w1;
                    if (!(std::min({w0, w1, w2}) > 0.05)) continue;
                    const glm::dvec3 p = flat.designPoint(q);
                    const int ink = flat.inside(p) ? reference.colorIndexAt(p) : -1;
                    const Color expected = ink >= 0 ? genome.palette[std::size_t(ink)] : genome.background;
                    const std::uint8_t* got = texture.row(j) + i * 3;
                    differing += got[0] != expected.r || got[1] != expected.g || got[2] != expected.b;
                    ++checked;
                }
        }
        EXPECT_GT(checked, n * n / 20);
        EXPECT_LE(differing, checked / 100) << differing << " of " << checked << " texels differ";
    }
}

TEST(BakeCli, BakingOntoABuiltInObjectLoadsNoModule) {
    // The built-in objects and the writers are in the executable; only a mesh file needs assimp
    // (the window module), so a bake onto the vase starts as fast as a render.
    const auto dir = test::outputDir("bake-cli-modules");
    auto r = runMarbler({"bake", test::examplePath("slate-block.marble.json"), "--mesh", "cube", "-o",
                         (dir / "c.glb").string(), "--texture", "64", "--quiet"},
                        {{"LD_DEBUG", "files"}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_NE(r.err.find("libpng"), std::string::npos) << "LD_DEBUG should trace the loads";
    EXPECT_EQ(r.err.find("marbler-window.so"), std::string::npos);
    EXPECT_EQ(r.err.find("marbler-imageio.so"), std::string::npos);
    EXPECT_EQ(r.err.find("assimp"), std::string::npos);
}

TEST(BakeCli, HelpDescribesEveryOption) {
    auto r = runMarbler({"bake", "--help"});
    EXPECT_EQ(r.exitCode, 0);
    for (const char* option : {"-o", "--mesh", "--texture", "--aa", "--slices", "--count", "--width",
                               "--height", "--threads", "--quiet", ".glb", ".gltf", ".obj"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option;
    r = runMarbler({"--help"});
    EXPECT_NE(r.out.find("bake"), std::string::npos);
}

} // namespace
} // namespace marbler
