#pragma once
/// The workbench's model: the nine designs of the current generation, the parents the user has
/// selected, every generation since the session began (a tree: back, forward and branches), and
/// the favourites shelf. No widgets here, so the breeding logic is tested without a window.

#include "marbler/Genome.h"
#include "marbler/Mesh.h"
#include "marbler/Operators.h"
#include "marbler/Steer.h"
#include "shared/Lineage.h"
#include "shared/ViewController.h"

#include <QByteArray>
#include <QDateTime>
#include <QObject>
#include <QString>
#include <QStringList>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace marbler::ui {

/// The grid holds this many designs (3 x 3).
inline constexpr int CellCount = 9;

/// What the model keeps of a design that is not in memory (issue 28): enough to name it, find its
/// thumbnail and keep names unique, without the design itself.
struct CellInfo {
    bool present = false;            ///< the cell holds a design
    int dimension = 2;               ///< 2: flat, 3: solid
    std::string contentId;           ///< genomeId() of the design (thumbnails, "less like this")
    std::string id;                  ///< meta.id, or the content id when it has none
    std::optional<std::string> name; ///< meta.name
};

/// One state of the grid: what each cell holds, which cells are parents, and how it came to be.
struct Generation {
    /// The designs. In the model's history only the generations in memory hold them (`held`);
    /// PopulationModel::generation() reads the others back.
    std::array<std::optional<Genome>, CellCount> cells;
    /// Whether `cells` holds the designs; false in the model's history for a generation kept
    /// packed or on disk (issue 28), whose `info` then says what its cells hold.
    bool held = true;
    std::array<CellInfo, CellCount> info{}; ///< set by describeCells() from `cells`
    std::array<bool, CellCount> selected{};
    QString description; ///< "Alter of 1 parent", "New random population", "Opened a.marble.json"
    /// The generation this one grew from (an index into the history, always an earlier one), or
    /// -1 for a root (the session's first generation).
    int parent = -1;
    /// The number the user sees, "Generation 3": 1 for a root, the parent's number + 1 after
    /// (its depth in the tree). Bred designs record it (meta.lineage.generation, "(g3 #7)").
    int number = 1;
    /// The branch it is on, numbered from 1 in the order branches were started: a generation is
    /// on its parent's branch when it is that parent's first child, and starts a new branch
    /// otherwise (and when it is a root other than the first generation).
    int branch = 1;
    std::vector<int> parentCells; ///< the cells whose designs this generation was bred from
};

/// Sets history[k]'s number and branch from its parent and the generations before it (see
/// Generation). The parent must be -1 or an index below k.
void numberGeneration(std::vector<Generation>& history, std::size_t k);
/// Sets a generation's `info` from its cells.
void describeCells(Generation& generation);

/// A design kept aside on the favourites shelf, saved as a genome file.
struct Favourite {
    Genome genome;
    QString file;
};

/// What names a breeding session in the list of kept sessions (SessionStore.h), saved with it.
struct SessionLabel {
    QString name;      ///< empty: none (the document then has no name)
    QDateTime created; ///< invalid: unknown
    bool operator==(const SessionLabel&) const = default;
};

/// The population, its history and the favourites. Every change that alters the grid's designs
/// (breeding, a new random population, loading a file, bringing back a favourite or a design of
/// another generation) adds a generation as a child of the current one, so back/forward undoes
/// and redoes any of them. History is a tree and nothing is ever dropped: a change made after
/// going back starts a new branch beside the old one. Back goes to the parent generation;
/// Forward goes to the child last visited or made from the current generation (the newest child
/// when none has been, as after a resume), so Back then Forward always returns to where one
/// was. A new model holds an empty placeholder grid that is not a generation: the first designs
/// (a random population, opened files) replace it and become generation 1, so there is never
/// an empty grid to go back to.
struct SavedSession;

class PopulationModel : public QObject {
    Q_OBJECT
public:
    explicit PopulationModel(QObject* parent = nullptr);

