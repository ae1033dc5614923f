#pragma once
/// The design open in the editor, and every edit of it as an undoable command. No widgets: the
/// editor window shows it and tests drive it headless.
///
/// Steps are numbered as Growth.h numbers them: the entries of `initial`, then those of
/// `operations`. Any step may be edited, moved, muted or deleted, however far back; the design
/// after it re-forms, since a render is a pure function of the genome.
///
/// A muted step stays in the editor's list but is left out of what is drawn (renderedDesign) and
/// of the genome written to a file, which keeps it aside in `meta.editor.muted` (meta is
/// free-form and kept on save, genome-format.md) so that the editor can put it back on open:
/// every other reader renders exactly what the editor showed.

#include "marbler/Genome.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <QByteArray>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace marbler::ui {

/// One state of the document: the design and its muted flags (EditorDocument.cpp).
struct EditorState;
/// What one edit changed: the steps, flags and fields replaced (EditorDocument.cpp).
struct EditorDelta;

class EditorDocument : public QObject {
    Q_OBJECT
public:
    /// Takes a design as read from a file or handed over by the workbench: steps kept aside in
    /// meta.editor.muted go back into the list, muted. The undo stack starts empty and clean.
    /// The design (and every step an edit brings) is held as a save and a reload give it
    /// (vectors normalised, fields a tool lacks at their defaults), so that a saved or recovered
    /// design equals the one edited, exactly; a design the format refuses is held as it is.
    explicit EditorDocument(Genome design, QObject* parent = nullptr);
    ~EditorDocument() override;

    /// Every step, muted ones included (meta without "editor").
    const Genome& design() const { return mDesign; }
    /// What is drawn: the design without its muted steps.
    Genome renderedDesign() const;
    /// What a file holds: renderedDesign with the muted steps in meta.editor.muted.
    Genome fileGenome() const;

    QUndoStack* undoStack() { return &mUndo; }

    std::size_t stepCount() const;
    const Operation& step(std::size_t i) const;
    /// Whether step i belongs to `initial`.
    bool isInitial(std::size_t i) const { return i < mDesign.initial.size(); }
    bool isMuted(std::size_t i) const;
    /// "comb 3", "drop 1": the tool's name and the step's number from 1 (i + 1, the number the
    /// step list and the timeline show).
    QString stepName(std::size_t i) const;

    // Edits. Each is one undo command named by what changed ("comb 3: spacing 18 → 23").
    // `mergeId` >= 0 merges consecutive commands with the same id into one undo step (a drag of
    // a slider or a handle passes the same id from press to release); -1 never merges.

    /// Adds a step so that it becomes step `at` (stepCount(), the default: after every step),
    /// in `initial` where the tool may stand there and `at` is within it, else in `operations`
    /// (insertionIndex). Returns its step index.
    std::size_t addStep(const Operation& op, std::optional<std::size_t> at = std::nullopt);
    /// Adds several steps as one undo step (a drop pattern, a spray's drops), in their order
    /// from step `at` on (default: after every step). Returns the index of the first.
    std::size_t addSteps(const std::vector<Operation>& ops, const QString& text,
                         std::optional<std::size_t> at = std::nullopt);
    /// The index a step of `tool` added at `at` gets (see addStep).
    std::size_t insertionIndex(Tool tool, std::optional<std::size_t> at) const;
    /// Replaces step i (its tool stays a valid one for its part).
    void setStep(std::size_t i, const Operation& op, int mergeId = -1);
    void removeStep(std::size_t i);
    /// Inserts a copy right after step i; returns the copy's index.
    std::size_t duplicateStep(std::size_t i);
    /// Moves step `from` to index `to` within its own part (initial or operations); a move
    /// across parts is refused (returns false) when the tool is not allowed there.
    bool moveStep(std::size_t from, std::size_t to);
    void setMuted(std::size_t i, bool muted);
    /// Mutes or unmutes steps `first` to `last` as one undo step (a folded group of the list).
    void setMuted(std::size_t first, std::size_t last, bool muted);
    void setPaletteColor(int index, Color color, int mergeId = -1);
    /// Adds an ink to the palette (at most MaxPaletteSize); returns its index or -1.
    int addPaletteColor(Color color);
    void setBackground(Color color, int mergeId = -1);
    void setBleed(double bleed, int mergeId = -1);
    /// Makes the bath wrap (a straight-repeat tile) or not, one undo step; wrapping is refused
    /// (editRefused) where a step cannot wrap.
    void setWrap(bool wrap);
    /// Replaces the whole design (a raster source chosen, a design dropped in), one undo step.
    void replaceDesign(const Genome& design, const QString& text);

