// The editor window: the document wired to the canvas, the panels and the history.

#include "editor/EditorWindow.h"
#include "marbler/Mesh.h"

#include "editor/BathSizes.h"
#include "editor/EditorCanvas.h"
#include "editor/EditorExports.h"
#include "editor/HistoryDock.h"
#include "editor/PaletteEditor.h"
#include "editor/ParamForm.h"
#include "editor/Recovery.h"
#include "editor/StepList.h"
#include "editor/Timeline.h"
#include "editor/ToolOptions.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Growth.h"
#include "marbler/Params.h"
#include "shared/BakeObject.h"
#include "shared/DesignDialog.h"
#include "shared/Help.h"
#include "shared/Language.h"
#include "shared/Lineage.h"
#include "shared/RenameDialog.h"
#include "shared/RenderService.h"
#include "shared/SectionControls.h"
#include "shared/StartDialog.h"

#include <QAbstractSpinBox>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTextBrowser>
#include <QToolBar>
#include <QUndoView>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <utility>

namespace marbler::ui {

namespace {

/// The steps panel's width: the list and the form's labels and fields, no more (the form
/// scrolls when a step has more), so that the canvas and the object view get the room.
constexpr int StepsPanelWidth = 360;
/// The tool panel's width: the widest tool's options but for long words (they scroll).
constexpr int ToolPanelWidth = 230;

/// Every editor open in this process, so that a file is edited in one window at a time.
QList<QPointer<EditorWindow>>& openEditors() {
    static QList<QPointer<EditorWindow>> editors;
    return editors;
}

} // namespace

Genome blankDesign(int dimension) {
    Genome g;
    g.dimension = dimension == 3 ? 3 : 2;
    g.palette = {Color{0x1f, 0x4e, 0x79}, Color{0xc8, 0x55, 0x3d}, Color{0x2a, 0x9d, 0x8f}};
    g.meta.name = dimension == 3 ? "Untitled solid" : "Untitled design";
    return g;
}

// ---- EditorWindow -------------------------------------------------------------------------

EditorWindow::EditorWindow(Genome design, RenderService* renderer, const QString& file, QWidget* parent,
                           const QString& recoveryFolder)
    : QMainWindow(parent) {
    setAttribute(Qt::WA_DeleteOnClose);
    setObjectName(QStringLiteral("editorWindow"));
    openEditors().append(this);
    mDocument = new EditorDocument(std::move(design), this);
    mFiles = new EditorFiles(mDocument, this, [this] { return mSlice; });
    connect(mFiles, &EditorFiles::message, this,
            [this](const QString& text, int ms) { statusBar()->showMessage(text, ms); });
    connect(mFiles, &EditorFiles::fileSaved, this, &EditorWindow::fileSaved);
    connect(mFiles, &EditorFiles::openEditorRequested, this, &EditorWindow::openEditorRequested);
    connect(mFiles, &EditorFiles::reloaded, this, [this] { selectStep(std::nullopt); });
    if (!file.isEmpty()) {
        mDocument->setFileName(file);
        mDocument->noteFileOnDisk();
        addRecentFile(file);
    }
    const QString folder =
        recoveryFolder == QStringLiteral("<default>") ? defaultRecoveryFolder() : recoveryFolder;
    if (!folder.isEmpty()) mAutosave = std::make_unique<EditorAutosave>(mDocument, folder);

    const int dimension = mDocument->design().dimension;
    if (dimension == 3) mSlice = Slice{2, mDocument->design().size.z / 2.0};

    mCanvas = new EditorCanvas(renderer, this);
    mCanvas->setObjectName(QStringLiteral("editorCanvas"));
    mCompare = new EditorCanvas(renderer, this);
    mCompare->setObjectName(QStringLiteral("compareCanvas"));
    mCompare->setTool(EditorTool::Pick);
    mCompare->hide();
    auto* canvases = new QSplitter(Qt::Horizontal, this);
    canvases->addWidget(mCanvas);
    canvases->addWidget(mCompare);
    if (dimension == 3) {
        mObject = new SolidObjectView(renderer, this);
        mObject->setObjectName(QStringLiteral("objectView"));
        canvases->addWidget(mObject);
        // Issue 23: the section's plane dragged in the object view's corner turns it.
        connect(mObject, &SolidObjectView::sliceTurned, this, &EditorWindow::setSlice);
        mCanvas->setSlice(mSlice);
        mCompare->setSlice(mSlice);
    } else {
        // ---- Issue 23 (flatui): a flat design on an object beside the canvas, on demand
        // (View ▸ Show on object), its object chosen in the view's corner.
        mObject = new SolidObjectView(renderer, this);
        mObject->setObjectName(QStringLiteral("objectView"));
        mObject->offerObjects();
        canvases->addWidget(mObject);
        mObject->setVisible(QSettings().value(QStringLiteral("editor/objectPreview"), false).toBool());
    }
    setCentralWidget(canvases);
    mExports = new EditorExports(
        mDocument, renderer, mFiles, this, [this] { return mSlice; }, mObject);
    connect(mExports, &EditorExports::message, this,
            [this](const QString& text, int ms) { statusBar()->showMessage(text, ms); });
    connect(mExports, &EditorExports::fileSaved, this, &EditorWindow::fileSaved);

    buildDocks();
    buildMenus();
    wireDocument();
    // The canvas gets most of the room; the panels keep what their widgets need.
    canvases->setStretchFactor(0, 3);
    if (mObject) {
        // The section and the object share the middle, three to two.
        canvases->setStretchFactor(2, 2);
        canvases->setSizes({600, 0, 400});
    }
    const auto dock = [this](const char* name) { return findChild<QDockWidget*>(QLatin1String(name)); };
    resizeDocks({dock("stepsDock"), dock("paletteDock")}, {StepsPanelWidth + 20, 220}, Qt::Horizontal);
    resizeDocks({dock("stepsDock"), dock("historyDock")}, {600, 120}, Qt::Vertical);
    resizeDocks({dock("paletteDock"), dock("toolDock")}, {150, 400}, Qt::Vertical);

    if (dimension == 3) setSlice(mSlice);
    // Undo and Redo from anywhere in the window, a text field with the focus included.
    qApp->installEventFilter(this);
    mToolSettings.color = 0;
    mCanvas->setToolSettings(mToolSettings);
    setTool(Tool::Drop);
    stepsChanged();
    designChanged();
    updateTitle();
    // A laptop's screen holds it whole (1,366 x 768 and up); a remembered size comes next.
    QSize size(1280, 860);
    if (const QScreen* screen = QGuiApplication::primaryScreen())
        size = size.boundedTo(screen->availableGeometry().size() - QSize(16, 48));
    resize(size);
    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("editor/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("editor/state")).toByteArray());
}

EditorWindow::~EditorWindow() {
    openEditors().removeAll(this);
}

bool EditorWindow::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride && isUndoKey(static_cast<QKeyEvent*>(event))) {
        // A spin box or line edit of this window would take the key for its own text undo.
        auto* widget = qobject_cast<QWidget*>(watched);
        if (widget && isAncestorOf(widget) &&
            (qobject_cast<QAbstractSpinBox*>(widget) || qobject_cast<QLineEdit*>(widget))) {
            event->ignore();
            return true;
        }
    }
    return QMainWindow::eventFilter(watched, event);
}