    /// The seed every random draw of this session derives from (random populations, breeding).
    std::uint64_t sessionSeed() const { return mSessionSeed; }
    void setSessionSeed(std::uint64_t seed) { mSessionSeed = seed; }

    /// The design in a cell (nullptr when empty).
    const Genome* cell(int index) const;
    bool isSelected(int index) const;
    /// Indices of the selected cells, in grid order.
    std::vector<int> selectedCells() const;
    int selectedCount() const;
    /// Toggles a cell's selection; an empty cell cannot be selected.
    void toggleSelected(int index);
    void setSelected(int index, bool selected);
    void clearSelection();

    /// Why an operator cannot run with the current selection, in the window's words and with
    /// what to do about it ("Swap needs exactly 2 parents: click two designs"); empty when it can.
    /// The disabled operators' tooltips and the status bar say this.
    QString whyNot(GeneticOperator op) const;
    /// Keeps the selected parents in their cells and fills every other cell with offspring,
    /// seeded by the session seed and the new generation's index in the history (unique, so
    /// breeding again from a generation one went back to draws anew). Throws marbler::Error
    /// (InputError for a wrong parent count or mixed dimensions).
    void apply(GeneticOperator op, double strength);
    /// apply() in three steps, so that the window breeds off the GUI thread: prepareBreed takes
    /// what the operators need from the population as it is now (and throws what apply() throws
    /// for a request that cannot run), breedPending makes the children on any thread, and
    /// commitBreed makes them the new generation (apply() is the three in a row).
    struct PendingBreed {
        GeneticOperator op = GeneticOperator::Alter;
        SteerRequest steer; ///< steer.breed is the request; steer.rounds only when steered
        bool steered = false;
        bool wildcard = false;
        std::array<bool, CellCount> selected{}; ///< the parents' cells, as they were
        /// The generation bred from, and the history's size then.
        int current = 0;
        std::size_t historySize = 0;
        std::vector<Genome> children; ///< set by breedPending
        std::string explanation;      ///< why, when steered
    };
    PendingBreed prepareBreed(GeneticOperator op, double strength) const;
    /// Touches nothing of the model: safe on any thread. Throws marbler::Error.
    static void breedPending(PendingBreed& pending);
    /// Throws RuntimeFailure when the population has moved on since prepareBreed.
    void commitBreed(PendingBreed pending);
    /// Whether apply() makes its last offspring cell a wildcard (on by default; wildcardChild,
    /// Operators.h): a fresh design of the parents' family, or a free random one without a
    /// family, seeded from the generation's seed, against breeding fatigue. Its
    /// meta.lineage.operator is "wildcard". Off, steering shows no fresh designs either: every
    /// child is then a variation of the picks.
    bool wildcardCell() const { return mWildcard; }
    void setWildcardCell(bool on) { mWildcard = on; }
    // --- Steering (issue 26, Steer.h) ---
    /// Whether apply() ranks its offspring by what the picks so far say (on by default in the
    /// window, off in a bare model): steerBreed over pickRounds().
    bool steering() const { return mSteering; }
    void setSteering(bool on) { mSteering = on; }
    /// The rounds of picks that led to the current generation, oldest first: for each bred
    /// generation on the way from the root, its parents' cells (picked) and the other designs
    /// of the generation they were picked from (passed over, or disliked); then the current
    /// generation's selection against its other cells.
    std::vector<PickRound> pickRounds() const;
    /// "Less like this" on a cell's design: steering treats it as passed over, twice as strongly.
    /// Kept with the design's content for the session (not saved).
    void setDisliked(int index, bool disliked);
    bool isDisliked(int index) const;
    /// Why the current generation's children were chosen ("more like your last 3 picks: finer
    /// patterns"); empty when it was not steered.
    QString steerExplanation() const;
    // --- end steering ---
    /// The seed apply() would use for the next generation.
    std::uint64_t nextBreedSeed() const;
    /// Colourways (Colourways.h): keeps the selected parents and fills every other cell with
    /// colourways of them, seeded as apply() is: palette variations of the one parent (`mix`
    /// false, at `strength`) or palettes mixed from the parents (`mix` true). An ordinary
    /// generation, saved with the session like any other; `description` names it (default
    /// "Colourways of 1 parent"). Throws marbler::Error as apply() does.
    void applyColourways(bool mix, double strength, const QString& description = {});
    /// Why applyColourways cannot run with the current selection (empty when it can).
    QString whyNoColourways(bool mix) const;

