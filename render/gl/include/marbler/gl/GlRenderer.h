#pragma once
/// The OpenGL shader back end: renders genomes offscreen (framebuffer objects on a
/// QOffscreenSurface), 2D designs, 3D slices and solid genomes on meshes. Qt's OpenGL types stay
/// in the implementation (pimpl), so users of this header need only QtGui's QImage-free API.

#include "marbler/Genome.h"
#include "marbler/Mesh.h"
#include "marbler/Sampling.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marbler::gl {

/// A cutting plane through a solid object: points with dot(normal, p) > offset (in the fitted
/// design box) are cut away, showing the marbled inside.
struct CutPlane {
    glm::dvec3 normal{0.0, 0.0, 1.0};
    double offset = 0.0;
};

/// How a solid genome is shown on an object.
struct MeshSettings {
    int width = 512, height = 512;
    std::string mesh = DefaultMesh; ///< a built-in name (builtinMeshNames()) or a file path
    /// Orbit camera about the design box centre, +y up: the eye sits at
    /// centre + D * (cos pitch sin yaw, sin pitch, cos pitch cos yaw), looking at the centre.
    double yaw = 30.0, pitch = 20.0; ///< degrees
    /// D in units of the fitted object's bounding radius about the box centre. 0 (the default):
    /// framed, so the object fills the view at any angle and aspect: D is the nearest distance
    /// that keeps every vertex in view, and the view is then shifted and scaled (an off-centre
    /// frustum) so the object's projected bounds are centred and span 92 % of the view's width
    /// or height.
    double distance = 0.0;
    double fovY = 50.0; ///< vertical field of view before the framing and the zoom, degrees
    /// Magnification of the image about the view's centre (the framed object's centre), by
    /// narrowing the frustum: the eye stays where it is, outside the object.
    double zoom = 1.0;
    bool lighting = true; ///< false: the marbling's own colours, unlit (tests, flat previews)
    int supersample = 3;  ///< 1, 3 or 5 (n x n)
    std::optional<CutPlane> cut;
    Color clearColor{0x2b, 0x2b, 0x2b};
    int threads = 0; ///< CPU workers when the CPU shades the samples (renderMeshHybrid); 0: every core
};

/// The first pass of a mesh render, read back: per sample of the n x n supersampled raster
/// (width * n by height * n, rows bottom to top as GL reads them), where the object is seen, for a caller
/// that colours the samples itself (the CPU kernel, where the GL is a software rasteriser).
struct MeshGBuffer {
    int width = 0, height = 0; ///< the output raster
    int supersample = 1;       ///< n
    /// 4 floats a sample: the design point relative to `reference`, and w = 1 where the object
    /// covers the sample (0: the clear colour).
    std::vector<float> positions;
    /// 4 floats a sample: the unit normal facing the way the GL shading pass takes it, w = 0.
    std::vector<float> normals;
    glm::dvec3 reference{0.0}; ///< the design box centre
    glm::dvec3 eye{0.0};       ///< the camera, relative to `reference`
    glm::dvec3 light{0.0};     ///< unit direction towards the key light
};

/// An offscreen GL renderer. Owns a GL context, current on the thread that created it; use it
/// from that thread only.
///
/// Lifetime: destroy every renderer before the QGuiApplication it runs under (an application
/// that makes its own QGuiApplication must reset its renderers first). Where no
/// QGuiApplication exists, the first renderer (or available()) makes one itself, never
/// destroys it, and installs a message handler that keeps Qt's warnings off stderr (set
/// MARBLER_QT_MESSAGES=1 to see them). Renderers still alive at exit (held in statics) are torn
/// down by an exit handler that runs before the driver's own, so the process exits cleanly; a
/// renderer must not be used after exit() has begun.
class GlRenderer {
public:
    /// Creates an offscreen OpenGL 4.3+ core context. Throws RuntimeFailure when none can be made
    /// (no display, no driver) with the reason.
    GlRenderer();
    ~GlRenderer();
    GlRenderer(const GlRenderer&) = delete;
    GlRenderer& operator=(const GlRenderer&) = delete;

    /// Whether an offscreen context can be made here (tries once, caches the answer).
    static bool available(std::string* reason = nullptr);

    /// Renders a 2D genome or a slice of a 3D one, exactly as the CPU renderer samples it.
    /// Outputs larger than the GPU's framebuffer limit are rendered in tiles.
    /// Throws InputError for bad settings, RuntimeFailure for GL failures.
    Image render(const Genome& genome, const RenderSettings& settings);

    /// Renders a solid genome on an object fitted into its design box. Throws InputError for a
    /// 2D genome or a mesh that cannot be loaded.
    Image renderMesh(const Genome& genome, const MeshSettings& settings);

    /// Only the rasterising pass of renderMesh (same checks and throws), read back; see
    /// shadeMeshOnCpu (HybridMesh.h) for the other pass.
    MeshGBuffer renderMeshGBuffer(const Genome& genome, const MeshSettings& settings);

    /// The driver's renderer string (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)").
    std::string rendererName() const;

    /// The GL version the context got, e.g. "4.5".
    std::string glVersion() const;

    /// Compiles and links a program from GLSL sources (after `#include` expansion against the
    /// shipped shader files) and discards it: for tests and shader development. Throws
    /// RuntimeFailure carrying the numbered assembled source and the driver's log.
    void checkProgram(const std::string& vertexSource, const std::string& fragmentSource);

    /// Blocks until the GPU has finished every command (glFinish), for benchmarks.
    void finish();

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace marbler::gl
