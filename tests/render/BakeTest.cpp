// Baking: the texture holds the design at the surface points behind its texels, generated UVs
// never overlap, the dilation covers the seams, and the glTF, GLB and OBJ files are well formed.

#include "marbler/Bake.h"
#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Mesh.h"
#include "marbler/Sampling.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <random>

namespace marbler {
namespace {

std::array<std::uint8_t, 3> bytesOf(Color c) {
    return {c.r, c.g, c.b};
}

std::array<std::uint8_t, 3> texel(const Image& image, int i, int j) {
    const std::uint8_t* p = image.row(j) + std::size_t(i) * 3;
    return {p[0], p[1], p[2]};
}

/// The design point of a mesh point as the window places the mesh (GlRenderer::drawGBuffer),
/// worked out here independently of placeMesh: bounding-box centre to the design box centre,
/// scaled by the largest factor that keeps the box inside. A flat design: the x-y bounds fitted
/// to its rectangle, +y up (docs/cli.md).
glm::dvec3 windowPlacement(const Genome& genome, const MeshData& mesh, const glm::dvec3& p) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::vec3& v : mesh.positions) {
        lo = glm::min(lo, glm::dvec3(v));
        hi = glm::max(hi, glm::dvec3(v));
    }
    const int axes = genome.dimension == 3 ? 3 : 2;
    double scale = 1e300;
    for (int k = 0; k < axes; ++k)
        scale = std::min(scale, genome.size[k] / (hi[k] - lo[k]));
    const glm::dvec3 q = (p - 0.5 * (lo + hi)) * scale;
    if (genome.dimension == 2) return {0.5 * genome.size.x + q.x, 0.5 * genome.size.y - q.y, 0.0};
    return 0.5 * genome.size + q;
}

/// Barycentric weights of q in (a, b, c), solved as q = a + beta (b - a) + gamma (c - a).
glm::dvec3 weights(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 q) {
    const glm::dvec2 e1 = b - a, e2 = c - a, r = q - a;
    const double det = e1.x * e2.y - e1.y * e2.x;
    const double beta = (r.x * e2.y - r.y * e2.x) / det, gamma = (e1.x * r.y - e1.y * r.x) / det;
    return {1.0 - beta - gamma, beta, gamma};
}

