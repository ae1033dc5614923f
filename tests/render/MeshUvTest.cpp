// The built-in objects' own texture coordinates: within the unit square, no two triangles on one
// texel, no triangle wrapping round a seam, every texture read the right way round from outside,
// and the seams where they were placed.

#include "marbler/Mesh.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace marbler {
namespace {

double uvArea(const MeshData& mesh, std::size_t t) {
    // Signed, in MeshData's convention (v downwards): negative for a triangle that runs
    // counter-clockwise in the texture as seen on screen, v up.
    const glm::dvec2 a = mesh.uvs[mesh.indices[t * 3]], b = mesh.uvs[mesh.indices[t * 3 + 1]],
                     c = mesh.uvs[mesh.indices[t * 3 + 2]];
    const glm::dvec2 e1 = b - a, e2 = c - a;
    return 0.5 * (e1.x * e2.y - e1.y * e2.x);
}

double area3d(const MeshData& mesh, std::size_t t) {
    const glm::dvec3 a = mesh.positions[mesh.indices[t * 3]], b = mesh.positions[mesh.indices[t * 3 + 1]],
                     c = mesh.positions[mesh.indices[t * 3 + 2]];
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

TEST(MeshUv, EveryBuiltInObjectHasUvsWithinTheUnitSquare) {
    for (const std::string& name : builtinMeshNames()) {
        SCOPED_TRACE(name);
        const MeshData mesh = builtinMesh(name);
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
        EXPECT_FALSE(mesh.uvsArePatches);
        for (const glm::vec2& uv : mesh.uvs) {
            ASSERT_GE(uv.x, 0.0f);
            ASSERT_LE(uv.x, 1.0f);
            ASSERT_GE(uv.y, 0.0f);
            ASSERT_LE(uv.y, 1.0f);
        }
    }
}

TEST(MeshUv, NoTriangleWrapsRoundASeam) {
    // A triangle across a seam would stretch over most of the texture: its UV area far beyond
    // its share of the surface, its edges spanning most of the texture (the cube's faces, the
    // longest parts, span a third). The texture's density (UV area per surface area)
    // varies over an object (the sphere's and vase's rows shrink to their poles), but by less
    // than a factor 100 between any triangle and the object's median.
    for (const std::string& name : builtinMeshNames()) {
        SCOPED_TRACE(name);
        const MeshData mesh = builtinMesh(name);
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        const std::size_t triangles = mesh.indices.size() / 3;
        std::vector<double> density;
        for (std::size_t t = 0; t < triangles; ++t)
            if (area3d(mesh, t) > 1e-9) density.push_back(std::abs(uvArea(mesh, t)) / area3d(mesh, t));
        ASSERT_FALSE(density.empty());
        std::vector<double> sorted = density;
        std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
        const double median = sorted[sorted.size() / 2];
        ASSERT_GT(median, 0.0);
        int tooDense = 0, tooLong = 0;
        for (std::size_t t = 0, k = 0; t < triangles; ++t) {
            for (int e = 0; e < 3; ++e) {
                const glm::dvec2 a = mesh.uvs[mesh.indices[t * 3 + std::size_t(e)]];
                const glm::dvec2 b = mesh.uvs[mesh.indices[t * 3 + std::size_t((e + 1) % 3)]];
                if (glm::length(a - b) > 0.5) ++tooLong;
            }
            if (area3d(mesh, t) > 1e-9 && density[k++] > 100.0 * median) ++tooDense;
        }
        EXPECT_EQ(tooLong, 0) << "edges spanning half the texture: a triangle across a seam";
        EXPECT_EQ(tooDense, 0);
    }
}

TEST(MeshUv, NoTwoTrianglesShareATexel) {
    // Texel centres of a 512 texture inside two triangles' UVs: one texel would then have to
    // show two places of the surface. Triangles with no area on the surface (at a pole, where a
    // row of vertices meets in one point) still own their texels alone.
    const int n = 512;
    for (const std::string& name : builtinMeshNames()) {
        SCOPED_TRACE(name);
        const MeshData mesh = builtinMesh(name);
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        std::vector<int> owners(std::size_t(n) * std::size_t(n), 0);
        for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t) {
            const glm::dvec2 a = glm::dvec2(mesh.uvs[mesh.indices[t * 3]]) * double(n);
            const glm::dvec2 b = glm::dvec2(mesh.uvs[mesh.indices[t * 3 + 1]]) * double(n);
            const glm::dvec2 c = glm::dvec2(mesh.uvs[mesh.indices[t * 3 + 2]]) * double(n);
            const glm::dvec2 e1 = b - a, e2 = c - a;
            const double det = e1.x * e2.y - e1.y * e2.x;
            if (det == 0.0) continue;
            for (int j = std::max(0, int(std::min({a.y, b.y, c.y})) - 1);
                 j <= std::min(n - 1, int(std::max({a.y, b.y, c.y})) + 1); ++j)
                for (int i = std::max(0, int(std::min({a.x, b.x, c.x})) - 1);
                     i <= std::min(n - 1, int(std::max({a.x, b.x, c.x})) + 1); ++i) {
                    const glm::dvec2 r = glm::dvec2(i + 0.5, j + 0.5) - a;
                    const double beta = (r.x * e2.y - r.y * e2.x) / det,
                                 gamma = (e1.x * r.y - e1.y * r.x) / det;
                    // Strictly inside: a centre on a shared edge belongs to both sides' edge.
                    if (beta > 1e-9 && gamma > 1e-9 && beta + gamma < 1.0 - 1e-9)
                        ++owners[std::size_t(j) * std::size_t(n) + std::size_t(i)];
                }
        }
        long shared = 0, covered = 0;
        for (int count : owners) {
            shared += count > 1;
            covered += count > 0;
        }
        EXPECT_EQ(shared, 0);
        EXPECT_GT(covered, long(n) * n / 3) << "the texture should be mostly used";
    }
}

TEST(MeshUv, TexturesReadTheRightWayRoundFromOutside) {
    // Every triangle runs counter-clockwise seen from outside (its front); its texture then runs
    // counter-clockwise too, with v up, unless the texture is mirrored on it. In MeshData's v-down
    // convention, that is a negative signed area. Triangles with no area (at poles) are skipped.
    for (const std::string& name : builtinMeshNames()) {
        SCOPED_TRACE(name);
        const MeshData mesh = builtinMesh(name);
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        int mirrored = 0, checked = 0;
        for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t) {
            if (area3d(mesh, t) < 1e-9 || std::abs(uvArea(mesh, t)) < 1e-12) continue;
            ++checked;
            mirrored += uvArea(mesh, t) > 0.0;
        }
        EXPECT_GT(checked, 0);
        EXPECT_EQ(mirrored, 0) << "of " << checked;
    }
}

