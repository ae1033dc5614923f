// Baking a design into an object's texture, and writing the object as glTF 2.0 or OBJ.
//
// The writers are Marbler's own (nlohmann-json for glTF's JSON) rather than assimp's exporter:
// the formats are small and exactly specified, the `marbler` executable then needs no assimp
// (which lives in the window module), and the output is ours to hold to the specification in
// tests (accessor bounds, buffer alignment, texture coordinates' orientation).

#include "marbler/Bake.h"

#include "marbler/AtomicFile.h"
#include "marbler/Error.h"
#include "marbler/ImageFile.h"
#include "marbler/ImageFormats.h"
#include "marbler/Threads.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>
#include <limits>
#include <mutex>
#include <thread>

namespace marbler {
namespace fs = std::filesystem;

glm::dvec3 MeshPlacement::designPoint(const glm::dvec3& p) const {
    const glm::dvec3 q = (p - meshCentre) * scale;
    if (planar) return {designCentre.x + q.x, designCentre.y - q.y, 0.0};
    return designCentre + q;
}

MeshPlacement placeMesh(const Genome& genome, const MeshData& mesh) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    MeshPlacement placement;
    if (mesh.positions.empty()) return placement;
    placement.meshCentre = 0.5 * (lo + hi);
    placement.planar = genome.dimension == 2;
    const glm::dvec3 extent = hi - lo;
    // The fit of GlRenderer's drawGBuffer: every axis the mesh spans, so the window and the bake
    // put the same design point on the same vertex.
    const int axes = placement.planar ? 2 : 3;
    double scale = std::numeric_limits<double>::max();
    for (int k = 0; k < axes; ++k)
        if (extent[k] > 0.0) scale = std::min(scale, genome.size[k] / extent[k]);
    placement.scale = scale == std::numeric_limits<double>::max() ? 1.0 : scale;
    placement.designCentre = 0.5 * genome.size;
    if (placement.planar) placement.designCentre.z = 0.0;
    return placement;
}

FlatOnUvs::FlatOnUvs(const Genome& genome)
    : size(genome.size.x, genome.size.y)
    , side(std::max(genome.size.x, genome.size.y))
    , origin(0.5 * (size - glm::dvec2(side))) {}

glm::dvec3 FlatOnUvs::designPoint(const glm::dvec2& uv) const {
    return {origin.x + uv.x * side, origin.y + uv.y * side, 0.0};
}

bool FlatOnUvs::inside(const glm::dvec3& q) const {
    return q.x >= 0.0 && q.x <= size.x && q.y >= 0.0 && q.y <= size.y;
}

bool hasUsableUvs(const MeshData& mesh) {
    if (mesh.uvs.empty() || mesh.uvs.size() != mesh.positions.size()) return false;
    for (const glm::vec2& uv : mesh.uvs)
        if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) return false;
    return true;
}

namespace {

/// For the pair of triangles t and t + 1: whether they share an edge (two vertex indices), as
/// the two halves of a quad do, and if so the vertices in the order the quad's cell takes them:
/// t's own vertex, the shared edge's two ends, t + 1's own vertex.
bool sharedEdge(const MeshData& mesh, std::size_t t, std::uint32_t quad[4]) {
    const std::uint32_t* a = &mesh.indices[t * 3];
    const std::uint32_t* b = &mesh.indices[t * 3 + 3];
    for (int k = 0; k < 3; ++k) {
        // a's edge from a[k + 1] to a[k + 2], opposite a[k]; b holds it as b[m + 1], b[m + 2] in
        // either order when the two triangles meet along it.
        const std::uint32_t p = a[(k + 1) % 3], q = a[(k + 2) % 3];
        for (int m = 0; m < 3; ++m) {
            const std::uint32_t r = b[(m + 1) % 3], u = b[(m + 2) % 3];
            if (((r == p && u == q) || (r == q && u == p)) && b[m] != a[k] && p != q) {
                quad[0] = a[k];
                quad[1] = p;
                quad[2] = q;
                quad[3] = b[m];
                return true;
            }
        }
    }
    return false;
}

} // namespace

