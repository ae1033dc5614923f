#pragma once
/// The OpenGL shader back end: renders genomes offscreen (framebuffer objects on a
/// QOffscreenSurface), 2D designs, 3D slices, and solid and flat genomes on meshes. Qt's OpenGL types stay
/// in the implementation (pimpl), so users of this header need only QtGui's QImage-free API.

#include "marbler/Genome.h"
#include "marbler/Mesh.h"
#include "marbler/ObjectView.h"
#include "marbler/Sampling.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marbler::gl {

// The object render's plain data (CutPlane, MeshSettings, MeshGBuffer) lives with the CPU's
// object path in marbler/ObjectView.h; these names keep the GL back end's spelling.
using marbler::CutPlane;
using marbler::MeshGBuffer;
using marbler::MeshSettings;

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

    /// Renders a design on an object, as the CPU's object path does (ObjectView.h): a solid
    /// genome carved from its design box, a flat one laid on the object's own texture
    /// coordinates (looked up at every sample through the inverse maps). Throws InputError for
    /// a mesh that cannot be loaded, or a flat genome on a mesh without texture coordinates.
    Image renderMesh(const Genome& genome, const MeshSettings& settings);

    /// Only the rasterising pass of renderMesh (same checks and throws), read back, with the
    /// texture coordinates for a flat genome; see shadeMeshOnCpu (HybridMesh.h) for the other
    /// pass.
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
