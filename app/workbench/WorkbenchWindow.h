#pragma once
/// The evolution workbench: a 3 x 3 grid of designs, parents chosen by clicking, the four genetic
/// operators, back/forward through generations, a lineage view of the generation tree, a
/// favourites shelf, and a Help menu (the guide, About). The status bar says what the window is
/// doing and where files went.

#include "marbler/Operators.h"
#include "marbler/gl/Backend.h"
// Complete for the designOpened signal: moc registers the pointer type of a complete class
// only, and a test spying on the signal needs it.
#include "shared/DesignDialog.h"
#include "workbench/LineagePanel.h"
#include "workbench/PopulationModel.h"
#include "workbench/Session.h"

#include <QCache>
#include <QHash>
#include <QMainWindow>
#include <QMultiHash>
#include <QPointer>
#include <QSet>
#include <QTimer>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

class QAction;
class QComboBox;
namespace marbler {
struct PaperOptions;
}
class QDialog;
class QLabel;
class QListWidget;
class QMenu;
class QPushButton;
class QSlider;
class QTreeWidget;
class QToolBar;
class QTreeWidgetItem;

namespace marbler::ui {

class ColourwaysController;
class DesignCell;
class EditorWindow;
class FavouritesShelf;
class HelpMenu;
class OperatorActions;
class PopulationBar;
class RenameDialog;
class RendererMenu;
class RenderService;
struct RecoveredDesign;
class SavedFileNotice;
class SessionsController;
class SessionsDialog;
class StatusLine;

class WorkbenchWindow : public QMainWindow {
    Q_OBJECT
public:
    /// The lineage's icons (LineagePanel.h).
    static constexpr int LineageIconSide = LineagePanel::IconSide;

    /// The render service is shared (the editor uses it too) and must outlive the window.
    explicit WorkbenchWindow(RenderService* renderer, QWidget* parent = nullptr);
    ~WorkbenchWindow() override;

    PopulationModel* model() const { return mModel; }
    DesignCell* cell(int index) const { return mCells[std::size_t(index)]; }
    QAction* operatorAction(GeneticOperator op) const;
    QAction* backAction() const { return mBack; }
    QAction* forwardAction() const { return mForward; }
    QListWidget* favouritesList() const;
    /// The lineage: "Current designs", then "Generations", the generation tree (a branch's
    /// generations under a "Branch N" item placed after the generation it grew from), each
    /// generation with its nine designs as a thumbnail mosaic and as child items.
    QTreeWidget* lineageTree() const;
    /// In the lineage, items of generations and designs hold the generation's history index in
    /// this role (column 0), items of designs their cell in LineageCellRole, and branch items
    /// their branch number in LineageBranchRole.
    static constexpr int LineageGenerationRole = LineagePanel::GenerationRole;
    static constexpr int LineageCellRole = LineagePanel::CellRole;
    static constexpr int LineageBranchRole = LineagePanel::BranchRole;
    /// Whether the lineage shows the rendered thumbnail of a design (else a blank, until it
    /// arrives; thumbnails are rendered only for the items in view).
    bool hasLineageThumbnail(const Genome& genome) const;
    /// The alteration strength the slider gives, 0..1.
    double strength() const;
    void setStrength(double strength);

