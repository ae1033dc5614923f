#pragma once
/// The boundary between the `marbler` executable and marbler-window.so, the module that holds
/// everything that needs Qt: the workbench window and the OpenGL back end (with assimp for mesh
/// files). The executable links neither, so the headless verbs start without loading them; the
/// window, `render --gpu`, `render --mesh`, `bake --mesh FILE` and `doctor` load the module on
/// first use (marbler/Modules.h).

#include "marbler/Genome.h"
#include "marbler/Mesh.h"
#include "marbler/Sampling.h"
#include "marbler/gl/Backend.h"    // GlProbe only: a plain struct
#include "marbler/gl/GlRenderer.h" // MeshSettings only: a plain struct, no GL code
#include "marbler/gl/RenderView.h" // ViewRequest only: a plain struct, no GL code

#include <string>

namespace marbler::app {

/// What the machine's OpenGL gives Marbler, and the back end the window will render with.
struct GlReport {
    gl::GlProbe probe;
    std::string backend;    ///< "GPU" or "CPU": what the window renders with
    std::string backendWhy; ///< why, in words
};

class WindowModule {
public:
    virtual ~WindowModule() = default;
    /// Runs the workbench window (argv as main() got it); returns the exit status.
    virtual int runWorkbench(int argc, char** argv) = 0;
    /// A view rendered by gl::renderView with the module's GL renderer (`render --gpu`,
    /// `render --mesh`). Throws InputError for bad settings, RuntimeFailure when there is no GL
    /// 4.3 context or the driver fails.
    virtual Image renderView(const Genome& genome, const gl::ViewRequest& request) = 0;
    /// Reads a mesh file with assimp (gl::loadMesh), for `bake`. Throws InputError when it
    /// cannot be read.
    virtual MeshData loadMesh(const std::string& file) = 0;
    /// Probes OpenGL (makes an offscreen context when it can) for `marbler doctor`.
    virtual GlReport probeGl() = 0;
    /// The Qt version the module runs with.
    virtual std::string qtVersion() const = 0;
};

/// The module, loaded on first call. Throws RuntimeFailure when it cannot be loaded.
WindowModule& windowModule();

inline constexpr const char* WindowModuleFile = "marbler-window.so";
inline constexpr const char* WindowModuleEntry = "marbler_window_module";

} // namespace marbler::app