MeshData withGeneratedUvs(const MeshData& mesh, int textureSize) {
    const std::size_t triangles = mesh.indices.size() / 3;
    if (triangles == 0) throw InputError("the mesh has no triangles");
    const std::size_t cells = (triangles + 1) / 2;
    const auto side = std::size_t(std::ceil(std::sqrt(double(cells))));
    const double cell = double(textureSize) / double(side); // texels
    std::vector<std::uint8_t> isQuad(cells, 0);
    std::vector<std::array<std::uint32_t, 4>> quads(cells);
    bool anySplit = false;
    for (std::size_t c = 0; c < cells; ++c) {
        isQuad[c] = 2 * c + 1 < triangles && sharedEdge(mesh, 2 * c, quads[c].data());
        anySplit = anySplit || !isQuad[c];
    }
    // Each patch keeps `gutter` texels from its cell's edges. Two triangles that share an edge
    // (a quad) share the cell's diagonal, so the texture runs on across it as the surface does;
    // two that do not are drawn `apart` from it (sqrt 2 times as much, since the distance is
    // measured across the diagonal), so dilation has room on every side.
    const double gutter = 1.5, apart = std::sqrt(2.0) * gutter;
    const double quadLeg = cell - 2.0 * gutter, splitLeg = quadLeg - apart;
    if ((anySplit ? splitLeg : quadLeg) < 3.0)
        throw InputError("the mesh's " + std::to_string(triangles) +
                         " triangles are too many for generated texture coordinates in a " +
                         std::to_string(textureSize) + " texture (each would get under 3 " +
                         "texels); give a larger --texture or a mesh with its own texture coordinates");

    MeshData out;
    out.uvsArePatches = true;
    out.positions.reserve(triangles * 3);
    out.normals.reserve(triangles * 3);
    out.uvs.reserve(triangles * 3);
    out.indices.reserve(triangles * 3);
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::size_t c = t / 2;
        const double x0 = double(c % side) * cell, y0 = double(c / side) * cell;
        const std::uint32_t v[3] = {mesh.indices[t * 3], mesh.indices[t * 3 + 1], mesh.indices[t * 3 + 2]};
        glm::dvec2 uvOf[3];
        if (isQuad[c]) {
            // The quad's corners: t's own vertex at the top left, the shared edge along the
            // diagonal, t + 1's own vertex at the bottom right.
            const glm::dvec2 corner[4] = {{x0 + gutter, y0 + gutter},
                                          {x0 + cell - gutter, y0 + gutter},
                                          {x0 + gutter, y0 + cell - gutter},
                                          {x0 + cell - gutter, y0 + cell - gutter}};
            for (int k = 0; k < 3; ++k)
                for (int q = 0; q < 4; ++q)
                    if (quads[c][std::size_t(q)] == v[k] && (q != (t % 2 == 0 ? 3 : 0))) uvOf[k] = corner[q];
        } else {
            // Lower-left half of the cell for the first of a pair, upper-right for the second,
            // as a right isosceles triangle; the right angle goes to the vertex opposite the
            // longest edge, the one nearest a right angle.
            const bool firstOfPair = t % 2 == 0;
            const glm::dvec2 rightAngle = firstOfPair ? glm::dvec2(x0 + gutter, y0 + gutter)
                                                      : glm::dvec2(x0 + cell - gutter, y0 + cell - gutter);
            const double along = firstOfPair ? splitLeg : -splitLeg;
            const glm::dvec2 corner[3] = {rightAngle, rightAngle + glm::dvec2(along, 0.0),
                                          rightAngle + glm::dvec2(0.0, along)};
            int right = 0;
            double longest = -1.0;
            for (int k = 0; k < 3; ++k) {
                const double opposite = glm::length(glm::dvec3(mesh.positions[v[(k + 1) % 3]]) -
                                                    glm::dvec3(mesh.positions[v[(k + 2) % 3]]));
                if (opposite > longest) {
                    longest = opposite;
                    right = k;
                }
            }
            for (int k = 0; k < 3; ++k)
                uvOf[k] = corner[(k - right + 3) % 3];
        }
        // The triangle keeps its vertex order (its facing).
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t source = v[k];
            const glm::dvec2 uv = uvOf[k] / double(textureSize);
            out.positions.push_back(mesh.positions[source]);
            out.normals.push_back(source < mesh.normals.size() ? mesh.normals[source] : glm::vec3(0.0f));
            out.uvs.emplace_back(float(uv.x), float(uv.y));
            out.indices.push_back(std::uint32_t(t * 3 + std::size_t(k)));
        }
    }
    return out;
}