    /// Replaces the grid with nine random designs of the dimension (2 or 3): of one pattern
    /// family (Families.h) when `family` names one of that dimension, else a mix of the
    /// dimension's families and the free random generator, every cell a different one where
    /// there are enough.
    void newRandomPopulation(int dimension, const std::string& family = {});
    /// Where placeDesigns() puts designs.
    enum class Placement {
        /// Into the selected cells first, then empty ones, then over the rest in grid order.
        IntoSelected,
        /// Never over a parent: into empty cells first, then over designs that are not selected;
        /// the parents stay selected.
        KeepParents,
    };
    /// The cells placeDesigns() would fill with `count` designs, in order (fewer when there is
    /// no room). Lets the window see, before anything changes, which designs would be replaced.
    std::vector<int> placementCells(std::size_t count, Placement placement = Placement::IntoSelected) const;
    /// Puts designs into cells as one new generation, in the order placementCells() gives.
    /// Returns the cells used (designs beyond them are not placed).
    std::vector<int> placeDesigns(const std::vector<Genome>& designs, const QString& description,
                                  Placement placement = Placement::IntoSelected);
    /// Starts a generation of only these designs, from cell `first` on, every other cell empty
    /// and nothing selected: for designs of another kind (flat or solid) than the grid's, which
    /// cannot breed with it. The grid they replace stays a generation back. Returns the cells used.
    std::vector<int> startGenerationOf(const std::vector<Genome>& designs, const QString& description,
                                       int first = 0);
    /// Puts one design into a given cell as a new generation.
    void setCell(int index, const Genome& genome, const QString& description);
    /// Changes the locks of a cell's design in place (not a new generation: locks are a
    /// property of the design the user is steering, not a breeding step).
    void setCellLocks(int index, const Locks& locks);
    /// Changes the angle a cell's solid design is seen from, in place like the locks (the
    /// angle lives in the design's meta.view, so it travels with it).
    void setCellView(int index, const ViewAngle& view);
    /// Names a cell's design (meta.name, and meta.note; an empty note removes it), in place like
    /// the locks. A name another design of the session has (any generation, a favourite) gets a
    /// number: a second "Harbour Green" is "Harbour Green 2". With `exact`, the name is kept as
    /// given (a file name the user chose). Returns the name given; empty when the cell is empty.
    QString renameCell(int index, const QString& name, const QString& note, bool exact = false);
    /// Names a favourite, its file written again; the name made unique as renameCell does.
    /// Returns the name given; empty when there is no such favourite or its file cannot be written.
    QString renameFavourite(int index, const QString& name, const QString& note);
    /// Every name the session's designs have (all generations, the favourites), but those of the
    /// design with id `except` (a design keeps its own name).
    std::set<std::string> sessionNames(const std::string& except = {}) const;

