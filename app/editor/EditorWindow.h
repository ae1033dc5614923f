#pragma once
/// The manual editor: one design, made and refined step by step. The canvas in the middle shows
/// the design live (re-rendered at any zoom, coarse first, never on the GUI thread); the mouse
/// tools add steps to it; the step list, the parameter form and the canvas's handles edit any
/// step, however far back; the palette recolours; the history lists every edit (QUndoView) and
/// the timeline scrubs, plays and compares the design's making. A solid design shows the same
/// canvas as a movable cross-section (where clicks place the 3D tools) beside the design on its
/// object.
///
/// Every edit goes through EditorDocument, so undo and redo are exact; the design autosaves to
/// a recovery file (Recovery.h) that the next start offers after a crash.

#include "editor/EditorDocument.h"
#include "editor/EditorFiles.h"
#include "editor/Gestures.h"
#include "editor/SolidObjectView.h"
#include "marbler/Genome.h"
#include "marbler/Mesh.h"
#include "marbler/Sampling.h"
#include "shared/SavedFiles.h"
#include "shared/ViewController.h"

#include <QImage>
#include <QMainWindow>
#include <QPointer>
#include <QString>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

class QActionGroup;
class QDialog;
class QLabel;
class QListWidget;
class QUndoView;

namespace marbler::ui {

class EditorAutosave;
class EditorExports;
class HistoryDock;
class SectionControls;
class EditorCanvas;
class ParamForm;
class PaletteEditor;
class RenameDialog;
class RenderService;
class StepList;
class Timeline;
class ToolOptions;
class SolidObjectView;

/// A fresh design to start from: a blank bath of the default size and background with a
/// three-ink palette (flat or solid).
Genome blankDesign(int dimension);

class EditorWindow : public QMainWindow {
    Q_OBJECT
public:
    /// Opens `design` (read from `file` when given; empty: a design not saved yet). The render
    /// service is shared with the workbench and must outlive the window. `recoveryFolder` is
    /// where the autosave goes (defaultRecoveryFolder(); empty: no autosave).
    EditorWindow(Genome design, RenderService* renderer, const QString& file = {}, QWidget* parent = nullptr,
                 const QString& recoveryFolder = QStringLiteral("<default>"));
    ~EditorWindow() override;

    EditorDocument* document() const { return mDocument; }
    EditorCanvas* canvas() const { return mCanvas; }
    StepList* stepList() const { return mSteps; }
    ParamForm* paramForm() const { return mForm; }
    PaletteEditor* paletteEditor() const { return mPalette; }
    Timeline* timeline() const { return mTimeline; }
    QUndoView* historyView() const;
    ToolOptions* toolOptions() const { return mToolOptions; }
    EditorAutosave* autosave() const { return mAutosave.get(); }

    /// The design the canvas shows now: the rendered design, or its state at the timeline's
    /// point while the timeline is not at the end.
    Genome shownDesign() const;
    /// The step selected in the list (document numbering).
    std::optional<std::size_t> selectedStep() const { return mSelected; }
    void selectStep(std::optional<std::size_t> step);
    void setTool(EditorTool tool);
    EditorTool tool() const;
    /// Solids: the cross-section the canvas shows and where clicks place the 3D tools.
    Slice slice() const { return mSlice; }
    void setSlice(const Slice& slice);

