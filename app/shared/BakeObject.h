#pragma once
/// "Bake onto object…" in the large view of a solid design: the design baked into the texture of
/// the object it is shown on and written as glTF binary (or .gltf, .obj), as `marbler bake` does,
/// on a thread of its own with a progress box.

#include "marbler/Genome.h"

#include <QObject>
#include <QString>

#include <functional>

class QPushButton;
class QWidget;

namespace marbler::ui {

/// The texture side the window bakes at (`marbler bake`'s default).
inline constexpr int WindowBakeTexture = 2048;

/// The button the large view of a solid design shows (object name "bakeObject"); a click asks
/// for the file (askSaveFile, SavedFiles.h: the design's name, .glb, in the folder used last),
/// then bakes `genome()` onto `mesh` (a built-in name or a mesh file) at `textureSize`. Errors go
/// to reportError; `written` gets each file the user asked for once it is complete. The bake is
/// cancelled and waited for if `parent` goes first.
QPushButton* makeBakeButton(QWidget* parent, std::function<Genome()> genome, QString mesh,
                            std::function<void(const QString&)> written, int textureSize = WindowBakeTexture);

} // namespace marbler::ui
