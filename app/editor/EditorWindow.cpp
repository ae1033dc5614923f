// The editor window: the document wired to the canvas, the panels and the history.

#include "editor/EditorWindow.h"
#include "marbler/Mesh.h"

#include "editor/AnimationExport.h"
#include "editor/BathSizes.h"
#include "editor/EditorCanvas.h"
#include "editor/PaletteEditor.h"
#include "editor/ParamForm.h"
#include "editor/Recovery.h"
#include "editor/StepList.h"
#include "editor/Timeline.h"
#include "editor/ToolOptions.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/Growth.h"
#include "marbler/Params.h"
#include "ui/DesignDialog.h"
#include "ui/ErrorReport.h"
#include "ui/Help.h"
#include "ui/PopulationModel.h"
#include "ui/RenderService.h"
#include "ui/StartDialog.h"

#include <QAbstractSpinBox>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QImageReader>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPainter>
#include <QProgressDialog>
#include <QPushButton>
#include <QRandomGenerator>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QTextBrowser>
#include <QThread>
#include <QToolBar>
#include <QUndoView>
#include <QVBoxLayout>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <span>
#include <utility>

namespace marbler::ui {

namespace {

const QString RecentKey = QStringLiteral("editor/recentFiles");
/// The steps panel's width: the list and the form's labels and fields, no more (the form
/// scrolls when a step has more), so that the canvas and the object view get the room.
constexpr int StepsPanelWidth = 360;
/// The tool panel's width: the widest tool's options but for long words (they scroll).
constexpr int ToolPanelWidth = 230;
constexpr int MaxRecent = 10;

QString designFilter() {
    return EditorWindow::tr("Designs (*.marble.json *.json *.png *.tif *.tiff);;All files (*)");
}

QString nameOf(const Genome& design) {
    const LineageInfo info = lineageOf(design);
    return info.name.isEmpty() ? EditorWindow::tr("Untitled design") : info.name;
}

/// Every editor open in this process, so that a file is edited in one window at a time.
QList<QPointer<EditorWindow>>& openEditors() {
    static QList<QPointer<EditorWindow>> editors;
    return editors;
}

/// A file named by its real path, so that two names of one file compare equal.
QString canonical(const QString& file) {
    const QFileInfo info(file);
    const QString real = info.canonicalFilePath();
    return real.isEmpty() ? info.absoluteFilePath() : real;
}

/// Whether `file` is an image (by its first bytes; by its name when it cannot be read): a design
/// opened from one is saved as a design file, never as JSON under the image's name.
bool isImageFile(const QString& file) {
    QFile f(file);
    if (f.open(QIODevice::ReadOnly)) {
        const QByteArray head = f.read(16);
        return imageKindOf(std::span(reinterpret_cast<const unsigned char*>(head.constData()),
                                     static_cast<std::size_t>(head.size()))) != ImageKind::NotAnImage;
    }
    static const QStringList imageSuffixes{"png", "tif", "tiff", "jpg", "jpeg", "webp", "exr", "gif", "bmp"};
    return imageSuffixes.contains(QFileInfo(file).suffix().toLower());
}

/// `file` with the design file's extension, unless it has a JSON one already.
QString withDesignExtension(const QString& file) {
    return file.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)
               ? file
               : file + QStringLiteral(".marble.json");
}

} // namespace

Genome blankDesign(int dimension) {
    Genome g;
    g.dimension = dimension == 3 ? 3 : 2;
    g.palette = {Color{0x1f, 0x4e, 0x79}, Color{0xc8, 0x55, 0x3d}, Color{0x2a, 0x9d, 0x8f}};
    g.meta.name = dimension == 3 ? "Untitled solid" : "Untitled design";
    return g;
}

// ---- ImageWriteJob ---------------------------------------------------------------------------

/// Renders a design into an image file on a thread of its own (the CPU renderer, every core),
/// written atomically; its progress and its end are told on the GUI thread.
class ImageWriteJob : public QObject {
public:
    /// Done so far, 0 to 1.
    std::function<void(double)> onProgress;
    /// Written (ok), cancelled (not ok, no error) or failed.
    std::function<void(bool ok, const QString& error)> onFinished;

