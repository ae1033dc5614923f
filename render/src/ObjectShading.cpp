#include "marbler/ObjectView.h"

#include "marbler/Bake.h"
#include "marbler/Error.h"
#include "marbler/Threads.h"
#include "marbler/Tools.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace marbler {
namespace {

/// mesh.frag's shade(): Lambert plus a Blinn highlight, over an ambient floor.
glm::dvec3 shade(const glm::dvec3& albedo, const glm::dvec3& position, glm::dvec3 normal,
                 const MeshGBuffer& g) {
    const double length = glm::length(normal);
    if (length > 0.0) normal /= length;
    const glm::dvec3 view = glm::normalize(g.eye - position);
    if (glm::dot(normal, view) < 0.0) normal = -normal;
    const double diffuse = std::max(glm::dot(normal, g.light), 0.0);
    const glm::dvec3 halfway = glm::normalize(g.light + view);
    const double specular = diffuse > 0.0 ? std::pow(std::max(glm::dot(normal, halfway), 0.0), 48.0) : 0.0;
    return albedo * (0.22 + 0.78 * diffuse) + glm::dvec3(0.12 * specular);
}

} // namespace

Image shadeMeshOnCpu(const Genome& genome, const MeshGBuffer& g, const MeshSettings& settings,
                     const RenderControl* control) {
    const bool flat = genome.dimension == 2;
    const int n = g.supersample;
    const int gw = g.width * n, gh = g.height * n;
    const std::size_t samples = std::size_t(gw) * std::size_t(gh);
    if (n < 1 || g.positions.size() != samples * 4 || g.normals.size() != samples * 4 ||
        (flat && g.uvs.size() != samples * 2))
        throw InputError("the G-buffer does not match its size");
    const FlatOnUvs flatOnUvs(genome);

    for (const PreparedOp& op : prepare(genome))
        if (op.color >= int(genome.palette.size()))
            throw InputError("colour index " + std::to_string(op.color) + " is outside the palette of " +
                             std::to_string(genome.palette.size()) + " inks");
    std::vector<glm::dvec3> palette;
    for (Color c : genome.palette)
        palette.push_back(linearOf(c));
    const glm::dvec3 background = linearOf(genome.background);
    const glm::dvec3 clear = linearOf(settings.clearColor);
    const CpuRenderer marbling(genome);
    // Soft edges (bleed) and a flat design's source image give colours, not palette indices.
    const bool soften = genome.bleed > 0.0 || (flat && genome.source);

    Image image;
    image.width = g.width;
    image.height = g.height;
    image.rgb.resize(std::size_t(g.width) * std::size_t(g.height) * 3);

    // Output rows are handed out by the one row loop, as the CPU renderer does. Each row's
    // covered samples go through the kernel a tile at a time; the uncovered ones (most of the
    // frame around an object) cost nothing.
    RowLoop rowLoop(0, g.height, settings.threads, control);
    const auto worker = [&] {
        std::vector<double> xs(std::size_t(g.width) * std::size_t(n * n));
        std::vector<double> ys(xs.size()), zs(xs.size());
        std::vector<int> colors(std::size_t(g.width) * std::size_t(n * n), -1);
        // With bleed, soft edges: the kernel's composited linear colours instead of indices.
        std::vector<double> soft(soften ? colors.size() * 3 : 0);
        std::vector<std::size_t> sampleOf(colors.size());
        std::vector<char> outside(flat ? colors.size() : 0);
        std::vector<glm::dvec3> sum(std::size_t(g.width));
        std::vector<int> coveredIn(std::size_t(g.width));
        for (int y; rowLoop.next(y);) {
            // GL's first row is the bottom of the view.
            const int glRow = g.height - 1 - y;
            int covered = 0;
            for (int x = 0; x < g.width; ++x)
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i) {
                        const std::size_t s =
                            std::size_t(glRow * n + j) * std::size_t(gw) + std::size_t(x * n + i);
                        if (g.positions[s * 4 + 3] > 0.0f) sampleOf[std::size_t(covered++)] = s;
                    }
            for (int k = 0; k < covered; ++k) {
                const std::size_t s = sampleOf[std::size_t(k)];
                glm::dvec3 q;
                if (flat) {
                    // The design point at the sample's texture coordinates.
                    q = flatOnUvs.designPoint({double(g.uvs[s * 2]), double(g.uvs[s * 2 + 1])});
                    outside[std::size_t(k)] = !flatOnUvs.inside(q);
                } else {
                    const float* p = &g.positions[s * 4];
                    q = g.reference + glm::dvec3(p[0], p[1], p[2]);
                }
                xs[std::size_t(k)] = q.x;
                ys[std::size_t(k)] = q.y;
                zs[std::size_t(k)] = q.z;
            }
            if (soften)
                marbling.linearColorsAt(xs.data(), ys.data(), zs.data(), std::size_t(covered), soft.data());
            else
                marbling.colorIndicesAt(xs.data(), ys.data(), zs.data(), std::size_t(covered), colors.data());
            std::fill(sum.begin(), sum.end(), glm::dvec3(0.0));
            std::fill(coveredIn.begin(), coveredIn.end(), 0);
            for (int k = 0; k < covered; ++k) {
                const std::size_t s = sampleOf[std::size_t(k)];
                const int c = colors[std::size_t(k)];
                const glm::dvec3 albedo =
                    flat && outside[std::size_t(k)] ? background
                    : soften ? glm::dvec3(soft[std::size_t(k) * 3], soft[std::size_t(k) * 3 + 1],
                                          soft[std::size_t(k) * 3 + 2])
                    : c >= 0 ? palette[std::size_t(c)]
                             : background;
                const float* p = &g.positions[s * 4];
                const float* nv = &g.normals[s * 4];
                const auto x = std::size_t((s % std::size_t(gw)) / std::size_t(n));
                sum[x] += settings.lighting ? shade(albedo, glm::dvec3(p[0], p[1], p[2]),
                                                    glm::dvec3(nv[0], nv[1], nv[2]), g)
                                            : albedo;
                ++coveredIn[x];
            }
            // The samples the object does not cover show the clear colour.
            std::uint8_t* out = image.row(y);
            const double weight = 1.0 / double(n * n);
            for (int x = 0; x < g.width; ++x) {
                const glm::dvec3 linear =
                    (sum[std::size_t(x)] + double(n * n - coveredIn[std::size_t(x)]) * clear) * weight;
                out[x * 3 + 0] = encodeSrgb8(std::clamp(linear.x, 0.0, 1.0));
                out[x * 3 + 1] = encodeSrgb8(std::clamp(linear.y, 0.0, 1.0));
                out[x * 3 + 2] = encodeSrgb8(std::clamp(linear.z, 0.0, 1.0));
            }
            rowLoop.done();
        }
    };
    rowLoop.run(worker);
    return image;
}

} // namespace marbler