    /// Generation history: every generation in the order they were made (a child always after
    /// its parent), each naming its parent. Only a few generations hold their designs in memory
    /// (`Generation::held`: the current one and the few last used); read the designs of any
    /// generation with generation(), which brings them back.
    const Generation& current() const { return mHistory[std::size_t(mCurrent)]; }
    const std::vector<Generation>& history() const { return mHistory; }
    /// A generation with its designs, read back (from the model's packed copy or the session's
    /// folder) when they were not in memory. The reference stays valid until the next call that
    /// may bring another generation back (generation(), pickRounds(), a new generation). When
    /// they cannot be read back its cells are empty, and generationUnreadable says why.
    const Generation& generation(int index) const;
    /// The bytes the history holds in memory: designs held, packed generations, the small
    /// fields (an estimate of the designs' size from their text). For the soak test and bench.
    std::size_t historyBytes() const;
    /// How many generations hold their designs in memory besides the current one.
    static constexpr int HeldGenerations = 8;
    int currentIndex() const { return mCurrent; }
    /// The generations grown from one (indices, oldest first).
    std::vector<int> children(int index) const;
    /// How the user names a generation: its number, with the branch after the first branch
    /// ("3", "3 (branch 2)"), as in "Generation 3 (branch 2)". The status bar, the lineage and
    /// the messages all say this.
    QString generationLabel(int index) const;
    /// Whether no design has been put in yet (the placeholder before generation 1).
    bool isEmptyWorkbench() const { return mEmptyStart; }
    bool canGoBack() const { return !mEmptyStart && current().parent >= 0; }
    bool canGoForward() const { return forwardTarget() >= 0; }
    /// To the parent generation.
    void goBack();
    /// To the child last visited or made from here (the newest when none was).
    void goForward();
    /// Jumps to any generation of any branch; Forward then retraces the way to it.
    void goTo(int index);

    /// Favourites: the folder they live in (created when needed). Default: the app data folder's
    /// "favourites", or $MARBLER_FAVOURITES_DIR when set.
    QString favouritesFolder() const { return mFavouritesFolder; }
    /// Sets the folder and loads what it holds; returns one message per file that did not load.
    QStringList setFavouritesFolder(const QString& folder);
    const std::vector<Favourite>& favourites() const { return mFavourites; }
    /// Saves a copy of the design to the folder. Throws marbler::Error when it cannot be saved.
    void addFavourite(const Genome& genome);
    /// Removes a favourite: its file goes into the favourites folder's trash (`.trash`, which
    /// the shelf never reads), from where restoreFavourite() brings it back. Returns the trashed
    /// file, empty when nothing was removed. Throws RuntimeFailure when the file cannot be moved
    /// (the favourite then stays).
    QString removeFavourite(int index);
    /// Brings a removed favourite back from the trash onto the shelf; returns whether it could.
    bool restoreRemovedFavourite(const QString& trashed);
    /// The files removed from the shelf, the most recent last (for "Restore removed favourite").
    const QStringList& removedFavourites() const { return mRemovedFavourites; }
    /// The trash folder of the favourites folder.
    QString favouritesTrashFolder() const;
    /// Re-reads the folder; returns one message per file that did not load.
    QStringList reloadFavourites();

    /// The default favourites folder (see favouritesFolder()).
    static QString defaultFavouritesFolder();