/// The UV of the vertex nearest `p` (any of them, where a seam duplicates it).
glm::vec2 uvNear(const MeshData& mesh, const glm::vec3& p) {
    std::size_t best = 0;
    for (std::size_t v = 1; v < mesh.positions.size(); ++v)
        if (glm::length(mesh.positions[v] - p) < glm::length(mesh.positions[best] - p)) best = v;
    return mesh.uvs[best];
}

TEST(MeshUv, RoundObjectsFaceTheFrontWithTheTexturesMiddleAndTopUp) {
    // The vase, sphere and torus: the texture's middle column on the front (+z), its seam at the
    // back, its top edge up; across from the left (-x) to the right (+x) seen from the front.
    for (const char* name : {"vase", "sphere", "torus"}) {
        SCOPED_TRACE(name);
        const MeshData mesh = builtinMesh(name);
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& p : mesh.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const glm::vec2 front = uvNear(mesh, {0.0f, 0.0f, hi.z});
        EXPECT_NEAR(front.x, 0.5f, 0.02f);
        EXPECT_LT(uvNear(mesh, {lo.x, 0.0f, 0.0f}).x, 0.3f);
        EXPECT_GT(uvNear(mesh, {hi.x, 0.0f, 0.0f}).x, 0.7f);
        const glm::vec2 back = uvNear(mesh, {0.0f, 0.0f, lo.z});
        EXPECT_TRUE(back.x < 0.02f || back.x > 0.98f) << back.x;
    }
    const MeshData sphere = builtinMesh("sphere");
    EXPECT_NEAR(uvNear(sphere, {0.0f, 1.0f, 0.0f}).y, 0.0f, 1e-6f) << "the top pole: the top edge";
    EXPECT_NEAR(uvNear(sphere, {0.0f, -1.0f, 0.0f}).y, 1.0f, 1e-6f);
    EXPECT_NEAR(uvNear(sphere, {0.0f, 0.0f, 1.0f}).y, 0.5f, 1e-6f) << "the equator: half way down";
}

TEST(MeshUv, TheCubeShowsEachFaceUprightOnItsOwnTile) {
    // The front face's tile: (1/3, 0) to (2/3, 1/3), its top-left corner at the front face's
    // top-left corner (-1, 1, 1) seen from the front.
    const MeshData cube = builtinMesh("cube");
    ASSERT_EQ(cube.positions.size(), 24u);
    ASSERT_EQ(cube.uvs.size(), 24u);
    for (std::size_t v = 16; v < 20; ++v) { // the fifth face, +z
        ASSERT_EQ(cube.normals[v], glm::vec3(0, 0, 1));
        const glm::vec3 p = cube.positions[v];
        const glm::vec2 uv = cube.uvs[v];
        EXPECT_NEAR(uv.x, p.x < 0.0f ? 1.0f / 3.0f + 1.0f / 128.0f : 2.0f / 3.0f - 1.0f / 128.0f, 1e-6f);
        EXPECT_NEAR(uv.y, p.y > 0.0f ? 1.0f / 128.0f : 1.0f / 3.0f - 1.0f / 128.0f, 1e-6f);
    }
}

} // namespace
} // namespace marbler
