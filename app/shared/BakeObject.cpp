#include "shared/BakeObject.h"

#include "marbler/Bake.h"
#include "marbler/Error.h"
#include "marbler/gl/Meshes.h"
#include "shared/BackgroundJob.h"
#include "shared/ErrorReport.h"
#include "shared/SavedFiles.h"

#include <QFileInfo>
#include <QPushButton>
#include <QSettings>

namespace marbler::ui {
namespace {

/// Bakes on a background job owned by the button, so closing the view cancels the bake and
/// waits for it; the button is disabled until the bake ends.
void startBake(QPushButton* button, Genome genome, QString mesh, QString file, int textureSize,
               std::function<void(const QString&)> written) {
    JobBox box(button->window(), QObject::tr("Baking %1…").arg(QFileInfo(file).fileName()),
               QStringLiteral("bakeProgress"));
    button->setEnabled(false);
    BackgroundJob::start(
        button, box,
        [genome = std::move(genome), mesh, file, textureSize](const RenderControl& control) {
            MeshData data = gl::meshByNameOrFile(mesh.toStdString());
            if (!hasUsableUvs(data)) data = withGeneratedUvs(data, textureSize);
            BakeSettings settings;
            settings.textureSize = textureSize;
            const BakedTexture baked = bakeTexture(genome, data, settings, &control);
            const std::string name = genome.meta.name.value_or("marbled");
            writeTexturedMesh(data, baked.image, file.toStdString(), name);
        },
        [button, file, written = std::move(written)](const JobOutcome& outcome) {
            button->setEnabled(true);
            if (outcome.failed())
                reportError(button->window(), QObject::tr("Cannot bake onto the object"), outcome.error);
            else if (outcome.done() && written)
                written(file);
        });
}

} // namespace

QPushButton* makeBakeButton(QWidget* parent, std::function<Genome()> genome, QString mesh,
                            std::function<void(const QString&)> written, int textureSize) {
    auto* button = new QPushButton(QObject::tr("&Bake onto object…"), parent);
    button->setObjectName(QStringLiteral("bakeObject"));
    button->setToolTip(
        QObject::tr("Write the object with the design baked into its texture, for other 3D tools "
                    "(glTF .glb or .gltf, OBJ; a %1 × %1 texture)")
            .arg(textureSize));
    QObject::connect(button, &QPushButton::clicked, button, [button, genome, mesh, written, textureSize] {
        const Genome design = genome();
        QSettings settings;
        QString file =
            askSaveFile(button->window(), QObject::tr("Bake onto object"),
                        suggestedFile(design, settings.value(QStringLiteral("files/bakeDir")).toString(),
                                      QStringLiteral(".glb")),
                        QObject::tr("3D objects (*.glb *.gltf *.obj)"));
        if (file.isEmpty()) return;
        // A name typed without a format gets glTF binary, one file that carries its texture.
        const QString suffix = QFileInfo(file).suffix().toLower();
        if (suffix.isEmpty())
            file += QStringLiteral(".glb");
        else if (suffix != QStringLiteral("glb") && suffix != QStringLiteral("gltf") &&
                 suffix != QStringLiteral("obj")) {
            reportError(button->window(), QObject::tr("Cannot bake onto the object"),
                        QObject::tr("%1: choose .glb, .gltf or .obj").arg(QFileInfo(file).fileName()));
            return;
        }
        settings.setValue(QStringLiteral("files/bakeDir"), QFileInfo(file).absolutePath());
        startBake(button, design, mesh, file, textureSize, written);
    });
    return button;
}

} // namespace marbler::ui