/// Bakes `genome` onto `meshName` without antialiasing and checks texel centres strictly inside
/// triangles picked at random: the 3D point from the triangle's UVs, its colour by the CPU
/// renderer. Exact, but for centres that land on an ink boundary within rounding (none
/// expected; a few in a thousand would still be tolerated).
/// `n`: the texture's size; the sanitised build bakes the sphere at half the size (the teapot's
/// and vase's triangles need the full one).
/// `ownUvs`: bake by the object's own texture coordinates instead of generated ones.
void expectTexelsHoldTheDesign(const Genome& genome, const std::string& meshName, int n = 1024,
                               bool ownUvs = false) {
    SCOPED_TRACE(meshName);
    const MeshData mesh = ownUvs ? builtinMesh(meshName) : withGeneratedUvs(builtinMesh(meshName), n);
    BakeSettings settings;
    settings.textureSize = n;
    settings.aa = "none";
    const BakedTexture baked = bakeTexture(genome, mesh, settings);
    ASSERT_EQ(baked.image.width, n);
    const CpuRenderer reference(genome);

    std::mt19937 random(5);
    int checked = 0, differing = 0, distinct = 0;
    std::array<std::uint8_t, 3> first{};
    const std::size_t triangles = mesh.indices.size() / 3;
    for (int pick = 0; pick < 600; ++pick) {
        const std::size_t t = random() % triangles;
        const std::uint32_t* v = &mesh.indices[t * 3];
        const glm::dvec2 a = glm::dvec2(mesh.uvs[v[0]]) * double(n),
                         b = glm::dvec2(mesh.uvs[v[1]]) * double(n),
                         c = glm::dvec2(mesh.uvs[v[2]]) * double(n);
        for (int j = int(std::min({a.y, b.y, c.y})); j <= int(std::max({a.y, b.y, c.y})); ++j)
            for (int i = int(std::min({a.x, b.x, c.x})); i <= int(std::max({a.x, b.x, c.x})); ++i) {
                const glm::dvec3 w = weights(a, b, c, {i + 0.5, j + 0.5});
                if (!(w.x > 1e-6 && w.y > 1e-6 && w.z > 1e-6)) continue;
                const glm::dvec3 p = w.x * glm::dvec3(mesh.positions[v[0]]) +
                                     w.y * glm::dvec3(mesh.positions[v[1]]) +
                                     w.z * glm::dvec3(mesh.positions[v[2]]);
                const glm::dvec3 q = windowPlacement(genome, mesh, p);
                std::array<std::uint8_t, 3> expected;
                bool same;
                const auto got = texel(baked.image, i, j);
                if (genome.bleed > 0.0) {
                    // Soft edges: the composited colour (rounded to 8 bits once, in either order).
                    double rgb[3];
                    reference.linearColorsAt(&q.x, &q.y, &q.z, 1, rgb);
                    for (int k = 0; k < 3; ++k)
                        expected[std::size_t(k)] = encodeSrgb8(std::clamp(rgb[k], 0.0, 1.0));
                    same = true;
                    for (int k = 0; k < 3; ++k)
                        same =
                            same && std::abs(int(got[std::size_t(k)]) - int(expected[std::size_t(k)])) <= 1;
                } else {
                    const int index = reference.colorIndexAt(q);
                    expected = bytesOf(index >= 0 ? genome.palette[std::size_t(index)] : genome.background);
                    same = got == expected;
                }
                if (!same) ++differing;
                if (checked == 0) first = got;
                if (got != first) ++distinct;
                ++checked;
            }
    }
    ASSERT_GT(checked, 5000 * n / 1024 * n / 1024);
    EXPECT_GT(distinct, checked / 20) << "the texels checked should not all show one colour";
    EXPECT_LE(differing, checked / 1000) << differing << " of " << checked << " texels differ";
}

TEST(Bake, TexelsHoldTheSoftEdgesOfABleed) {
    // Format version 2's bleed: a texel shows the inks composited as a render does.
    Genome genome = test::loadExample("slate-block.marble.json");
    genome.bleed = 30.0;
    expectTexelsHoldTheDesign(genome, "sphere", test::fullOrSanitized(1024, 512));
}

TEST(Bake, TexelsHoldTheSolidAtTheirSurfacePoints) {
    expectTexelsHoldTheDesign(test::loadExample("slate-block.marble.json"), "sphere",
                              test::fullOrSanitized(1024, 512));
    // The same code on another mesh: in the release build only.
    if (!test::Sanitized) expectTexelsHoldTheDesign(test::loadExample("slate-block.marble.json"), "teapot");
}

TEST(Bake, TexelsHoldAFlatDesignProjectedAlongZ) {
    expectTexelsHoldTheDesign(test::loadExample("flame-comb-vortex.marble.json"), "vase");
}

TEST(Bake, EveryBuiltInObjectBakesAt256ByItsOwnUvs) {
    // The objects' own texture coordinates serve any texture size: at 256 the generated ones
    // are refused for the vase and the teapot (too many triangles), their own are not.
    for (const std::string& name : builtinMeshNames()) {
        ASSERT_TRUE(hasUsableUvs(builtinMesh(name))) << name;
        expectTexelsHoldTheDesign(test::loadExample("slate-block.marble.json"), name, 256, true);
    }
}