EditorWindow* EditorWindow::editorFor(const QString& file) {
    if (file.isEmpty()) return nullptr;
    const QString wanted = canonicalFile(file);
    for (const QPointer<EditorWindow>& e : openEditors())
        if (e && !e->mDocument->fileName().isEmpty() && canonicalFile(e->mDocument->fileName()) == wanted)
            return e;
    return nullptr;
}

void EditorWindow::buildDocks() {
    const int dimension = mDocument->design().dimension;

    auto* stepsPanel = new QWidget(this);
    auto* stepsLayout = new QVBoxLayout(stepsPanel);
    stepsLayout->setContentsMargins(4, 4, 4, 4);
    mSteps = new StepList(stepsPanel);
    mSteps->setObjectName(QStringLiteral("stepList"));
    mForm = new ParamForm(stepsPanel);
    mForm->setObjectName(QStringLiteral("paramForm"));
    // The form scrolls inside a panel of its own width: a step with many fields (a 3D comb) or a
    // tool switched never widens the dock, so the canvas never moves by itself.
    auto* formScroll = new QScrollArea(stepsPanel);
    formScroll->setObjectName(QStringLiteral("paramScroll"));
    formScroll->setWidget(mForm);
    formScroll->setWidgetResizable(true);
    formScroll->setFrameShape(QFrame::NoFrame);
    formScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    formScroll->setMinimumWidth(StepsPanelWidth);
    auto* split = new QSplitter(Qt::Vertical, stepsPanel);
    split->addWidget(mSteps);
    split->addWidget(formScroll);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);
    split->setSizes({200, 300});
    stepsLayout->addWidget(split);
    auto* stepsDock = new QDockWidget(tr("Steps"), this);
    stepsDock->setObjectName(QStringLiteral("stepsDock"));
    stepsDock->setWidget(stepsPanel);
    addDockWidget(Qt::RightDockWidgetArea, stepsDock);

    mPalette = new PaletteEditor(this);
    mPalette->setObjectName(QStringLiteral("paletteEditor"));
    auto* paletteDock = new QDockWidget(tr("Inks"), this);
    paletteDock->setObjectName(QStringLiteral("paletteDock"));
    paletteDock->setWidget(mPalette);
    addDockWidget(Qt::LeftDockWidgetArea, paletteDock);

    mToolOptions = new ToolOptions(this);
    mToolOptions->setObjectName(QStringLiteral("toolOptions"));
    mToolOptions->setDimension(dimension); // a solid's circle and sphere: their axis row
    auto* toolDock = new QDockWidget(tr("Tool"), this);
    toolDock->setObjectName(QStringLiteral("toolDock"));
    auto* toolPanel = new QWidget(this);
    auto* toolLayout = new QVBoxLayout(toolPanel);
    toolLayout->setContentsMargins(4, 4, 4, 4);
    toolLayout->addWidget(mToolOptions);
    if (dimension == 3) {
        mSection = new SectionControls([this] { return mDocument->design().size; }, mSlice, toolPanel);
        mSection->setObjectName(QStringLiteral("sectionControls"));
        toolLayout->addWidget(mSection);
        connect(mSection, &SectionControls::sliceChosen, this, &EditorWindow::setSlice);
        connect(mSection, &SectionControls::meshChosen, this,
                [this](const QString& mesh) { mObject->setMesh(mesh); });
    }
    toolLayout->addStretch();
    // As the form: the options of the tool chosen scroll in a panel of their own width, so that
    // switching tools never moves the canvas.
    auto* toolScroll = new QScrollArea(this);
    toolScroll->setObjectName(QStringLiteral("toolScroll"));
    toolScroll->setWidget(toolPanel);
    toolScroll->setWidgetResizable(true);
    toolScroll->setFrameShape(QFrame::NoFrame);
    toolScroll->setMinimumWidth(ToolPanelWidth);
    toolDock->setWidget(toolScroll);
    addDockWidget(Qt::LeftDockWidgetArea, toolDock);

    mHistory = new HistoryDock(mDocument, this);
    connect(mHistory, &HistoryDock::message, this,
            [this](const QString& text, int ms) { statusBar()->showMessage(text, ms); });
    addDockWidget(Qt::RightDockWidgetArea, mHistory);

    mTimeline = new Timeline(this);
    mTimeline->setObjectName(QStringLiteral("timeline"));
    auto* timelineDock = new QDockWidget(tr("Timeline"), this);
    timelineDock->setObjectName(QStringLiteral("timelineDock"));
    timelineDock->setWidget(mTimeline);
    addDockWidget(Qt::BottomDockWidgetArea, timelineDock);

    mStatus = new QLabel(this);
    statusBar()->addPermanentWidget(mStatus);
}

void EditorWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QMenu* newMenu = file->addMenu(tr("&New design"));
    newMenu->addAction(tr("Blank &flat bath"), this, [this] { emit openEditorRequested(blankDesign(2), {}); })
        ->setShortcut(QKeySequence::New);
    newMenu->addAction(tr("Blank &solid block"), this,
                       [this] { emit openEditorRequested(blankDesign(3), {}); });
    newMenu->addAction(tr("&Random design"), mFiles, &EditorFiles::startFromRandom);
    newMenu->addAction(tr("From a &picture…"), mFiles, &EditorFiles::startFromSourceImage)
        ->setToolTip(tr("A flat design whose bath is a picture (its source)"));
    file->addAction(tr("&Open…"), mFiles, &EditorFiles::openFileDialog)->setShortcut(QKeySequence::Open);
    QMenu* recent = file->addMenu(tr("Open &recent"));
    connect(recent, &QMenu::aboutToShow, mFiles, [this, recent] { mFiles->fillRecentMenu(recent); });
    file->addSeparator();
    file->addAction(tr("&Save"), this, &EditorWindow::save)->setShortcut(QKeySequence::Save);
    // Ctrl+Shift+S everywhere: QKeySequence::SaveAs is empty on some desktops (X11 without a
    // platform theme).
    file->addAction(tr("Save &as…"), this, &EditorWindow::saveAs)
        ->setShortcut(QKeySequence(tr("Ctrl+Shift+S")));
    file->addAction(tr("&Export image…"), this, &EditorWindow::exportImage)
        ->setShortcut(QKeySequence(tr("Ctrl+E")));
    file->addAction(tr("Export &animation…"), this, &EditorWindow::exportAnimation)
        ->setShortcut(QKeySequence(tr("Ctrl+Shift+E")));
    // The design, flat or solid, baked onto a built-in object or a mesh file (BakeObject.h).
    file->addMenu(makeBakeMenu(
        this, [this] { return mDocument->renderedDesign(); }, {},
        [this](const QString& baked) {
            statusBar()->showMessage(tr("Baked onto %1").arg(QDir::toNativeSeparators(baked)), 6000);
        }));
    file->addSeparator();
    QAction* send = file->addAction(tr("Send to &grid"), this, [this] {
        emit sendToGrid(mDocument->renderedDesign());
        statusBar()->showMessage(tr("Sent to the breeding grid"), 4000);
    });
    send->setShortcut(QKeySequence(tr("Ctrl+G")));
    send->setToolTip(tr("Put this design into the breeding grid as a new design to breed from"));
    file->addSeparator();
    QAction* recover =
        file->addAction(tr("Recover &unsaved designs…"), this, [this] { emit recoveriesRequested(); });
    recover->setObjectName(QStringLiteral("recoverAction"));
    recover->setToolTip(
        tr("Designs that editors left unsaved when Marbler stopped, kept until you discard them"));
    file->addSeparator();
    file->addAction(tr("&Close"), this, &QWidget::close)->setShortcut(QKeySequence::Close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = mDocument->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = mDocument->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    QAction* rename = edit->addAction(tr("Re&name…"), this, [this] { renameDesign(); });
    rename->setObjectName(QStringLiteral("renameDesignAction"));
    rename->setShortcut(QKeySequence(Qt::Key_F2));
    rename->setStatusTip(tr("Names the design and gives it a note (one undo step)"));
    edit->addSeparator();
    // The step list's own actions (Ctrl+D, Del, M), for the whole window: one action a key, as
    // two with the same key would be ambiguous where both apply and neither would run.
    for (QAction* action : mSteps->actions()) {
        action->setShortcutContext(Qt::WindowShortcut);
        edit->addAction(action);
    }
    edit->addSeparator();
    mWrap = edit->addAction(tr("Bath &wraps (straight repeat)"));
    mWrap->setObjectName(QStringLiteral("bathWraps"));
    mWrap->setCheckable(true);
    connect(mWrap, &QAction::triggered, this, [this](bool on) { mDocument->setWrap(on); });

    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    QToolBar* bar = addToolBar(tr("Tools"));
    bar->setObjectName(QStringLiteral("toolsBar"));
    mTools = new QActionGroup(this);
    const int dimension = mDocument->design().dimension;
    for (const EditorTool t : editorTools()) {
        if (!toolAvailable(t, dimension)) continue;
        QAction* a = tools->addAction(toolName(t));
        a->setCheckable(true);
        a->setData(t.index());
        a->setToolTip(ui::toolTip(t));
        a->setShortcut(toolShortcut(t));
        a->setObjectName(QStringLiteral("tool-") +
                         QString::fromUtf8(toolId(t).data(), qsizetype(toolId(t).size())));
        mTools->addAction(a);
        bar->addAction(a);
        connect(a, &QAction::triggered, this, [this, t] { setTool(t); });
    }

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(tr("&Fit"), this, [this] { mCanvas->fitView(); })->setShortcut(QKeySequence(tr("0")));
    view->addAction(tr("Zoom &in"), this, [this] { mCanvas->zoomIn(); })->setShortcut(QKeySequence::ZoomIn);
    view->addAction(tr("Zoom &out"), this, [this] { mCanvas->zoomOut(); })
        ->setShortcut(QKeySequence::ZoomOut);
    view->addAction(tr("&Compare two states"), this,
                    [this] { mTimeline->setComparing(!mTimeline->comparing()); })
        ->setShortcut(QKeySequence(tr("Ctrl+K")));
    view->addAction(tr("&Play the making"), this,
                    [this] { mTimeline->playing() ? mTimeline->stop() : mTimeline->play(); })
        ->setShortcut(QKeySequence(Qt::Key_P));

    // ---- Issue 23 (flatui): a flat design's object preview beside the canvas.
    if (mObject && mDocument->design().dimension != 3) {
        QAction* onObject = view->addAction(tr("Show on &object"));
        onObject->setObjectName(QStringLiteral("showOnObject"));
        onObject->setCheckable(true);
        onObject->setChecked(mObject->isVisibleTo(this));
        onObject->setShortcut(QKeySequence(tr("Ctrl+Shift+O")));
        onObject->setToolTip(tr("Show the design on an object beside the canvas, updated after each edit"));
        connect(onObject, &QAction::toggled, this, [this](bool on) {
            QSettings().setValue(QStringLiteral("editor/objectPreview"), on);
            mObject->setVisible(on);
        });
    }

    // ---- Issue 27 (fix-canvas): the repeat preview, the bath's shapes in New design.
    QMenu* repeat = view->addMenu(tr("&Repeat preview"));
    repeat->setObjectName(QStringLiteral("repeatPreviewMenu"));
    auto* repeatGroup = new QActionGroup(repeat);
    using Repeat = EditorCanvas::RepeatPreview;
    struct RepeatEntry {
        Repeat mode;
        QString name, key;
        const char* id;
    };
    for (const RepeatEntry& e :
         {RepeatEntry{Repeat::Off, tr("&Off"), QString(), "repeatOff"},
          RepeatEntry{Repeat::Plain, tr("&Plain repeat (3 × 3)"), tr("Ctrl+Shift+R"), "repeatPlain"},
          RepeatEntry{Repeat::Mirror, tr("&Mirror repeat (3 × 3)"), tr("Ctrl+Shift+M"), "repeatMirror"}}) {
        const Repeat mode = e.mode;
        QAction* a = repeat->addAction(e.name, this, [this, mode] { mCanvas->setRepeatPreview(mode); });
        a->setObjectName(QString::fromLatin1(e.id));
        a->setCheckable(true);
        a->setChecked(mode == Repeat::Off);
        if (!e.key.isEmpty()) a->setShortcut(QKeySequence(e.key));
        repeatGroup->addAction(a);
    }
    repeat->setToolTip(
        tr("Show the design tiled 3 × 3, plainly or as the mirror repeat tile, to judge its seams"));
    addBathSizeMenus(newMenu, [this](const Genome& g) { emit openEditorRequested(g, {}); });
    addLanguageMenu(view, this); // issue 25: View ▸ Language
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* guide = help->addAction(tr("Editor &guide"), this, &EditorWindow::showGuide);
    guide->setObjectName(QStringLiteral("editorGuideAction"));
    guide->setShortcut(QKeySequence(Qt::Key_F1));
    guide->setToolTip(tr("How the editor works, and every keyboard shortcut"));
}

