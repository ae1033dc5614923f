#pragma once
/// The evolution workbench: a 3 x 3 grid of designs, parents chosen by clicking, the four genetic
/// operators, back/forward through generations, a lineage view and a favourites shelf.

#include "marbler/Operators.h"
#include "marbler/gl/Backend.h"
#include "ui/PopulationModel.h"
#include "ui/Session.h"

#include <QCache>
#include <QMainWindow>
#include <QPointer>
#include <QTimer>

#include <array>
#include <cstdint>

class QAction;
class QComboBox;
class QLabel;
class QListWidget;
class QMenu;
class QPushButton;
class QSlider;
class QTreeWidget;

namespace marbler::ui {

class DesignCell;
class DesignDialog;
class RenderService;
class SessionsDialog;

class WorkbenchWindow : public QMainWindow {
    Q_OBJECT
public:
    /// The render service is shared (the editor uses it too) and must outlive the window.
    explicit WorkbenchWindow(RenderService* renderer, QWidget* parent = nullptr);
    ~WorkbenchWindow() override;

    PopulationModel* model() const { return mModel; }
    DesignCell* cell(int index) const { return mCells[std::size_t(index)]; }
    QAction* operatorAction(GeneticOperator op) const;
    QAction* backAction() const { return mBack; }
    QAction* forwardAction() const { return mForward; }
    QListWidget* favouritesList() const { return mFavouritesList; }
    QTreeWidget* lineageTree() const { return mLineageTree; }
    /// The alteration strength the slider gives, 0..1.
    double strength() const;
    void setStrength(double strength);

    /// Loads genome files into the selected cells, then free ones (or into `cell` and on).
    /// A file that does not load is reported and changes nothing. Returns whether all loaded.
    bool openFiles(const QStringList& files, int cell = -1);
    /// Breeds the selected parents with an operator; errors are reported.
    bool applyOperator(GeneticOperator op);
    /// A fresh random population (2: flat, 3: solid); remembers the choice.
    void newRandomPopulation(int dimension);
    /// Brings back a saved session: its generations, the current one, the seed, the kind box
    /// and the object.
    void resumeSession(SavedSession session);
    /// The object solid designs are shown on ("vase", "sphere", ...; see meshNames()).
    QString mesh() const;
    void setMesh(const QString& mesh);
    /// Kept sessions (SessionStore.h): the session folder whose store File ▸ Sessions shows
    /// (set by startSession; empty: no store, and the menu entries are disabled).
    void setSessionStore(const QString& sessionFolder);
    QString sessionStoreFolder() const { return mSessionFolder; }
    /// The id of the session being bred and saved (empty when none is saved).
    QString currentSessionId() const;
    /// Switches to a kept session; the current one is saved already and stays kept. A session
    /// that does not load is reported, moved aside as `.bad`, and the current one goes on.
    bool resumeKeptSession(const QString& id);
    /// Renames a kept session (the current one too); errors are reported.
    bool renameSession(const QString& id, const QString& name);
    /// Deletes a kept session into the store's trash (not the current one); returns the trashed
    /// file for restoreDeletedSession(), empty when nothing was deleted (errors are reported).
    QString deleteSession(const QString& id);
    /// Brings back a deleted session; errors are reported.
    bool restoreDeletedSession(const QString& trashed);
    /// File ▸ Sessions: the kept sessions to resume, rename or delete (not modal, deleted on
    /// close; one at a time).
    SessionsDialog* openSessionsDialog();
    QAction* sessionsAction() const { return mSessionsAction; }
    QMenu* recentSessionsMenu() const { return mRecentSessions; }
    /// Keeps a cell's design on the favourites shelf.
    bool keepFavourite(int cell);
    /// Removes a favourite from the shelf (into the trash), saying how to undo it.
    bool removeFavourite(int favourite);
    /// Brings back the favourite removed last; false when there is none or it cannot be.
    bool restoreRemovedFavourite();
    /// Edit ▸ Restore removed favourite, and the status bar's Undo beside its message.
    QAction* restoreFavouriteAction() const { return mRestoreFavourite; }
    QPushButton* undoRemoveButton() const { return mUndoRemove; }
    /// Puts a favourite back into a cell (-1: the selected or first free cell).
    void restoreFavourite(int favourite, int cell = -1);
    /// Whether every cell shows its final image (for screenshots and tests).
    bool renderingDone() const;
    /// Shows a cell's design large (double-click, Enter); returns the dialog (not modal, deleted
    /// on close), or nullptr for an empty cell.
    DesignDialog* openDesign(int index);
    /// Remembers the renderer preference (View ▸ Renderer) and has the service choose again,
    /// which re-renders every design.
    void setRendererPreference(gl::BackendPreference preference);
    /// The View ▸ Renderer entry of a preference.
    QAction* rendererAction(gl::BackendPreference preference) const;

signals:
    /// Every visible design has its final image.
    void renderingFinished();
    /// A design was opened large (tests close the dialog).
    void designOpened(DesignDialog* dialog);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void buildActions();
    void buildDocks();
    void readSettings();
    void updateCells();
    void updateActions();
    void updateLineage();
    void updateFavourites();
    void showBackend();
    void requestRender(int cell, bool previewOnly = false);
    void requestAllRenders();
    void onRendered(std::uint64_t key, const QImage& image, bool final);
    void onRenderFailed(std::uint64_t key, const QString& message);
    void onCellClicked(int index);
    void onFocusMove(int index, int dx, int dy);
    void onOrbit(int index, QPoint delta, bool finished);
    void showCellMenu(int index, const QPoint& globalPos);
    void showFavouriteMenu(const QPoint& pos);
    void openFileDialog();
    void fillRecentSessions();
    void saveDesign(int index);
    QString renderCacheKey(int cell) const;

    RenderService* mRenderer;
    PopulationModel* mModel;
    std::array<DesignCell*, CellCount> mCells{};
    std::array<double, CellCount> mYaw{};
    std::array<double, CellCount> mPitch{};
    std::array<bool, CellCount> mFinal{};
    std::array<QString, CellCount> mPendingCacheKey;
    QCache<QString, QImage> mImageCache{48};
    QAction* mAlter = nullptr;
    QAction* mRecombine = nullptr;
    QAction* mSwap = nullptr;
    QAction* mReinit = nullptr;
    QAction* mBack = nullptr;
    QAction* mForward = nullptr;
    QSlider* mStrength = nullptr;
    QComboBox* mDimension = nullptr;
    QComboBox* mMesh = nullptr;
    QListWidget* mFavouritesList = nullptr;
    QTreeWidget* mLineageTree = nullptr;
    QLabel* mBackendLabel = nullptr;
    std::array<QAction*, 3> mRendererActions{}; ///< by gl::BackendPreference
    QTimer mResizeTimer;
    bool mSaveFailureShown = false;
    QString mSessionFolder;
    QAction* mSessionsAction = nullptr;
    QMenu* mRecentSessions = nullptr;
    QPointer<SessionsDialog> mSessionsDialog;
    QAction* mRestoreFavourite = nullptr;
    QPushButton* mUndoRemove = nullptr;
};

/// Reports a session file that does not load (once), moving it aside as `.bad` first.
void reportBadSession(QWidget* parent, const QString& file, const QString& what);

/// The caption a cell shows under a design: its name (a bred design's carries " (gN #K)",
/// generation N, design K, as the status bar and the lineage count) and how it was made.
QString designCaption(const Genome& genome);

} // namespace marbler::ui
