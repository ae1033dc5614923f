#include "marbler/gl/HybridMesh.h"

namespace marbler::gl {

Image renderMeshHybrid(GlRenderer& renderer, const Genome& genome, const MeshSettings& settings,
                       const RenderControl* control) {
    return shadeMeshOnCpu(genome, renderer.renderMeshGBuffer(genome, settings), settings, control);
}

} // namespace marbler::gl
