#include "shared/BakeObject.h"

#include "marbler/Bake.h"
#include "marbler/Error.h"
#include "marbler/gl/Meshes.h"
#include "shared/BackgroundJob.h"
#include "shared/ErrorReport.h"
#include "shared/MeshChooser.h"
#include "shared/SavedFiles.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QPushButton>
#include <QSettings>

#include <filesystem>
#include <system_error>
#include <vector>

namespace marbler::ui {
namespace {

/// Bakes on a background job owned by the menu, so closing the window cancels the bake and
/// waits for it; the menu (and the large view's button) is disabled until the bake ends.
void startBake(QMenu* menu, QWidget* window, Genome genome, QString mesh, QString file, int textureSize,
               std::function<void(const QString&)> written) {
    JobBox box(window, QObject::tr("Baking %1…").arg(QFileInfo(file).fileName()),
               QStringLiteral("bakeProgress"));
    // The large view's button, when the menu is its, waits with the menu.
    auto* button = qobject_cast<QPushButton*>(menu->parentWidget());
    menu->setEnabled(false);
    if (button) button->setEnabled(false);
    BackgroundJob::start(
        menu, box,
        [genome = std::move(genome), mesh, file, textureSize](const RenderControl& control) {
            MeshData data = gl::meshByNameOrFile(mesh.toStdString());
            if (!hasUsableUvs(data)) data = withGeneratedUvs(data, textureSize);
            BakeSettings settings;
            settings.textureSize = textureSize;
            const BakedTexture baked = bakeTexture(genome, data, settings, &control);
            const std::string name = genome.meta.name.value_or("marbled");
            // Writing a large texture's PNG takes a while and cannot stop half way: a cancel
            // that comes meanwhile removes what was written, so a cancelled bake leaves nothing.
            const std::vector<std::filesystem::path> files =
                writeTexturedMesh(data, baked.image, file.toStdString(), name);
            if (control.cancelled()) {
                std::error_code ignored;
                for (const std::filesystem::path& written : files)
                    std::filesystem::remove(written, ignored);
                throw Cancelled();
            }
        },
        [menu, button, window, file, written = std::move(written)](const JobOutcome& outcome) {
            menu->setEnabled(true);
            if (button) button->setEnabled(true);
            if (outcome.failed())
                reportError(window, QObject::tr("Cannot bake onto the object"), outcome.error);
            else if (outcome.done() && written)
                written(file);
        });
}

/// Asks for the file to write and bakes `genome()` onto `mesh` into it.
void askAndBake(QMenu* menu, const std::function<Genome()>& genome, const QString& mesh,
                const std::function<void(const QString&)>& written, int textureSize) {
    QWidget* window = menu->parentWidget() ? menu->parentWidget()->window() : menu->window();
    if (mesh.isEmpty()) return;
    if (!isBuiltinMesh(mesh.toStdString())) {
        if (const QString problem = meshFileProblem(mesh); !problem.isEmpty()) {
            reportError(window, QObject::tr("Cannot bake onto the object"), problem);
            return;
        }
    }
    const Genome design = genome();
    QSettings settings;
    QString file =
        askSaveFile(window, QObject::tr("Bake onto object"),
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
        reportError(window, QObject::tr("Cannot bake onto the object"),
                    QObject::tr("%1: choose .glb, .gltf or .obj").arg(QFileInfo(file).fileName()));
        return;
    }
    settings.setValue(QStringLiteral("files/bakeDir"), QFileInfo(file).absolutePath());
    startBake(menu, window, design, mesh, file, textureSize, written);
}

} // namespace

QMenu* makeBakeMenu(QWidget* parent, std::function<Genome()> genome, QString shown,
                    std::function<void(const QString&)> written, int textureSize) {
    auto* menu = new QMenu(QObject::tr("&Bake onto object"), parent);
    menu->setObjectName(QStringLiteral("bakeObjectMenu"));
    menu->setToolTipsVisible(true);
    const QString tip =
        QObject::tr("Write the object with the design baked into its texture, following the object's "
                    "texture coordinates, for other 3D tools (glTF .glb or .gltf, OBJ; a %1 × %1 texture)")
            .arg(textureSize);
    menu->setToolTip(tip);
    const auto add = [&](const QString& text, const QString& name, std::function<QString()> mesh) {
        QAction* action = menu->addAction(text);
        action->setObjectName(name);
        action->setToolTip(tip);
        QObject::connect(action, &QAction::triggered, menu, [menu, genome, written, textureSize, mesh] {
            askAndBake(menu, genome, mesh(), written, textureSize);
        });
    };
    if (!shown.isEmpty()) {
        const QString label = isBuiltinMesh(shown.toStdString()) ? shown : QFileInfo(shown).fileName();
        add(QObject::tr("The object shown (%1)…").arg(label), QStringLiteral("bakeOntoShown"),
            [shown] { return shown; });
        menu->addSeparator();
    }
    for (const std::string& name : builtinMeshNames()) {
        const QString mesh = QString::fromStdString(name);
        add(mesh + QStringLiteral("…"), QStringLiteral("bakeOnto:") + mesh, [mesh] { return mesh; });
    }
    menu->addSeparator();
    add(QObject::tr("&Mesh file…"), QStringLiteral("bakeOntoMeshFile"),
        [menu] { return chooseMeshFile(menu->parentWidget() ? menu->parentWidget()->window() : nullptr); });
    return menu;
}

QPushButton* makeBakeButton(QWidget* parent, std::function<Genome()> genome, QString mesh,
                            std::function<void(const QString&)> written, int textureSize) {
    auto* button = new QPushButton(QObject::tr("&Bake onto object…"), parent);
    button->setObjectName(QStringLiteral("bakeObject"));
    QMenu* menu = makeBakeMenu(button, std::move(genome), std::move(mesh), std::move(written), textureSize);
    button->setToolTip(menu->toolTip());
    // Popped up rather than set with setMenu, whose exec would block the caller of click().
    QObject::connect(button, &QPushButton::clicked, menu,
                     [button, menu] { menu->popup(button->mapToGlobal(QPoint(0, button->height()))); });
    return button;
}

} // namespace marbler::ui
