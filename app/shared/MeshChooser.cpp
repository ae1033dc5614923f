#include "shared/MeshChooser.h"

#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>

#include <utility>

namespace marbler::ui {

namespace {

MeshFileChooser& meshFileChooserHook() {
    static MeshFileChooser hook;
    return hook;
}

} // namespace

void setMeshFileChooser(MeshFileChooser chooser) {
    meshFileChooserHook() = std::move(chooser);
}

QString chooseMeshFile(QWidget* parent) {
    if (const MeshFileChooser& chooser = meshFileChooserHook()) return chooser(parent);
    return QFileDialog::getOpenFileName(
        parent, QCoreApplication::translate("MeshChooser", "Show the designs on a mesh"), QString(),
        QCoreApplication::translate("MeshChooser",
                                    "Meshes (*.obj *.stl *.ply *.gltf *.glb *.off);;All files (*)"));
}

QString meshFileProblem(const QString& file) {
    const QFileInfo info(file);
    const auto tr = [](const char* text) { return QCoreApplication::translate("MeshChooser", text); };
    if (!info.exists()) return tr("%1: no such mesh file").arg(file);
    if (!info.isFile()) return tr("%1: not a mesh file").arg(file);
    if (!info.isReadable()) return tr("%1: the mesh file cannot be read (permission denied)").arg(file);
    return {};
}

} // namespace marbler::ui
