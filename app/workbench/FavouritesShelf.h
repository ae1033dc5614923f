#pragma once
/// The workbench's Favourites dock: designs kept aside as genome files in the favourites folder,
/// shown with thumbnails, dragged or double-clicked back into the grid, removed into the trash
/// with an Undo beside the message (and Edit ▸ Restore removed favourite). Owns its dock, its
/// list, the restore action and the Undo button; the window places a favourite into the grid
/// when asked (restoreRequested).

#include <QObject>
#include <QString>

#include <cstdint>
#include <functional>

class QAction;
class QDockWidget;
class QListWidget;
class QMainWindow;
class QMenu;
class QPoint;
class QPushButton;
class QStatusBar;

namespace marbler::ui {

class PopulationModel;
class RenameDialog;
class RenderService;

class FavouritesShelf : public QObject {
    Q_OBJECT
public:
    /// Render keys the shelf takes from the render service, one a favourite (the queue renders
    /// lower keys first: the window takes its cells' before the shelf is made).
    static constexpr std::uint64_t KeyCount = std::uint64_t(1) << 32;
    static constexpr int ThumbnailSide = 96;

    /// Adds Edit ▸ Restore removed favourite to `editMenu`; buildDock() and addUndoButton() make
    /// the rest when the window gets there. `mesh` says the object solid designs are shown on;
    /// `noteSavedFile` tells where a kept favourite went. The render service must outlive the shelf.
    FavouritesShelf(QMainWindow* window, PopulationModel* model, RenderService* renderer, QMenu* editMenu,
                    std::function<QString()> mesh, std::function<void(const QString&)> noteSavedFile);

    /// The dock with the list (object name "favouritesDock").
    QDockWidget* buildDock();
    /// The Undo button beside the message that a favourite was removed, on `statusBar`.
    void addUndoButton(QStatusBar* statusBar);
    /// Drops the thumbnails still asked for (the window is closing).
    void cancelThumbnails();

    QListWidget* list() const { return mList; }
    QAction* restoreAction() const { return mRestore; }
    QPushButton* undoRemoveButton() const { return mUndoRemove; }

    /// Keeps a cell's design on the shelf.
    bool keep(int cell);
    /// Removes a favourite (into the trash), saying how to undo it.
    bool remove(int favourite);
    /// F2 or "Rename…": asks for a favourite's name and note; its file is written again with
    /// them. Returns the dialog (not modal), or nullptr when there is no such favourite.
    RenameDialog* rename(int favourite);
    /// Brings back the favourite removed last; false when there is none or it cannot be.
    bool restoreRemoved();
    /// The list anew from the model, thumbnails asked for.
    void update();

signals:
    /// A favourite double-clicked or put into the grid from its menu.
    void restoreRequested(int favourite);

private:
    void showMenu(const QPoint& pos);

    QMainWindow* mWindow;
    PopulationModel* mModel;
    RenderService* mRenderer;
    std::uint64_t mKeyBase; ///< the favourites' render keys: mKeyBase + row
    std::function<QString()> mMesh;
    std::function<void(const QString&)> mNoteSavedFile;
    QListWidget* mList = nullptr;
    QAction* mRestore = nullptr;
    QPushButton* mUndoRemove = nullptr;
};

} // namespace marbler::ui