    ~ImageWriteJob() override {
        mCancel.store(true);
        if (mThread) mThread->wait();
        delete mThread;
    }
    bool running() const { return mThread && mThread->isRunning(); }
    void cancel() { mCancel.store(true); }
    void start(Genome design, RenderSettings settings, std::filesystem::path file, ExportOptions options) {
        if (mThread) mThread->wait();
        delete mThread;
        mCancel.store(false);
        mThread = QThread::create([this, design = std::move(design), settings, file = std::move(file),
                                   options = std::move(options)] {
            QString error;
            bool ok = false;
            RenderControl control;
            control.cancel = &mCancel;
            control.progress = [this](double f) {
                QMetaObject::invokeMethod(
                    this,
                    [this, f] {
                        if (onProgress) onProgress(f);
                    },
                    Qt::QueuedConnection);
            };
            try {
                renderToFile(design, settings, file, options, &control);
                ok = true;
            } catch (const Cancelled&) {
            } catch (const std::exception& e) {
                error = QString::fromStdString(e.what());
            }
            QMetaObject::invokeMethod(
                this,
                [this, ok, error] {
                    // Taken out first: the handler is one run's, and may start the next run.
                    const auto finished = std::exchange(onFinished, nullptr);
                    onProgress = nullptr;
                    if (finished) finished(ok, error);
                },
                Qt::QueuedConnection);
        });
        mThread->start();
    }

private:
    QThread* mThread = nullptr;
    std::atomic<bool> mCancel{false};
};

// ---- EditorWindow -------------------------------------------------------------------------

