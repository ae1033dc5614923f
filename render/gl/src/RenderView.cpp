#include "marbler/gl/RenderView.h"

#include "marbler/Error.h"
#include "marbler/gl/HybridMesh.h"
#include "marbler/gl/Meshes.h"

namespace marbler::gl {

Image renderView(const Genome& genome, const ViewRequest& request, GlRenderer* gl,
                 const RenderControl* control, const CpuRenderer* prepared) {
    if (request.object) {
        if (request.useGl) {
            if (!gl) throw RuntimeFailure("the GPU renderer was asked for, but there is no OpenGL renderer");
            return gl->renderMesh(genome, *request.object);
        }
        // On the CPU: GL, where there is any, rasterises a solid's object (it keeps the mesh
        // loaded); with none, or for a flat design on its texture coordinates, the CPU does.
        return gl && genome.dimension == 3 ? renderMeshHybrid(*gl, genome, *request.object, control)
                                           : renderObjectOnCpu(genome, meshByNameOrFile(request.object->mesh),
                                                               *request.object, control);
    }
    if (request.useGl) {
        if (!gl) throw RuntimeFailure("the GPU renderer was asked for, but there is no OpenGL renderer");
        return gl->render(genome, request.raster);
    }
    if (prepared) return prepared->render(request.raster, control);
    return CpuRenderer(genome).render(request.raster, control);
}

} // namespace marbler::gl