QDialog* EditorWindow::showGuide() {
    if (!mGuide) {
        mGuide = new QDialog(this);
        mGuide->setObjectName(QStringLiteral("editorGuide"));
        mGuide->setWindowTitle(tr("Marbler editor guide"));
        auto* browser = new QTextBrowser(mGuide);
        browser->setObjectName(QStringLiteral("guideBrowser"));
        auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, mGuide);
        connect(buttons, &QDialogButtonBox::rejected, mGuide, &QDialog::close);
        auto* layout = new QVBoxLayout(mGuide);
        layout->addWidget(browser, 1);
        layout->addWidget(buttons);
        mGuide->resize(560, 640);
    }
    const QString intro = tr(
        "<h2>The editor</h2>"
        "<p>A design is a list of steps: inks dropped on the bath, then strokes that move them. Pick a tool, "
        "then click or drag on the canvas; a new step goes after the selected step (or at the timeline's "
        "point) and the canvas shows the design just after it. The stylus draws free-hand: its path follows "
        "the drag (a pen's pressure too), the panel sets its pull, reach and rake, and its path's points "
        "are its handles.</p>"
        "<p>Select a step to change it in the form or with its handles, however far back; mute, duplicate, "
        "move or delete it from the list. Undo and redo work from anywhere; edits you undo and then leave "
        "by making another stay under History ▸ Other branches, one click away.</p>"
        "<p>The timeline scrubs through the making of the design, plays it and compares two states. "
        "Inks holds the palette and the bath's colour.</p>"
        "<h3>Keys</h3>");
    mGuide->findChild<QTextBrowser*>(QStringLiteral("guideBrowser"))
        ->setHtml(intro + shortcutTableHtml(shortcutActions(this)));
    mGuide->show();
    mGuide->raise();
    return mGuide;
}

