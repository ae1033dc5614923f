// The built-in objects, generated in code (no assimp), so the headless verbs have them.

#include "marbler/Mesh.h"

#include "marbler/Error.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace marbler {
namespace {

constexpr float Pi = std::numbers::pi_v<float>;

/// A rectangle of the texture, in MeshData's UV convention (v downwards): where one part of an
/// object lays out its texture coordinates.
struct UvBox {
    float u0 = 0.0f, v0 = 0.0f, u1 = 1.0f, v1 = 1.0f;
    glm::vec2 at(float s, float t) const { return {u0 + s * (u1 - u0), v0 + t * (v1 - v0)}; }
};

/// The gap kept round each part of an object whose texture holds several (cube faces, teapot
/// parts), so the bake's dilation has room and a filtered lookup at a part's edge stays on it.
constexpr float UvMargin = 1.0f / 128.0f;

/// The grid column of a turn about +y (phi = 2 pi u, z = r sin phi) that faces the back (-z):
/// where the texture's seam goes, out of sight from the front; the front faces its middle.
int backColumn(int around) {
    return around * 3 / 4;
}

UvBox inset(UvBox box) {
    return {box.u0 + UvMargin, box.v0 + UvMargin, box.u1 - UvMargin, box.v1 - UvMargin};
}

/// A regular grid of (u, v) in [0,1]^2 mapped by `point` (position, normal), triangulated;
/// u wraps round (the seam shares positions but gets its own column so normals stay smooth).
///
/// Texture coordinates run across `box` once round, with u mirrored and v upwards, so that
/// seen from outside (the triangles' front) the texture reads the right way round, its top at
/// the grid's v = 1 end. The texture's seam, its left and right edges, lies on column
/// `seamColumn` (0: the geometry's own seam): that column's vertices are duplicated (the same
/// positions and normals, the copy appended after the grid) so that no triangle wraps round the
/// texture. Positions, normals and the triangles' order do not depend on where the seam is.
void addGrid(MeshData& mesh, int uSteps, int vSteps,
             const std::function<void(float, float, glm::vec3&, glm::vec3&)>& point, UvBox box = {},
             int seamColumn = 0) {
    auto base = std::uint32_t(mesh.positions.size());
    // The texture's across coordinate of column i: 1 at the seam's own column, falling to 0 at
    // the seam again after one turn.
    auto across = [&](int i) {
        return i == seamColumn ? 1.0f : float((seamColumn - i + uSteps) % uSteps) / float(uSteps);
    };
    for (int j = 0; j <= vSteps; ++j) {
        for (int i = 0; i <= uSteps; ++i) {
            glm::vec3 p, n;
            const float v = float(j) / float(vSteps);
            point(float(i) / float(uSteps), v, p, n);
            mesh.positions.push_back(p);
            mesh.normals.push_back(n);
            mesh.uvs.push_back(box.at(across(i), 1.0f - v));
        }
    }
    auto seamCopy = std::uint32_t(mesh.positions.size());
    if (seamColumn > 0) {
        for (int j = 0; j <= vSteps; ++j) {
            const auto from = base + std::uint32_t(j * (uSteps + 1) + seamColumn);
            mesh.positions.push_back(mesh.positions[from]);
            mesh.normals.push_back(mesh.normals[from]);
            mesh.uvs.push_back(box.at(0.0f, 1.0f - float(j) / float(vSteps)));
        }
    }
    // Vertex (i, j) as the cells of column `cell` take it: the column before the seam takes
    // the seam's copy.
    auto at = [&](int i, int j, int cell) {
        if (seamColumn > 0 && i == seamColumn && cell == seamColumn - 1) return seamCopy + std::uint32_t(j);
        return base + std::uint32_t(j * (uSteps + 1) + i);
    };
    for (int j = 0; j < vSteps; ++j) {
        for (int i = 0; i < uSteps; ++i) {
            mesh.indices.insert(mesh.indices.end(), {at(i, j, i), at(i, j + 1, i), at(i + 1, j + 1, i)});
            mesh.indices.insert(mesh.indices.end(), {at(i, j, i), at(i + 1, j + 1, i), at(i + 1, j, i)});
        }
    }
}

/// A solid of revolution about +y from a profile (radius, height) running from the bottom axis
/// point to the top axis point; normals from the profile's tangent, so the surface is smooth.
/// The texture runs round and up the object (its top edge at the top), its seam at the back (-z).
void addLathe(MeshData& mesh, const std::vector<glm::vec2>& profile, int around, UvBox box = {}) {
    int steps = int(profile.size()) - 1;
    addGrid(
        mesh, around, steps,
        [&](float u, float v, glm::vec3& p, glm::vec3& n) {
            int k = int(std::lround(v * float(steps)));
            glm::vec2 prev = profile[std::size_t(std::max(k - 1, 0))];
            glm::vec2 next = profile[std::size_t(std::min(k + 1, steps))];
            glm::vec2 tangent = next - prev;
            glm::vec2 outward = glm::normalize(glm::vec2(tangent.y, -tangent.x));
            float phi = 2.0f * Pi * u;
            // With v running up the profile, this turning sense makes addGrid's triangles
            // counter-clockwise seen from outside (front faces outward, as the cut plane assumes).
            float c = std::cos(phi), s = std::sin(phi);
            p = {profile[std::size_t(k)].x * c, profile[std::size_t(k)].y, profile[std::size_t(k)].x * s};
            n = glm::normalize(glm::vec3(outward.x * c, outward.y, outward.x * s));
        },
        box, backColumn(around));
}

/// A tube of varying radius along a path (for the spout and handle of the teapot), ends closed;
/// its side's texture in `side` (around and along), each end's a disc in `ends[0]`, `ends[1]`.
void addTube(MeshData& mesh, const std::function<glm::vec3(float)>& path,
             const std::function<float(float)>& radius, int along, int around, UvBox side,
             const UvBox (&ends)[2]) {
    auto frame = [&](float t, glm::vec3& x, glm::vec3& y, glm::vec3& z) {
        float h = 1e-3f;
        z = glm::normalize(path(std::min(t + h, 1.0f)) - path(std::max(t - h, 0.0f)));
        glm::vec3 helper = std::abs(z.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
        x = glm::normalize(glm::cross(helper, z));
        y = glm::cross(z, x);
    };
    addGrid(
        mesh, around, along,
        [&](float u, float v, glm::vec3& p, glm::vec3& n) {
            glm::vec3 x, y, z;
            frame(v, x, y, z);
            float phi = 2.0f * Pi * u;
            n = std::cos(phi) * x - std::sin(phi) * y; // this sense winds the faces outward
            p = path(v) + radius(v) * n;
        },
        side);
    for (float t : {0.0f, 1.0f}) {
        const UvBox& disc = ends[t == 0.0f ? 0 : 1];
        // The far end is seen from the other side, so its disc turns the other way.
        const float turn = t == 0.0f ? 1.0f : -1.0f;
        glm::vec3 x, y, z;
        frame(t, x, y, z);
        glm::vec3 outward = t == 0.0f ? -z : z;
        auto centre = std::uint32_t(mesh.positions.size());
        mesh.positions.push_back(path(t));
        mesh.normals.push_back(outward);
        mesh.uvs.push_back(disc.at(0.5f, 0.5f));
        for (int i = 0; i <= around; ++i) {
            float phi = 2.0f * Pi * float(i) / float(around);
            mesh.positions.push_back(path(t) + radius(t) * (std::cos(phi) * x + std::sin(phi) * y));
            mesh.normals.push_back(outward);
            mesh.uvs.push_back(disc.at(0.5f + 0.5f * std::cos(phi), 0.5f + 0.5f * turn * std::sin(phi)));
        }
        for (int i = 0; i < around; ++i) {
            std::uint32_t a = centre + 1 + std::uint32_t(i), b = a + 1;
            if (t == 0.0f)
                mesh.indices.insert(mesh.indices.end(), {centre, b, a});
            else
                mesh.indices.insert(mesh.indices.end(), {centre, a, b});
        }
    }
}

MeshData sphere() {
    // Same orientation as a lathe: v from the bottom pole to the top one. The texture by
    // longitude and latitude (the top pole along its top edge), its seam the back meridian.
    MeshData mesh;
    addGrid(
        mesh, 96, 48,
        [](float u, float v, glm::vec3& p, glm::vec3& n) {
            float theta = Pi * v, phi = 2.0f * Pi * u;
            n = {std::sin(theta) * std::cos(phi), -std::cos(theta), std::sin(theta) * std::sin(phi)};
            p = n;
        },
        {}, backColumn(96));
    return mesh;
}

MeshData cube() {
    // Per-face vertices: each face its own flat normal, so the shading has crisp edges while the
    // marbling (a function of position only) runs on across them.
    // The texture by faces, six square tiles in two rows (the top two thirds of the texture):
    // left, front, right above back, top, bottom, so the first row runs on round the sides.
    // Each face shows its tile upright and unmirrored seen from outside: the sides with +y up,
    // the top with its back edge up, the bottom with its front edge up.
    MeshData mesh;
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::ivec2 tiles[6] = {{2, 0}, {0, 0}, {1, 1}, {2, 1}, {1, 0}, {0, 1}}; // (column, row)
    for (int face = 0; face < 6; ++face) {
        const glm::vec3& n = normals[face];
        glm::vec3 u = std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        glm::vec3 v = glm::cross(n, u);
        // The tile's up and right directions on the face, right x up = n (seen from outside).
        const glm::vec3 up = std::abs(n.y) > 0.5f ? glm::vec3(0, 0, -n.y) : glm::vec3(0, 1, 0);
        const glm::vec3 right = glm::cross(up, n);
        const UvBox tile = inset({float(tiles[face].x) / 3.0f, float(tiles[face].y) / 3.0f,
                                  float(tiles[face].x + 1) / 3.0f, float(tiles[face].y + 1) / 3.0f});
        auto base = std::uint32_t(mesh.positions.size());
        for (auto [a, b] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
            const glm::vec3 p = n + a * u + b * v;
            mesh.positions.push_back(p);
            mesh.normals.push_back(n);
            mesh.uvs.push_back(tile.at(0.5f + 0.5f * glm::dot(p, right), 0.5f - 0.5f * glm::dot(p, up)));
        }
        // u x v = n, so (0,1,2) runs counter-clockwise seen from outside.
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return mesh;
}

MeshData torus() {
    // A circle of radius `minor` turned about +y, traversed so its outward normal is (cos t, sin t).
    MeshData mesh;
    // The texture by its two angles: across, round the axis (the seam at the back); down, round
    // the tube from the inner equator over the top and back (the seam inside the hole).
    const float major = 1.0f, minor = 0.4f;
    addGrid(
        mesh, 128, 64,
        [&](float u, float v, glm::vec3& p, glm::vec3& n) {
            float phi = 2.0f * Pi * u, t = 2.0f * Pi * v - Pi;
            float c = std::cos(phi), s = std::sin(phi);
            n = {std::cos(t) * c, std::sin(t), std::cos(t) * s};
            p = glm::vec3((major + minor * std::cos(t)) * c, minor * std::sin(t),
                          (major + minor * std::cos(t)) * s);
        },
        {}, backColumn(128));
    return mesh;
}

/// A panel of `uSteps` x `vSteps` cells: the point at (s, t) in [0, 1]^2 is
/// origin + s right + t up + depth(s, t) n with n = normalize(right x up), its normal from the
/// surface's tangents; the texture across `box` upright and unmirrored seen from the n side
/// (s to the right, t upwards).
void addPanel(MeshData& mesh, const glm::vec3& origin, const glm::vec3& right, const glm::vec3& up,
              int uSteps, int vSteps, UvBox box, const std::function<float(float, float)>& depth = {}) {
    const glm::vec3 n = glm::normalize(glm::cross(right, up));
    auto point = [&](float s, float t) {
        return origin + s * right + t * up + (depth ? depth(s, t) : 0.0f) * n;
    };
    auto base = std::uint32_t(mesh.positions.size());
    for (int j = 0; j <= vSteps; ++j)
        for (int i = 0; i <= uSteps; ++i) {
            const float s = float(i) / float(uSteps), t = float(j) / float(vSteps);
            mesh.positions.push_back(point(s, t));
            glm::vec3 normal = n;
            if (depth) {
                const float h = 1e-3f;
                const glm::vec3 ds = point(std::min(s + h, 1.0f), t) - point(std::max(s - h, 0.0f), t);
                const glm::vec3 dt = point(s, std::min(t + h, 1.0f)) - point(s, std::max(t - h, 0.0f));
                const glm::vec3 c = glm::cross(ds, dt);
                if (glm::length(c) > 0.0f) normal = glm::normalize(c);
            }
            mesh.normals.push_back(normal);
            mesh.uvs.push_back(box.at(s, 1.0f - t));
        }
    auto at = [&](int i, int j) { return base + std::uint32_t(j * (uSteps + 1) + i); };
    // right x up = n, so (i, j), (i + 1, j), (i + 1, j + 1) runs counter-clockwise seen from n.
    for (int j = 0; j < vSteps; ++j)
        for (int i = 0; i < uSteps; ++i) {
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
}

/// The part of the texture a surface of `width` x `height` takes when a flat design, laid over
/// the whole texture by its longer side, is to show undistorted on it: the largest box of that
/// aspect, centred.
UvBox boxOfAspect(float width, float height) {
    const float aspect = width / height;
    if (aspect >= 1.0f) {
        const float h = 0.5f / aspect;
        return {0.0f, 0.5f - h, 1.0f, 0.5f + h};
    }
    const float w = 0.5f * aspect;
    return {0.5f - w, 0.0f, 0.5f + w, 1.0f};
}

MeshData book() {
    // A closed hardback standing upright, its front cover facing the front (+z) and the spine
    // on the left. The covers and spine take the texture as a book's jacket lies flat: back
    // cover, spine, front cover from left to right, undistorted, across the texture's middle;
    // the page edges (top, bottom and fore-edge) take strips above and below, as marbled edges.
    MeshData mesh;
    const float w = 1.4f, h = 2.0f, d = 0.32f, total = 2.0f * w + d;
    const UvBox jacket = boxOfAspect(total, h);
    auto across = [&](float from, float to) {
        return UvBox{jacket.u0 + from / total, jacket.v0, jacket.u0 + to / total, jacket.v1};
    };
    const float x0 = -0.5f * w, x1 = 0.5f * w, y0 = -0.5f * h, z0 = -0.5f * d, z1 = 0.5f * d;
    addPanel(mesh, {x0, y0, z1}, {w, 0, 0}, {0, h, 0}, 14, 20, inset(across(w + d, total))); // front
    addPanel(mesh, {x0, y0, z0}, {0, 0, d}, {0, h, 0}, 4, 20, inset(across(w, w + d)));      // spine
    addPanel(mesh, {x1, y0, z0}, {-w, 0, 0}, {0, h, 0}, 14, 20, inset(across(0.0f, w)));     // back
    // The page edges, each undistorted in its own strip: the fore-edge (on its side, running up
    // the book from left to right) below the jacket, the top and bottom edges above it.
    const float below = 0.5f * (1.0f + jacket.v1), above = 0.5f * jacket.v0;
    const float foreHeight = 0.9f * d / h, edgeHeight = 0.46f * d / w;
    addPanel(mesh, {x1, y0, z0}, {0, h, 0}, {0, 0, d}, 20, 4,
             inset({0.05f, below - 0.5f * foreHeight, 0.95f, below + 0.5f * foreHeight})); // fore-edge
    addPanel(mesh, {x0, -y0, z1}, {w, 0, 0}, {0, 0, -d}, 14, 4,
             inset({0.02f, above - 0.5f * edgeHeight, 0.48f, above + 0.5f * edgeHeight})); // top
    addPanel(mesh, {x0, y0, z0}, {w, 0, 0}, {0, 0, d}, 14, 4,
             inset({0.52f, above - 0.5f * edgeHeight, 0.98f, above + 0.5f * edgeHeight})); // bottom
    return mesh;
}

MeshData cushion() {
    // A square cushion, puffed, facing the front: its face takes the whole texture, upright.
    // Open at the back (seen from behind, its inside shows, as a shell).
    MeshData mesh;
    const float side = 1.6f, puff = 0.28f;
    addPanel(mesh, {-0.5f * side, -0.5f * side, 0.0f}, {side, 0, 0}, {0, side, 0}, 40, 40, inset({}),
             [&](float s, float t) {
                 // Full in the middle, falling to the seam round the edge.
                 const float a = std::sin(Pi * s), b = std::sin(Pi * t);
                 return puff * std::pow(std::max(a * b, 0.0f), 0.45f);
             });
    return mesh;
}

MeshData cloth() {
    // A cloth hanging in folds from a straight top edge, as a curtain: the folds deepen towards
    // the hem. The texture upright across it, undistorted in the flat.
    MeshData mesh;
    const float width = 1.6f, height = 2.0f, folds = 3.5f, depth = 0.16f;
    addPanel(mesh, {-0.5f * width, -0.5f * height, 0.0f}, {width, 0, 0}, {0, height, 0}, 96, 40,
             boxOfAspect(width, height), [&](float s, float t) {
                 return depth * (0.35f + 0.65f * (1.0f - t)) * std::sin(2.0f * Pi * folds * s);
             });
    return mesh;
}

MeshData wall() {
    // A stretch of wall, flat, facing the front, papered: the texture upright across it.
    MeshData mesh;
    const float width = 2.4f, height = 1.8f;
    addPanel(mesh, {-0.5f * width, -0.5f * height, 0.0f}, {width, 0, 0}, {0, height, 0}, 12, 9,
             boxOfAspect(width, height));
    return mesh;
}

std::vector<glm::vec2> smoothProfile(const std::vector<glm::vec2>& keys, int perSegment) {
    // Catmull-Rom through the key points, so lathe normals vary smoothly.
    std::vector<glm::vec2> out;
    for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
        glm::vec2 p0 = keys[k == 0 ? 0 : k - 1], p1 = keys[k], p2 = keys[k + 1];
        glm::vec2 p3 = keys[std::min(k + 2, keys.size() - 1)];
        for (int s = 0; s < perSegment; ++s) {
            float t = float(s) / float(perSegment);
            float t2 = t * t, t3 = t2 * t;
            out.push_back(0.5f *
                          ((2.0f * p1) + (-p0 + p2) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                           (-p0 + 3.0f * p1 - 3.0f * p2 + p3) * t3));
        }
    }
    out.push_back(keys.back());
    for (glm::vec2& p : out)
        p.x = std::max(p.x, 0.0f);
    return out;
}

MeshData vase() {
    MeshData mesh;
    std::vector<glm::vec2> keys = {{0.0f, -1.0f},  {0.45f, -1.0f}, {0.5f, -0.95f}, {0.62f, -0.6f},
                                   {0.7f, -0.1f},  {0.55f, 0.35f}, {0.3f, 0.7f},   {0.28f, 0.85f},
                                   {0.38f, 0.98f}, {0.3f, 1.0f},   {0.0f, 1.0f}};
    addLathe(mesh, smoothProfile(keys, 8), 96);
    return mesh;
}

MeshData teapot() {
    // A lathe-turned body and lid with a tube spout and handle: teapot-like, not Newell's patches.
    // The texture by parts: the body round and up in the top 60%, the spout and the handle round
    // and along in a band each below it, their four end discs side by side at the bottom.
    MeshData mesh;
    std::vector<glm::vec2> keys = {{0.0f, -0.75f}, {0.55f, -0.75f}, {0.85f, -0.45f}, {0.95f, -0.05f},
                                   {0.8f, 0.35f},  {0.55f, 0.5f},   {0.5f, 0.55f},   {0.3f, 0.62f},
                                   {0.1f, 0.7f},   {0.12f, 0.82f},  {0.0f, 0.9f}};
    addLathe(mesh, smoothProfile(keys, 8), 96, inset({0.0f, 0.0f, 1.0f, 0.6f}));
    auto disc = [](int k) { return inset({0.1f * float(k), 0.9f, 0.1f * float(k + 1), 1.0f}); };
    const UvBox spoutEnds[2] = {disc(0), disc(1)}, handleEnds[2] = {disc(2), disc(3)};
    addTube(
        mesh, [](float t) { return glm::vec3(0.7f + 0.75f * t, -0.2f + 0.75f * t * t + 0.1f * t, 0.0f); },
        [](float t) { return 0.2f - 0.11f * t; }, 24, 24, inset({0.0f, 0.6f, 1.0f, 0.75f}), spoutEnds);
    addTube(
        mesh,
        [](float t) {
            float a = Pi * (0.5f - t * 1.05f) * 0.95f;
            return glm::vec3(-0.85f - 0.38f * std::cos(a), 0.1f + 0.4f * std::sin(a), 0.0f);
        },
        [](float) { return 0.075f; }, 32, 16, inset({0.0f, 0.75f, 1.0f, 0.9f}), handleEnds);
    return mesh;
}

} // namespace

namespace {

struct BuiltinMesh {
    const char* name;
    MeshData (*make)();
};

/// The one list of built-in objects; the first is DefaultMesh.
constexpr BuiltinMesh BuiltinMeshes[] = {{"vase", vase},       {"sphere", sphere}, {"cube", cube},
                                         {"torus", torus},     {"teapot", teapot}, {"book", book},
                                         {"cushion", cushion}, {"cloth", cloth},   {"wall", wall}};

} // namespace

std::vector<std::string> builtinMeshNames() {
    std::vector<std::string> names;
    for (const BuiltinMesh& mesh : BuiltinMeshes)
        names.emplace_back(mesh.name);
    return names;
}

std::string builtinMeshList() {
    std::string list;
    for (const BuiltinMesh& mesh : BuiltinMeshes)
        list += (list.empty() ? "" : ", ") + std::string(mesh.name);
    return list;
}

bool isBuiltinMesh(const std::string& name) {
    for (const BuiltinMesh& mesh : BuiltinMeshes)
        if (mesh.name == name) return true;
    return false;
}

MeshData builtinMesh(const std::string& name) {
    for (const BuiltinMesh& mesh : BuiltinMeshes)
        if (mesh.name == name) return mesh.make();
    throw InputError("unknown built-in mesh \"" + name + "\" (" + builtinMeshList() + ", or a mesh file)");
}

} // namespace marbler