namespace {

/// Barycentric coordinates of q in the triangle (a, b, c); false for a degenerate triangle.
bool barycentric(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& q,
                 glm::dvec3& w) {
    const glm::dvec2 e1 = b - a, e2 = c - a, r = q - a;
    const double det = e1.x * e2.y - e1.y * e2.x;
    if (det == 0.0 || !std::isfinite(det)) return false;
    const double beta = (r.x * e2.y - r.y * e2.x) / det;
    const double gamma = (e1.x * r.y - e1.y * r.x) / det;
    w = {1.0 - beta - gamma, beta, gamma};
    return true;
}

} // namespace

BakedTexture bakeTexture(const Genome& genome, const MeshData& mesh, const BakeSettings& settings,
                         const RenderControl* control) {
    const int n = settings.textureSize;
    if (n < 1 || n > MaxBakeTexture)
        throw InputError("texture size must be between 1 and " + std::to_string(MaxBakeTexture) + " (got " +
                         std::to_string(n) + ")");
    if (genome.source)
        throw InputError("a design with a source image cannot be baked yet (only inks and the background)");
    if (!hasUsableUvs(mesh))
        throw InputError("the mesh has no texture coordinates within [0, 1] to bake into");
    const AaPattern pattern = aaPattern(settings.aa);
    const MeshPlacement placement = placeMesh(genome, mesh);
    const FlatOnUvs flatOnUvs(genome);
    const bool throughUvs = genome.dimension == 2 && !mesh.uvsArePatches;

    // Which triangle each texel centre lies in, in index order (the first wins an overlap).
    const std::size_t texels = std::size_t(n) * std::size_t(n);
    std::vector<std::int32_t> owner(texels, -1);
    const std::size_t triangles = mesh.indices.size() / 3;
    auto uvOf = [&](std::uint32_t v) { return glm::dvec2(mesh.uvs[v]) * double(n); };
    BakedTexture result;
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::dvec2 a = uvOf(mesh.indices[t * 3]), b = uvOf(mesh.indices[t * 3 + 1]),
                         c = uvOf(mesh.indices[t * 3 + 2]);
        glm::dvec3 probe;
        if (!barycentric(a, b, c, a, probe)) continue; // no area in UV space: no texel is its own
        const int i0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}) - 0.5)));
        const int i1 = std::min(n - 1, int(std::ceil(std::max({a.x, b.x, c.x}) - 0.5)));
        const int j0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}) - 0.5)));
        const int j1 = std::min(n - 1, int(std::ceil(std::max({a.y, b.y, c.y}) - 0.5)));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                std::int32_t& slot = owner[std::size_t(j) * std::size_t(n) + std::size_t(i)];
                if (slot >= 0) continue;
                glm::dvec3 w;
                barycentric(a, b, c, {i + 0.5, j + 0.5}, w);
                if (w.x >= 0.0 && w.y >= 0.0 && w.z >= 0.0) {
                    slot = std::int32_t(t);
                    ++result.coveredTexels;
                }
            }
    }

    std::vector<glm::dvec3> palette;
    for (Color c : genome.palette)
        palette.push_back(linearOf(c));
    const glm::dvec3 background = linearOf(genome.background);
    const CpuRenderer marbling(genome);
    const bool soften = genome.bleed > 0.0;
    Image& image = result.image;
    image.width = image.height = n;
    image.rgb.resize(texels * 3);
    std::vector<std::uint8_t> filled(texels, 0);

    // Rows handed out by the one row loop, as the CPU renderer does; a row's samples go through
    // the kernel together.
    RowLoop rowLoop(0, n, settings.threads, control);
    const std::size_t perTexel = pattern.offsets.size();
    const auto worker = [&] {
        std::vector<double> xs(std::size_t(n) * perTexel), ys(xs.size()), zs(xs.size());
        std::vector<int> colors(xs.size());
        // With bleed, soft edges: the kernel's composited linear colours instead of indices.
        std::vector<double> soft(soften ? xs.size() * 3 : 0);
        // Samples beyond a flat design's rectangle (through the UVs): the background.
        std::vector<std::uint8_t> outside(xs.size(), 0);
        std::vector<int> columns;
        for (int j; rowLoop.next(j);) {
            columns.clear();
            std::size_t count = 0;
            for (int i = 0; i < n; ++i) {
                const std::int32_t t = owner[std::size_t(j) * std::size_t(n) + std::size_t(i)];
                if (t < 0) continue;
                columns.push_back(i);
                const std::uint32_t* v = &mesh.indices[std::size_t(t) * 3];
                const glm::dvec2 a = uvOf(v[0]), b = uvOf(v[1]), c = uvOf(v[2]);
                for (const glm::dvec2& offset : pattern.offsets) {
                    glm::dvec3 w;
                    barycentric(a, b, c, {i + 0.5 + offset.x, j + 0.5 + offset.y}, w);
                    // A sample past the triangle's edge is pulled back onto it, so every
                    // sample is a point of the surface (the centre's weights stay exact).
                    if (w.x < 0.0 || w.y < 0.0 || w.z < 0.0) {
                        w = glm::max(w, glm::dvec3(0.0));
                        w /= w.x + w.y + w.z;
                    }
                    glm::dvec3 q;
                    if (throughUvs) {
                        const glm::dvec2 uv = w.x * glm::dvec2(mesh.uvs[v[0]]) +
                                              w.y * glm::dvec2(mesh.uvs[v[1]]) +
                                              w.z * glm::dvec2(mesh.uvs[v[2]]);
                        q = flatOnUvs.designPoint(uv);
                        outside[count] = !flatOnUvs.inside(q);
                    } else {
                        const glm::dvec3 p = w.x * glm::dvec3(mesh.positions[v[0]]) +
                                             w.y * glm::dvec3(mesh.positions[v[1]]) +
                                             w.z * glm::dvec3(mesh.positions[v[2]]);
                        q = placement.designPoint(p);
                    }
                    xs[count] = q.x;
                    ys[count] = q.y;
                    zs[count] = q.z;
                    ++count;
                }
            }
            if (soften)
                marbling.linearColorsAt(xs.data(), ys.data(), zs.data(), count, soft.data());
            else
                marbling.colorIndicesAt(xs.data(), ys.data(), zs.data(), count, colors.data());
            std::size_t k = 0;
            for (int i : columns) {
                glm::dvec3 sum(0.0);
                for (std::size_t s = 0; s < perTexel; ++s, ++k) {
                    const int color = colors[k];
                    const glm::dvec3 seen =
                        outside[k] ? background
                        : soften   ? glm::dvec3(soft[k * 3], soft[k * 3 + 1], soft[k * 3 + 2])
                        : color >= 0 && std::size_t(color) < palette.size() ? palette[std::size_t(color)]
                                                                            : background;
                    sum += pattern.weights[s] * seen;
                }
                std::uint8_t* out = image.row(j) + std::size_t(i) * 3;
                out[0] = encodeSrgb8(std::clamp(sum.x, 0.0, 1.0));
                out[1] = encodeSrgb8(std::clamp(sum.y, 0.0, 1.0));
                out[2] = encodeSrgb8(std::clamp(sum.z, 0.0, 1.0));
                filled[std::size_t(j) * std::size_t(n) + std::size_t(i)] = 1;
            }
            rowLoop.done();
        }
    };
    rowLoop.run(worker);

    // Dilation: each pass gives every empty texel beside a filled one (of 8) their mean, so a
    // texture lookup at a triangle's edge, which blends the texels round it, finds the surface's
    // colours there rather than the background's.
    std::vector<std::uint8_t> next = filled;
    for (int pass = 0; pass < settings.dilation; ++pass) {
        bool any = false;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::size_t at = std::size_t(j) * std::size_t(n) + std::size_t(i);
                if (filled[at]) continue;
                int sum[3] = {0, 0, 0}, count = 0;
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di) {
                        const int x = i + di, y = j + dj;
                        if (x < 0 || y < 0 || x >= n || y >= n) continue;
                        const std::size_t from = std::size_t(y) * std::size_t(n) + std::size_t(x);
                        if (!filled[from]) continue;
                        for (int ch = 0; ch < 3; ++ch)
                            sum[ch] += image.rgb[from * 3 + std::size_t(ch)];
                        ++count;
                    }
                if (count == 0) continue;
                for (int ch = 0; ch < 3; ++ch)
                    image.rgb[at * 3 + std::size_t(ch)] = std::uint8_t((sum[ch] + count / 2) / count);
                next[at] = 1;
                any = true;
            }
        filled = next;
        if (!any) break;
    }
    const std::uint8_t bg[3] = {genome.background.r, genome.background.g, genome.background.b};
    for (std::size_t at = 0; at < texels; ++at)
        if (!filled[at]) std::memcpy(&image.rgb[at * 3], bg, 3);
    return result;
}

