#pragma once
/// The one way a window asks for a mesh file to show designs on (the breeding window's object
/// box, the editor's object preview): a file dialog by default, anything a test installs
/// instead, so no test ever blocks on the dialog.

#include <QString>

#include <functional>

class QWidget;

namespace marbler::ui {

/// Asks for a mesh file; returns its path, empty when the user cancelled.
using MeshFileChooser = std::function<QString(QWidget* parent)>;

/// Replaces the file dialog (tests); an empty chooser restores it.
void setMeshFileChooser(MeshFileChooser chooser);

/// Asks for an OBJ, STL, PLY or glTF file through the installed chooser; empty when cancelled.
QString chooseMeshFile(QWidget* parent);

/// Why `file` cannot be read as a mesh before it is even opened (missing, not a file, not
/// readable); empty when it can be tried. Whether it holds triangles, and texture coordinates
/// for a flat design, the render service finds out (RenderService::meshUnreadable).
QString meshFileProblem(const QString& file);

} // namespace marbler::ui
