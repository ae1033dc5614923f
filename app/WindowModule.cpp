// marbler-window.so: the workbench window and the GL back end behind app::WindowModule.

#include "WindowModule.h"

#include "marbler/Error.h"
#include "marbler/gl/Backend.h"
#include "marbler/gl/GlRenderer.h"
#include "marbler/gl/Meshes.h"
#include "marbler/gl/RenderView.h"
#include "workbench/Workbench.h"

#include <QSettings>
#include <QString>
#include <QtGlobal>

#include <memory>

namespace marbler::app {
namespace {

class Module final : public WindowModule {
public:
    int runWorkbench(int argc, char** argv) override { return ui::runWorkbench(argc, argv); }

    Image renderView(const Genome& genome, const gl::ViewRequest& request) override {
        if (!request.object) checkRenderSettings(genome, request.raster);
        return gl::renderView(genome, request, &renderer());
    }

    MeshData loadMesh(const std::string& file) override { return gl::loadMesh(file); }

    GlReport probeGl() override {
        GlReport report;
        report.probe = gl::probeGl();
        // The window's choice as it would make it now: the environment's override, else the
        // window's remembered setting (the window's QSettings file, named here because doctor
        // runs without the window's application object).
        const QString stored = QSettings(QStringLiteral("Marbler"), QStringLiteral("Marbler"))
                                   .value(QStringLiteral("view/renderer"), QStringLiteral("auto"))
                                   .toString();
        const gl::BackendPreference preference = gl::environmentBackendPreference().value_or(
            gl::parseBackendPreference(stored.toStdString()).value_or(gl::BackendPreference::Auto));
        const gl::BackendChoice choice = gl::chooseBackend(report.probe, preference);
        report.backend = choice.useGl ? "GPU" : "CPU";
        report.backendWhy = choice.why;
        return report;
    }

    std::string qtVersion() const override { return qVersion(); }

private:
    /// One renderer for the process, made on first use (the GL back end tears it down at exit).
    gl::GlRenderer& renderer() {
        if (!mRenderer) {
            std::string reason;
            if (!gl::GlRenderer::available(&reason)) throw RuntimeFailure("no OpenGL 4.3 context: " + reason);
            mRenderer = std::make_unique<gl::GlRenderer>();
        }
        return *mRenderer;
    }

    std::unique_ptr<gl::GlRenderer> mRenderer;
};

} // namespace
} // namespace marbler::app

extern "C" __attribute__((visibility("default"))) marbler::app::WindowModule* marbler_window_module() {
    static auto* module = new marbler::app::Module; // never destroyed: GL tears itself down at exit
    return module;
}