    /// Loads genome files into the grid as a new generation (see placeOpened()): into the
    /// selected cells, then free ones, asking first when designs would be replaced; one file
    /// dropped on a cell goes into that cell (`cell`). A file that does not load is reported and
    /// changes nothing. A picture without a design in it is offered to Marble a picture
    /// (offerMarblePicture). Returns whether all loaded (a picture: whether it was marbled).
    bool openFiles(const QStringList& files, int cell = -1);
    /// Puts opened designs (files, favourites, dropped designs) into the grid; `names` say what
    /// they are in messages, `cell` is an explicit target (a drop on a cell) or -1. Designs of
    /// the grid's kind go into the selected cells, then free ones, then the rest, and when that
    /// would replace designs the user is asked (chooseOpenPlacement): replace them, or a new
    /// generation that keeps the parents, or nothing. A single design dropped on a cell replaces
    /// that cell without a question unless it is a selected parent. Designs of the other kind
    /// (flat among solid or the reverse), which could not breed with the grid, start a
    /// generation of their own kind; a mixed set opens the first file's kind and reports the
    /// rest. `description` names the new generation ("Opened NAMES" when empty). Returns the
    /// cells filled (none when cancelled).
    /// Nine designs whose bath is the picture `file` (ImageDesign.h: a flow and strokes over it,
    /// no ink), named "NAME marbled 1" to "… 9", as a new generation of all nine (the grid before
    /// one generation back; no question, as for a new random population). Reports a picture
    /// that cannot be read and returns no cells.
    std::vector<int> marblePicture(const QString& file);
    std::vector<int> placeOpened(const std::vector<Genome>& designs, const QStringList& names, int cell = -1,
                                 const QString& description = {});
    /// Opens a design in an editor window of its own ("Open in editor" on a cell and in the
    /// large view, File ▸ New design, File ▸ Open in editor); `file` is the file it was read
    /// from, if any. The editor's Send to grid places its design here as an opened design
    /// (placeOpened), to breed from; its saved files show on the status bar.
    EditorWindow* openEditor(const Genome& design, const QString& file = {});
    /// Offers, one by one, the designs editors left unsaved when Marbler stopped (Recovery.h:
    /// the autosaves in `folder`), but those declined before; old ones are purged first. Each one
    /// accepted opens in an editor exactly as it was, its changes still unsaved; each one
    /// declined is kept, for File ▸ Recover unsaved designs…. `accept` answers instead of the
    /// user (tests). Returns the editors opened.
    std::vector<EditorWindow*> offerRecoveries(const QString& folder,
                                               std::function<bool(const QString& name)> accept = {});
    /// File ▸ Recover unsaved designs… (also in the editor): every design left in `folder`
    /// (default: defaultRecoveryFolder()), declined ones too, to open or discard. Non-modal.
    QDialog* showRecoveries(const QString& folder = {});
    /// Opens a recovered design in an editor as it was (unsaved) and removes its recovery file
    /// once the editor's own autosave holds it.
    EditorWindow* recover(const RecoveredDesign& design);
    /// File ▸ New marbled paper: the A4 paper `marbler paper --seed SEED` makes (Paper.h) goes
    /// into the grid as an opened design does (placeOpened), a starting point to breed from.
    /// Returns the cells filled. The menu's action (object name "newPaperAction") asks for the
    /// sheet, inks, passes, pastel and seed first (PaperDialog.h).
    std::vector<int> newPaper(std::uint64_t seed);
    /// As newPaper(seed), with the options of `marbler paper` (size, colours, passes, pastel).
    std::vector<int> newPaper(std::uint64_t seed, const PaperOptions& options);
    /// Edit ▸ Copy design (Ctrl+C): puts a cell's genome on the clipboard as genome text; -1:
    /// the focused cell when it holds a design, else the first selected one. Says so on the
    /// status bar; false when there is no design to copy.
    bool copyDesign(int cell = -1);
    /// Edit ▸ Paste design (Ctrl+V): the genome on the clipboard goes into the grid as File ▸
    /// Open puts an opened file (placeOpened, asking before it replaces designs); files copied
    /// in a file manager open as files. Text that is no genome changes nothing and is said on
    /// the status bar. Returns whether a design was placed.
    bool pasteDesign();
    QAction* copyDesignAction() const { return mCopyDesign; }
    QAction* pasteDesignAction() const { return mPasteDesign; }
    /// Breeds the selected parents with an operator at once; errors are reported.
    bool applyOperator(GeneticOperator op);
    /// What the operator actions (buttons, menu, Ctrl+1..4) do: breeds at once, unless the
    /// generation bred last is still rendering; then the click waits for its renders (a later
    /// click replacing it, going to another generation dropping it) and the status bar says so.
    /// Fast clicks so make one generation each time the grid has caught up, not one per click.
    void requestOperator(GeneticOperator op);
    /// A design's "More like this" (its right-click menu): the next generation bred from it alone
    /// (Alter at the strength set, steered as any), whatever else was selected.
    void moreLikeThis(int index);
    /// A fresh random population (2: flat, 3: solid) of the family chosen in the tool bar (or
    /// mixed families); remembers the choices.
    void newRandomPopulation(int dimension);
    /// Chooses the family of new populations: a family's name (Families.h), or empty for mixed
    /// families. A name of the other kind than the kind box's, or no family, chooses the mix.
    void setPopulationFamily(const QString& family);
    QString populationFamily() const;
    /// Brings back a saved session: its generations, the current one, the seed, the kind box
    /// and the object.
    void resumeSession(SavedSession session);
    /// The object solid designs are shown on ("vase", "sphere", ...; see meshNames(), or a mesh
    /// file's path).
    QString mesh() const;
    void setMesh(const QString& mesh);
    /// The object flat designs are shown on, as mesh(); empty (the default): flat. Kept with
    /// the session.
    QString flatMesh() const;
    void setFlatMesh(const QString& mesh);
    /// The object a design of `dimension` is shown on: mesh() or flatMesh() (empty: flat).
    QString objectFor(int dimension) const { return dimension == 3 ? mesh() : flatMesh(); }
    /// The "New population" bar's object box (tests).
    QComboBox* objectBox() const;
    /// Brings a design of any generation back into the grid as a new generation (placed as
    /// PopulationModel::placeDesigns places it), so Back undoes it. A design of the other kind
    /// (solid among flat, or the reverse) starts a generation of its own, as an opened one does.
    void bringBackDesign(int generation, int cell);
    /// Kept sessions (SessionStore.h): the session folder whose store File ▸ Sessions shows
    /// (set by startSession; empty: no store, and the menu entries are disabled).
    void setSessionStore(const QString& sessionFolder);
    QString sessionStoreFolder() const;
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
    QAction* sessionsAction() const;
    QMenu* recentSessionsMenu() const;
    /// Keeps a cell's design on the favourites shelf.
    bool keepFavourite(int cell);
    /// Removes a favourite from the shelf (into the trash), saying how to undo it.
    bool removeFavourite(int favourite);
    /// Brings back the favourite removed last; false when there is none or it cannot be.
    bool restoreRemovedFavourite();
    /// Edit ▸ Restore removed favourite, and the status bar's Undo beside its message.
    QAction* restoreFavouriteAction() const;
    QPushButton* undoRemoveButton() const;
    /// Puts a favourite back into a cell (-1: the selected or first free cell).
    void restoreFavourite(int favourite, int cell = -1);
    /// Whether every cell shows its final image (for screenshots and tests).
    bool renderingDone() const;
    /// Shows a cell's design large (double-click, Enter); returns the dialog (not modal, deleted
    /// on close), or nullptr for an empty cell.
    DesignDialog* openDesign(int index);
    /// F2 or Rename…: asks for the name and note of a cell's design (-1: the focused design, else
    /// the first selected; a favourite when the shelf has the focus). Returns the dialog (not
    /// modal, deleted on close), or nullptr when there is no design to name.
    RenameDialog* renameDesign(int index = -1);
    /// Edit ▸ Rename… (F2).
    QAction* renameAction() const { return mRename; }
    /// Remembers the renderer preference (View ▸ Renderer) and has the service choose again,
    /// which re-renders every design.
    void setRendererPreference(gl::BackendPreference preference);
    /// The View ▸ Renderer entry of a preference.
    QAction* rendererAction(gl::BackendPreference preference) const;
    /// The renderer in use and why ("Rendering on the CPU (2 threads): ..."), as the About box
    /// says it; empty while the service is still choosing.
    QString rendererDescription() const;