    /// The window's files: open, save, the questions a save asks, the design into an image.
    EditorFiles* files() const { return mFiles; }
    /// File ▸ Save, Save as…, Reload and the design into an image (EditorFiles.h).
    bool save();
    bool saveAs();
    /// Edit ▸ Rename… (F2): asks for the design's name and note (not modal); the rename is one
    /// undo step and the title follows. Returns the dialog.
    RenameDialog* renameDesign();
    bool saveTo(const QString& file);
    bool reloadFromDisk();
    bool writeDesignImage(const QString& image);
    /// The answers tests give to the questions of saving and exporting (EditorFiles.h).
    using UnsavedAnswer = EditorFiles::UnsavedAnswer;
    using ImageSaveAnswer = EditorFiles::ImageSaveAnswer;
    using DiskChangeAnswer = EditorFiles::DiskChangeAnswer;
    void setUnsavedAnswer(std::optional<UnsavedAnswer> answer);
    void setImageSaveAnswer(std::optional<ImageSaveAnswer> answer);
    void setDiskChangeAnswer(std::optional<DiskChangeAnswer> answer);
    void setOverwriteAnswer(std::optional<bool> answer);

    /// Where a step made now goes, in document numbering: after the selected step, else at the
    /// timeline's point (nullopt: after every step).
    std::optional<std::size_t> insertionPoint() const;
    /// The History panel's list of branches (one click switches to one).
    QListWidget* branchList() const;

    /// File ▸ Export animation… (asks before replacing a file) and Export image….
    void exportAnimation();
    void exportImage();
    /// Help ▸ Editor guide (F1): how the editor works and every shortcut, from its actions.
    QDialog* showGuide();

    /// The editor open on `file` (the same file by its canonical path), if any.
    static EditorWindow* editorFor(const QString& file);

    /// The files opened or saved in the editor, newest first (EditorFiles::recentFiles).
    static QStringList recentFiles() { return EditorFiles::recentFiles(); }
    static void addRecentFile(const QString& file) { EditorFiles::addRecentFile(file); }

signals:
    /// "Send to grid": the design goes into the breeding grid as a new design to breed from.
    void sendToGrid(const marbler::Genome& design);
    /// A file was written (the workbench's status bar says where).
    void fileSaved(const QString& file);
    /// File ▸ New design / Open…: the workbench opens another editor.
    void openEditorRequested(const marbler::Genome& design, const QString& file);
    /// File ▸ Recover unsaved designs…: the workbench lists what crashed editors left.
    void recoveriesRequested();

protected:
    void closeEvent(QCloseEvent* event) override;
    /// Undo and Redo keys pressed in a field of this window go to the window's actions.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void buildMenus();
    void buildDocks();
    void wireDocument();
    void updateTitle();
    void designChanged();
    void stepsChanged();
    void showShown();
    void refreshForm();
    /// Makes ink `index` the one the tools lay, in the palette, the tool panel and the canvas
    /// alike (whichever of them chose it).
    void setCurrentInk(int index);
    /// The canvas's handles for the selected step, at the timeline's end only.
    void updateHandles();
    /// A bath that wraps takes only spray and stretch along an axis: the other tools are
    /// disabled (saying why), and Edit ▸ Bath wraps shows the state.
    void updateWrap();

    EditorDocument* mDocument = nullptr;
    std::unique_ptr<EditorAutosave> mAutosave;
    EditorCanvas* mCanvas = nullptr;
    EditorCanvas* mCompare = nullptr;
    StepList* mSteps = nullptr;
    ParamForm* mForm = nullptr;
    PaletteEditor* mPalette = nullptr;
    Timeline* mTimeline = nullptr;
    HistoryDock* mHistory = nullptr;
    EditorFiles* mFiles = nullptr;
    EditorExports* mExports = nullptr;
    ToolOptions* mToolOptions = nullptr;
    SolidObjectView* mObject = nullptr;
    SectionControls* mSection = nullptr; ///< a solid's section and object (none for a flat design)
    QActionGroup* mTools = nullptr;
    QAction* mWrap = nullptr; ///< Edit ▸ Bath wraps
    QLabel* mStatus = nullptr;
    ToolSettings mToolSettings;
    Slice mSlice{2, 0.0};
    std::optional<std::size_t> mSelected;
    bool mFormEditing = false; ///< an edit from the form is being applied (no rebuild)
    QDialog* mGuide = nullptr;
};

} // namespace marbler::ui
