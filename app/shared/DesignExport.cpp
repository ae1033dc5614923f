#include "shared/DesignExport.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/PrintProfile.h"
#include "marbler/RenderToFile.h"
#include "marbler/Repeat.h"
#include "marbler/Separations.h"
#include "marbler/Vector.h"
#include "marbler/gl/GlRenderer.h"
#include "marbler/gl/RenderView.h"
#include "shared/ErrorReport.h"
#include "shared/SourcePermissions.h"

#include <QFileInfo>
#include <QWidget>

#include <algorithm>

namespace marbler::ui {

QString exportCancelledMessage(const QString& file) {
    return DesignExport::tr("Export cancelled: %1 was not written").arg(QFileInfo(file).fileName());
}

DesignExport::DesignExport(QWidget* window)
    : QObject(window)
    , mWindow(window) {}

DesignExport::~DesignExport() {
    // Cancelled and waited for; renderToFile leaves no partial file.
    delete mJob;
}

bool DesignExport::exportTo(const Genome& design, const ObjectView& object, const QString& file, QSize pixels,
                            const QString& aa, std::optional<double> dpi, std::optional<SolidExport> solid,
                            int bitsPerSample, bool mirrorRepeatTile, bool straightRepeatTile) {
    if (mJob) return false;
    // A straight repeat only where the bath wraps (then the render's edges meet exactly).
    const bool straight =
        straightRepeatTile && design.wrap && design.lattice == Lattice::Straight && design.dimension != 3;
    const bool tile = (mirrorRepeatTile || straight) && design.dimension != 3;
    if (const QString problem = exportSizeProblem(tile ? pixels * 2 : pixels); !problem.isEmpty()) {
        reportError(mWindow, tr("Cannot export the image"), problem);
        return false;
    }
    RenderSettings render;
    render.width = std::max(1, pixels.width());
    render.height = std::max(1, pixels.height());
    render.aa = aa.toStdString();
    if (design.dimension == 3) render.slice = solid ? solid->slice : Slice{2, design.size.z / 2.0};
    ExportOptions options;
    options.dpi = dpi;
    options.bitsPerSample = bitsPerSample;
    // The object as the view shows it: the same mesh, angle and zoom, framed at the export's size,
    // on the window's back end (the GPU shades, or GL only rasterises and the CPU kernel colours).
    // A tile is made from one whole render on the CPU, as marbler render --repeat mirror does.
    gl::ViewRequest view;
    view.raster = render;
    if (design.dimension == 3 && solid && solid->objectView && !tile) {
        gl::MeshSettings mesh;
        mesh.width = render.width;
        mesh.height = render.height;
        mesh.mesh = object.mesh.toStdString();
        mesh.yaw = object.angle.yaw;
        mesh.pitch = object.angle.pitch;
        mesh.zoom = object.zoom;
        view.object = mesh;
        view.useGl = object.useGl;
    }
    // A source outside the design's folder is read only when the user allowed it for the view.
    Genome genome = design;
    SourcePermissions::session().apply(genome);

    return start(file, [genome, view, file, options, tile, straight](const RenderControl& control) {
        if (tile || view.object) {
            // The tile is made in memory from the whole render. An object needs a GL context of
            // this thread's own: a GL renderer stays on the thread that made it.
            std::optional<gl::GlRenderer> renderer;
            if (view.object) renderer.emplace();
            Image image = gl::renderView(genome, view, renderer ? &*renderer : nullptr, &control);
            if (control.cancelled()) throw Cancelled();
            ExportOptions written = options;
            if (tile) {
                // As marbler render --repeat mirror, the tile carries the genome.
                written.genome = serializeGenome(genome);
                image = straight ? straightRepeat(image) : mirrorRepeat(image);
            }
            writeImage(image, file.toStdString(), written);
        } else {
            // Rendered and written in strips, so memory stays bounded at any size.
            renderToFile(genome, view.raster, file.toStdString(), options, &control);
        }
    });
}

namespace {
/// The flat render an export of print files makes: the design at `pixels` with `aa`.
RenderSettings flatRender(QSize pixels, const QString& aa) {
    RenderSettings render;
    render.width = std::max(1, pixels.width());
    render.height = std::max(1, pixels.height());
    render.aa = aa.toStdString();
    return render;
}
} // namespace

bool DesignExport::exportCmykTo(const Genome& design, const QString& file, QSize pixels, const QString& aa,
                                std::optional<double> dpi, const QString& profile, RenderingIntent intent,
                                int bitsPerSample) {
    if (mJob) return false;
    if (const QString problem = exportSizeProblem(pixels); !problem.isEmpty()) {
        reportError(mWindow, tr("Cannot export the image"), problem);
        return false;
    }
    Genome genome = design;
    SourcePermissions::session().apply(genome);
    CmykTiffOptions options;
    options.intent = intent;
    options.bitsPerSample = bitsPerSample;
    options.dpi = dpi;
    return start(file, [genome, render = flatRender(pixels, aa), file, profile = profile.toStdString(),
                        options](const RenderControl& control) {
        // The same steps as marbler render --icc: the profile read and checked, then the render
        // converted strip by strip.
        renderToCmykTiff(genome, render, file.toStdString(), loadPrintProfile(profile), options, &control);
    });
}

bool DesignExport::exportSeparationsTo(const Genome& design, const QString& folder, QSize pixels,
                                       const QString& aa, std::optional<double> dpi, int maskBits) {
    if (mJob) return false;
    if (const QString problem = exportSizeProblem(pixels); !problem.isEmpty()) {
        reportError(mWindow, tr("Cannot export the image"), problem);
        return false;
    }
    SeparationFileOptions options;
    options.maskBits = maskBits;
    options.dpi = dpi;
    return start(folder, [genome = design, render = flatRender(pixels, aa), folder,
                          options](const RenderControl& control) {
        // The same steps as marbler render --separations, so the files are the same.
        const RasterSeparations separations = renderSeparations(genome, render, &control);
        if (control.cancelled()) throw Cancelled();
        writeSeparations(separations, folder.toStdString(), options);
    });
}

bool DesignExport::exportSvgTo(const Genome& design, const QString& file, double tolerance) {
    if (mJob) return false;
    VectorOptions options;
    options.tolerance = tolerance;
    return start(
        file,
        [genome = design, options, file](const RenderControl& control) {
            // The same steps as marbler svg, so the files are byte for byte the same. Tracing
            // cannot be interrupted; a cancel during it leaves no file.
            const VectorDesign traced = traceDesign(genome, options);
            if (control.cancelled()) throw Cancelled();
            writeSvg(traced, file.toStdString(), decimalsFor(options.tolerance));
        },
        true);
}

bool DesignExport::start(const QString& file, BackgroundJob::Work work, bool busy) {
    if (mJob) return false;
    JobBox box(mWindow, tr("Exporting %1…").arg(QFileInfo(file).fileName()),
               QStringLiteral("exportProgress"));
    box.busy = busy;
    mJob = BackgroundJob::start(this, box, std::move(work), [this, file](const JobOutcome& outcome) {
        mJob = nullptr;
        if (outcome.failed()) reportError(mWindow, tr("Cannot export the image"), outcome.error);
        emit finished(file, outcome.done(), outcome.error);
    });
    return true;
}

void DesignExport::cancel() {
    if (mJob) mJob->cancel();
}

} // namespace marbler::ui