    /// Help ▸ Marbler guide (F1) and About Qt.
    QAction* guideAction() const;
    QAction* aboutQtAction() const;
    /// Shows the guide (not modal, one at a time, deleted on close) and returns it.
    QDialog* showGuide();
    /// Shows the About box (not modal, one at a time, deleted on close) and returns it.
    QDialog* showAbout();
    /// Says on the status bar that a file was written (full path, "Show in folder").
    void noteSavedFile(const QString& file);
    SavedFileNotice* savedFileNotice() const;

    /// Colourways (ColourwaysController.h), Breed ▸ Colourways: while on, the grid breeds only
    /// palettes (Colourways.h): Alter varies the parent's palette (the slider sets how much),
    /// Recombine mixes the parents' palettes, Swap and Change initial state are off (their
    /// tooltips say why). Turning it on with one design selected fills a new generation with
    /// that design and eight colourways of it; turning it off returns to ordinary breeding.
    QAction* colourwaysAction() const;
    bool colourwaysMode() const;
    void setColourwaysMode(bool on);
    /// Breed ▸ Export colourway sheet…: the grid's designs as one image (Sheet.h), PNG or TIFF,
    /// rendered off the GUI thread with a progress dialog; `file` empty asks for one
    /// (askSaveFile). The status bar notes the file when written. Returns whether it started.
    bool exportColourwaySheet(const QString& file = {});
    QAction* exportSheetAction() const;
    /// Whether a sheet is being written.
    bool sheetExportRunning() const;
    /// The width of a sheet's cells in pixels (default 600; the height follows the design).
    void setSheetCellWidth(int width);

signals:
    /// Every visible design has its final image.
    void renderingFinished();
    /// A design was opened large (tests close the dialog).
    void designOpened(DesignDialog* dialog);
    /// An editor window was opened (tests drive it).
    void editorOpened(EditorWindow* editor);

protected:
    void closeEvent(QCloseEvent* event) override;
    /// Files dropped anywhere but on a cell open like File ▸ Open.
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void buildActions();
    /// The cell Copy design copies: the focused one holding a design, else the first selected
    /// (-1: none).
    int designToCopy() const;
    void buildDocks();
    void readSettings();
    void updateCells();
    /// Puts designs into a generation of their own (every other cell empty) and the kind box to
    /// their kind, saying on the status bar that the grid before is one generation back: designs
    /// of the other kind than the grid's, and the nine of a marbled picture.
    std::vector<int> startGenerationOfKind(const std::vector<Genome>& designs, const QString& description,
                                           int first = 0);
    void updateActions();
    void updateTask();
    void requestRender(int cell, bool previewOnly = false);
    void requestAllRenders();
    void onRendered(std::uint64_t key, const QImage& image, bool final);
    void onRenderFailed(std::uint64_t key, const QString& message);
    void onCellClicked(int index);
    void onFocusMove(int index, int dx, int dy);
    void onOrbit(int index, QPoint delta, bool finished);
    void showCellMenu(int index, const QPoint& globalPos);
    void openFileDialog();
    void marblePictureDialog();
    void saveDesign(int index);
    QString renderCacheKey(int cell) const;
    /// The angle a cell's solid is seen from (while it is being turned, the drag's).
    ViewAngle cellViewAngle(int cell) const;