void EditorWindow::wireDocument() {
    connect(mDocument, &EditorDocument::changed, this, &EditorWindow::designChanged);
    connect(mDocument, &EditorDocument::stepsChanged, this, &EditorWindow::stepsChanged);
    connect(mDocument, &EditorDocument::modifiedChanged, this, &EditorWindow::updateTitle);
    connect(mDocument, &EditorDocument::fileNameChanged, this, &EditorWindow::updateTitle);
    connect(mDocument, &EditorDocument::editRefused, this, [this](const QString& why) {
        statusBar()->showMessage(why, 12000);
        // The form shows the design's values again, not the refused one.
        refreshForm();
        updateWrap();
    });
    // A rename (and its undo) changes the title.
    connect(mDocument, &EditorDocument::changed, this, &EditorWindow::updateTitle);

    // Gestures: one drag, one step.
    connect(mCanvas, &EditorCanvas::stepsMade, this,
            [this](const std::vector<Operation>& ops, const QString& text) {
                if (ops.empty()) return;
                // Where the user works: after the selected step, else at the timeline's point.
                const std::optional<std::size_t> at = insertionPoint();
                const std::size_t first = ops.size() == 1 ? mDocument->addStep(ops.front(), at)
                                                          : mDocument->addSteps(ops, text, at);
                const std::size_t last = first + ops.size() - 1;
                if (ops.size() == 1)
                    selectStep(first);
                else
                    selectStep(last);
                // The canvas shows the design just after what was added: all of it when that is the end,
                // else up to the new steps (the timeline says where), so new ink is seen where it went.
                const auto rendered = mDocument->renderedIndex(last);
                const std::size_t total = stepCount(mDocument->renderedDesign());
                if (!rendered || *rendered + 1 >= total) {
                    mTimeline->setGrowth(double(total));
                } else {
                    mTimeline->setGrowth(double(*rendered + 1));
                    statusBar()->showMessage(
                        tr("Added as step %1 of %2; the timeline shows the design up to it (End shows all)")
                            .arg(*rendered + 1)
                            .arg(total),
                        6000);
                }
            });
    connect(mCanvas, &EditorCanvas::handleDragged, this,
            [this](std::size_t rendered, const Operation& op, bool final) {
                const auto step = mDocument->documentIndex(rendered);
                if (!step) return;
                mCanvas->setDragging(!final);
                mDocument->setStep(*step, op, mDocument->mergeFor(!final));
            });
    connect(mCanvas, &EditorCanvas::gestureRefused, this,
            [this](const QString& why) { statusBar()->showMessage(why, 10000); });
    connect(mCanvas, &EditorCanvas::inkPicked, this, [this](int color, std::optional<std::size_t> rendered) {
        if (color >= 0) setCurrentInk(color);
        if (rendered) selectStep(mDocument->documentIndex(*rendered));
        statusBar()->showMessage(color >= 0 ? tr("Ink %1 picked").arg(color + 1) : tr("The bare bath"), 3000);
    });

    // The list and the form.
    connect(mSteps, &StepList::currentChanged, this, [this](std::optional<std::size_t> i) {
        if (i != mSelected) selectStep(i);
    });
    connect(mSteps, &StepList::moveRequested, this, [this](std::size_t from, std::size_t to) {
        if (mDocument->moveStep(from, to)) selectStep(to);
    });
    connect(mSteps, &StepList::mutedToggled, mDocument,
            qOverload<std::size_t, bool>(&EditorDocument::setMuted));
    connect(mSteps, &StepList::rangeMutedToggled, mDocument,
            qOverload<std::size_t, std::size_t, bool>(&EditorDocument::setMuted));
    connect(mSteps, &StepList::duplicateRequested, this,
            [this](std::size_t i) { selectStep(mDocument->duplicateStep(i)); });
    connect(mSteps, &StepList::deleteRequested, this, [this](std::size_t i) {
        mDocument->removeStep(i);
        selectStep(std::nullopt);
    });
    // Enter in a field commits it and gives the canvas the keys again.
    connect(mForm, &ParamForm::committed, this, [this] { mCanvas->setFocus(Qt::OtherFocusReason); });
    connect(mForm, &ParamForm::edited, this, [this](const Operation& op, const QString&, bool dragging) {
        if (!mSelected) return;
        mCanvas->setDragging(dragging);
        mFormEditing = true;
        mDocument->setStep(*mSelected, op, mDocument->mergeFor(dragging));
        mFormEditing = false;
    });
    // Enter in a field commits it and hands the keys back to the canvas (tool keys, Space, Undo).
    connect(mForm, &ParamForm::committed, this, [this] { mCanvas->setFocus(Qt::OtherFocusReason); });

    // Inks.
    connect(mPalette, &PaletteEditor::colorChanged, this, [this](int index, Color c, bool dragging) {
        mCanvas->setDragging(dragging);
        mDocument->setPaletteColor(index, c, mDocument->mergeFor(dragging));
    });
    connect(mPalette, &PaletteEditor::backgroundChanged, this, [this](Color c, bool dragging) {
        mCanvas->setDragging(dragging);
        mDocument->setBackground(c, mDocument->mergeFor(dragging));
    });
    connect(mPalette, &PaletteEditor::bleedChanged, this, [this](double bleed, bool dragging) {
        mCanvas->setDragging(dragging);
        mDocument->setBleed(bleed, mDocument->mergeFor(dragging));
    });
    connect(mPalette, &PaletteEditor::inkAdded, this, [this](Color c) {
        const int index = mDocument->addPaletteColor(c);
        if (index < 0)
            statusBar()->showMessage(tr("A design holds at most %1 inks").arg(int(MaxPaletteSize)), 5000);
        else
            setCurrentInk(index);
    });
    connect(mPalette, &PaletteEditor::currentInkChanged, this, &EditorWindow::setCurrentInk);
    connect(mToolOptions, &ToolOptions::settingsChanged, this, [this](const ToolSettings& s) {
        mToolSettings = s;
        mCanvas->setToolSettings(s);
        mPalette->setCurrentInk(s.color);
    });

    // The timeline.
    connect(mTimeline, &Timeline::growthChanged, this, [this](double) { showShown(); });
    connect(mTimeline, &Timeline::compareChanged, this, [this](bool on, double) {
        mCompare->setVisible(on);
        showShown();
    });
    connect(mTimeline, &Timeline::exportAnimationRequested, this, &EditorWindow::exportAnimation);

    // ---- Issue 27 (fix-canvas): compare captions, deleting an ink, palette presets.
    connect(mTimeline, &Timeline::captionsChanged, this, [this](const QString& shown, const QString& other) {
        mCanvas->setCaption(shown);
        mCompare->setCaption(other);
    });
    connect(mPalette, &PaletteEditor::inkRemoved, this, [this](int index, int replacement) {
        if (!mDocument->removePaletteColor(index, replacement))
            statusBar()->showMessage(
                tr("Ink %1 is laid by steps and there is no other ink for them").arg(index + 1), 5000);
    });
    connect(mPalette, &PaletteEditor::presetChosen, this, [this](int index) {
        const PalettePreset& preset = palettePresets()[std::size_t(index)];
        mDocument->replaceDesign(withPalettePreset(mDocument->fileGenome(), preset),
                                 tr("Palette: %1").arg(preset.name));
    });
}

