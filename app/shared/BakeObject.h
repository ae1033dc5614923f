#pragma once
/// "Bake onto object…" in the large view and the editor: the design baked into the texture of
/// the object it is shown on and written as glTF binary (or .gltf, .obj), as `marbler bake` does,
/// on a thread of its own with a progress box.

#include "marbler/Genome.h"

#include <QObject>
#include <QString>

#include <functional>

class QMenu;
class QPushButton;
class QWidget;

namespace marbler::ui {

/// The texture side the window bakes at (`marbler bake`'s default).
inline constexpr int WindowBakeTexture = 2048;

/// The button the large view of a design shows (object name "bakeObject"); a click pops up
/// makeBakeMenu (object name "bakeObjectMenu"); a choice asks for the file (askSaveFile, SavedFiles.h: the
/// design's name, .glb, in the folder used last), then bakes `genome()` onto the object chosen (`mesh` is the
/// one shown: a built-in name, a mesh file or empty) at `textureSize`. Errors go to reportError; `written`
/// gets each file the user asked for once it is complete. The bake is cancelled and waited for if `parent`
/// goes first.
QPushButton* makeBakeButton(QWidget* parent, std::function<Genome()> genome, QString mesh,
                            std::function<void(const QString&)> written, int textureSize = WindowBakeTexture);

/// The objects a design, flat or solid, can be baked onto: the object it is shown on when
/// `shown` is not empty (action "bakeOntoShown"), each built-in ("bakeOnto:NAME") and a mesh
/// file asked for with chooseMeshFile ("bakeOntoMeshFile"). Choosing one bakes as the button
/// does, through the object's own texture coordinates (bakeTexture, as `marbler bake`); the
/// menu is disabled while it bakes. The large view's button pops it up; the editor's File menu
/// holds it.
QMenu* makeBakeMenu(QWidget* parent, std::function<Genome()> genome, QString shown,
                    std::function<void(const QString&)> written, int textureSize = WindowBakeTexture);

} // namespace marbler::ui