TEST(Bake, AFlatDesignLiesOnAnObjectsOwnUvs) {
    // On the sphere's own UVs (covering the whole texture) a flat design is the design itself:
    // texel (i, j) shows the design at the texel's point of the design fitted into the unit
    // square by its longer side, aspect kept, centred; beyond its rectangle, the background.
    Genome genome = test::loadExample("flame-comb-vortex.marble.json");
    genome.size.y = 0.5 * genome.size.x; // a landscape design: background bands above and below
    const int n = 256;
    BakeSettings settings;
    settings.textureSize = n;
    settings.aa = "none";
    settings.dilation = 0;
    const BakedTexture baked = bakeTexture(genome, builtinMesh("sphere"), settings);
    const CpuRenderer reference(genome);
    const double side = genome.size.x, top = 0.5 * (genome.size.y - side);
    int differing = 0, inside = 0, band = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec3 q(side * (i + 0.5) / n, top + side * (j + 0.5) / n, 0.0);
            const bool within = q.y >= 0.0 && q.y <= genome.size.y;
            const int index = within ? reference.colorIndexAt(q) : -1;
            const auto expected =
                bytesOf(index >= 0 ? genome.palette[std::size_t(index)] : genome.background);
            differing += texel(baked.image, i, j) != expected;
            inside += within;
            band += !within;
        }
    EXPECT_EQ(baked.coveredTexels, std::size_t(n) * std::size_t(n)) << "the sphere's UVs cover the texture";
    EXPECT_GT(inside, n * n / 3);
    EXPECT_GT(band, n * n / 3);
    EXPECT_LE(differing, n * n / 1000) << differing << " texels differ";
}

TEST(Bake, GeneratedUvsKeepTheFlatProjection) {
    // A mosaic of patches is no layout of the design: a flat design is still projected along z.
    const MeshData mesh = withGeneratedUvs(builtinMesh("cube"), 64);
    EXPECT_TRUE(mesh.uvsArePatches);
    EXPECT_FALSE(builtinMesh("cube").uvsArePatches);
}

TEST(Bake, AntialiasedTexelsAgreeWithSingleSamples) {
    // rgss averages four samples within the texel, each on the triangle: where the design is
    // uniform round a texel, it shows that colour exactly; elsewhere it is a blend close to it.
    const Genome genome = test::loadExample("slate-block.marble.json");
    const int n = 1024;
    const MeshData mesh = withGeneratedUvs(builtinMesh("sphere"), n);
    BakeSettings settings;
    settings.textureSize = n;
    settings.aa = "none";
    settings.dilation = 0;
    const Image single = bakeTexture(genome, mesh, settings).image;
    settings.aa = "rgss";
    const Image smooth = bakeTexture(genome, mesh, settings).image;
    const auto background = bytesOf(genome.background);
    long uniform = 0, uniformSame = 0;
    for (int j = 1; j + 1 < n; ++j)
        for (int i = 1; i + 1 < n; ++i) {
            const auto centre = texel(single, i, j);
            bool same = centre != background;
            for (int dj = -1; dj <= 1 && same; ++dj)
                for (int di = -1; di <= 1 && same; ++di)
                    same = texel(single, i + di, j + dj) == centre;
            if (!same) continue;
            ++uniform;
            if (texel(smooth, i, j) == centre) ++uniformSame;
        }
    ASSERT_GT(uniform, 100000);
    EXPECT_GE(double(uniformSame), 0.99 * double(uniform));
    const test::ImageDiff diff = test::compareImages(single, smooth, 0);
    EXPECT_LT(diff.shareWithin, 1.0) << "rgss should change some edge texels";
    EXPECT_GT(diff.shareWithin, 0.8);
}

/// Rasterises every triangle's strict interior on a grid of `n` cells; the number of cells
/// claimed twice.
long overlaps(const MeshData& mesh, int n) {
    std::vector<std::uint8_t> hits(std::size_t(n) * std::size_t(n), 0);
    long twice = 0;
    for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t) {
        const glm::dvec2 a = glm::dvec2(mesh.uvs[mesh.indices[t * 3]]) * double(n);
        const glm::dvec2 b = glm::dvec2(mesh.uvs[mesh.indices[t * 3 + 1]]) * double(n);
        const glm::dvec2 c = glm::dvec2(mesh.uvs[mesh.indices[t * 3 + 2]]) * double(n);
        for (int j = std::max(0, int(std::min({a.y, b.y, c.y})) - 1);
             j <= std::min(n - 1, int(std::max({a.y, b.y, c.y})) + 1); ++j)
            for (int i = std::max(0, int(std::min({a.x, b.x, c.x})) - 1);
                 i <= std::min(n - 1, int(std::max({a.x, b.x, c.x})) + 1); ++i) {
                const glm::dvec3 w = weights(a, b, c, {i + 0.5, j + 0.5});
                if (w.x > 0.0 && w.y > 0.0 && w.z > 0.0 &&
                    hits[std::size_t(j) * std::size_t(n) + std::size_t(i)]++)
                    ++twice;
            }
    }
    return twice;
}