std::optional<std::size_t> EditorWindow::insertionPoint() const {
    if (mSelected && *mSelected < mDocument->stepCount()) return *mSelected + 1;
    if (mTimeline->atEnd()) return std::nullopt;
    // After the last step the timeline has grown whole (rendered numbering to the document's).
    const auto grown = static_cast<std::size_t>(std::floor(mTimeline->growth()));
    if (grown == 0) return 0;
    const auto step = mDocument->documentIndex(grown - 1);
    return step ? std::optional<std::size_t>(*step + 1) : std::nullopt;
}

Genome EditorWindow::shownDesign() const {
    Genome rendered = mDocument->renderedDesign();
    if (mTimeline->atEnd()) return rendered;
    const double g = std::clamp(mTimeline->growth(), 0.0, double(stepCount(rendered)));
    return designAtGrowth(rendered, g);
}

void EditorWindow::showShown() {
    const Genome shown = shownDesign();
    mCanvas->setDesign(shown);
    if (mTimeline->comparing()) {
        const Genome rendered = mDocument->renderedDesign();
        const double g = std::clamp(mTimeline->compareGrowth(), 0.0, double(stepCount(rendered)));
        mCompare->setDesign(designAtGrowth(rendered, g));
    }
    if (mObject) mObject->setDesign(shown);
    updateHandles();
}

