#pragma once
/// A design on an object with the CPU kernel doing the marbling: GL (even a software
/// rasteriser) rasterises only the G-buffer of positions and normals (and a flat design's
/// texture coordinates), which is cheap, and the kernel evaluates the colour rule at those
/// points on every core, which is the expensive part and where a software rasteriser is
/// several times slower than the kernel.

#include "marbler/CpuRenderer.h"
#include "marbler/ObjectView.h"
#include "marbler/gl/GlRenderer.h"

namespace marbler::gl {

/// The second pass on the CPU (marbler/ObjectView.h).
using marbler::shadeMeshOnCpu;

/// Both passes: renderer.renderMeshGBuffer, then shadeMeshOnCpu.
Image renderMeshHybrid(GlRenderer& renderer, const Genome& genome, const MeshSettings& settings,
                       const RenderControl* control = nullptr);

} // namespace marbler::gl
