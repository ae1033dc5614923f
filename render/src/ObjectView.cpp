#include "marbler/ObjectView.h"

#include "marbler/Error.h"
#include "marbler/Threads.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace marbler {
namespace {

/// A framed object spans this share of the view's width or height (the rest is the margin).
constexpr double FrameFill = 0.92;

/// Sample rows a worker rasterises at a time.
constexpr int BandRows = 16;

/// A vertex after the camera: window coordinates (samples, y up as GL counts), depth, and 1/w
/// for perspective-correct interpolation.
struct ScreenVertex {
    double x = 0.0, y = 0.0, z = 0.0, invW = 0.0;
};

} // namespace

void checkMeshSettings(const MeshSettings& settings, glm::dvec3& cutNormal, double& cutOffset) {
    if (settings.width < 1 || settings.height < 1 || settings.width > MaxMeshSide ||
        settings.height > MaxMeshSide)
        throw InputError("mesh render size must be 1 to " + std::to_string(MaxMeshSide) +
                         " pixels a side (got " + std::to_string(settings.width) + "x" +
                         std::to_string(settings.height) + ")");
    int n = settings.supersample;
    if (n != 1 && n != 3 && n != 5)
        throw InputError("supersample must be 1, 3 or 5 (got " + std::to_string(n) + ")");
    if (!(settings.fovY > 1.0 && settings.fovY < 170.0))
        throw InputError("the field of view must lie between 1 and 170 degrees");
    if (!std::isfinite(settings.yaw) || !std::isfinite(settings.pitch) || !(settings.distance >= 0.0) ||
        !std::isfinite(settings.distance) || !(settings.zoom > 0.0) || !std::isfinite(settings.zoom))
        throw InputError(
            "the camera needs finite yaw and pitch, a distance of 0 or more and a positive zoom");
    cutNormal = glm::dvec3(0.0);
    cutOffset = 0.0;
    if (settings.cut) {
        double len = glm::length(settings.cut->normal);
        if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(settings.cut->offset))
            throw InputError("the cutting plane needs a finite, non-zero normal");
        cutNormal = settings.cut->normal / len;
        cutOffset = settings.cut->offset / len;
    }
}

FittedMesh fitMesh(const MeshData& mesh) {
    FittedMesh fitted;
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    fitted.boxSize = hi - lo;
    fitted.centre = 0.5 * (lo + hi);
    fitted.points.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) {
        fitted.points.push_back(glm::dvec3(p) - fitted.centre);
        fitted.radius = std::max(fitted.radius, glm::length(fitted.points.back()));
    }
    return fitted;
}

glm::dvec3 objectBox(const Genome& genome) {
    return genome.dimension == 2 ? glm::dvec3(std::max(genome.size.x, genome.size.y)) : genome.size;
}

bool hasOwnUvs(const MeshData& mesh) {
    return !mesh.uvsArePatches && !mesh.uvs.empty() && mesh.uvs.size() == mesh.positions.size();
}

void checkFlatDesignFits(const Genome& genome, bool meshHasOwnUvs, const std::string& meshName) {
    if (genome.dimension != 2 || meshHasOwnUvs) return;
    throw InputError("'" + meshName +
                     "' has no texture coordinates, and a flat design lies on an object's own UVs: "
                     "export the mesh with UVs (in Blender, unwrap it and export OBJ or glTF with UV "
                     "coordinates), choose a built-in object (" +
                     builtinMeshList() + "), or show a solid design on it");
}