// --- Writing ---------------------------------------------------------------------------------

std::vector<std::string> texturedMeshExtensions() {
    return {".glb", ".gltf", ".obj"};
}

namespace {

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) throw RuntimeFailure("cannot read back '" + file.string() + "'");
    return bytes;
}

/// The texture as PNG bytes, by the project's own PNG writer (through a temporary file).
std::string pngBytes(const Image& texture, AtomicFileSet& files, const fs::path& beside) {
    const fs::path temp = files.add(beside).temporary();
    writeImage(texture, temp);
    return readBytes(temp);
}

template <typename T> void append(std::string& buffer, const std::vector<T>& values) {
    buffer.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    while (buffer.size() % 4 != 0)
        buffer.push_back('\0'); // glTF aligns every view to 4 bytes
}

glm::vec3 unitNormal(const MeshData& mesh, std::size_t v) {
    glm::vec3 n = v < mesh.normals.size() ? mesh.normals[v] : glm::vec3(0.0f);
    const float length = glm::length(n);
    return length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

/// The glTF document and its binary buffer; `embeddedPng` is stored in the buffer (GLB) unless
/// empty, else the image is `pngUri`.
std::pair<nlohmann::ordered_json, std::string> gltfDocument(const MeshData& mesh, const std::string& name,
                                                            const std::string& embeddedPng,
                                                            const std::string& pngUri) {
    using Json = nlohmann::ordered_json;
    std::vector<glm::vec3> normals(mesh.positions.size());
    for (std::size_t v = 0; v < normals.size(); ++v)
        normals[v] = unitNormal(mesh, v);
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }

    std::string buffer;
    Json views = Json::array();
    auto view = [&](auto& values, int target) {
        const std::size_t offset = buffer.size();
        append(buffer, values);
        Json v = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(values[0])}};
        if (target) v["target"] = target;
        views.push_back(v);
        return int(views.size()) - 1;
    };
    const int positionView = view(mesh.positions, 34962); // ARRAY_BUFFER
    const int normalView = view(normals, 34962);
    const int uvView = view(mesh.uvs, 34962);
    const int indexView = view(mesh.indices, 34963); // ELEMENT_ARRAY_BUFFER
    const std::size_t vertices = mesh.positions.size();
    Json accessors = Json::array({
        {{"bufferView", positionView},
         {"componentType", 5126},
         {"count", vertices},
         {"type", "VEC3"},
         {"min", {lo.x, lo.y, lo.z}},
         {"max", {hi.x, hi.y, hi.z}}},
        {{"bufferView", normalView}, {"componentType", 5126}, {"count", vertices}, {"type", "VEC3"}},
        {{"bufferView", uvView}, {"componentType", 5126}, {"count", vertices}, {"type", "VEC2"}},
        {{"bufferView", indexView},
         {"componentType", 5125},
         {"count", mesh.indices.size()},
         {"type", "SCALAR"}},
    });
    Json image = {{"name", name}};
    if (!embeddedPng.empty()) {
        const std::size_t offset = buffer.size();
        buffer += embeddedPng;
        while (buffer.size() % 4 != 0)
            buffer.push_back('\0');
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", embeddedPng.size()}});
        image["bufferView"] = int(views.size()) - 1;
        image["mimeType"] = "image/png";
    } else {
        image["uri"] = pngUri;
    }
    Json doc = {
        {"asset", {{"version", "2.0"}, {"generator", "Marbler (marbler bake)"}}},
        {"scene", 0},
        {"scenes", Json::array({{{"nodes", Json::array({0})}}})},
        {"nodes", Json::array({{{"mesh", 0}, {"name", name}}})},
        {"meshes",
         Json::array({{{"name", name},
                       {"primitives",
                        Json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                                      {"indices", 3},
                                      {"material", 0}}})}}})},
        // The marbling is the surface's colour; a stone-like, non-metallic finish.
        {"materials", Json::array({{{"name", name},
                                    {"pbrMetallicRoughness",
                                     {{"baseColorTexture", {{"index", 0}}},
                                      {"metallicFactor", 0.0},
                                      {"roughnessFactor", 0.5}}}}})},
        // Linear filtering with mipmaps, clamped: the dilated gutters are what the edges blend with.
        {"samplers",
         Json::array({{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 33071}, {"wrapT", 33071}}})},
        {"textures", Json::array({{{"sampler", 0}, {"source", 0}}})},
        {"images", Json::array({image})},
        {"buffers", Json::array({{{"byteLength", buffer.size()}}})},
        {"bufferViews", views},
        {"accessors", accessors},
    };
    return {doc, buffer};
}

