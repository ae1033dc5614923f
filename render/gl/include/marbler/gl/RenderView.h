#pragma once
/// One "render this view" request: what a view shows (a flat design, a cross-section of a solid,
/// or a solid on an object seen from an orbit camera), at what size and antialiasing, and on
/// which back end (gl::chooseBackend's decision). The command line (`render --gpu`, `--mesh`),
/// the window's render service and the large view's export each build one and hand it to
/// renderView, so the choice between the GL shaders, the CPU kernel and the hybrid object path
/// is made in one place.
///
/// The request itself is plain data (no GL types), so the `marbler` executable can build one and
/// pass it to the window module (app/WindowModule.h).

#include "marbler/CpuRenderer.h"
#include "marbler/Genome.h"
#include "marbler/Sampling.h"
#include "marbler/gl/GlRenderer.h"

#include <optional>

namespace marbler::gl {

/// A view to render.
struct ViewRequest {
    /// A flat design, or a solid's cross-section (`raster.slice`): the size, antialiasing,
    /// region and threads. Ignored when `object` is set.
    RenderSettings raster;
    /// A solid on an object (its size, mesh, camera, zoom, supersampling and cut).
    std::optional<MeshSettings> object;
    /// The back end (BackendChoice::useGl): the GL shaders, or the CPU kernel. On the CPU an
    /// object is rasterised by GL where there is a renderer and only coloured by the kernel
    /// (renderMeshHybrid), else rasterised on the CPU too (renderObjectOnCpu).
    bool useGl = false;
};

/// Renders `request`. `gl` is a GL renderer of the calling thread: needed for the GL back end,
/// used for an object's rasterising where given, and may be null otherwise. `prepared` is the
/// genome already prepared for the CPU kernel (CpuRenderer), reused across renders of one
/// design; without it one is made. Throws InputError for bad settings, RuntimeFailure when GL is
/// needed and missing or the driver fails, Cancelled when `control` cancels (CPU work only).
Image renderView(const Genome& genome, const ViewRequest& request, GlRenderer* gl,
                 const RenderControl* control = nullptr, const CpuRenderer* prepared = nullptr);

} // namespace marbler::gl