    /// The file the design was opened from or saved to (empty: never saved).
    QString fileName() const { return mFileName; }
    void setFileName(const QString& file);
    /// Unsaved changes (the undo stack is not at its clean index).
    bool isModified() const { return !mUndo.isClean(); }
    /// Writes fileGenome() atomically (a temporary renamed over the file) and marks the stack
    /// clean; on failure returns false with the reason in `error` and changes nothing.
    bool saveAs(const QString& file, QString* error);
    /// Marks the design saved in `file` by other means (an image written with it inside): the
    /// stack clean, the file the document's, its bytes the ones known.
    void markSaved(const QString& file);
    /// Marks the design unsaved without an edit: a design recovered after a crash, whose
    /// changes never reached its file.
    void markModified();

    /// Whether the file was changed by someone else since this document read or wrote it (its
    /// bytes differ from those seen then, or it is gone). False without a file.
    bool fileChangedOnDisk() const;
    /// Remembers the file's present bytes as the ones this document knows (after opening it).
    void noteFileOnDisk();

    // History as a tree: an edit made after undoing keeps the undone edits as a branch, so no
    // state is ever unreachable. The undo stack holds the current line of edits; every other
    // line is a branch, shown by the History panel and switched to with one click.

    /// One branch as the History panel names it.
    struct BranchInfo {
        int forkAt = 0;   ///< edits it shares with the current line
        int length = 0;   ///< its edits after the fork
        QString forkText; ///< the last shared edit ("" when it leaves from the opened design)
        QString lastText; ///< its newest edit
    };
    std::vector<BranchInfo> branches() const;
    /// Makes branch `k` the current line, at its newest edit; the line left becomes a branch.
    /// One undo step is not made: the history itself is switched.
    void switchToBranch(std::size_t k);
    /// One line of history: its edits in order, each what it changed.
    struct Line;

    /// The bytes the history holds (the undo stack and every branch): it grows with what the
    /// edits changed, not with the design's size, since only the present design is held whole.
    std::size_t historyBytes() const;

signals:
    /// The design changed (any edit, undo or redo).
    void changed();
    /// Steps were added, removed, moved or muted (the list must be rebuilt), after changed().
    void stepsChanged();
    void modifiedChanged(bool modified);
    void fileNameChanged(const QString& file);
    /// A branch was made, switched to or dropped.
    void branchesChanged();
    /// An edit was not made, and why (a step that cannot lie in a bath that wraps).
    void editRefused(const QString& why);

private:
    friend class EditorCommand;
    /// Applies an edit to the present state (forward) or takes it back; the commands' undo and
    /// redo.
    void applyEdit(const EditorDelta& edit, bool forward);
    /// Before an edit is pushed: a redo tail that the push would drop is kept as a branch.
    void keepRedoBranch();
    Line currentLine() const;
    /// The edit the stack is at now, as shared by its commands and branches (mOpened at index
    /// 0): a state is known by the edit that reached it.
    std::shared_ptr<const EditorDelta> currentState() const;

    Genome mDesign;
    std::vector<bool> mMuted; ///< one flag a step
    QUndoStack mUndo;
    QString mFileName;
    QByteArray mDiskHash;                       ///< the file's bytes (a hash) as last read or written
    std::shared_ptr<const EditorDelta> mOpened; ///< stands for the state at the start of every line
    std::shared_ptr<const EditorDelta> mSaved;  ///< the edit that reached the state last saved (null: none)
    std::vector<std::shared_ptr<Line>> mBranches;
    bool mQuiet = false; ///< a history switch in progress: signals once at its end

public:
    /// Removes ink `index` from the palette as one undo step ("Delete ink 2: #c8553d"). Steps
    /// (muted ones too) that lay it lay `replacement` instead (an index of the palette before
    /// the removal, not `index`); the inks after it move down one. Refused (false, nothing
    /// changed) for an index out of range, or when a step lays the ink and `replacement` is no
    /// other ink.
    bool removePaletteColor(int index, int replacement = -1);
    /// How many steps (muted ones too) lay ink `index`.
    std::size_t inkUseCount(int index) const;

    // ---- Issue 22 (editor): the numbering of rendered steps and the merging of a drag's edits,
    // the document's own, moved here from the editor window.

    /// The document step of a rendered (unmuted) step, if there is one.
    std::optional<std::size_t> documentIndex(std::size_t rendered) const;
    /// The rendered index of a document step (nullopt: muted or out of range).
    std::optional<std::size_t> renderedIndex(std::size_t step) const;
    /// The merge id of an edit: one id from the press of a drag to its release (its last edit
    /// included), -1 for an edit made at once.
    int mergeFor(bool dragging);
    /// Whether a drag's edits are being merged now (from its press to its release).
    bool dragActive() const { return mDragMerge.active; }

private:
    /// One drag, one undo step: the id its edits share.
    struct DragMerge {
        bool active = false;
        int id = 0;
        int next = 1;
    };
    DragMerge mDragMerge;
};

} // namespace marbler::ui
