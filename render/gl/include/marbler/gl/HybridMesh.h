#pragma once
/// A solid design on an object with the CPU kernel doing the marbling: GL (even a software
/// rasteriser) rasterises only the G-buffer of positions and normals, which is cheap, and the
/// kernel evaluates the colour rule at those points on every core, which is the expensive part
/// and where a software rasteriser is several times slower than the kernel.

#include "marbler/CpuRenderer.h"
#include "marbler/gl/GlRenderer.h"

namespace marbler::gl {

/// The second pass of a mesh render on the CPU: the colour rule at each covered sample of
/// `gbuffer`, lit as the GL shading pass lights it (unless `settings.lighting` is off), averaged
/// in linear light with `settings.clearColor` where the object does not cover a sample. Agrees
/// with GlRenderer::renderMesh up to the GPU's float rounding. Runs on every core. Throws
/// InputError for a colour index outside the palette, Cancelled when cancelled.
Image shadeMeshOnCpu(const Genome& genome, const MeshGBuffer& gbuffer, const MeshSettings& settings,
                     const RenderControl* control = nullptr);

/// Both passes: renderer.renderMeshGBuffer, then shadeMeshOnCpu.
Image renderMeshHybrid(GlRenderer& renderer, const Genome& genome, const MeshSettings& settings,
                       const RenderControl* control = nullptr);

} // namespace marbler::gl