TEST(Bake, GeneratedUvsAreDisjointAndInTheUnitSquare) {
    for (const std::string& name : builtinMeshNames()) {
        SCOPED_TRACE(name);
        const MeshData original = builtinMesh(name);
        const MeshData mesh = withGeneratedUvs(original, 2048);
        const std::size_t triangles = original.indices.size() / 3;
        ASSERT_EQ(mesh.indices.size(), original.indices.size());
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        EXPECT_TRUE(hasUsableUvs(mesh));
        double area = 0.0;
        for (std::size_t t = 0; t < triangles; ++t) {
            // The same surface triangle, vertex order (facing) kept.
            for (int k = 0; k < 3; ++k)
                ASSERT_EQ(mesh.positions[mesh.indices[t * 3 + std::size_t(k)]],
                          original.positions[original.indices[t * 3 + std::size_t(k)]]);
            const glm::dvec2 a = mesh.uvs[mesh.indices[t * 3]], b = mesh.uvs[mesh.indices[t * 3 + 1]],
                             c = mesh.uvs[mesh.indices[t * 3 + 2]];
            const double doubled = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
            ASSERT_GT(doubled, 0.0);
            area += 0.5 * doubled;
        }
        EXPECT_LE(area, 1.0);
        EXPECT_GT(area, 0.25) << "the atlas should use a fair share of the texture";
        // Finer than the texture, so even thin slivers between neighbours would be caught.
        EXPECT_EQ(overlaps(mesh, 8192), 0);
    }
    // Triangles that cannot get a few texels each are refused, not squeezed.
    EXPECT_THROW(withGeneratedUvs(builtinMesh("teapot"), 256), InputError);
}

TEST(Bake, GeneratedUvsKeepQuadsWhole) {
    // Two consecutive triangles that share an edge (each face of the cube, each cell of the
    // sphere's grid) share their cell's diagonal: the shared vertices get the same UVs in both,
    // so the texture runs on across the edge as the surface does.
    for (const char* name : {"cube", "sphere"}) {
        SCOPED_TRACE(name);
        const MeshData original = builtinMesh(name);
        const MeshData mesh = withGeneratedUvs(original, 2048);
        std::size_t quads = 0;
        for (std::size_t t = 0; t + 1 < original.indices.size() / 3; t += 2) {
            std::size_t shared = 0;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    if (original.indices[t * 3 + std::size_t(i)] ==
                        original.indices[t * 3 + 3 + std::size_t(j)]) {
                        ++shared;
                        EXPECT_EQ(mesh.uvs[t * 3 + std::size_t(i)], mesh.uvs[t * 3 + 3 + std::size_t(j)]);
                    }
            if (shared == 2) ++quads;
        }
        EXPECT_EQ(quads, original.indices.size() / 6) << "every pair of the grid is a quad";
    }
}

TEST(Bake, OwnUvsAreKeptOnlyWithinTheUnitSquare) {
    MeshData mesh = builtinMesh("cube");
    EXPECT_TRUE(hasUsableUvs(mesh)) << "its own, by faces";
    mesh.uvs.clear();
    EXPECT_FALSE(hasUsableUvs(mesh));
    mesh.uvs.assign(mesh.positions.size(), glm::vec2(0.5f));
    EXPECT_TRUE(hasUsableUvs(mesh));
    mesh.uvs[3].x = 1.5f; // a tiled coordinate: one texel would serve several points
    EXPECT_FALSE(hasUsableUvs(mesh));
}