    RenderService* mRenderer;
    std::uint64_t mCellKeys; ///< the cells' render keys: mCellKeys + index (RenderService::newKeys)
    PopulationModel* mModel;
    std::array<DesignCell*, CellCount> mCells{};
    /// The cell whose solid the user is turning (-1: none) and its angle so far; the angle is
    /// written into the design (PopulationModel::setCellView) once, on release.
    int mOrbitCell = -1;
    ViewAngle mOrbitAngle;
    std::array<bool, CellCount> mFinal{};
    std::array<QString, CellCount> mPendingCacheKey;
    /// The design (genomeId) whose image each cell shows, and the one last asked for.
    std::array<std::string, CellCount> mShownDesign;
    std::array<std::string, CellCount> mRequestedDesign;
    QCache<QString, QImage> mImageCache{48};
    OperatorActions* mOperators = nullptr;
    QAction* mBack = nullptr;
    QAction* mForward = nullptr;
    PopulationBar* mPopulation = nullptr;
    FavouritesShelf* mFavourites = nullptr;
    LineagePanel* mLineage = nullptr;
    SessionsController* mSessions = nullptr;
    ColourwaysController* mColourways = nullptr;
    StatusLine* mStatus = nullptr;
    HelpMenu* mHelp = nullptr;
    RendererMenu* mRendererMenu = nullptr;
    QTimer mResizeTimer;
    QAction* mCopyDesign = nullptr;
    QAction* mPasteDesign = nullptr;
    QAction* mRename = nullptr;
};

/// The caption a cell shows under a design: its name (a bred design's carries " (gN #K)",
/// generation N, design K, as the status bar and the lineage count) and how it was made.
QString designCaption(const Genome& genome);

} // namespace marbler::ui