    /// Session autosave (Session.h): with a file set, the whole session (every generation, the
    /// current one, the seed, the kind and the object) is written to it atomically after every
    /// change of the population: a new generation, back/forward, a lock changed, the object
    /// changed. Selecting parents alone does not write; the selection goes with the next save.
    /// An empty workbench is never written. Setting a file writes it at once. Empty: no autosave.
    void setSessionFile(const QString& file);
    QString sessionFile() const { return mSessionFile; }
    /// Writes the session now; false (and sessionSaveFailed) when it could not be written.
    bool saveSession();
    /// Replaces the history with a saved one (its generations, current generation, seed and
    /// object), then autosaves as after any change.
    void restoreSession(SavedSession session);
    /// The session's name and creation time, saved with it; setting them autosaves.
    const SessionLabel& sessionLabel() const { return mSessionLabel; }
    void setSessionLabel(const SessionLabel& label);
    /// The object solid designs are shown on (a built-in name or a mesh file's path), kept with
    /// the session.
    QString mesh() const { return mMesh; }
    void setMesh(const QString& mesh);
    /// The object flat designs are shown on, laid on its texture coordinates (a built-in name or
    /// a mesh file's path); empty (the default): flat. Kept with the session.
    QString flatMesh() const { return mFlatMesh; }
    void setFlatMesh(const QString& mesh);
    /// The object a design of `dimension` is shown on: mesh() or flatMesh() (empty: flat).
    QString objectFor(int dimension) const { return dimension == 3 ? mMesh : mFlatMesh; }
    /// The kind of the current grid: the dimension of its first design (2 when empty).
    int populationDimension() const;

signals:
    /// The designs of the grid changed (a new generation or going back/forward).
    void populationChanged();
    /// One cell's design changed in place (locks, view angle).
    void cellChanged(int index);
    void selectionChanged();
    void historyChanged();
    void favouritesChanged();
    /// The session could not be autosaved (the message names the file and the reason).
    void sessionSaveFailed(const QString& message);
    /// A generation's designs could not be read back from the session's folder (a file deleted
    /// or damaged behind the window's back); the message names the file and the reason.
    void generationUnreadable(const QString& message);

private:
    /// Adds a generation as a child of the current one (a root when it replaces the empty
    /// placeholder) and makes it current.
    void pushGeneration(Generation generation);
    /// Gives a new generation's designs names no other design of the session has.
    void uniqueNames(Generation& generation) const;
    /// The generation goForward() goes to, -1 when the current one has no child.
    int forwardTarget() const;
    /// Makes a generation current and remembers the way to it for Forward.
    void setCurrent(int index);
    void autosave();
    /// Tells the views that the current generation (population, selection, history) changed,
    /// and saves the session.
    void currentGenerationChanged();
    Generation& currentMutable() { return mHistory[std::size_t(mCurrent)]; }
    /// The current generation's designs changed in place: its info and its file are redone.
    void currentChangedInPlace();
    /// The rounds apply() steers by: the newest of pickRounds() that steerBreed reads.
    std::vector<PickRound> steerRounds(const std::vector<Genome>& parents) const;
    /// Brings a generation's designs back into memory; false (and generationUnreadable) when they
    /// cannot be read back.
    bool bringBack(int index);
    /// The current generation's selection changed: its file is to be written again.
    void selectionEdited();
    /// The rounds of pickRounds(), newest first, stopping once `enough` says so.
    template <typename Enough> std::vector<PickRound> roundsNewestFirst(Enough enough) const;
    /// Marks a generation used; lets the least recently used ones go beyond HeldGenerations.
    void touch(int index) const;
    /// Drops a generation's designs from memory, packing them unless its file on disk is current.
    void release(int index) const;

    std::uint64_t mSessionSeed = 1;
    mutable std::vector<Generation> mHistory; ///< designs brought back by generation() (const)
    int mCurrent = 0;
    /// Per generation, the child Forward goes to (-1: the newest child). Not saved: after a
    /// resume the way to the current generation is remembered again.
    std::vector<int> mForwardChild;
    bool mEmptyStart = true;
    bool mWildcard = true;
    bool mSteering = false;               ///< steering (issue 26)
    std::set<std::string> mDisliked;      ///< genomeIds marked "less like this" (issue 26)
    std::map<int, QString> mExplanations; ///< per steered generation, why (issue 26)
    QString mFavouritesFolder;
    std::vector<Favourite> mFavourites;
    QString mSessionFile;
    /// Per generation, how its designs are kept when not in memory (issue 28).
    struct Stored {
        QByteArray packed; ///< the generation's file text, compressed; empty: on disk (or held)
        bool dirty = true; ///< its file in mDiskFolder is missing or older than the generation
    };
    mutable std::vector<Stored> mStored;
    /// The generations holding designs besides the current one, the most recently used last.
    mutable std::vector<int> mHeld;
    /// The folder whose generation files are current for the generations not dirty (the
    /// session's generations folder, Session.h); empty: none.
    QString mDiskFolder;
    QString mMesh = QString::fromLatin1(DefaultMesh);
    QString mFlatMesh;
    SessionLabel mSessionLabel;
    QStringList mRemovedFavourites;
};

} // namespace marbler::ui