TEST(Bake, DilationCoversTheGuttersWithTheSurfaceColour) {
    // A design that is ink everywhere on the object: after dilation, no texel within its reach
    // of a triangle may show the background.
    const Genome genome = parseGenome(R"({"format": "marbler-genome", "version": 1, "dimension": 3,
        "size": [100, 100, 100], "background": "#ffffff", "palette": ["#203040"],
        "initial": [{"tool": "spray", "center": [50, 50, 50], "radius": 200, "color": 0}], "operations": []})",
                                      "ink.marble.json");
    const int n = 512;
    const MeshData mesh = withGeneratedUvs(builtinMesh("cube"), n);
    BakeSettings settings;
    settings.textureSize = n;
    settings.dilation = 2;
    const BakedTexture baked = bakeTexture(genome, mesh, settings);
    settings.dilation = 0;
    const Image bare = bakeTexture(genome, mesh, settings).image;
    const std::array<std::uint8_t, 3> ink{0x20, 0x30, 0x40}, white{0xff, 0xff, 0xff};
    long covered = 0, reached = 0, missed = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if (texel(bare, i, j) == ink) ++covered;
            bool near = false;
            for (int dj = -2; dj <= 2 && !near; ++dj)
                for (int di = -2; di <= 2 && !near; ++di)
                    near = i + di >= 0 && j + dj >= 0 && i + di < n && j + dj < n &&
                           texel(bare, i + di, j + dj) == ink;
            if (!near) continue;
            ++reached;
            if (texel(baked.image, i, j) != ink) ++missed;
        }
    EXPECT_EQ(std::size_t(covered), baked.coveredTexels);
    EXPECT_GT(reached, covered) << "the dilation should reach past the triangles";
    EXPECT_EQ(missed, 0);
    EXPECT_EQ(texel(baked.image, n - 1, n - 1), white) << "far from every triangle: the background";
}

TEST(Bake, FlatDesignsAreProjectedAlongZ) {
    // A 2D design on the cube: the front face (z = +1) shows the design over the whole square,
    // upright: the mesh's top (+y) is the design's top (y = 0).
    const Genome genome = test::loadExample("flame-comb-vortex.marble.json");
    const MeshData mesh = builtinMesh("cube");
    const MeshPlacement placement = placeMesh(genome, mesh);
    const glm::dvec3 topLeft = placement.designPoint({-1.0, 1.0, 1.0});
    const glm::dvec3 bottomRight = placement.designPoint({1.0, -1.0, -1.0});
    const double w = genome.size.x, h = genome.size.y, side = std::min(w, h);
    EXPECT_NEAR(topLeft.x, 0.5 * (w - side), 1e-9);
    EXPECT_NEAR(topLeft.y, 0.5 * (h - side), 1e-9);
    EXPECT_NEAR(bottomRight.x, 0.5 * (w + side), 1e-9);
    EXPECT_NEAR(bottomRight.y, 0.5 * (h + side), 1e-9);
    EXPECT_EQ(placement.designPoint({0.3, 0.2, 1.0}), placement.designPoint({0.3, 0.2, -1.0}));
}

// --- Files -----------------------------------------------------------------------------------

std::uint32_t u32(const std::string& bytes, std::size_t at) {
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, 4);
    return value;
}