void EditorWindow::designChanged() {
    const Genome& design = mDocument->design();
    mTimeline->setStepCount(stepCount(mDocument->renderedDesign()));
    showShown();
    mPalette->setDesign(design);
    mToolOptions->setPalette(design.palette);
    if (!mFormEditing) refreshForm();
    // Keep the step list's details (a changed parameter shows in its row).
    if (!mFormEditing && !mDocument->dragActive()) stepsChanged();
    updateWrap();
    updateTitle();
}

void EditorWindow::updateWrap() {
    const Genome& design = mDocument->design();
    const bool wraps = design.wrap;
    Genome wrapped = design;
    wrapped.wrap = true;
    const std::string problem = wraps ? std::string() : wrapProblem(wrapped);
    mWrap->setChecked(wraps);
    mWrap->setEnabled(wraps || problem.empty());
    mWrap->setToolTip(wraps ? tr("The bath wraps: the design is a repeat tile, and takes only spray and "
                                 "stretch along an axis. Turn it off to use every tool.")
                      : problem.empty()
                          ? tr("Make the bath wrap: the design becomes a straight-repeat tile")
                          : tr("This design cannot wrap: %1").arg(QString::fromStdString(problem)));
    if (!mTools) return;
    bool currentDisabled = false;
    const std::vector<EditorTool> all = editorTools();
    for (QAction* a : mTools->actions()) {
        const auto found = std::find_if(all.begin(), all.end(),
                                        [a](EditorTool t) { return t.index() == a->data().toInt(); });
        if (found == all.end()) continue;
        const EditorTool t = *found;
        // The editor's own drop patterns lay drops; the picker changes nothing.
        const bool may = t == EditorTool::Pick || (t.inRegistry() ? toolMayWrap(t.tool()) : false);
        a->setEnabled(!wraps || may);
        a->setToolTip(!wraps || may
                          ? ui::toolTip(t)
                          : tr("%1 (not in a bath that wraps: turn off Edit ▸ Bath wraps to use it)")
                                .arg(ui::toolTip(t)));
        if (a->isChecked() && !a->isEnabled()) currentDisabled = true;
    }
    if (currentDisabled) setTool(Tool::Spray);
}

void EditorWindow::stepsChanged() {
    std::vector<StepRow> rows;
    rows.reserve(mDocument->stepCount());
    for (std::size_t i = 0; i < mDocument->stepCount(); ++i) {
        StepRow row;
        const Operation& op = mDocument->step(i);
        const ToolSpec& spec = toolSpec(op.tool);
        row.name = registryText(spec.name);
        if (spec.laysInk) row.name += tr(" · ink %1").arg(op.color + 1);
        row.detail = mDocument->stepName(i);
        row.muted = mDocument->isMuted(i);
        row.initial = mDocument->isInitial(i);
        row.tool = QString::fromUtf8(spec.name.data(), qsizetype(spec.name.size()));
        row.tool = QString::fromUtf8(spec.name.data(), qsizetype(spec.name.size())); // groups and the filter
        rows.push_back(row);
    }
    mSteps->setRows(rows);
    if (mSelected && *mSelected >= mDocument->stepCount()) mSelected.reset();
    mSteps->setCurrent(mSelected);
    mTimeline->setStepCount(stepCount(mDocument->renderedDesign()));
    mStatus->setText(tr("%n step(s)", "", int(mDocument->stepCount())));
}

