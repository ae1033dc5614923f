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
#include "editor/Gestures.h"
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

class QAction;
class QActionGroup;
class QComboBox;
class QDialog;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QMenu;
class QPainter;
class QSlider;
class QSplitter;
class QUndoView;

namespace marbler::ui {

class AnimationExportJob;
class ImageWriteJob;
class EditorAutosave;
class EditorCanvas;
class ParamForm;
class PaletteEditor;
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
    QUndoView* historyView() const { return mHistory; }
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

    /// Saves to the document's file, asking for one when it has none; errors are reported.
    bool save();
    /// Asks for a file (the design's name in the folder used last; askSaveFile, which tests
    /// replace) and saves there.
    bool saveAs();
    /// Saves to `file` atomically; errors are reported. Returns success.
    bool saveTo(const QString& file);
    /// What closing with unsaved changes does when the question cannot be asked (tests):
    /// unset asks the user.
    enum class UnsavedAnswer { Save, Discard, Cancel };
    void setUnsavedAnswer(std::optional<UnsavedAnswer> answer) { mUnsavedAnswer = answer; }
    /// Save on a design opened from an image: a new design file (the default), the image written
    /// again with the design inside, or nothing. Unset asks the user.
    enum class ImageSaveAnswer { DesignFile, UpdateImage, Cancel };
    void setImageSaveAnswer(std::optional<ImageSaveAnswer> answer) { mImageSaveAnswer = answer; }
    /// Save on a file that someone else changed since it was opened or saved here. Unset asks.
    enum class DiskChangeAnswer { Overwrite, Reload, SaveAs, Cancel };
    void setDiskChangeAnswer(std::optional<DiskChangeAnswer> answer) { mDiskChangeAnswer = answer; }
    /// Whether an existing file may be replaced by an export (unset asks the user).
    void setOverwriteAnswer(std::optional<bool> answer) { mOverwriteAnswer = answer; }

    /// Reads the document's file again (an undoable replacement of the design, clean after it).
    bool reloadFromDisk();
    /// Renders the design into `image` (PNG or TIFF) at that image's pixel size, with the design
    /// inside, in the background with progress and cancel; the image becomes the document's file.
    /// Returns whether the render started.
    bool writeDesignImage(const QString& image);
    /// Where a step made now goes, in document numbering: after the selected step, else at the
    /// timeline's point (nullopt: after every step).
    std::optional<std::size_t> insertionPoint() const;
    /// The History panel's list of branches (one click switches to one).
    QListWidget* branchList() const { return mBranchList; }

    /// File ▸ Export animation… (asks before replacing a file) and Export image….
    void exportAnimation();
    void exportImage();
    /// Help ▸ Editor guide (F1): how the editor works and every shortcut, from its actions.
    QDialog* showGuide();

    /// The editor open on `file` (the same file by its canonical path), if any.
    static EditorWindow* editorFor(const QString& file);

    /// The files opened or saved in the editor, newest first (QSettings editor/recentFiles).
    static QStringList recentFiles();
    static void addRecentFile(const QString& file);

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
    /// Whether the window may close or its design be left: asks about unsaved changes.
    bool maybeKeepChanges();
    void updateTitle();
    /// The design's name as the title shows it: its file's name, else its own name.
    QString displayName() const;
    void designChanged();
    void stepsChanged();
    void showShown();
    void refreshForm();
    /// Makes ink `index` the one the tools lay, in the palette, the tool panel and the canvas
    /// alike (whichever of them chose it).
    void setCurrentInk(int index);
    /// The canvas's handles for the selected step, at the timeline's end only.
    void updateHandles();
    /// The document step of a rendered (unmuted) step and back.
    std::optional<std::size_t> documentIndex(std::size_t rendered) const;
    std::optional<std::size_t> renderedIndex(std::size_t step) const;
    /// The merge id of an edit: one id from the press of a drag to its release.
    int mergeFor(bool dragging);
    void openFileDialog();
    void fillRecentMenu();
    void startFromRandom();
    void startFromSourceImage();
    /// Whether `file` may be written: it does not exist, or the user lets it be replaced.
    bool mayOverwrite(const QString& file);
    void fillBranchList();

    EditorDocument* mDocument = nullptr;
    RenderService* mRenderer;
    std::unique_ptr<EditorAutosave> mAutosave;
    EditorCanvas* mCanvas = nullptr;
    EditorCanvas* mCompare = nullptr;
    QSplitter* mCanvases = nullptr;
    StepList* mSteps = nullptr;
    ParamForm* mForm = nullptr;
    PaletteEditor* mPalette = nullptr;
    Timeline* mTimeline = nullptr;
    QUndoView* mHistory = nullptr;
    ToolOptions* mToolOptions = nullptr;
    SolidObjectView* mObject = nullptr;
    AnimationExportJob* mAnimationJob = nullptr; ///< Export animation's writer, made on first use
    QComboBox* mSliceAxis = nullptr;
    QSlider* mSlicePosition = nullptr;
    QDoubleSpinBox* mSliceValue = nullptr;
    bool mSliceUpdating = false; ///< the slice's widgets are being set to it (no feedback)
    QActionGroup* mTools = nullptr;
    QMenu* mRecentMenu = nullptr;
    QLabel* mStatus = nullptr;
    ToolSettings mToolSettings;
    Slice mSlice{2, 0.0};
    std::optional<std::size_t> mSelected;
    bool mFormEditing = false; ///< an edit from the form is being applied (no rebuild)
    bool mDragActive = false;
    int mMergeId = 0;
    int mNextMergeId = 1;
    std::optional<UnsavedAnswer> mUnsavedAnswer;
    std::optional<ImageSaveAnswer> mImageSaveAnswer;
    std::optional<DiskChangeAnswer> mDiskChangeAnswer;
    std::optional<bool> mOverwriteAnswer;
    QListWidget* mBranchList = nullptr;
    QLabel* mBranchLabel = nullptr;
    QDialog* mGuide = nullptr;
    ImageWriteJob* mImageJob = nullptr; ///< Save into an image, made on first use
};

/// A solid design on its object, turned by dragging (its angle kept in meta.view), the object
/// chosen from the built-ins or a mesh file. Rendered by the render service, coarse while
/// turning.
class SolidObjectView : public QWidget {
    Q_OBJECT
public:
    SolidObjectView(RenderService* renderer, QWidget* parent = nullptr);
    ~SolidObjectView() override;
    void setDesign(const Genome& design);
    void setMesh(const QString& mesh);
    QString mesh() const { return mMesh; }
    /// The cross-section the editor shows: drawn in the corner as a plane through the block.
    void setSlice(const Slice& slice);
    ViewAngle angle() const { return mAngle; }
    const QImage& image() const { return mImage; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    void request(bool previewOnly);
    void paintSlice(QPainter& p) const;
    RenderService* mRenderer;
    std::uint64_t mKey;
    Genome mDesign;
    QString mMesh = QString::fromLatin1(DefaultMesh);
    ViewAngle mAngle;
    QImage mImage;
    QPointF mLast;
    bool mTurning = false;
    std::optional<Slice> mSlice;
};

} // namespace marbler::ui