/// Checks a glTF document against its binary buffer: every view inside the buffer and
/// 4-aligned, every accessor inside its view, POSITION's min and max those of the data, indices
/// within the vertices. Returns the bytes of the image's view (GLB) or empty.
std::string checkGltf(const nlohmann::json& doc, const std::string& bin) {
    EXPECT_EQ(doc["asset"]["version"], "2.0");
    EXPECT_EQ(doc["buffers"].size(), 1u);
    EXPECT_EQ(doc["buffers"][0]["byteLength"].get<std::size_t>(), bin.size());
    for (const auto& view : doc["bufferViews"]) {
        const std::size_t offset = view.value("byteOffset", std::size_t(0)), length = view["byteLength"];
        EXPECT_EQ(offset % 4, 0u);
        EXPECT_LE(offset + length, bin.size());
    }
    const auto& primitive = doc["meshes"][0]["primitives"][0];
    const auto& accessors = doc["accessors"];
    auto sizeOf = [](const nlohmann::json& a) {
        const std::size_t component = a["componentType"] == 5126 || a["componentType"] == 5125 ? 4 : 0;
        const std::string type = a["type"];
        const std::size_t components = type == "VEC3" ? 3 : type == "VEC2" ? 2 : type == "SCALAR" ? 1 : 0;
        return component * components;
    };
    const auto& position = accessors[primitive["attributes"]["POSITION"].get<std::size_t>()];
    const std::size_t vertices = position["count"];
    for (const char* attribute : {"POSITION", "NORMAL", "TEXCOORD_0"}) {
        const auto& a = accessors[primitive["attributes"][attribute].get<std::size_t>()];
        EXPECT_EQ(a["count"].get<std::size_t>(), vertices) << attribute;
        const auto& view = doc["bufferViews"][a["bufferView"].get<std::size_t>()];
        EXPECT_LE(a.value("byteOffset", std::size_t(0)) + a["count"].get<std::size_t>() * sizeOf(a),
                  view["byteLength"].get<std::size_t>())
            << attribute;
    }
    auto floats = [&](const nlohmann::json& a) {
        const auto& view = doc["bufferViews"][a["bufferView"].get<std::size_t>()];
        std::vector<float> values(a["count"].get<std::size_t>() * sizeOf(a) / 4);
        std::memcpy(values.data(), bin.data() + view.value("byteOffset", std::size_t(0)), values.size() * 4);
        return values;
    };
    const std::vector<float> p = floats(position);
    for (int k = 0; k < 3; ++k) {
        float lo = std::numeric_limits<float>::max(), hi = -lo;
        for (std::size_t v = 0; v < vertices; ++v)
            lo = std::min(lo, p[v * 3 + std::size_t(k)]), hi = std::max(hi, p[v * 3 + std::size_t(k)]);
        EXPECT_EQ(position["min"][std::size_t(k)].get<float>(), lo);
        EXPECT_EQ(position["max"][std::size_t(k)].get<float>(), hi);
    }
    for (float t : floats(accessors[primitive["attributes"]["TEXCOORD_0"].get<std::size_t>()])) {
        EXPECT_GE(t, 0.0f);
        EXPECT_LE(t, 1.0f);
    }
    const auto& indices = accessors[primitive["indices"].get<std::size_t>()];
    EXPECT_EQ(indices["componentType"], 5125);
    EXPECT_EQ(indices["count"].get<std::size_t>() % 3, 0u);
    const auto& indexView = doc["bufferViews"][indices["bufferView"].get<std::size_t>()];
    std::vector<std::uint32_t> index(indices["count"].get<std::size_t>());
    std::memcpy(index.data(), bin.data() + indexView.value("byteOffset", std::size_t(0)), index.size() * 4);
    EXPECT_LT(*std::max_element(index.begin(), index.end()), vertices);
    const auto& material = doc["materials"][primitive["material"].get<std::size_t>()];
    const std::size_t texture = material["pbrMetallicRoughness"]["baseColorTexture"]["index"];
    const auto& image = doc["images"][doc["textures"][texture]["source"].get<std::size_t>()];
    if (!image.contains("bufferView")) return {};
    EXPECT_EQ(image["mimeType"], "image/png");
    const auto& view = doc["bufferViews"][image["bufferView"].get<std::size_t>()];
    return bin.substr(view.value("byteOffset", std::size_t(0)), view["byteLength"].get<std::size_t>());
}

struct Baked {
    MeshData mesh;
    Image texture;
};

Baked bakeVase(int n) {
    const Genome genome = test::loadExample("slate-block.marble.json");
    BakeSettings settings;
    settings.textureSize = n;
    settings.aa = "none";
    Baked baked{withGeneratedUvs(builtinMesh("vase"), n), {}};
    baked.texture = bakeTexture(genome, baked.mesh, settings).image;
    return baked;
}

