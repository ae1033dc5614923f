#include "marbler/gl/RenderView.h"

#include "marbler/Error.h"
#include "marbler/gl/HybridMesh.h"

namespace marbler::gl {

Image renderView(const Genome& genome, const ViewRequest& request, GlRenderer* gl,
                 const RenderControl* control, const CpuRenderer* prepared) {
    if (request.object) {
        if (!gl) throw RuntimeFailure("showing a solid design on an object needs OpenGL");
        return request.useGl ? gl->renderMesh(genome, *request.object)
                             : renderMeshHybrid(*gl, genome, *request.object, control);
    }
    if (request.useGl) {
        if (!gl) throw RuntimeFailure("the GPU renderer was asked for, but there is no OpenGL renderer");
        return gl->render(genome, request.raster);
    }
    if (prepared) return prepared->render(request.raster, control);
    return CpuRenderer(genome).render(request.raster, control);
}

} // namespace marbler::gl