void putU32(std::string& out, std::uint32_t value) {
    for (int k = 0; k < 4; ++k)
        out.push_back(char((value >> (8 * k)) & 0xff));
}

/// A number for OBJ text: enough digits to give the float back exactly.
std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(value));
    return text;
}

} // namespace

std::vector<fs::path> writeTexturedMesh(const MeshData& mesh, const Image& texture, const fs::path& file,
                                        const std::string& name) {
    const std::string extension = lowerExtension(file);
    if (extension != ".glb" && extension != ".gltf" && extension != ".obj")
        throw InputError("'" + file.string() + "': unknown mesh format '" + extension +
                         "' (use .glb, .gltf or .obj)");
    if (!hasUsableUvs(mesh)) throw InputError("the mesh has no texture coordinates to write");
    if (mesh.indices.size() % 3 != 0 || mesh.indices.empty())
        throw InputError("the mesh has no triangles to write");

    std::error_code ec;
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    if (!fs::is_directory(folder, ec))
        throw RuntimeFailure("cannot write '" + file.string() + "': no folder '" + folder.string() + "'");
    // OBJ and MTL names end at white space.
    std::string objName = name.empty() ? "marbled" : name;
    for (char& c : objName)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';

    AtomicFileSet files;
    fs::path pngFile = file;
    pngFile.replace_extension(".png");
    const std::string pngName = pngFile.filename().string();

    if (extension == ".glb") {
        const std::string png = pngBytes(texture, files, pngFile);
        auto [doc, bin] = gltfDocument(mesh, name, png, "");
        std::string json = doc.dump();
        while (json.size() % 4 != 0)
            json.push_back(' '); // the JSON chunk is padded with spaces
        std::string glb;
        putU32(glb, 0x46546C67); // "glTF"
        putU32(glb, 2);
        putU32(glb, std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
        putU32(glb, std::uint32_t(json.size()));
        putU32(glb, 0x4E4F534A); // "JSON"
        glb += json;
        putU32(glb, std::uint32_t(bin.size()));
        putU32(glb, 0x004E4942); // "BIN\0"
        glb += bin;
        // The PNG's temporary file (in `files`, never committed) served only to encode it.
        AtomicFileSet onlyGlb;
        onlyGlb.add(file).write(glb);
        return onlyGlb.commit();
    }

    if (extension == ".gltf") {
        fs::path binFile = file;
        binFile.replace_extension(".bin");
        writeImage(texture, files.add(pngFile).temporary());
        auto [doc, bin] = gltfDocument(mesh, name, "", pngName);
        doc["buffers"][0]["uri"] = binFile.filename().string();
        files.add(binFile).write(bin);
        files.add(file).write(doc.dump(2) + "\n");
        return files.commit();
    }

    // OBJ: v/vt/vn per vertex (vt's v counts upwards), one material whose diffuse map is the PNG.
    fs::path mtlFile = file;
    mtlFile.replace_extension(".mtl");
    writeImage(texture, files.add(pngFile).temporary());
    files.add(mtlFile).write("# Marbler (marbler bake)\nnewmtl " + objName +
                             "\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nillum 1\nmap_Kd " + pngName + "\n");
    std::string obj =
        "# Marbler (marbler bake)\nmtllib " + mtlFile.filename().string() + "\no " + objName + "\n";
    obj.reserve(mesh.positions.size() * 120 + mesh.indices.size() * 12);
    for (const glm::vec3& p : mesh.positions)
        obj += "v " + number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
    for (const glm::vec2& uv : mesh.uvs)
        obj += "vt " + number(uv.x) + " " + number(1.0f - uv.y) + "\n";
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 n = unitNormal(mesh, v);
        obj += "vn " + number(n.x) + " " + number(n.y) + " " + number(n.z) + "\n";
    }
    obj += "usemtl " + objName + "\n";
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        obj += "f";
        for (int k = 0; k < 3; ++k) {
            const std::string index = std::to_string(mesh.indices[t + std::size_t(k)] + 1);
            obj += " " + index + "/" + index + "/" + index;
        }
        obj += "\n";
    }
    files.add(file).write(obj);
    return files.commit();
}

} // namespace marbler