EditorWindow::EditorWindow(Genome design, RenderService* renderer, const QString& file, QWidget* parent,
                           const QString& recoveryFolder)
    : QMainWindow(parent)
    , mRenderer(renderer) {
    setAttribute(Qt::WA_DeleteOnClose);
    setObjectName(QStringLiteral("editorWindow"));
    openEditors().append(this);
    mDocument = new EditorDocument(std::move(design), this);
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
    mCanvases = new QSplitter(Qt::Horizontal, this);
    mCanvases->addWidget(mCanvas);
    mCanvases->addWidget(mCompare);
    if (dimension == 3) {
        mObject = new SolidObjectView(renderer, this);
        mObject->setObjectName(QStringLiteral("objectView"));
        mCanvases->addWidget(mObject);
        mCanvas->setSlice(mSlice);
        mCompare->setSlice(mSlice);
    }
    setCentralWidget(mCanvases);

    buildDocks();
    buildMenus();
    wireDocument();
    // The canvas gets most of the room; the panels keep what their widgets need.
    mCanvases->setStretchFactor(0, 3);
    if (mObject) {
        // The section and the object share the middle, three to two.
        mCanvases->setStretchFactor(2, 2);
        mCanvases->setSizes({600, 0, 400});
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
    fillBranchList();
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
    delete mImageJob; // waits for its thread
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
    const QString wanted = canonical(file);
    for (const QPointer<EditorWindow>& e : openEditors())
        if (e && !e->mDocument->fileName().isEmpty() && canonical(e->mDocument->fileName()) == wanted)
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
    auto* toolDock = new QDockWidget(tr("Tool"), this);
    toolDock->setObjectName(QStringLiteral("toolDock"));
    auto* toolPanel = new QWidget(this);
    auto* toolLayout = new QVBoxLayout(toolPanel);
    toolLayout->setContentsMargins(4, 4, 4, 4);
    toolLayout->addWidget(mToolOptions);
    if (dimension == 3) {
        // The cross-section: its axis and where along it.
        auto* row = new QHBoxLayout;
        row->addWidget(new QLabel(tr("Section"), toolPanel));
        mSliceAxis = new QComboBox(toolPanel);
        mSliceAxis->setObjectName(QStringLiteral("sliceAxis"));
        mSliceAxis->addItems({tr("x"), tr("y"), tr("z")});
        mSliceAxis->setCurrentIndex(mSlice.axis);
        mSliceAxis->setToolTip(
            tr("The axis the cross-section is cut across; clicks on it place the 3D tools"));
        row->addWidget(mSliceAxis);
        toolLayout->addLayout(row);
        mSlicePosition = new QSlider(Qt::Horizontal, toolPanel);
        mSlicePosition->setObjectName(QStringLiteral("slicePosition"));
        mSlicePosition->setRange(0, 1000);
        mSlicePosition->setValue(500);
        mSlicePosition->setToolTip(tr("Where along its axis the cross-section is cut (PgUp / PgDn move it)"));
        // Where the section is, as a number too (design units along its axis).
        mSliceValue = new QDoubleSpinBox(toolPanel);
        mSliceValue->setObjectName(QStringLiteral("sliceValue"));
        mSliceValue->setDecimals(1);
        mSliceValue->setToolTip(tr("Where the cross-section is cut, in design units along its axis"));
        auto* positionRow = new QHBoxLayout;
        positionRow->addWidget(mSlicePosition, 1);
        positionRow->addWidget(mSliceValue);
        toolLayout->addLayout(positionRow);
        const auto sliceChanged = [this] {
            if (mSliceUpdating) return;
            const glm::dvec3 size = mDocument->design().size;
            const int axis = mSliceAxis->currentIndex();
            setSlice(Slice{axis, size[axis] * mSlicePosition->value() / 1000.0});
        };
        connect(mSliceAxis, &QComboBox::currentIndexChanged, this, sliceChanged);
        connect(mSlicePosition, &QSlider::valueChanged, this, sliceChanged);
        connect(mSliceValue, &QDoubleSpinBox::valueChanged, this, [this](double value) {
            if (mSliceUpdating) return;
            const glm::dvec3 size = mDocument->design().size;
            setSlice(
                Slice{mSliceAxis->currentIndex(), std::clamp(value, 0.0, size[mSliceAxis->currentIndex()])});
        });
        auto* meshRow = new QHBoxLayout;
        meshRow->addWidget(new QLabel(tr("Object"), toolPanel));
        auto* mesh = new QComboBox(toolPanel);
        mesh->setObjectName(QStringLiteral("objectMesh"));
        mesh->addItems(meshNames());
        mesh->addItem(tr("Mesh file…"));
        mesh->setToolTip(tr("The object the design is shown on (drag the object to turn it)"));
        meshRow->addWidget(mesh);
        toolLayout->addLayout(meshRow);
        connect(mesh, &QComboBox::activated, this, [this, mesh](int index) {
            if (index < int(meshNames().size())) {
                mObject->setMesh(mesh->itemText(index));
                return;
            }
            const QString file = QFileDialog::getOpenFileName(
                this, tr("Show the design on a mesh"), QString(),
                tr("Meshes (*.obj *.ply *.stl *.off *.gltf *.glb);;All files (*)"));
            if (file.isEmpty()) return;
            mObject->setMesh(file);
        });
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

    mHistory = new QUndoView(mDocument->undoStack(), this);
    mHistory->setMinimumHeight(60);
    mHistory->setObjectName(QStringLiteral("historyView"));
    mHistory->setEmptyLabel(tr("Opened"));
    mHistory->setToolTip(tr("Every edit; click one to go back (or forward) to it"));
    // Every other line of edits: an edit made after undoing leaves the undone ones here.
    mBranchList = new QListWidget(this);
    mBranchList->setObjectName(QStringLiteral("branchList"));
    mBranchList->setToolTip(tr("Edits you undid and then left by making another: click one to go back to it "
                               "(the edits you leave stay here)"));
    mBranchList->setMaximumHeight(110);
    auto* historyPanel = new QWidget(this);
    auto* historyLayout = new QVBoxLayout(historyPanel);
    historyLayout->setContentsMargins(0, 0, 0, 0);
    historyLayout->addWidget(mHistory, 1);
    mBranchLabel = new QLabel(tr("Other branches"), historyPanel);
    historyLayout->addWidget(mBranchLabel);
    historyLayout->addWidget(mBranchList);
    connect(mBranchList, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        const int k = mBranchList->row(item);
        if (k < 0) return;
        mDocument->switchToBranch(std::size_t(k));
        statusBar()->showMessage(tr("Switched to another branch of the history"), 4000);
    });
    auto* historyDock = new QDockWidget(tr("History"), this);
    historyDock->setObjectName(QStringLiteral("historyDock"));
    historyDock->setWidget(historyPanel);
    addDockWidget(Qt::RightDockWidgetArea, historyDock);

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
    newMenu->addAction(tr("&Random design"), this, &EditorWindow::startFromRandom);
    newMenu->addAction(tr("From a &picture…"), this, &EditorWindow::startFromSourceImage)
        ->setToolTip(tr("A flat design whose bath is a picture (its source)"));
    file->addAction(tr("&Open…"), this, &EditorWindow::openFileDialog)->setShortcut(QKeySequence::Open);
    mRecentMenu = file->addMenu(tr("Open &recent"));
    connect(mRecentMenu, &QMenu::aboutToShow, this, &EditorWindow::fillRecentMenu);
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
    // The step list's own actions (Ctrl+D, Del, M), for the whole window: one action a key, as
    // two with the same key would be ambiguous where both apply and neither would run.
    for (QAction* action : mSteps->actions()) {
        action->setShortcutContext(Qt::WindowShortcut);
        edit->addAction(action);
    }

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
        "point) and the canvas shows the design just after it.</p>"
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
    connect(mDocument, &EditorDocument::branchesChanged, this, &EditorWindow::fillBranchList);
    connect(mDocument->undoStack(), &QUndoStack::indexChanged, this, &EditorWindow::fillBranchList);

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
                const auto rendered = renderedIndex(last);
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
                const auto step = documentIndex(rendered);
                if (!step) return;
                mCanvas->setDragging(!final);
                mDocument->setStep(*step, op, mergeFor(!final));
            });
    connect(mCanvas, &EditorCanvas::inkPicked, this, [this](int color, std::optional<std::size_t> rendered) {
        if (color >= 0) setCurrentInk(color);
        if (rendered) selectStep(documentIndex(*rendered));
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
        mDocument->setStep(*mSelected, op, mergeFor(dragging));
        mFormEditing = false;
    });
    // Enter in a field commits it and hands the keys back to the canvas (tool keys, Space, Undo).
    connect(mForm, &ParamForm::committed, this, [this] { mCanvas->setFocus(Qt::OtherFocusReason); });

    // Inks.
    connect(mPalette, &PaletteEditor::colorChanged, this, [this](int index, Color c, bool dragging) {
        mCanvas->setDragging(dragging);
        mDocument->setPaletteColor(index, c, mergeFor(dragging));
    });
    connect(mPalette, &PaletteEditor::backgroundChanged, this, [this](Color c, bool dragging) {
        mCanvas->setDragging(dragging);
        mDocument->setBackground(c, mergeFor(dragging));
    });
    connect(mPalette, &PaletteEditor::bleedChanged, this, [this](double bleed, bool dragging) {
        mCanvas->setDragging(dragging);
        mDocument->setBleed(bleed, mergeFor(dragging));
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

int EditorWindow::mergeFor(bool dragging) {
    if (dragging) {
        if (!mDragActive) {
            mDragActive = true;
            mMergeId = mNextMergeId++;
        }
        return mMergeId;
    }
    if (mDragActive) {
        mDragActive = false; // the release closes the drag's step
        return mMergeId;
    }
    return -1;
}

std::optional<std::size_t> EditorWindow::insertionPoint() const {
    if (mSelected && *mSelected < mDocument->stepCount()) return *mSelected + 1;
    if (mTimeline->atEnd()) return std::nullopt;
    // After the last step the timeline has grown whole (rendered numbering to the document's).
    const auto grown = static_cast<std::size_t>(std::floor(mTimeline->growth()));
    if (grown == 0) return 0;
    const auto step = documentIndex(grown - 1);
    return step ? std::optional<std::size_t>(*step + 1) : std::nullopt;
}

std::optional<std::size_t> EditorWindow::documentIndex(std::size_t rendered) const {
    std::size_t seen = 0;
    for (std::size_t i = 0; i < mDocument->stepCount(); ++i) {
        if (mDocument->isMuted(i)) continue;
        if (seen == rendered) return i;
        ++seen;
    }
    return std::nullopt;
}

std::optional<std::size_t> EditorWindow::renderedIndex(std::size_t step) const {
    if (step >= mDocument->stepCount() || mDocument->isMuted(step)) return std::nullopt;
    std::size_t rendered = 0;
    for (std::size_t i = 0; i < step; ++i)
        if (!mDocument->isMuted(i)) ++rendered;
    return rendered;
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
    if (!mFormEditing && !mDragActive) stepsChanged();
    updateTitle();
}

void EditorWindow::stepsChanged() {
    std::vector<StepRow> rows;
    rows.reserve(mDocument->stepCount());
    for (std::size_t i = 0; i < mDocument->stepCount(); ++i) {
        StepRow row;
        const Operation& op = mDocument->step(i);
        const ToolSpec& spec = toolSpec(op.tool);
        row.name = QString::fromUtf8(spec.name.data(), qsizetype(spec.name.size()));
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

void EditorWindow::fillBranchList() {
    const auto branches = mDocument->branches();
    mBranchList->clear();
    for (const EditorDocument::BranchInfo& b : branches) {
        const QString from = b.forkText.isEmpty() ? tr("the opened design") : tr("“%1”").arg(b.forkText);
        auto* item = new QListWidgetItem(
            tr("After %1: %n more edit(s), last “%2”", "", b.length).arg(from, b.lastText), mBranchList);
        item->setToolTip(tr("Click to switch to this branch"));
    }
    mBranchLabel->setVisible(!branches.empty());
    mBranchList->setVisible(!branches.empty());
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
    mCanvas->setHandlesFor(show ? renderedIndex(*mSelected) : std::nullopt);
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
    if (mSliceValue) {
        // The number and the slider say where it is, whichever moved it.
        mSliceUpdating = true;
        const double extent = mDocument->design().size[slice.axis];
        mSliceAxis->setCurrentIndex(slice.axis);
        mSliceValue->setRange(0.0, extent);
        mSliceValue->setValue(slice.value);
        mSliceValue->setPrefix(tr("%1 = ").arg(QLatin1String(axisName(slice.axis))));
        if (extent > 0.0) mSlicePosition->setValue(int(std::lround(slice.value / extent * 1000.0)));
        mSliceUpdating = false;
    }
}

QString EditorWindow::displayName() const {
    const QString file = mDocument->fileName();
    return file.isEmpty() ? nameOf(mDocument->design()) : QFileInfo(file).fileName();
}

void EditorWindow::updateTitle() {
    setWindowTitle(tr("%1[*] — Marbler editor").arg(displayName()));
    setWindowModified(mDocument->isModified());
}

// ---- files ----------------------------------------------------------------------------------

bool EditorWindow::save() {
    const QString file = mDocument->fileName();
    if (file.isEmpty()) return saveAs();
    if (isImageFile(file)) {
        // A design opened from an image: its genome file is a new file, or the image is written
        // again with the design inside; JSON never goes under the image's name.
        ImageSaveAnswer answer = ImageSaveAnswer::DesignFile;
        if (mImageSaveAnswer) {
            answer = *mImageSaveAnswer;
        } else {
            QMessageBox box(QMessageBox::Question, tr("Save a design opened from an image"),
                            tr("“%1” is an image. Save the design as a design file, or write the image again "
                               "with the design inside?")
                                .arg(QFileInfo(file).fileName()),
                            QMessageBox::Cancel, this);
            QPushButton* asFile = box.addButton(tr("Save as design file…"), QMessageBox::AcceptRole);
            QPushButton* asImage = box.addButton(tr("Update the image"), QMessageBox::DestructiveRole);
            asImage->setToolTip(tr("Render the design into %1 at its size; the picture there is replaced")
                                    .arg(QFileInfo(file).fileName()));
            box.setDefaultButton(asFile);
            box.exec();
            answer = box.clickedButton() == asFile    ? ImageSaveAnswer::DesignFile
                     : box.clickedButton() == asImage ? ImageSaveAnswer::UpdateImage
                                                      : ImageSaveAnswer::Cancel;
        }
        switch (answer) {
        case ImageSaveAnswer::DesignFile:
            return saveAs();
        case ImageSaveAnswer::UpdateImage:
            return writeDesignImage(file);
        case ImageSaveAnswer::Cancel:
            return false;
        }
        return false;
    }
    return saveTo(file);
}

bool EditorWindow::saveAs() {
    const QString folder = QSettings().value(QStringLiteral("files/saveDir")).toString();
    const QString current = mDocument->fileName();
    QString suggested;
    if (current.isEmpty())
        suggested = suggestedFile(mDocument->renderedDesign(), folder, QStringLiteral(".marble.json"));
    else if (isImageFile(current))
        suggested = QFileInfo(current).dir().filePath(QFileInfo(current).completeBaseName() +
                                                      QStringLiteral(".marble.json"));
    else
        suggested = current;
    const QString chosen =
        askSaveFile(this, tr("Save design"), suggested, tr("Marbler designs (*.marble.json)"));
    if (chosen.isEmpty()) return false;
    // A name without the extension gets it (the Open dialog lists designs by it); the file
    // dialog asked about the name typed, so a file of the full name is asked about here.
    const QString file = withDesignExtension(chosen);
    if (file != chosen && !mayOverwrite(file)) return false;
    QSettings().setValue(QStringLiteral("files/saveDir"), QFileInfo(file).absolutePath());
    return saveTo(file);
}

bool EditorWindow::saveTo(const QString& file) {
    if (!mDocument->fileName().isEmpty() && canonical(file) == canonical(mDocument->fileName()) &&
        mDocument->fileChangedOnDisk()) {
        // Someone else wrote the file since this editor read or wrote it: never overwritten
        // without a word.
        DiskChangeAnswer answer = DiskChangeAnswer::Cancel;
        if (mDiskChangeAnswer) {
            answer = *mDiskChangeAnswer;
        } else {
            QMessageBox box(
                QMessageBox::Warning, tr("The file was changed"),
                tr("“%1” was changed by another program or window since it was opened here. "
                   "Overwrite those changes, reload the file (your changes stay in Undo), or save "
                   "under another name?")
                    .arg(QFileInfo(file).fileName()),
                QMessageBox::Cancel, this);
            QPushButton* overwrite = box.addButton(tr("Overwrite"), QMessageBox::DestructiveRole);
            QPushButton* reload = box.addButton(tr("Reload"), QMessageBox::ResetRole);
            QPushButton* other = box.addButton(tr("Save as…"), QMessageBox::AcceptRole);
            box.setDefaultButton(other);
            box.exec();
            answer = box.clickedButton() == overwrite ? DiskChangeAnswer::Overwrite
                     : box.clickedButton() == reload  ? DiskChangeAnswer::Reload
                     : box.clickedButton() == other   ? DiskChangeAnswer::SaveAs
                                                      : DiskChangeAnswer::Cancel;
        }
        switch (answer) {
        case DiskChangeAnswer::Overwrite:
            break;
        case DiskChangeAnswer::Reload:
            reloadFromDisk();
            return false;
        case DiskChangeAnswer::SaveAs:
            return saveAs();
        case DiskChangeAnswer::Cancel:
            return false;
        }
    }
    QString error;
    if (!mDocument->saveAs(file, &error)) {
        reportError(this, tr("Cannot save the design"), error);
        return false;
    }
    addRecentFile(file);
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(file)), 5000);
    emit fileSaved(file);
    return true;
}

bool EditorWindow::reloadFromDisk() {
    const QString file = mDocument->fileName();
    if (file.isEmpty()) return false;
    try {
        Genome design = loadDesign(QFile::encodeName(file).toStdString());
        mDocument->replaceDesign(design, tr("Reload %1").arg(QFileInfo(file).fileName()));
        mDocument->markSaved(file);
    } catch (const Error& e) {
        reportError(this, tr("Cannot reload the design"), QString::fromStdString(e.what()));
        return false;
    }
    selectStep(std::nullopt);
    statusBar()->showMessage(tr("Reloaded %1; Undo brings your changes back").arg(QFileInfo(file).fileName()),
                             6000);
    return true;
}

bool EditorWindow::writeDesignImage(const QString& image) {
    if (mImageJob && mImageJob->running()) {
        statusBar()->showMessage(tr("The image is being written already"), 4000);
        return false;
    }
    const Genome design = mDocument->renderedDesign();
    RenderSettings settings;
    // The image's own size; where its format has no reader here, the design's.
    const QSize pixels = QImageReader(image).size();
    settings.width = pixels.isValid() ? pixels.width() : int(std::lround(design.size.x));
    settings.height = pixels.isValid() ? pixels.height() : int(std::lround(design.size.y));
    settings.aa = "rgss";
    if (design.dimension == 3) settings.slice = mSlice;
    ExportOptions options;
    // The file's genome, muted steps and all, so that the image opens as it is edited.
    options.genome = serializeGenome(mDocument->fileGenome());
    if (!mImageJob) mImageJob = new ImageWriteJob;
    auto* progress =
        new QProgressDialog(tr("Writing %1…").arg(QFileInfo(image).fileName()), tr("Cancel"), 0, 1000, this);
    progress->setObjectName(QStringLiteral("imageProgress"));
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(300);
    progress->setAutoClose(false);
    progress->setAutoReset(false);
    mImageJob->onProgress = [progress](double f) { progress->setValue(int(std::lround(f * 1000.0))); };
    connect(progress, &QProgressDialog::canceled, mImageJob, [job = mImageJob] { job->cancel(); });
    // The design is saved in the image when it is still the state the render started from.
    const QString stateText = QString::fromStdString(options.genome);
    mImageJob->onFinished = [this, progress, image, stateText](bool ok, const QString& error) {
        QObject::disconnect(progress, nullptr, mImageJob, nullptr);
        progress->close();
        progress->deleteLater();
        if (ok) {
            if (QString::fromStdString(serializeGenome(mDocument->fileGenome())) == stateText)
                mDocument->markSaved(image);
            addRecentFile(image);
            statusBar()->showMessage(
                tr("Wrote %1 with the design inside").arg(QDir::toNativeSeparators(image)), 5000);
            emit fileSaved(image);
        } else if (!error.isEmpty()) {
            reportError(this, tr("Cannot write the image"), error);
        } else {
            statusBar()->showMessage(tr("Cancelled; the image is as it was"), 4000);
        }
    };
    mImageJob->start(design, settings, std::filesystem::path(QFile::encodeName(image).toStdString()),
                     options);
    return true;
}

bool EditorWindow::mayOverwrite(const QString& file) {
    if (!QFileInfo::exists(file)) return true;
    if (mOverwriteAnswer) return *mOverwriteAnswer;
    return QMessageBox::question(this, tr("Replace the file?"),
                                 tr("“%1” exists already. Replace it?").arg(QFileInfo(file).fileName()),
                                 QMessageBox::Yes | QMessageBox::Cancel,
                                 QMessageBox::Cancel) == QMessageBox::Yes;
}

QStringList EditorWindow::recentFiles() {
    return QSettings().value(RecentKey).toStringList();
}

void EditorWindow::addRecentFile(const QString& file) {
    QStringList files = recentFiles();
    const QString path = QFileInfo(file).absoluteFilePath();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > MaxRecent)
        files.removeLast();
    QSettings().setValue(RecentKey, files);
}

void EditorWindow::fillRecentMenu() {
    mRecentMenu->clear();
    const QStringList files = recentFiles();
    for (const QString& f : files) {
        QAction* a = mRecentMenu->addAction(QFileInfo(f).fileName(), this, [this, f] {
            try {
                emit openEditorRequested(loadDesign(f.toStdString()), f);
            } catch (const Error& e) {
                reportError(this, tr("Cannot open the design"), QString::fromStdString(e.what()));
            }
        });
        a->setToolTip(QDir::toNativeSeparators(f));
        a->setEnabled(QFileInfo::exists(f));
    }
    if (files.isEmpty()) mRecentMenu->addAction(tr("No recent designs"))->setEnabled(false);
}

void EditorWindow::openFileDialog() {
    const QString file = QFileDialog::getOpenFileName(this, tr("Open a design"), QString(), designFilter());
    if (file.isEmpty()) return;
    try {
        emit openEditorRequested(loadDesign(file.toStdString()), file);
    } catch (const Error& e) {
        reportError(this, tr("Cannot open the design"), QString::fromStdString(e.what()));
    }
}

void EditorWindow::startFromRandom() {
    Genome g = randomGenome(QRandomGenerator::global()->generate64(), mDocument->design().dimension);
    emit openEditorRequested(g, {});
}

void EditorWindow::startFromSourceImage() {
    const QString image =
        QFileDialog::getOpenFileName(this, tr("A picture for the bath"), QString(),
                                     tr("Images (*.png *.jpg *.jpeg *.tif *.tiff *.webp *.bmp)"));
    if (image.isEmpty()) return;
    // A new flat design whose bath is the picture. It is named by its full path and may be read
    // from there (the user chose it just now); saved beside the picture, the design renders
    // anywhere the two travel together.
    const QFileInfo info(image);
    Genome g = blankDesign(2);
    g.source = SourceImage{info.absoluteFilePath().toStdString()};
    g.baseDirectory = info.absolutePath().toStdString();
    g.allowExternalSource = true;
    g.meta.name = info.completeBaseName().toStdString();
    emit openEditorRequested(g, {});
}

void EditorWindow::exportImage() {
    // The large view exports at print size, in vector form and on objects; it opens on the design.
    auto* dialog = new DesignDialog(mDocument->renderedDesign(), mRenderer,
                                    mObject ? mObject->mesh() : QString::fromLatin1(DefaultMesh), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &DesignDialog::fileSaved, this, &EditorWindow::fileSaved);
    // It is open in this editor already.
    if (auto* again = dialog->findChild<QWidget*>(QStringLiteral("openInEditor"))) again->hide();
    dialog->show();
}

void EditorWindow::exportAnimation() {
    if (mAnimationJob && mAnimationJob->running()) {
        statusBar()->showMessage(tr("An animation is being written already"), 4000);
        return;
    }
    const Genome design = mDocument->renderedDesign();
    AnimationExportSettings start;
    const QString folder = QSettings().value(QStringLiteral("files/exportDir")).toString();
    start.path = suggestedFile(design, folder, QStringLiteral(".gif"));
    if (design.dimension == 3) start.slice = mSlice;
    AnimationExportDialog dialog(design, start, this);
    if (dialog.exec() != QDialog::Accepted) return;
    const AnimationExportSettings settings = dialog.settings();
    if (!mayOverwrite(withAnimationExtension(settings.path, settings.format))) return;
    QSettings().setValue(QStringLiteral("files/exportDir"), QFileInfo(settings.path).absolutePath());
    if (!mAnimationJob) mAnimationJob = new AnimationExportJob(this);
    auto* progress =
        new QProgressDialog(tr("Writing the making of the design…"), tr("Cancel"), 0, 1000, this);
    progress->setObjectName(QStringLiteral("animationProgress"));
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(300);
    progress->setAutoClose(false);
    progress->setAutoReset(false);
    connect(mAnimationJob, &AnimationExportJob::progress, progress,
            [progress](double f) { progress->setValue(int(std::lround(f * 1000.0))); });
    connect(progress, &QProgressDialog::canceled, mAnimationJob, &AnimationExportJob::cancel);
    connect(mAnimationJob, &AnimationExportJob::finished, progress,
            [this, progress, path = settings.path](bool ok, const QString& error) {
                // Closing a progress dialog says "cancelled": let go of the job first.
                QObject::disconnect(progress, nullptr, mAnimationJob, nullptr);
                QObject::disconnect(mAnimationJob, nullptr, progress, nullptr);
                progress->close();
                progress->deleteLater();
                if (ok) {
                    statusBar()->showMessage(tr("Wrote %1").arg(QDir::toNativeSeparators(path)), 5000);
                    emit fileSaved(path);
                } else if (!error.isEmpty()) {
                    reportError(this, tr("Cannot write the animation"), error);
                } else {
                    statusBar()->showMessage(tr("Animation cancelled; nothing was written"), 4000);
                }
            });
    if (!mAnimationJob->start(design, settings)) {
        progress->deleteLater();
        statusBar()->showMessage(tr("An animation is being written already"), 4000);
    }
}

bool EditorWindow::maybeKeepChanges() {
    if (!mDocument->isModified()) return true;
    UnsavedAnswer answer;
    if (mUnsavedAnswer) {
        answer = *mUnsavedAnswer;
    } else {
        const auto button = QMessageBox::warning(
            this, tr("Unsaved changes"),
            tr("“%1” has changes that are not saved. Save them?").arg(displayName()),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        answer = button == QMessageBox::Save      ? UnsavedAnswer::Save
                 : button == QMessageBox::Discard ? UnsavedAnswer::Discard
                                                  : UnsavedAnswer::Cancel;
    }
    switch (answer) {
    case UnsavedAnswer::Save:
        return save();
    case UnsavedAnswer::Discard:
        return true;
    case UnsavedAnswer::Cancel:
        return false;
    }
    return false;
}

void EditorWindow::closeEvent(QCloseEvent* event) {
    if (!maybeKeepChanges()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("editor/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("editor/state"), saveState());
    if (mAutosave) mAutosave->discard(); // a normal close: nothing to recover
    event->accept();
}

// ---- SolidObjectView -------------------------------------------------------------------------

SolidObjectView::SolidObjectView(RenderService* renderer, QWidget* parent)
    : QWidget(parent)
    , mRenderer(renderer)
    , mKey(renderer->newKey()) {
    setMinimumSize(200, 200);
    setToolTip(tr("The design on its object: drag to turn it"));
    connect(mRenderer, &RenderService::rendered, this, [this](std::uint64_t key, const QImage& image, bool) {
        if (key != mKey) return;
        mImage = image;
        update();
    });
}

SolidObjectView::~SolidObjectView() {
    mRenderer->cancel(mKey);
}

void SolidObjectView::setDesign(const Genome& design) {
    // The design's own angle at first; after that the angle the user turned it to.
    if (mDesign.dimension != 3) mAngle = viewAngleOf(design);
    mDesign = design;
    request(false);
}

void SolidObjectView::setSlice(const Slice& slice) {
    mSlice = slice;
    update();
}

void SolidObjectView::setMesh(const QString& mesh) {
    mMesh = mesh;
    request(false);
}

void SolidObjectView::request(bool previewOnly) {
    if (mDesign.dimension != 3 || width() < 8 || height() < 8) return;
    RenderRequest r;
    r.genome = mDesign;
    setViewAngle(r.genome, mAngle);
    const qreal dpr = devicePixelRatioF();
    const int side = int(std::min(width(), height()) * dpr);
    r.size = QSize(side, side);
    r.mesh = mMesh;
    r.yaw = mAngle.yaw;
    r.pitch = mAngle.pitch;
    r.previewOnly = previewOnly;
    mRenderer->request(mKey, std::move(r));
}

void SolidObjectView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().window());
    if (mImage.isNull()) {
        p.drawText(rect(), Qt::AlignCenter, tr("Rendering…"));
        return;
    }
    QSizeF size = QSizeF(mImage.size()) / devicePixelRatioF();
    size.scale(QSizeF(this->size()), Qt::KeepAspectRatio);
    const QRectF target((width() - size.width()) / 2, (height() - size.height()) / 2, size.width(),
                        size.height());
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.drawImage(target, mImage);
    if (mSlice && mDesign.dimension == 3) paintSlice(p);
}

void SolidObjectView::paintSlice(QPainter& p) const {
    // The block in an oblique view in the corner, the section a plane through it: where the
    // canvas cuts, at a glance, whatever the object's shape.
    const glm::dvec3 size = mDesign.size;
    const double extent = std::max({size.x, size.y, size.z, 1e-9});
    constexpr double Side = 64.0;
    const QPointF origin(12.0, height() - 14.0);
    const auto at = [&](glm::dvec3 q) {
        q /= extent;
        return origin + QPointF((q.x + 0.5 * q.z) * Side, -(q.y + 0.35 * q.z) * Side);
    };
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(30, 30, 30, 200));
    p.drawRoundedRect(QRectF(origin.x() - 8.0, origin.y() - Side * 1.5, Side * 2.9, Side * 1.5 + 8.0), 6.0,
                      6.0);
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(220, 220, 220, 200), 1.0));
    const glm::dvec3 corner[8] = {
        {0, 0, 0},      {size.x, 0, 0},      {size.x, size.y, 0},      {0, size.y, 0},
        {0, 0, size.z}, {size.x, 0, size.z}, {size.x, size.y, size.z}, {0, size.y, size.z}};
    constexpr int Edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& e : Edges)
        p.drawLine(at(corner[e[0]]), at(corner[e[1]]));
    // The plane: the block's extent along the two other axes, at the section's value.
    const int axis = mSlice->axis;
    const SlicePlane section = slicePlane(3, axis, mSlice->value);
    const glm::dvec2 span = section.extent(size);
    QPolygonF plane;
    for (const auto& [ua, ub] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}})
        plane << at(section.fromPlane({ua * span.x, ub * span.y}));
    p.setPen(QPen(QColor(255, 170, 40), 1.5));
    p.setBrush(QColor(255, 170, 40, 90));
    p.drawPolygon(plane);
    p.setPen(QColor(235, 235, 235));
    p.drawText(QPointF(origin.x() + Side * 1.55, origin.y() - 2.0),
               tr("%1 = %2").arg(QLatin1String(axisName(axis))).arg(mSlice->value, 0, 'f', 1));
}

void SolidObjectView::resizeEvent(QResizeEvent*) {
    request(false);
}

void SolidObjectView::mousePressEvent(QMouseEvent* event) {
    mTurning = true;
    mLast = event->position();
}

void SolidObjectView::mouseMoveEvent(QMouseEvent* event) {
    if (!mTurning) return;
    const QPointF d = event->position() - mLast;
    mLast = event->position();
    mAngle = mAngle.dragged(d.x(), d.y());
    request(true);
}

void SolidObjectView::mouseReleaseEvent(QMouseEvent*) {
    if (!mTurning) return;
    mTurning = false;
    request(false);
}

} // namespace marbler::ui