void EditorWindow::setCurrentInk(int index) {
    mToolSettings.color = index;
    mToolOptions->setSettings(mToolSettings);
    mCanvas->setToolSettings(mToolSettings);
    mPalette->setCurrentInk(index);
}

void EditorWindow::refreshForm() {
    if (!mSelected || *mSelected >= mDocument->stepCount())
        mForm->clear();
    else
        mForm->setStep(mDocument->step(*mSelected), mDocument->design().dimension, mDocument->design());
    updateHandles();
}

void EditorWindow::updateHandles() {
    // Handles edit the design itself, so they show only at the timeline's end: before it the
    // canvas shows steps part grown, and a handle dragged there would write the part back.
    const bool show = mSelected && *mSelected < mDocument->stepCount() && mTimeline->atEnd();
    mCanvas->setHandlesFor(show ? mDocument->renderedIndex(*mSelected) : std::nullopt);
}

void EditorWindow::selectStep(std::optional<std::size_t> step) {
    if (step && *step >= mDocument->stepCount()) step.reset();
    mSelected = step;
    mSteps->setCurrent(step);
    refreshForm();
}

void EditorWindow::setTool(EditorTool tool) {
    mCanvas->setTool(tool);
    mToolOptions->setTool(tool);
    mToolOptions->setSettings(mToolSettings);
    for (QAction* a : mTools->actions())
        if (a->data().toInt() == tool.index()) a->setChecked(true);
    statusBar()->showMessage(ui::toolTip(tool), 4000);
}

EditorTool EditorWindow::tool() const {
    return mCanvas->tool();
}

void EditorWindow::setSlice(const Slice& slice) {
    mSlice = slice;
    mCanvas->setSlice(slice);
    mCompare->setSlice(slice);
    if (mObject) mObject->setSlice(slice);
    // The number and the slider say where it is, whichever moved it.
    if (mSection) mSection->showSlice(slice);
}

void EditorWindow::updateTitle() {
    setWindowTitle(tr("%1[*] — Marbler editor").arg(mFiles->displayName()));
    setWindowModified(mDocument->isModified());
}

// ---- the parts' own work, kept in the window's API -------------------------------------------

bool EditorWindow::save() {
    return mFiles->save();
}

RenameDialog* EditorWindow::renameDesign() {
    return askRename(this, mDocument->design(), [this](const QString& name, const QString& note) {
        Genome named = mDocument->fileGenome();
        setNameAndNote(named, name, note);
        if (named.meta == mDocument->fileGenome().meta) return;
        mDocument->replaceDesign(named, tr("Rename to “%1”").arg(name));
        statusBar()->showMessage(tr("Renamed to “%1”").arg(name), 4000);
    });
}

bool EditorWindow::saveAs() {
    return mFiles->saveAs();
}

bool EditorWindow::saveTo(const QString& file) {
    return mFiles->saveTo(file);
}

bool EditorWindow::reloadFromDisk() {
    return mFiles->reloadFromDisk();
}

bool EditorWindow::writeDesignImage(const QString& image) {
    return mFiles->writeDesignImage(image);
}

void EditorWindow::setUnsavedAnswer(std::optional<UnsavedAnswer> answer) {
    mFiles->setUnsavedAnswer(answer);
}

void EditorWindow::setImageSaveAnswer(std::optional<ImageSaveAnswer> answer) {
    mFiles->setImageSaveAnswer(answer);
}

void EditorWindow::setDiskChangeAnswer(std::optional<DiskChangeAnswer> answer) {
    mFiles->setDiskChangeAnswer(answer);
}

void EditorWindow::setOverwriteAnswer(std::optional<bool> answer) {
    mFiles->setOverwriteAnswer(answer);
}

void EditorWindow::exportImage() {
    mExports->exportImage();
}

void EditorWindow::exportAnimation() {
    mExports->exportAnimation();
}

QUndoView* EditorWindow::historyView() const {
    return mHistory->historyView();
}

QListWidget* EditorWindow::branchList() const {
    return mHistory->branchList();
}

void EditorWindow::closeEvent(QCloseEvent* event) {
    if (!mFiles->maybeKeepChanges()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("editor/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("editor/state"), saveState());
    if (mAutosave) mAutosave->discard(); // a normal close: nothing to recover
    event->accept();
}

} // namespace marbler::ui
