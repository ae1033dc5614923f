// Solid genomes on objects: the built-in meshes, loading files, baselines of the renders, the
// cube's faces against a CPU ray cast, and the cutting plane.

#include "GlTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/gl/Meshes.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <set>

namespace marbler {
namespace {

/// Signed volume by the divergence theorem: positive when every face winds outward.
double signedVolume(const gl::MeshData& mesh) {
    double volume = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
            c(mesh.positions[mesh.indices[t + 2]]);
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

/// The area-weighted sum of the triangles' normals by their winding (zero for a closed mesh).
glm::dvec3 windingNormal(const gl::MeshData& mesh) {
    glm::dvec3 sum(0.0);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
            c(mesh.positions[mesh.indices[t + 2]]);
        sum += 0.5 * glm::cross(b - a, c - a);
    }
    return sum;
}

TEST(Meshes, BuiltinsAreClosedAndWoundOutward) {
    // The sheets (a cushion's face, a hanging cloth, a wall) are open surfaces facing the front
    // (+z); every other object is closed and wound outward, as the cut's cap assumes.
    const std::set<std::string> sheets = {"cushion", "cloth", "wall"};
    for (const std::string& name : gl::builtinMeshNames()) {
        gl::MeshData mesh = gl::builtinMesh(name);
        ASSERT_FALSE(mesh.indices.empty()) << name;
        EXPECT_EQ(mesh.indices.size() % 3, 0u) << name;
        EXPECT_EQ(mesh.positions.size(), mesh.normals.size()) << name;
        for (std::uint32_t i : mesh.indices)
            ASSERT_LT(i, mesh.positions.size()) << name;
        const glm::dvec3 winding = windingNormal(mesh);
        if (sheets.count(name)) {
            EXPECT_GT(winding.z, 0.9 * glm::length(winding)) << name << " should face the front";
        } else {
            EXPECT_LT(glm::length(winding), 1e-3) << name << " is not closed";
            EXPECT_GT(signedVolume(mesh), 0.0) << name << " winds inward";
        }
    }
    EXPECT_NEAR(signedVolume(gl::builtinMesh("book")), 1.4 * 2.0 * 0.32, 1e-5);
    EXPECT_NEAR(signedVolume(gl::builtinMesh("cube")), 8.0, 1e-9);
    EXPECT_NEAR(signedVolume(gl::builtinMesh("sphere")), 4.0 / 3.0 * std::numbers::pi, 0.02);
    EXPECT_NEAR(signedVolume(gl::builtinMesh("torus")), 2.0 * std::numbers::pi * std::numbers::pi * 0.16,
                0.01);
    EXPECT_THROW(gl::builtinMesh("dodecahedron"), InputError);
}

TEST(Meshes, FilesLoadThroughAssimp) {
    std::filesystem::path dir = test::outputDir("gl-mesh-files");
    test::writeFile(dir / "tetra.obj",
                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    gl::MeshData mesh = gl::loadMesh((dir / "tetra.obj").string());
    EXPECT_EQ(mesh.indices.size(), 12u);
    EXPECT_NEAR(signedVolume(mesh), 1.0 / 6.0, 1e-6);
    test::writeFile(dir / "quad.stl", "solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                      "vertex 1 1 0\nendloop\nendfacet\nendsolid q\n");
    EXPECT_EQ(gl::loadMesh((dir / "quad.stl").string()).indices.size(), 3u);
    test::writeFile(dir / "broken.obj", "this is not a mesh\n");
    for (const char* bad : {"missing.obj", "broken.obj"}) {
        std::string file = (dir / bad).string();
        try {
            gl::loadMesh(file);
            ADD_FAILURE() << bad << " loaded";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
        }
    }
}

class GlMesh : public ::testing::Test {
protected:
    void SetUp() override {
        MARBLER_REQUIRE_GL_OR_SKIP();
        mGenome = loadGenome(test::dataDir() / "examples" / "slate-block.marble.json");
    }
    Genome mGenome;
};

/// Compares with tests/data/gl/<name>.png; MARBLER_UPDATE_BASELINES=1 writes the baseline.
void expectMatchesBaseline(const Image& actual, const std::string& name) {
    std::filesystem::path baseline = test::dataDir() / "gl" / (name + ".png");
    const char* update = std::getenv("MARBLER_UPDATE_BASELINES");
    if (update && std::string(update) == "1") {
        test::savePng(actual, baseline);
        return;
    }
    Image expected = test::loadPng(baseline);
    ASSERT_EQ(expected.width, actual.width) << "no baseline " << baseline;
    ASSERT_EQ(expected.height, actual.height);
    std::size_t far = 0;
    double sum = 0.0;
    for (std::size_t k = 0; k < actual.rgb.size(); ++k) {
        int diff = std::abs(int(actual.rgb[k]) - int(expected.rgb[k]));
        sum += diff;
        if (diff > 24) ++far;
    }
    double mean = sum / double(actual.rgb.size());
    // Drivers round and rasterise a little differently: a small mean difference and a few
    // pixels along ink edges and silhouettes are allowed, a different picture is not.
    bool ok = mean < 1.5 && double(far) < 0.01 * double(actual.rgb.size());
    EXPECT_TRUE(ok) << name << ": mean difference " << mean << ", " << far << " channels off by more than 24";
    if (!ok) {
        std::filesystem::path dir = test::outputDir("gl-mesh-" + name);
        test::savePng(actual, dir / (name + "-actual.png"));
        ADD_FAILURE() << "actual image saved in " << dir;
    }
}

TEST_F(GlMesh, BuiltinObjectsMatchBaselines) {
    for (const std::string& name : gl::builtinMeshNames()) {
        gl::MeshSettings settings;
        settings.width = 160;
        settings.height = 128;
        settings.mesh = name;
        expectMatchesBaseline(test::glRenderer()->renderMesh(mGenome, settings), "mesh-" + name);
    }
    gl::MeshSettings cut;
    cut.width = 160;
    cut.height = 160;
    cut.mesh = "sphere";
    cut.yaw = 35.0;
    cut.pitch = 25.0;
    cut.cut = gl::CutPlane{{0.3, 0.2, 1.0}, 0.3 * 500 + 0.2 * 500 + 1.0 * 500};
    expectMatchesBaseline(test::glRenderer()->renderMesh(mGenome, cut), "mesh-sphere-cut");
}

/// The design point a pixel of an unlit cube render sees, by ray casting the design box the
/// cube fills (the camera of MeshSettings' documentation); nullopt off the cube.
std::optional<glm::dvec3> castIntoBox(const Genome& genome, const gl::MeshSettings& s, double px, double py) {
    glm::dvec3 centre = 0.5 * genome.size;
    double radius = 0.5 * glm::length(genome.size);
    double yaw = glm::radians(s.yaw), pitch = glm::radians(s.pitch);
    glm::dvec3 toEye(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    glm::dvec3 eye = centre + toEye * (s.distance * radius);
    glm::dvec3 forward = -toEye;
    glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
    glm::dvec3 up = glm::cross(right, forward);
    double t = std::tan(glm::radians(s.fovY) / 2.0);
    double nx = (2.0 * px / s.width - 1.0) * t * double(s.width) / s.height;
    double ny = (1.0 - 2.0 * py / s.height) * t;
    glm::dvec3 dir = glm::normalize(forward + nx * right + ny * up);
    double t0 = -1e300, t1 = 1e300;
    for (int k = 0; k < 3; ++k) {
        double a = (0.0 - eye[k]) / dir[k], b = (genome.size[k] - eye[k]) / dir[k];
        t0 = std::max(t0, std::min(a, b));
        t1 = std::min(t1, std::max(a, b));
    }
    if (!(t0 < t1) || t0 < 0.0) return std::nullopt;
    return eye + t0 * dir;
}

TEST_F(GlMesh, CubeFacesMeetWithoutSeams) {
    // Seen from a corner, three faces meet in three edges. Unlit, every pixel must show the
    // marbling of the solid point it sees (a CPU ray cast), so the faces' colours join along
    // the edges exactly as the solid's colours do.
    gl::MeshSettings s;
    s.width = 200;
    s.height = 200;
    s.mesh = "cube";
    s.yaw = 45.0;
    s.pitch = 35.26;
    s.distance = 2.6; // the ray cast's explicit orbit, not the framed one
    s.supersample = 1;
    s.lighting = false;
    Image image = test::glRenderer()->renderMesh(mGenome, s);
    CpuRenderer cpu(mGenome);
    auto expectedIndex = [&](double px, double py) -> int {
        auto p = castIntoBox(mGenome, s, px, py);
        return p ? cpu.colorIndexAt(*p) : -2;
    };
    auto colourOf = [&](int index) {
        Color c = index == -2 ? s.clearColor
                  : index < 0 ? mGenome.background
                              : mGenome.palette[std::size_t(index)];
        return c;
    };
    int checked = 0, mismatched = 0, unexplained = 0;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            int index = expectedIndex(x + 0.5, y + 0.5);
            if (index == -2) continue;
            ++checked;
            Color want = colourOf(index);
            const std::uint8_t* got = image.row(y) + x * 3;
            if (std::abs(got[0] - want.r) <= 2 && std::abs(got[1] - want.g) <= 2 &&
                std::abs(got[2] - want.b) <= 2)
                continue;
            ++mismatched;
            // Allowed only where the ray cast a fraction of a pixel away sees something else.
            bool boundary = false;
            for (double dy : {-0.6, 0.0, 0.6})
                for (double dx : {-0.6, 0.0, 0.6})
                    if (expectedIndex(x + 0.5 + dx, y + 0.5 + dy) != index) boundary = true;
            if (!boundary) ++unexplained;
        }
    }
    EXPECT_GT(checked, s.width * s.height / 4);
    EXPECT_LE(mismatched, checked / 100) << mismatched << " of " << checked;
    EXPECT_EQ(unexplained, 0) << "pixels that show the wrong solid point away from any boundary";
    if (unexplained) test::savePng(image, test::outputDir("gl-cube-seams") / "cube.png");
}

TEST_F(GlMesh, CutShowsTheInsideAndBadInputsThrow) {
    gl::MeshSettings s;
    s.width = 96;
    s.height = 96;
    s.mesh = "cube";
    s.yaw = 0.0;
    s.pitch = 0.0;
    s.lighting = false;
    s.supersample = 1;
    // Cut the front half away (the camera is on +z): the centre pixel then sees the plane
    // z = 500 of the solid, by the CPU's colour rule.
    s.cut = gl::CutPlane{{0, 0, 1}, 500.0};
    Image image = test::glRenderer()->renderMesh(mGenome, s);
    CpuRenderer cpu(mGenome);
    int index = cpu.colorIndexAt({500.0, 500.0, 500.0});
    Color want = index < 0 ? mGenome.background : mGenome.palette[std::size_t(index)];
    const std::uint8_t* got = image.row(48) + 48 * 3;
    EXPECT_NEAR(got[0], want.r, 2);
    EXPECT_NEAR(got[1], want.g, 2);
    EXPECT_NEAR(got[2], want.b, 2);

    gl::MeshSettings bad;
    bad.mesh = (test::outputDir("gl-mesh-bad") / "nothing.ply").string();
    EXPECT_THROW(test::glRenderer()->renderMesh(mGenome, bad), InputError);
    bad.mesh = "sphere";
    bad.supersample = 4;
    EXPECT_THROW(test::glRenderer()->renderMesh(mGenome, bad), InputError);
    // A flat design lies on the object's own texture coordinates; this file has none.
    const Genome flat = loadGenome(test::dataDir() / "examples" / "five-stones.marble.json");
    bad.supersample = 3;
    bad.mesh = (test::outputDir("gl-mesh-bad") / "bare.obj").string();
    test::writeFile(bad.mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_THROW(test::glRenderer()->renderMesh(flat, bad), InputError);
}

} // namespace
} // namespace marbler