TEST(BakeFiles, GlbIsGltf2WithItsTextureInside) {
    const auto dir = test::outputDir("bake-glb");
    const Baked baked = bakeVase(1024);
    const auto written = writeTexturedMesh(baked.mesh, baked.texture, dir / "vase.glb", "Slate vase");
    ASSERT_EQ(written.size(), 1u);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1) << "no temporary file is left";
    const std::string glb = test::readFile(dir / "vase.glb");
    ASSERT_GE(glb.size(), 28u);
    EXPECT_EQ(u32(glb, 0), 0x46546C67u);
    EXPECT_EQ(u32(glb, 4), 2u);
    EXPECT_EQ(u32(glb, 8), glb.size());
    const std::uint32_t jsonLength = u32(glb, 12);
    EXPECT_EQ(u32(glb, 16), 0x4E4F534Au);
    EXPECT_EQ(jsonLength % 4, 0u);
    ASSERT_LE(20 + jsonLength + 8, glb.size());
    const std::uint32_t binLength = u32(glb, 20 + jsonLength);
    EXPECT_EQ(u32(glb, 24 + jsonLength), 0x004E4942u);
    EXPECT_EQ(binLength % 4, 0u);
    ASSERT_EQ(28 + jsonLength + binLength, glb.size());
    const nlohmann::json doc = nlohmann::json::parse(glb.substr(20, jsonLength));
    EXPECT_EQ(doc["nodes"][0]["name"], "Slate vase");
    const std::string png = checkGltf(doc, glb.substr(28 + jsonLength, binLength));
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    // The embedded PNG decodes to the baked texture exactly.
    test::writeFile(dir / "texture.png", png);
    const Image decoded = test::readImage8(dir / "texture.png");
    EXPECT_EQ(decoded.width, 1024);
    EXPECT_EQ(decoded.rgb, baked.texture.rgb);
}

TEST(BakeFiles, GltfReferencesItsBufferAndTexture) {
    const auto dir = test::outputDir("bake-gltf");
    const Baked baked = bakeVase(1024);
    writeTexturedMesh(baked.mesh, baked.texture, dir / "vase.gltf");
    const nlohmann::json doc = nlohmann::json::parse(test::readFile(dir / "vase.gltf"));
    EXPECT_EQ(doc["buffers"][0]["uri"], "vase.bin");
    EXPECT_EQ(doc["images"][0]["uri"], "vase.png");
    checkGltf(doc, test::readFile(dir / "vase.bin"));
    EXPECT_EQ(test::readImage8(dir / "vase.png").rgb, baked.texture.rgb);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 3);
}

TEST(BakeFiles, ObjAndMtlReferenceTheTexture) {
    const auto dir = test::outputDir("bake-obj");
    const Baked baked = bakeVase(1024);
    writeTexturedMesh(baked.mesh, baked.texture, dir / "vase.obj", "Slate vase");
    const std::string obj = test::readFile(dir / "vase.obj");
    const std::string mtl = test::readFile(dir / "vase.mtl");
    EXPECT_NE(obj.find("mtllib vase.mtl\n"), std::string::npos);
    EXPECT_NE(obj.find("usemtl Slate_vase\n"), std::string::npos);
    EXPECT_NE(mtl.find("newmtl Slate_vase\n"), std::string::npos);
    EXPECT_NE(mtl.find("map_Kd vase.png\n"), std::string::npos);
    EXPECT_EQ(test::readImage8(dir / "vase.png").rgb, baked.texture.rgb);
    std::size_t faces = 0, vts = 0;
    for (std::size_t at = obj.find('\n'); at != std::string::npos; at = obj.find('\n', at + 1)) {
        if (obj.compare(at + 1, 2, "f ") == 0) ++faces;
        if (obj.compare(at + 1, 3, "vt ") == 0) ++vts;
    }
    EXPECT_EQ(faces, baked.mesh.indices.size() / 3);
    EXPECT_EQ(vts, baked.mesh.uvs.size());
}

TEST(BakeFiles, UnknownFormatAndMissingFolderLeaveNothing) {
    const auto dir = test::outputDir("bake-bad");
    const Baked baked = bakeVase(1024);
    EXPECT_THROW(writeTexturedMesh(baked.mesh, baked.texture, dir / "vase.fbx"), InputError);
    EXPECT_THROW(writeTexturedMesh(baked.mesh, baked.texture, dir / "no" / "vase.glb"), RuntimeFailure);
    MeshData noUvs = baked.mesh;
    noUvs.uvs.clear();
    EXPECT_THROW(writeTexturedMesh(noUvs, baked.texture, dir / "vase.obj"), InputError);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 0);
}

} // namespace
} // namespace marbler