ObjectCamera frameObject(const glm::dvec3& designSize, const FittedMesh& mesh, const MeshSettings& settings) {
    // Fit: the largest uniform scale that keeps the object inside the design box, centred in it.
    // Its positions are then design coordinates, relative to the box centre (the reference).
    ObjectCamera view;
    view.reference = 0.5 * designSize;
    double scale = std::numeric_limits<double>::max();
    for (int k = 0; k < 3; ++k)
        if (mesh.boxSize[k] > 0.0) scale = std::min(scale, designSize[k] / mesh.boxSize[k]);
    if (scale == std::numeric_limits<double>::max()) scale = 1.0;
    view.scale = scale;
    double radius = mesh.radius * scale;

    double yaw = glm::radians(settings.yaw), pitch = glm::radians(settings.pitch);
    glm::dvec3 toEye(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    glm::dvec3 up = std::abs(toEye.y) > 0.999 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    glm::dvec3 forward = -toEye;
    glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    glm::dvec3 cameraUp = glm::cross(right, forward);
    const double aspect = double(settings.width) / settings.height;
    const double tanY = std::tan(glm::radians(settings.fovY) / 2.0), tanX = tanY * aspect;
    double eyeDistance = settings.distance * radius;
    // Clip-space shift and scale after the projection: the framing and the zoom, an off-centre
    // frustum that leaves the eye (and so the shading) where it is.
    double frameScale = settings.zoom, frameX = 0.0, frameY = 0.0;
    if (!(settings.distance > 0.0)) {
        // Framed. First the nearest eye (looking at the centre) that sees every vertex inside
        // the margin: a vertex at (x, y) across the view and z towards the eye projects to
        // x / ((D - z) tanX), so it fits when D >= z + |x| / (FrameFill tanX), and likewise for y.
        eyeDistance = 0.0;
        for (const glm::dvec3& p : mesh.points) {
            const glm::dvec3 q = p * scale;
            const double z = glm::dot(q, toEye);
            eyeDistance = std::max({eyeDistance, z + std::abs(glm::dot(q, right)) / (FrameFill * tanX),
                                    z + std::abs(glm::dot(q, cameraUp)) / (FrameFill * tanY)});
        }
        // Never inside the bounding sphere, where the near plane would cut the object.
        eyeDistance = std::max(eyeDistance, 1.05 * radius);
        // Then the object's projected bounds, centred and scaled to span FrameFill of the
        // view's width or height: seen from aside, an object reaches further to one side.
        glm::dvec2 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
        for (const glm::dvec3& p : mesh.points) {
            const glm::dvec3 q = p * scale;
            const double depth = eyeDistance - glm::dot(q, toEye);
            const glm::dvec2 ndc(glm::dot(q, right) / (depth * tanX), glm::dot(q, cameraUp) / (depth * tanY));
            lo = glm::min(lo, ndc);
            hi = glm::max(hi, ndc);
        }
        const glm::dvec2 half = 0.5 * (hi - lo), middle = 0.5 * (hi + lo);
        if (half.x > 0.0 || half.y > 0.0) {
            frameScale *= FrameFill / std::max(half.x, half.y);
            frameX = middle.x;
            frameY = middle.y;
        }
    }
    view.eye = toEye * eyeDistance;
    double nearPlane = std::max(eyeDistance - 1.01 * radius, 1e-3 * radius);
    double farPlane = eyeDistance + 1.01 * radius;
    glm::dmat4 lookAt = glm::lookAt(view.eye, glm::dvec3(0.0), up);
    glm::dmat4 frame(1.0); // x' = s (x - cx w), y' = s (y - cy w) in clip space
    frame[0][0] = frame[1][1] = frameScale;
    frame[3][0] = -frameScale * frameX;
    frame[3][1] = -frameScale * frameY;
    glm::dmat4 projection =
        frame * glm::perspective(glm::radians(settings.fovY), aspect, nearPlane, farPlane);
    view.viewProjection = projection * lookAt;
    // A key light above and to the left of the camera.
    view.light = glm::normalize(toEye * 0.9 + cameraUp * 0.6 - right * 0.45);
    return view;
}

MeshGBuffer rasterizeObject(const Genome& genome, const MeshData& mesh, const MeshSettings& settings,
                            const RenderControl* control) {
    glm::dvec3 cutNormal;
    double cutOffset = 0.0;
    checkMeshSettings(settings, cutNormal, cutOffset);
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) throw InputError("the object has no triangles");
    for (std::uint32_t index : mesh.indices)
        if (index >= mesh.positions.size())
            throw InputError("the object's triangles name a vertex it does not have");
    const bool flat = genome.dimension == 2;
    checkFlatDesignFits(genome, hasOwnUvs(mesh), settings.mesh);
    const FittedMesh fitted = fitMesh(mesh);
    const ObjectCamera view = frameObject(objectBox(genome), fitted, settings);
    const int n = settings.supersample;
    const int gw = settings.width * n, gh = settings.height * n;

    MeshGBuffer result;
    result.width = settings.width;
    result.height = settings.height;
    result.supersample = n;
    result.reference = view.reference;
    result.eye = view.eye;
    result.light = view.light;
    const std::size_t samples = std::size_t(gw) * std::size_t(gh);
    result.positions.assign(samples * 4, 0.0f);
    result.normals.assign(samples * 4, 0.0f);
    if (flat) result.uvs.assign(samples * 2, 0.0f);

    // The vertices as the G-buffer pass takes them: design coordinates about the box centre,
    // then the camera, then window coordinates in samples (GL's: x right, y up).
    std::vector<glm::dvec3> design(fitted.points.size()), normals(fitted.points.size());
    std::vector<ScreenVertex> screen(fitted.points.size());
    for (std::size_t v = 0; v < fitted.points.size(); ++v) {
        design[v] = fitted.points[v] * view.scale;
        const glm::dvec3 normal(mesh.normals.size() > v ? mesh.normals[v] : glm::vec3(0.0f));
        const double length = glm::length(normal);
        normals[v] = length > 0.0 ? normal / length : glm::dvec3(0, 1, 0);
        const glm::dvec4 clip = view.viewProjection * glm::dvec4(design[v], 1.0);
        // The eye stays outside the bounding sphere and the near plane in front of it, so w > 0.
        const double invW = 1.0 / clip.w;
        screen[v] = {(clip.x * invW * 0.5 + 0.5) * gw, (clip.y * invW * 0.5 + 0.5) * gh, clip.z * invW, invW};
    }
    const glm::dvec3 cutRelative = cutNormal;
    const double cutOffsetRelative = cutOffset - glm::dot(cutNormal, view.reference);
    const double eyeSide = glm::dot(cutNormal, view.eye) - cutOffsetRelative;

    // Bands of sample rows, each worker owning its band's depth and G-buffer rows. Each
    // triangle is binned once to the bands its rows reach, in the mesh's order (the order the
    // depth test breaks ties in), so a band visits only its own triangles.
    const int bands = (gh + BandRows - 1) / BandRows;
    const std::size_t triangles = mesh.indices.size() / 3;
    std::vector<std::size_t> binStart(std::size_t(bands) + 1, 0);
    std::vector<std::uint32_t> binned;
    {
        std::vector<std::pair<int, int>> reach(triangles, {0, -1}); // first and last band
        for (std::size_t t = 0; t < triangles; ++t) {
            const ScreenVertex &a = screen[mesh.indices[t * 3]], &b = screen[mesh.indices[t * 3 + 1]],
                               &c = screen[mesh.indices[t * 3 + 2]];
            const double minY = std::min({a.y, b.y, c.y}), maxY = std::max({a.y, b.y, c.y});
            // Samples sit at half-integers: rows j with j + 0.5 in [minY, maxY].
            const double first = std::max(0.0, std::ceil(minY - 0.5));
            const double last = std::min(double(gh - 1), std::floor(maxY - 0.5));
            if (!(first <= last)) continue;
            reach[t] = {int(first) / BandRows, int(last) / BandRows};
            for (int band = reach[t].first; band <= reach[t].second; ++band)
                ++binStart[std::size_t(band) + 1];
        }
        for (int band = 0; band < bands; ++band)
            binStart[std::size_t(band) + 1] += binStart[std::size_t(band)];
        binned.resize(binStart.back());
        std::vector<std::size_t> fill(binStart.begin(), binStart.end() - 1);
        for (std::size_t t = 0; t < triangles; ++t)
            for (int band = reach[t].first; band <= reach[t].second; ++band)
                binned[fill[std::size_t(band)]++] = std::uint32_t(t);
    }
    RowLoop rowLoop(0, bands, settings.threads, control);
    rowLoop.run([&] {
        std::vector<double> depth(std::size_t(gw) * BandRows);
        for (int band; rowLoop.next(band);) {
            const int y0 = band * BandRows, y1 = std::min(gh, y0 + BandRows);
            std::fill(depth.begin(), depth.end(), std::numeric_limits<double>::infinity());
            for (std::size_t k = binStart[std::size_t(band)]; k < binStart[std::size_t(band) + 1]; ++k) {
                const std::size_t t = binned[k];
                const std::uint32_t i0 = mesh.indices[t * 3], i1 = mesh.indices[t * 3 + 1],
                                    i2 = mesh.indices[t * 3 + 2];
                const ScreenVertex &a = screen[i0], &b = screen[i1], &c = screen[i2];
                const double minY = std::min({a.y, b.y, c.y}), maxY = std::max({a.y, b.y, c.y});
                // Samples sit at half-integers: rows j with j + 0.5 in [minY, maxY].
                const int rowFirst = std::max(y0, int(std::ceil(minY - 0.5)));
                const int rowLast = std::min(y1 - 1, int(std::floor(maxY - 0.5)));
                if (rowFirst > rowLast) continue;
                const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
                if (!(std::abs(area) > 0.0)) continue;
                // Counter-clockwise in window space (y up) faces the camera, as GL's default.
                const bool front = area > 0.0;
                const double minX = std::min({a.x, b.x, c.x}), maxX = std::max({a.x, b.x, c.x});
                const int colFirst = std::max(0, int(std::ceil(minX - 0.5)));
                const int colLast = std::min(gw - 1, int(std::floor(maxX - 0.5)));
                for (int j = rowFirst; j <= rowLast; ++j) {
                    const double sy = j + 0.5;
                    for (int i = colFirst; i <= colLast; ++i) {
                        const double sx = i + 0.5;
                        // Edge functions: the barycentric weights times the area.
                        double w0 = (c.x - b.x) * (sy - b.y) - (c.y - b.y) * (sx - b.x);
                        double w1 = (a.x - c.x) * (sy - c.y) - (a.y - c.y) * (sx - c.x);
                        double w2 = (b.x - a.x) * (sy - a.y) - (b.y - a.y) * (sx - a.x);
                        if (front ? (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) : (w0 > 0.0 || w1 > 0.0 || w2 > 0.0))
                            continue;
                        w0 /= area;
                        w1 /= area;
                        w2 /= area;
                        const double z = w0 * a.z + w1 * b.z + w2 * c.z;
                        double& stored = depth[std::size_t(j - y0) * std::size_t(gw) + std::size_t(i)];
                        if (!(z < stored)) continue;
                        // Perspective-correct weights for the attributes.
                        const double p0 = w0 * a.invW, p1 = w1 * b.invW, p2 = w2 * c.invW;
                        const double sum = p0 + p1 + p2;
                        const glm::dvec3 position =
                            (p0 * design[i0] + p1 * design[i1] + p2 * design[i2]) / sum;
                        if (settings.cut && glm::dot(cutRelative, position) > cutOffsetRelative) continue;
                        stored = z;
                        glm::dvec3 at = position;
                        glm::dvec3 normal =
                            glm::normalize(p0 * normals[i0] + p1 * normals[i1] + p2 * normals[i2]);
                        if (!front) {
                            if (settings.cut && eyeSide > 0.0) {
                                // Seen through the cut: the first solid point on this ray lies on
                                // the plane, so the cap shows the solid's colour there.
                                const glm::dvec3 ray = position - view.eye;
                                at = view.eye + (-eyeSide / glm::dot(cutRelative, ray)) * ray;
                                normal = cutRelative;
                            } else {
                                normal = -normal; // the inside of an open mesh
                            }
                        }
                        const std::size_t s = (std::size_t(j) * std::size_t(gw) + std::size_t(i)) * 4;
                        result.positions[s + 0] = float(at.x);
                        result.positions[s + 1] = float(at.y);
                        result.positions[s + 2] = float(at.z);
                        result.positions[s + 3] = 1.0f;
                        result.normals[s + 0] = float(normal.x);
                        result.normals[s + 1] = float(normal.y);
                        result.normals[s + 2] = float(normal.z);
                        result.normals[s + 3] = 0.0f;
                        if (flat) {
                            const glm::dvec2 uv =
                                (p0 * glm::dvec2(mesh.uvs[i0]) + p1 * glm::dvec2(mesh.uvs[i1]) +
                                 p2 * glm::dvec2(mesh.uvs[i2])) /
                                sum;
                            result.uvs[s / 2] = float(uv.x);
                            result.uvs[s / 2 + 1] = float(uv.y);
                        }
                    }
                }
            }
            rowLoop.done();
        }
    });
    return result;
}

Image renderObjectOnCpu(const Genome& genome, const MeshData& mesh, const MeshSettings& settings,
                        const RenderControl* control) {
    // The rasterising is quick beside the colouring: it is cancelled with it, and the progress
    // reported is the colouring's, so it runs once from 0 to 1.
    RenderControl rasterControl;
    if (control) rasterControl.cancel = control->cancel;
    return shadeMeshOnCpu(genome, rasterizeObject(genome, mesh, settings, &rasterControl), settings, control);
}

} // namespace marbler
