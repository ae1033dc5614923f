#include "workbench/WorkbenchWindow.h"
#include "marbler/Mesh.h"

#include "editor/EditorWindow.h"
#include "marbler/Error.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/ImageFormats.h"
#include "marbler/Paper.h"
#include "shared/BackgroundJob.h"
#include "shared/DesignDialog.h"
#include "shared/DesignExport.h"
#include "shared/ErrorReport.h"
#include "shared/GenomeClipboard.h"
#include "shared/Help.h"
#include "shared/Language.h"
#include "shared/RenameDialog.h"
#include "shared/RenderService.h"
#include "shared/SavedFiles.h"
#include "shared/StartDialog.h"
#include "workbench/ColourwaysController.h"
#include "workbench/DesignCell.h"
#include "workbench/FavouritesShelf.h"
#include "workbench/HelpMenu.h"
#include "workbench/OpenPlacement.h"
#include "workbench/OperatorActions.h"
#include "workbench/PaperDialog.h"
#include "workbench/PopulationBar.h"
#include "workbench/RendererMenu.h"
#include "workbench/SessionsController.h"
#include "workbench/StatusLine.h"
#include "workbench/Trash.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QClipboard>
#include <QCloseEvent>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHeaderView>
#include <QImageReader>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QPushButton>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSettings>
#include <QSignalBlocker>
#include <QSlider>
#include <QStatusBar>
#include <QTextBrowser>
#include <QToolBar>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace marbler::ui {

namespace {

/// File ▸ Open's filter: genome files, and the PNG and TIFF images Marbler writes, which carry
/// their genomes (marbler/GenomeImage.h).
QString openFilter() {
    return WorkbenchWindow::tr("Marbler designs (*.marble.json *.json *.png *.tif *.tiff);;"
                               "Genome files (*.marble.json *.json);;"
                               "Images with a genome (*.png *.tif *.tiff);;All files (*)");
}

} // namespace

WorkbenchWindow::WorkbenchWindow(RenderService* renderer, QWidget* parent)
    : QMainWindow(parent)
    , mRenderer(renderer)
    , mCellKeys(renderer->newKeys(CellCount))
    , mModel(new PopulationModel(this)) {
    setWindowTitle(tr("Marbler — evolution workbench"));
    mModel->setSessionSeed(QRandomGenerator::global()->generate64());

    auto* central = new QWidget(this);
    auto* grid = new QGridLayout(central);
    grid->setSpacing(4);
    grid->setContentsMargins(4, 4, 4, 4);
    for (int i = 0; i < CellCount; ++i) {
        auto* cell = new DesignCell(i, central);
        mCells[std::size_t(i)] = cell;
        grid->addWidget(cell, i / 3, i % 3);
        connect(cell, &DesignCell::clicked, this, &WorkbenchWindow::onCellClicked);
        connect(cell, &DesignCell::openRequested, this, &WorkbenchWindow::openDesign);
        connect(cell, &DesignCell::favouriteRequested, this, &WorkbenchWindow::keepFavourite);
        connect(cell, &DesignCell::contextMenuRequested, this, &WorkbenchWindow::showCellMenu);
        connect(cell, &DesignCell::renameRequested, this, [this](int i) { renameDesign(i); });
        connect(cell, &DesignCell::focusMoveRequested, this, &WorkbenchWindow::onFocusMove);
        connect(cell, &DesignCell::orbitDragged, this, &WorkbenchWindow::onOrbit);
        connect(cell, &DesignCell::filesDropped, this,
                [this](int index, const QStringList& files) { openFiles(files, index); });
        connect(cell, &DesignCell::genomeTextDropped, this, [this](int index, const QByteArray& json) {
            try {
                const Genome genome = parseGenome(json.toStdString(), "dropped design");
                const LineageInfo info = lineageOf(genome);
                placeOpened({genome}, {info.displayName()}, index, tr("Brought back a favourite"));
            } catch (const Error& e) {
                reportError(this, tr("Cannot use the dropped design"), QString::fromStdString(e.what()));
            }
        });
        connect(cell, &DesignCell::resized, this, [this] { mResizeTimer.start(); });
    }
    for (int r = 0; r < 3; ++r) {
        grid->setRowStretch(r, 1);
        grid->setColumnStretch(r, 1);
    }
    // Nine cells stay big enough to judge a design however small the window gets.
    central->setMinimumSize(3 * 120 + 16, 3 * 120 + 16);
    setCentralWidget(central);

    // Re-rendering nine cells on every pixel of a window drag would flood the queue.
    mResizeTimer.setSingleShot(true);
    mResizeTimer.setInterval(200);
    connect(&mResizeTimer, &QTimer::timeout, this, &WorkbenchWindow::requestAllRenders);

    buildActions();
    buildDocks();
    mHelp = new HelpMenu(this, mRenderer);
    setAcceptDrops(true);

    // The status bar: passing messages over the generation's summary, the last file saved and
    // what the window is doing.
    mStatus = new StatusLine(this);
    // Beside the message that a favourite was removed, while it shows.
    mFavourites->addUndoButton(statusBar());
    connect(mRenderer, &RenderService::backendReady, this, [this] {
        // Images from the other back end differ in the last bits: render everything anew (the
        // renderer menu says which one took over).
        mImageCache.clear();
        requestAllRenders();
    });
    connect(mRenderer, &RenderService::rendered, this, &WorkbenchWindow::onRendered);
    connect(mRenderer, &RenderService::failed, this, &WorkbenchWindow::onRenderFailed);
    connect(mRenderer, &RenderService::meshUnreadable, this,
            [this](const QString& mesh, const QString& message) {
                // Other views may show another file; only the grid's own object is replaced. Replaced
                // before the message, whose dialog runs an event loop in which more of these arrive.
                const bool solid = mesh == this->mesh(), flat = mesh == flatMesh();
                if (!solid && !flat) return;
                const QString fallback = QString::fromLatin1(DefaultMesh);
                if (solid) setMesh(fallback);
                if (flat) setFlatMesh(fallback);
                reportError(this, tr("Cannot show the mesh"),
                            tr("%1\n\nThe designs are shown on the %2 instead.").arg(message, fallback));
            });

    connect(this, &WorkbenchWindow::renderingFinished, mOperators, &OperatorActions::onRenderingFinished);
    connect(mModel, &PopulationModel::populationChanged, this, [this] {
        // Going to another generation drops a click still waiting: it was meant for this one.
        mOperators->onPopulationChanged();
        updateCells();
        requestAllRenders();
        mLineage->update();
    });
    connect(mModel, &PopulationModel::cellChanged, this, [this](int index) {
        updateCells(); // the lock marker
        mLineage->update();
        requestRender(index); // a new view angle (a lock change finds its image in the cache)
    });
    connect(mModel, &PopulationModel::selectionChanged, this, [this] {
        updateCells();
        updateActions();
    });
    connect(mModel, &PopulationModel::historyChanged, this, &WorkbenchWindow::updateActions);

    readSettings();
    mModel->setMesh(mPopulation->mesh());
    const QStringList favouriteErrors =
        mModel->setFavouritesFolder(PopulationModel::defaultFavouritesFolder());
    if (!favouriteErrors.isEmpty())
        statusBar()->showMessage(
            tr("Some favourites could not be read: %1").arg(favouriteErrors.join(QStringLiteral("; "))),
            10000);
    updateCells();
    updateActions();
    mLineage->update();
}

WorkbenchWindow::~WorkbenchWindow() {
    // Results for this window's keys may still arrive after it is gone; the service simply
    // has no receiver then, but the work itself is wasted, so drop it.
    for (int i = 0; i < CellCount; ++i)
        mRenderer->cancel(mCellKeys + std::uint64_t(i));
    mFavourites->cancelThumbnails(); // the lineage's go with its panel
}

void WorkbenchWindow::buildActions() {
    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    QMenu* editMenu = menuBar()->addMenu(tr("&Edit"));
    QMenu* breedMenu = menuBar()->addMenu(tr("&Breed"));
    // A greyed-out operator's tooltip says why; the menu shows it too.
    breedMenu->setToolTipsVisible(true);
    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->setObjectName(QStringLiteral("viewMenu"));

    QToolBar* bar = addToolBar(tr("Breeding"));
    bar->setObjectName(QStringLiteral("breedingToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);

    QAction* open = fileMenu->addAction(tr("&Open designs…"), this, &WorkbenchWindow::openFileDialog);
    open->setShortcut(QKeySequence::Open);
    open->setStatusTip(
        tr("Load genome files, or PNG and TIFF images Marbler wrote, into the selected cells, then free "
           "ones; asks before replacing designs"));
    QMenu* newDesign = fileMenu->addMenu(tr("New &design"));
    newDesign->setObjectName(QStringLiteral("newDesignMenu"));
    newDesign->setToolTipsVisible(true);
    newDesign->addAction(tr("Blank &flat bath"), this, [this] { openEditor(blankDesign(2)); })
        ->setToolTip(tr("Make a flat design by hand in the editor, from a bare bath"));
    newDesign->addAction(tr("Blank &solid block"), this, [this] { openEditor(blankDesign(3)); })
        ->setToolTip(tr("Make a solid design by hand in the editor, from a bare block"));
    newDesign
        ->addAction(tr("&Random design"), this,
                    [this] {
                        openEditor(
                            randomGenome(QRandomGenerator::global()->generate64(), mPopulation->dimension()));
                    })
        ->setToolTip(tr("A random design of the kind chosen on the tool bar, to edit by hand"));
    QAction* openInEditor = fileMenu->addAction(tr("Open in &editor…"), this, [this] {
        const QString file =
            QFileDialog::getOpenFileName(this, tr("Open a design in the editor"), QString(), openFilter());
        if (file.isEmpty()) return;
        try {
            openEditor(loadDesign(file.toStdString()), file);
        } catch (const Error& e) {
            reportError(this, tr("Cannot open the design"), QString::fromStdString(e.what()));
        }
    });
    openInEditor->setStatusTip(tr("Edit a genome file, or an image carrying a genome, step by step"));
    QAction* newRandom = fileMenu->addAction(tr("&New random population"), this,
                                             [this] { newRandomPopulation(mPopulation->dimension()); });
    newRandom->setShortcut(QKeySequence::New);
    newRandom->setIconText(tr("New random"));
    newRandom->setToolTip(tr("Nine new random designs of the kind chosen beside (Ctrl+N)"));
    QAction* picture =
        fileMenu->addAction(tr("&Marble a picture…"), this, &WorkbenchWindow::marblePictureDialog);
    picture->setObjectName(QStringLiteral("marblePictureAction"));
    picture->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M));
    picture->setStatusTip(
        tr("Nine flat designs whose bath is a picture you pick: flows and strokes carry its colours"));
    QAction* newPaperAction = fileMenu->addAction(tr("New marbled &paper…"), this, [this] {
        if (const std::optional<PaperChoice> paper = askPaper(this)) newPaper(paper->seed, paper->options);
    });
    newPaperAction->setObjectName(QStringLiteral("newPaperAction"));
    newPaperAction->setStatusTip(
        tr("A procedural marbled paper (as marbler paper makes) into the grid, to breed from"));
    fileMenu->addSeparator();
    mSessions = new SessionsController(this, mModel, fileMenu);
    fileMenu->addSeparator();
    fileMenu->addAction(tr("&Quit"), this, &QWidget::close)->setShortcut(QKeySequence::Quit);

    mBack = editMenu->addAction(style()->standardIcon(QStyle::SP_ArrowBack), tr("&Back a generation"), mModel,
                                &PopulationModel::goBack);
    mBack->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
    mBack->setIconText(tr("◀ Back"));
    mBack->setToolTip(tr("Back to the generation this one grew from (Ctrl+Z)"));
    mForward = editMenu->addAction(style()->standardIcon(QStyle::SP_ArrowForward),
                                   tr("&Forward a generation"), mModel, &PopulationModel::goForward);
    mForward->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z));
    mForward->setIconText(tr("Forward ▶"));
    mForward->setToolTip(tr("Forward to the generation last visited or made from this one (Ctrl+Shift+Z)"));
    editMenu->addSeparator();
    // Designs travel as genome text: into a chat, an editor, another window, and back.
    mCopyDesign = editMenu->addAction(tr("&Copy design"), this, [this] { copyDesign(); });
    mCopyDesign->setObjectName(QStringLiteral("copyDesignAction"));
    mCopyDesign->setShortcut(QKeySequence::Copy);
    mCopyDesign->setStatusTip(tr("Copies the focused design (else the first selected one) as genome text"));
    mPasteDesign = editMenu->addAction(tr("&Paste design"), this, [this] { pasteDesign(); });
    mPasteDesign->setObjectName(QStringLiteral("pasteDesignAction"));
    mPasteDesign->setShortcut(QKeySequence::Paste);
    mPasteDesign->setStatusTip(tr("Puts the genome on the clipboard into the grid, as File ▸ Open does"));
    mRename = editMenu->addAction(tr("&Rename…"), this, [this] { renameDesign(); });
    mRename->setObjectName(QStringLiteral("renameDesignAction"));
    mRename->setShortcut(QKeySequence(Qt::Key_F2));
    mRename->setStatusTip(tr("Names the focused design (else the first selected one) and gives it a note"));
    editMenu->addSeparator();
    QAction* clearSelection =
        editMenu->addAction(tr("Clear &selection"), mModel, &PopulationModel::clearSelection);
    clearSelection->setObjectName(QStringLiteral("clearSelectionAction"));
    clearSelection->setShortcut(QKeySequence(Qt::Key_Escape));
    editMenu->addSeparator();
    mFavourites = new FavouritesShelf(
        this, mModel, mRenderer, editMenu, [this] { return mesh(); },
        [this](const QString& file) { noteSavedFile(file); });
    connect(mFavourites, &FavouritesShelf::restoreRequested, this,
            [this](int favourite) { restoreFavourite(favourite); });

    mOperators = new OperatorActions(
        this, breedMenu, [this](GeneticOperator op) { return applyOperator(op); },
        [this] { return renderingDone(); });
    mOperators->addSteering(breedMenu, mModel); // issue 26

    // One offspring cell a fresh design of the parents' family, against breeding fatigue.
    breedMenu->addSeparator();
    QAction* wildcard = breedMenu->addAction(tr("&Wildcard cell"));
    wildcard->setObjectName(QStringLiteral("wildcardAction"));
    wildcard->setCheckable(true);
    wildcard->setChecked(QSettings().value(QStringLiteral("breed/wildcard"), true).toBool());
    wildcard->setStatusTip(
        tr("The last offspring cell of each generation is a fresh design of the parents' family"));
    mModel->setWildcardCell(wildcard->isChecked());
    connect(wildcard, &QAction::toggled, this, [this](bool on) {
        mModel->setWildcardCell(on);
        QSettings().setValue(QStringLiteral("breed/wildcard"), on);
    });

    bar->addAction(mBack);
    bar->addAction(mForward);
    bar->addSeparator();
    mOperators->addToToolBar(bar);
    mColourways = new ColourwaysController(
        this, mModel, [this](GeneticOperator op) { return operatorAction(op); },
        [this](const QString& file) { noteSavedFile(file); });
    connect(mColourways, &ColourwaysController::actionsChanged, this, &WorkbenchWindow::updateActions);
    mColourways->buildActions(breedMenu, bar);

    mOperators->addStrength(bar);

    // New populations on a row of their own: on one row the family box, New random and the
    // object box hid behind the bar's ›› at the default width, and on a 1,366-pixel screen.
    addToolBarBreak();
    bar = addToolBar(tr("New population"));
    bar->setObjectName(QStringLiteral("populationToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    mPopulation = new PopulationBar(bar, newRandom);
    connect(mPopulation, &PopulationBar::meshChanged, this, [this](const QString& mesh) {
        QSettings().setValue(QStringLiteral("view/mesh"), mesh);
        mModel->setMesh(mesh);
        requestAllRenders();
        mLineage->update(); // solid designs' thumbnails show the object
    });
    // Flat designs' object belongs to the session alone: a new one starts flat.
    connect(mPopulation, &PopulationBar::flatMeshChanged, this, [this](const QString& mesh) {
        mModel->setFlatMesh(mesh);
        updateCells(); // whether the cells turn
        requestAllRenders();
    });
}

void WorkbenchWindow::buildDocks() {
    QMenu* viewMenu = menuBar()->findChild<QMenu*>(QStringLiteral("viewMenu"));

    QDockWidget* favDock = mFavourites->buildDock();
    addDockWidget(Qt::RightDockWidgetArea, favDock);

    mLineage = new LineagePanel(this, mModel, mRenderer, [this] { return mesh(); });
    connect(mLineage, &LineagePanel::openDesignRequested, this, &WorkbenchWindow::openDesign);
    connect(mLineage, &LineagePanel::bringBackRequested, this, &WorkbenchWindow::bringBackDesign);
    QDockWidget* lineageDock = mLineage->dock();
    addDockWidget(Qt::RightDockWidgetArea, lineageDock);

    viewMenu->addAction(favDock->toggleViewAction());
    viewMenu->addAction(lineageDock->toggleViewAction());
    favDock->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    lineageDock->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L));

    mRendererMenu = new RendererMenu(this, mRenderer, viewMenu);
    addLanguageMenu(viewMenu, this); // issue 25: View ▸ Language
}

void WorkbenchWindow::setRendererPreference(gl::BackendPreference preference) {
    mRendererMenu->setPreference(preference);
}

QAction* WorkbenchWindow::rendererAction(gl::BackendPreference preference) const {
    return mRendererMenu->action(preference);
}

QString WorkbenchWindow::rendererDescription() const {
    return mRendererMenu->description();
}

QDialog* WorkbenchWindow::showGuide() {
    return mHelp->showGuide();
}

QDialog* WorkbenchWindow::showAbout() {
    return mHelp->showAbout();
}

QAction* WorkbenchWindow::guideAction() const {
    return mHelp->guideAction();
}

QAction* WorkbenchWindow::aboutQtAction() const {
    return mHelp->aboutQtAction();
}

SavedFileNotice* WorkbenchWindow::savedFileNotice() const {
    return mStatus->savedNotice();
}

void WorkbenchWindow::noteSavedFile(const QString& file) {
    // The notice holds the full path, long enough to reach "Show in folder"; a passing message
    // would only say it twice.
    mStatus->savedNotice()->showFile(file);
}

void WorkbenchWindow::updateTask() {
    int pending = 0;
    for (int i = 0; i < CellCount; ++i)
        if (!mFinal[std::size_t(i)] && mModel->cell(i)) ++pending;
    mStatus->setPending(pending);
}

void WorkbenchWindow::readSettings() {
    QSettings settings;
    if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray())) resize(1180, 860);
    if (!restoreState(settings.value(QStringLiteral("window/state")).toByteArray())) {
        // First start: docks wide enough for the lineage columns, the shelf above the lineage.
        const auto docks = findChildren<QDockWidget*>();
        resizeDocks(QList<QDockWidget*>(docks.begin(), docks.end()), QList<int>(docks.size(), 380),
                    Qt::Horizontal);
    }
    const int dimension = settings.value(QStringLiteral("population/dimension"), 2).toInt();
    mPopulation->setDimension(dimension);
    setPopulationFamily(settings.value(QStringLiteral("population/family")).toString());
    mOperators->strengthSlider()->setValue(settings.value(QStringLiteral("breed/strength"), 50).toInt());
    const QString mesh =
        settings.value(QStringLiteral("view/mesh"), QString::fromLatin1(DefaultMesh)).toString();
    mPopulation->setMesh(mesh);
}

void WorkbenchWindow::closeEvent(QCloseEvent* event) {
    // Each open editor asks about its unsaved changes first; one kept open keeps Marbler open.
    for (EditorWindow* editor : findChildren<EditorWindow*>(Qt::FindDirectChildrenOnly))
        if (editor->isVisible() && !editor->close()) {
            event->ignore();
            return;
        }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    settings.setValue(QStringLiteral("breed/strength"), mOperators->strengthSlider()->value());
    QMainWindow::closeEvent(event);
}

QAction* WorkbenchWindow::operatorAction(GeneticOperator op) const {
    return mOperators->action(op);
}

double WorkbenchWindow::strength() const {
    return mOperators->strength();
}

void WorkbenchWindow::setStrength(double strength) {
    mOperators->setStrength(strength);
}

void WorkbenchWindow::updateCells() {
    mPopulation->setShownKind(mModel->populationDimension());
    for (int i = 0; i < CellCount; ++i) {
        DesignCell* c = mCells[std::size_t(i)];
        const Genome* g = mModel->cell(i);
        c->setHasDesign(g != nullptr);
        c->setSelectedParent(mModel->isSelected(i));
        c->setOrbitEnabled(g && !objectFor(g->dimension).isEmpty());
        if (!g) {
            c->setCaption({});
            c->setChange({});
            c->setNote({});
            continue;
        }
        // Marked "less like this" (issue 26, steering): said on the cell.
        c->setCaption(mModel->isDisliked(i) ? tr("%1 · less like this").arg(designCaption(*g))
                                            : designCaption(*g));
        c->setChange(lineageOf(*g).change);
        c->setNote(noteOf(*g));
        const Locks locks = locksOf(*g);
        c->setLocked(locks.palette || locks.initial || locks.operations);
    }
}

void WorkbenchWindow::updateActions() {
    const int n = mModel->selectedCount();
    mOperators->update(*mModel);
    mColourways->updateActions();
    mBack->setEnabled(mModel->canGoBack());
    mForward->setEnabled(mModel->canGoForward());
    const auto& gen = mModel->current();
    if (mModel->isEmptyWorkbench()) {
        mStatus->setGeneration(
            tr("No designs yet: make a new random population (Ctrl+N) or open designs (Ctrl+O)"));
        return;
    }
    QString line = tr("Generation %1: %2 — %3 selected")
                       .arg(mModel->generationLabel(mModel->currentIndex()))
                       .arg(gen.description)
                       .arg(n == 1 ? tr("1 parent") : tr("%1 parents").arg(n));
    // Why the children were chosen (issue 26, steering).
    if (const QString why = mModel->steerExplanation(); !why.isEmpty()) line += tr(" — %1").arg(why);
    mStatus->setGeneration(line);
}

QString WorkbenchWindow::renderCacheKey(int index) const {
    const Genome* g = mModel->cell(index);
    if (!g) return {};
    const QSize size = mCells[std::size_t(index)]->size() * mCells[std::size_t(index)]->devicePixelRatioF();
    // Locks live in meta, and genomeId ignores meta, so a lock change keeps the image.
    const QString object = objectFor(g->dimension);
    return QStringLiteral("%1/%2x%3/%4/%5/%6")
        .arg(QString::fromStdString(genomeId(*g)))
        .arg(size.width())
        .arg(size.height())
        .arg(object)
        .arg(object.isEmpty() ? 0.0 : cellViewAngle(index).yaw)
        .arg(object.isEmpty() ? 0.0 : cellViewAngle(index).pitch);
}

ViewAngle WorkbenchWindow::cellViewAngle(int index) const {
    if (index == mOrbitCell) return mOrbitAngle;
    const Genome* g = mModel->cell(index);
    return g ? viewAngleOf(*g) : ViewAngle{};
}

void WorkbenchWindow::requestRender(int index, bool previewOnly) {
    const Genome* g = mModel->cell(index);
    DesignCell* c = mCells[std::size_t(index)];
    if (!g) {
        mRenderer->cancel(mCellKeys + std::uint64_t(index));
        mFinal[std::size_t(index)] = true;
        return;
    }
    const QString key = renderCacheKey(index);
    if (!previewOnly) {
        if (const QImage* cached = mImageCache.object(key)) {
            mRenderer->cancel(mCellKeys + std::uint64_t(index));
            c->setImage(*cached);
            mShownDesign[std::size_t(index)] = genomeId(*g);
            mFinal[std::size_t(index)] = true;
            return;
        }
    }
    // A cell showing another design's image (a new generation) shows "rendering…" until its
    // own arrives, never the old picture under the new name; the same design at another size
    // or angle keeps its image meanwhile.
    const std::string id = genomeId(*g);
    if (mShownDesign[std::size_t(index)] != id) {
        c->setImage(QImage());
        mShownDesign[std::size_t(index)].clear();
    }
    mRequestedDesign[std::size_t(index)] = id;
    RenderRequest request;
    request.genome = *g;
    const int margin = 12;
    request.size = ((c->size() - QSize(margin, margin)) * c->devicePixelRatioF()).expandedTo(QSize(16, 16));
    request.mesh = objectFor(g->dimension);
    request.flatOnObject = g->dimension != 3 && !request.mesh.isEmpty();
    const ViewAngle angle = cellViewAngle(index);
    request.yaw = angle.yaw;
    request.pitch = angle.pitch;
    request.previewOnly = previewOnly;
    mPendingCacheKey[std::size_t(index)] = previewOnly ? QString() : key;
    mFinal[std::size_t(index)] = false;
    mRenderer->request(mCellKeys + std::uint64_t(index), std::move(request));
    updateTask();
}

void WorkbenchWindow::requestAllRenders() {
    for (int i = 0; i < CellCount; ++i)
        requestRender(i);
    updateTask();
    if (renderingDone()) emit renderingFinished();
}

bool WorkbenchWindow::renderingDone() const {
    return std::all_of(mFinal.begin(), mFinal.end(), [](bool b) { return b; });
}

void WorkbenchWindow::onRendered(std::uint64_t key, const QImage& image, bool final) {
    // Other keys are other views' (the favourites, the lineage, a large view, an editor).
    if (key >= mCellKeys && key < mCellKeys + std::uint64_t(CellCount)) {
        const auto index = std::size_t(key - mCellKeys);
        mCells[index]->setImage(image);
        mShownDesign[index] = mRequestedDesign[index];
        if (final) {
            if (!mPendingCacheKey[index].isEmpty())
                mImageCache.insert(mPendingCacheKey[index], new QImage(image));
            mFinal[index] = true;
            updateTask();
            if (renderingDone()) emit renderingFinished();
        }
        return;
    }
    // The lineage's and the favourites' thumbnails: their objects take them.
}

void WorkbenchWindow::onRenderFailed(std::uint64_t key, const QString& message) {
    if (key >= mCellKeys && key < mCellKeys + std::uint64_t(CellCount)) {
        const auto index = std::size_t(key - mCellKeys);
        mCells[index]->setError(message);
        mFinal[index] = true;
        statusBar()->showMessage(tr("Design %1 cannot be rendered: %2").arg(index + 1).arg(message), 10000);
        updateTask();
        if (renderingDone()) emit renderingFinished();
    }
}

void WorkbenchWindow::onCellClicked(int index) {
    if (!mModel->cell(index)) {
        statusBar()->showMessage(tr("An empty cell: open a design (Ctrl+O) or drop a file here"), 4000);
        return;
    }
    mModel->toggleSelected(index);
}

void WorkbenchWindow::onFocusMove(int index, int dx, int dy) {
    const int row = std::clamp(index / 3 + dy, 0, 2);
    const int col = std::clamp(index % 3 + dx, 0, 2);
    mCells[std::size_t(row * 3 + col)]->setFocus(Qt::TabFocusReason);
}

void WorkbenchWindow::onOrbit(int index, QPoint delta, bool finished) {
    if (!mModel->cell(index)) return;
    mOrbitAngle = cellViewAngle(index).dragged(delta.x(), delta.y());
    mOrbitCell = index;
    if (!finished) {
        // While dragging only previews are worth rendering, and the session is not saved.
        requestRender(index, true);
        return;
    }
    // The angle belongs to the design; the model's cellChanged asks for the final image.
    mOrbitCell = -1;
    mModel->setCellView(index, mOrbitAngle);
}

bool WorkbenchWindow::applyOperator(GeneticOperator op) {
    if (colourwaysMode()) return mColourways->applyOperator(op, strength());
    if (const QString why = mModel->whyNot(op); !why.isEmpty()) {
        statusBar()->showMessage(why, 5000);
        return false;
    }
    // The children are made off the GUI thread: from a design of long stylus strokes a generation
    // takes seconds, and the window must keep drawing (and offer to cancel) meanwhile.
    auto pending = std::make_shared<PopulationModel::PendingBreed>();
    try {
        *pending = mModel->prepareBreed(op, strength());
    } catch (const Error& e) {
        reportError(this, tr("Cannot breed"), QString::fromStdString(e.what()));
        return false;
    }
    JobBox box(this, tr("Breeding generation %1…").arg(mModel->current().number + 1),
               QStringLiteral("breedProgress"));
    box.busy = true;
    box.minimumDurationMs = 500;
    const JobOutcome outcome = BackgroundJob::runWaiting(
        this, box, [pending](const RenderControl&) { PopulationModel::breedPending(*pending); });
    if (outcome.cancelled()) {
        statusBar()->showMessage(tr("Breeding cancelled: the generation is as it was"), 5000);
        return false;
    }
    try {
        if (outcome.failed()) throw RuntimeFailure(outcome.error.toStdString());
        mModel->commitBreed(std::move(*pending));
    } catch (const Error& e) {
        reportError(this, tr("Cannot breed"), QString::fromStdString(e.what()));
        return false;
    }
    statusBar()->showMessage(tr("Bred generation %1 with %2")
                                 .arg(mModel->generationLabel(mModel->currentIndex()))
                                 .arg(operatorLabel(op)),
                             5000);
    return true;
}

void WorkbenchWindow::requestOperator(GeneticOperator op) {
    mOperators->request(op);
}

void WorkbenchWindow::moreLikeThis(int index) {
    if (!mModel->cell(index)) return;
    mModel->clearSelection();
    mModel->setSelected(index, true);
    requestOperator(GeneticOperator::Alter);
}

void WorkbenchWindow::setPopulationFamily(const QString& family) {
    mPopulation->setFamily(family);
}

QString WorkbenchWindow::populationFamily() const {
    return mPopulation->family();
}

void WorkbenchWindow::newRandomPopulation(int dimension) {
    // Colourways vary one design's palette; a new population has no design picked for them, and
    // the mode left on made the operators recolour instead of breed (issue 29).
    if (colourwaysMode()) setColourwaysMode(false);
    QSettings().setValue(QStringLiteral("population/dimension"), dimension);
    mPopulation->setDimension(dimension);
    QSettings().setValue(QStringLiteral("population/family"), populationFamily());
    try {
        mModel->newRandomPopulation(dimension, populationFamily().toStdString());
    } catch (const Error& e) {
        reportError(this, tr("Cannot make a random population"), QString::fromStdString(e.what()));
    }
}

bool WorkbenchWindow::openFiles(const QStringList& files, int cell) {
    std::vector<Genome> designs;
    QStringList errors;
    QStringList names;
    QString picture; ///< the first plain picture: offered to Marble a picture (issue 29)
    for (const QString& file : files) {
        try {
            std::vector<std::string> warnings;
            // A genome file or an image that carries one: the command line's loader.
            designs.push_back(loadDesign(file.toStdString(), &warnings));
            names << QFileInfo(file).fileName();
            if (!warnings.empty()) statusBar()->showMessage(QString::fromStdString(warnings.front()), 8000);
        } catch (const GenomeError& e) {
            // A design whose genome is broken is reported, never taken for a picture.
            errors << QString::fromStdString(e.what());
        } catch (const Error& e) {
            if (picture.isEmpty() && QImageReader(file).canRead())
                picture = file;
            else
                errors << QString::fromStdString(e.what());
        }
    }
    // Several files dropped on one cell have no single target: they go where opened files go.
    placeOpened(designs, names, designs.size() == 1 ? cell : -1);
    bool pictureTaken = true;
    if (!picture.isEmpty()) {
        pictureTaken = offerMarblePicture(this, picture) && !marblePicture(picture).empty();
        if (!pictureTaken && designs.empty())
            statusBar()->showMessage(
                tr("Nothing opened: %1 holds no design").arg(QFileInfo(picture).fileName()), 8000);
    }
    if (!errors.isEmpty()) {
        reportError(this, tr("Cannot open a design"),
                    tr("These files could not be loaded; the population is unchanged by them.\n\n%1")
                        .arg(errors.join(QStringLiteral("\n"))));
        return false;
    }
    return pictureTaken;
}

std::vector<int> WorkbenchWindow::placeOpened(const std::vector<Genome>& opened, const QStringList& names,
                                              int cell, const QString& describe) {
    if (opened.empty()) return {};
    // One kind per generation: flat and solid designs cannot breed together, and the grid's
    // object, previews and operators all assume one kind. Designs of the grid's kind (of the
    // first design's, on an empty workbench) go where opened designs go; those of the other kind
    // then start a generation of their own (issue 29: they were refused).
    int kind = mModel->isEmptyWorkbench() ? opened.front().dimension : mModel->populationDimension();
    std::vector<Genome> designs, others;
    QStringList accepted, otherNames;
    for (std::size_t k = 0; k < opened.size(); ++k) {
        const QString name = int(k) < names.size() ? names[int(k)] : tr("design %1").arg(k + 1);
        (opened[k].dimension == kind ? designs : others).push_back(opened[k]);
        (opened[k].dimension == kind ? accepted : otherNames) << name;
    }
    if (designs.empty()) {
        designs = std::move(others);
        accepted = otherNames;
        kind = designs.front().dimension;
    } else if (!others.empty()) {
        std::vector<int> used = placeOpened(designs, accepted, cell, describe);
        if (used.empty()) return used; // the question was cancelled: nothing of either kind
        const QString kindName = kind == 3 ? tr("solid") : tr("flat");
        const QString otherKind = kind == 3 ? tr("flat") : tr("solid");
        const QString description = tr("Opened %1").arg(otherNames.join(QStringLiteral(", ")));
        mModel->startGenerationOf(others, description, 0);
        mPopulation->setDimension(others.front().dimension);
        statusBar()->showMessage(tr("Opened %1 and %2: the %3 designs are a generation of their own, the %4 "
                                    "ones one generation back (%5)")
                                     .arg(accepted.join(QStringLiteral(", ")),
                                          otherNames.join(QStringLiteral(", ")), otherKind, kindName,
                                          mBack->shortcut().toString(QKeySequence::NativeText)),
                                 15000);
        return used;
    }
    const QString description =
        describe.isEmpty() ? tr("Opened %1").arg(accepted.join(QStringLiteral(", "))) : describe;

    std::vector<int> used;
    if (mModel->isEmptyWorkbench()) {
        // Nothing to replace: the first designs, into the cell they were dropped on if any.
        if (cell >= 0 && cell < CellCount && designs.size() == 1) {
            mModel->setCell(cell, designs.front(), description);
            used = {cell};
        } else {
            used = mModel->placeDesigns(designs, description);
        }
    } else if (kind != mModel->populationDimension()) {
        return startGenerationOfKind(designs, description, cell >= 0 ? cell : 0);
    } else {
        const bool targeted = cell >= 0 && cell < CellCount && designs.size() == 1;
        OpenQuestion question;
        question.names = accepted;
        if (targeted) {
            // An explicit target is the user's choice, unless it would overwrite a parent.
            if (mModel->isSelected(cell)) question.replaced = {cell};
        } else {
            for (int c : mModel->placementCells(designs.size())) {
                if (mModel->cell(c)) question.replaced.push_back(c);
            }
        }
        for (int c : question.replaced)
            if (mModel->isSelected(c)) question.parents.push_back(c);
        std::optional<OpenChoice> choice = OpenChoice::Replace;
        if (!question.replaced.empty())
            choice = askOpenChoice() ? chooseOpenPlacement(this, question) : lastOpenChoice();
        if (!choice) {
            statusBar()->showMessage(tr("Nothing opened: the grid is as it was"), 5000);
            return {};
        }
        if (*choice == OpenChoice::NewGeneration) {
            used = mModel->placeDesigns(designs, description, PopulationModel::Placement::KeepParents);
        } else if (targeted) {
            mModel->setCell(cell, designs.front(), description);
            used = {cell};
        } else {
            used = mModel->placeDesigns(designs, description);
        }
    }
    if (used.size() < designs.size())
        statusBar()->showMessage(tr("%1: only %2 of %3 designs found room in the grid")
                                     .arg(description)
                                     .arg(used.size())
                                     .arg(designs.size()),
                                 10000);
    else
        statusBar()->showMessage(description, 5000);
    return used;
}

std::vector<int> WorkbenchWindow::startGenerationOfKind(const std::vector<Genome>& designs,
                                                        const QString& description, int first) {
    if (designs.empty()) return {};
    const int kind = designs.front().dimension;
    const int before = mModel->populationDimension();
    const bool wasEmpty = mModel->isEmptyWorkbench();
    const std::vector<int> used = mModel->startGenerationOf(designs, description, first);
    mPopulation->setDimension(kind);
    const auto kindName = [this](int dimension) { return dimension == 3 ? tr("solid") : tr("flat"); };
    const QString back = mBack->shortcut().toString(QKeySequence::NativeText);
    if (wasEmpty)
        statusBar()->showMessage(description, 5000);
    else if (kind != before)
        // Among designs of the other kind it could breed with none of them, and the operators
        // would grey out for no visible reason: it starts a generation of its own, and the grid
        // it replaces stays one step back.
        statusBar()->showMessage(tr("%1: %2 designs start a generation of their own; the %3 designs are one "
                                    "generation back (%4)")
                                     .arg(description, kindName(kind), kindName(before), back),
                                 10000);
    else
        statusBar()->showMessage(tr("%1; the grid before is one generation back (%2)").arg(description, back),
                                 10000);
    return used;
}

void WorkbenchWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void WorkbenchWindow::dropEvent(QDropEvent* event) {
    QStringList files;
    for (const QUrl& url : event->mimeData()->urls())
        if (url.isLocalFile()) files << url.toLocalFile();
    if (files.isEmpty()) return;
    event->acceptProposedAction();
    openFiles(files);
}

void WorkbenchWindow::openFileDialog() {
    const QString dir = QSettings().value(QStringLiteral("files/lastDir")).toString();
    const QStringList files = QFileDialog::getOpenFileNames(this, tr("Open designs"), dir, openFilter());
    if (files.isEmpty()) return;
    QSettings().setValue(QStringLiteral("files/lastDir"), QFileInfo(files.front()).absolutePath());
    openFiles(files);
}

int WorkbenchWindow::designToCopy() const {
    for (int i = 0; i < CellCount; ++i)
        if (mCells[std::size_t(i)]->hasFocus() && mModel->cell(i)) return i;
    const std::vector<int> selected = mModel->selectedCells();
    return selected.empty() ? -1 : selected.front();
}

bool WorkbenchWindow::copyDesign(int cell) {
    if (cell < 0) cell = designToCopy();
    const Genome* g = cell >= 0 && cell < CellCount ? mModel->cell(cell) : nullptr;
    if (!g) {
        statusBar()->showMessage(tr("Nothing copied: click or select a design first"), 5000);
        return false;
    }
    copyGenomeToClipboard(*g);
    const LineageInfo info = lineageOf(*g);
    statusBar()->showMessage(tr("Copied %1 to the clipboard as genome text")
                                 .arg(info.name.isEmpty() ? tr("design %1").arg(cell + 1) : info.name),
                             5000);
    return true;
}

std::vector<int> WorkbenchWindow::newPaper(std::uint64_t seed) {
    return newPaper(seed, PaperOptions{});
}

std::vector<int> WorkbenchWindow::newPaper(std::uint64_t seed, const PaperOptions& options) {
    Genome paper;
    try {
        paper = paperGenome(seed, options);
    } catch (const Error& e) {
        reportError(this, tr("Cannot make the paper"), QString::fromStdString(e.what()));
        return {};
    }
    const QString name = QString::fromStdString(paper.meta.name.value_or(""));
    return placeOpened({paper}, {name}, -1, tr("Marbled paper %1 (seed %2)").arg(name).arg(seed));
}

bool WorkbenchWindow::pasteDesign() {
    const ClipboardDesign pasted = clipboardDesign(QGuiApplication::clipboard()->mimeData());
    if (!pasted.files.isEmpty()) return openFiles(pasted.files);
    Genome genome;
    try {
        genome = parseClipboardGenome(pasted.genomeText);
    } catch (const Error& e) {
        // The clipboard is often something else entirely: a line, not a message box.
        statusBar()->showMessage(tr("Nothing pasted: the clipboard holds no Marbler design (%1)")
                                     .arg(QString::fromStdString(e.what())),
                                 10000);
        return false;
    }
    const LineageInfo info = lineageOf(genome);
    const QString name = info.displayName();
    return !placeOpened({genome}, {name}, -1, tr("Pasted %1").arg(name)).empty();
}

bool WorkbenchWindow::keepFavourite(int index) {
    return mFavourites->keep(index);
}

void WorkbenchWindow::restoreFavourite(int favourite, int index) {
    const auto& favourites = mModel->favourites();
    if (favourite < 0 || favourite >= int(favourites.size())) return;
    const Genome genome = favourites[std::size_t(favourite)].genome;
    const LineageInfo info = lineageOf(genome);
    placeOpened({genome}, {info.displayName()}, index, tr("Brought back a favourite"));
}

void WorkbenchWindow::showCellMenu(int index, const QPoint& globalPos) {
    const Genome* g = mModel->cell(index);
    QMenu menu(this);
    if (!g) {
        menu.addAction(tr("Open a design here…"), this, [this, index] {
            const QString file =
                QFileDialog::getOpenFileName(this, tr("Open a design"), QString(), openFilter());
            if (!file.isEmpty()) openFiles({file}, index);
        });
        menu.exec(globalPos);
        return;
    }
    menu.addAction(mModel->isSelected(index) ? tr("Deselect parent") : tr("Select as parent"), this,
                   [this, index] { mModel->toggleSelected(index); });
    menu.addAction(tr("More like this"), this, [this, index] { moreLikeThis(index); })
        ->setToolTip(tr("Breeds the next generation from this design alone"));
    menu.addAction(mModel->isDisliked(index) ? tr("No longer less like this") : tr("Less like this"), this,
                   [this, index] { mModel->setDisliked(index, !mModel->isDisliked(index)); })
        ->setToolTip(tr("Steering moves the next generations away from this design"));
    menu.addAction(tr("Open large…"), this, [this, index] { openDesign(index); });
    menu.addAction(tr("Open in editor"), this, [this, index] {
        if (const Genome* design = mModel->cell(index)) openEditor(*design);
    });
    menu.addAction(tr("Keep as favourite"), this, [this, index] { keepFavourite(index); })
        ->setShortcut(QKeySequence(Qt::Key_F));
    menu.addAction(tr("Rename…"), this, [this, index] { renameDesign(index); })
        ->setShortcut(mRename->shortcut());
    menu.addAction(tr("Save design…"), this, [this, index] { saveDesign(index); });
    menu.addAction(tr("Copy design"), this, [this, index] { copyDesign(index); })
        ->setShortcut(mCopyDesign->shortcut());
    menu.addSeparator();
    const Locks locks = locksOf(*g);
    const auto addLock = [&](const QString& text, const QString& tip, bool Locks::*field) {
        QAction* a = menu.addAction(text);
        a->setCheckable(true);
        a->setChecked(locks.*field);
        a->setToolTip(tip);
        connect(a, &QAction::toggled, this, [this, index, field](bool on) {
            const Genome* current = mModel->cell(index);
            if (!current) return;
            Locks l = locksOf(*current);
            l.*field = on;
            mModel->setCellLocks(index, l);
            updateCells();
        });
    };
    menu.setToolTipsVisible(true);
    addLock(tr("Lock palette"), tr("Operators keep this design's inks"), &Locks::palette);
    addLock(tr("Lock initial state"), tr("Operators keep this design's initial drops"), &Locks::initial);
    addLock(tr("Lock operations"), tr("Operators keep this design's strokes"), &Locks::operations);
    menu.exec(globalPos);
}

bool WorkbenchWindow::removeFavourite(int favourite) {
    return mFavourites->remove(favourite);
}

bool WorkbenchWindow::restoreRemovedFavourite() {
    return mFavourites->restoreRemoved();
}

QListWidget* WorkbenchWindow::favouritesList() const {
    return mFavourites->list();
}

QAction* WorkbenchWindow::restoreFavouriteAction() const {
    return mFavourites->restoreAction();
}

QPushButton* WorkbenchWindow::undoRemoveButton() const {
    return mFavourites->undoRemoveButton();
}

QTreeWidget* WorkbenchWindow::lineageTree() const {
    return mLineage->tree();
}

bool WorkbenchWindow::hasLineageThumbnail(const Genome& genome) const {
    return mLineage->hasThumbnail(genome);
}

void WorkbenchWindow::setSessionStore(const QString& sessionFolder) {
    mSessions->setStore(sessionFolder);
}

QString WorkbenchWindow::sessionStoreFolder() const {
    return mSessions->storeFolder();
}

QString WorkbenchWindow::currentSessionId() const {
    return mSessions->currentId();
}

bool WorkbenchWindow::resumeKeptSession(const QString& id) {
    return mSessions->resume(id);
}

bool WorkbenchWindow::renameSession(const QString& id, const QString& name) {
    return mSessions->rename(id, name);
}

QString WorkbenchWindow::deleteSession(const QString& id) {
    return mSessions->remove(id);
}

bool WorkbenchWindow::restoreDeletedSession(const QString& trashed) {
    return mSessions->restoreDeleted(trashed);
}

SessionsDialog* WorkbenchWindow::openSessionsDialog() {
    return mSessions->openDialog();
}

QAction* WorkbenchWindow::sessionsAction() const {
    return mSessions->sessionsAction();
}

QMenu* WorkbenchWindow::recentSessionsMenu() const {
    return mSessions->recentMenu();
}

QAction* WorkbenchWindow::colourwaysAction() const {
    return mColourways->modeAction();
}

bool WorkbenchWindow::colourwaysMode() const {
    return mColourways && mColourways->isOn();
}

void WorkbenchWindow::setColourwaysMode(bool on) {
    mColourways->setOn(on);
}

bool WorkbenchWindow::exportColourwaySheet(const QString& file) {
    return mColourways->exportSheet(file);
}

QAction* WorkbenchWindow::exportSheetAction() const {
    return mColourways->exportSheetAction();
}

bool WorkbenchWindow::sheetExportRunning() const {
    return mColourways->sheetRunning();
}

void WorkbenchWindow::setSheetCellWidth(int width) {
    mColourways->setSheetCellWidth(width);
}

void WorkbenchWindow::saveDesign(int index) {
    const Genome* g = mModel->cell(index);
    if (!g) return;
    Genome saved;
    const QString file = saveGenomeWithDialog(this, *g, &saved);
    if (file.isEmpty()) return;
    // Saved under a name of the user's own: the design is called that in the grid too.
    if (saved.meta.name != g->meta.name) {
        mModel->renameCell(index, QString::fromStdString(saved.meta.name.value_or("")), noteOf(saved), true);
        updateCells();
    }
    noteSavedFile(file);
}

RenameDialog* WorkbenchWindow::renameDesign(int index) {
    if (index < 0 && mFavourites->list()->hasFocus() && mFavourites->list()->currentRow() >= 0)
        return mFavourites->rename(mFavourites->list()->currentRow());
    if (index < 0) index = designToCopy();
    const Genome* g = index >= 0 && index < CellCount ? mModel->cell(index) : nullptr;
    if (!g) {
        statusBar()->showMessage(tr("Nothing to rename: click or select a design first"), 5000);
        return nullptr;
    }
    const std::string id = genomeId(*g);
    return askRename(this, *g, [this, index, id](const QString& name, const QString& note) {
        const Genome* shown = mModel->cell(index);
        if (!shown || genomeId(*shown) != id) return; // the grid moved on meanwhile
        const QString given = mModel->renameCell(index, name, note);
        updateCells();
        statusBar()->showMessage(given == name ? tr("Renamed design %1 to “%2”").arg(index + 1).arg(given)
                                               : tr("Renamed design %1 to “%2”: another design of this "
                                                    "session is called “%3”")
                                                     .arg(index + 1)
                                                     .arg(given, name),
                                 5000);
    });
}

DesignDialog* WorkbenchWindow::openDesign(int index) {
    const Genome* g = mModel->cell(index);
    if (!g) return nullptr;
    auto* dialog = new DesignDialog(*g, mRenderer, mPopulation->mesh(), this, mPopulation->flatMesh());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    // Turning the object in the large view turns the design, where the cell still holds it.
    const std::string id = genomeId(*g);
    connect(dialog, &DesignDialog::viewAngleChanged, this, [this, index, id](const ViewAngle& angle) {
        const Genome* shown = mModel->cell(index);
        if (shown && genomeId(*shown) == id) mModel->setCellView(index, angle);
    });
    connect(dialog, &DesignDialog::fileSaved, this, &WorkbenchWindow::noteSavedFile);
    // Issue 29: a cancelled export said nothing anywhere.
    connect(dialog, &DesignDialog::exportFinished, this,
            [this](const QString& file, bool written, const QString& error) {
                if (!written && error.isEmpty()) statusBar()->showMessage(exportCancelledMessage(file), 8000);
            });
    // Named in the large view: the cell's design takes the name (unique in the session).
    connect(dialog, &DesignDialog::renamed, this, [this, index, id, dialog](const Genome& design) {
        const Genome* shown = mModel->cell(index);
        if (!shown || genomeId(*shown) != id) return;
        const QString name = QString::fromStdString(design.meta.name.value_or(""));
        const QString given = mModel->renameCell(index, name, noteOf(design));
        if (given != name) dialog->rename(given, noteOf(design));
        updateCells();
    });
    connect(dialog, &DesignDialog::openInEditorRequested, this,
            [this](const Genome& design) { openEditor(design); });
    connect(dialog, &DesignDialog::genomeCopied, this, [this](const QString& name) {
        statusBar()->showMessage(tr("Copied %1 to the clipboard as genome text").arg(name), 5000);
    });
    dialog->show();
    emit designOpened(dialog);
    return dialog;
}

void WorkbenchWindow::bringBackDesign(int generation, int cell) {
    if (generation < 0 || generation >= int(mModel->history().size()) || cell < 0 || cell >= CellCount)
        return;
    // A copy: the generation may be one read back, which the new generation lets go again.
    const std::optional<Genome> design = mModel->generation(generation).cells[std::size_t(cell)];
    if (!design) return;
    const QString from =
        tr("design %1 of generation %2").arg(cell + 1).arg(mModel->generationLabel(generation));
    if (design->dimension != mModel->populationDimension()) {
        // A solid among flat designs (or the reverse) could breed with none of them: as an
        // opened design of the other kind, it starts a generation of its own.
        startGenerationOfKind({*design}, tr("Brought back %1").arg(from));
        return;
    }
    const std::vector<int> used = mModel->placeDesigns({*design}, tr("Brought back %1").arg(from));
    if (!used.empty())
        statusBar()->showMessage(tr("Brought back %1 into design %2").arg(from).arg(used.front() + 1), 5000);
}

void WorkbenchWindow::resumeSession(SavedSession session) {
    const int dimension = session.dimension;
    mModel->restoreSession(std::move(session));
    mPopulation->setDimension(dimension);
    setMesh(mModel->mesh());
    setFlatMesh(mModel->flatMesh());
    statusBar()->showMessage(
        tr("Resumed the last session at generation %1").arg(mModel->generationLabel(mModel->currentIndex())),
        5000);
}

QString WorkbenchWindow::mesh() const {
    return mPopulation->mesh();
}

QString designCaption(const Genome& genome) {
    const LineageInfo info = lineageOf(genome);
    QString caption = info.displayName();
    // The operator is said beside the name breeding gave ("… (g3 #5) · Recombine"); a name the
    // user gave (renamed, saved under a name of their own) stands alone.
    static const QRegularExpression bredName(QStringLiteral(R"(\(g\d+ #\d+\)$)"));
    if (!info.op.isEmpty() && (info.name.isEmpty() || bredName.match(info.name).hasMatch()))
        caption += QStringLiteral(" · ") + info.madeBy();
    return caption;
}

void WorkbenchWindow::setMesh(const QString& mesh) {
    mPopulation->setMesh(mesh);
}

QString WorkbenchWindow::flatMesh() const {
    return mPopulation->flatMesh();
}

void WorkbenchWindow::setFlatMesh(const QString& mesh) {
    mPopulation->setFlatMesh(mesh);
}

QComboBox* WorkbenchWindow::objectBox() const {
    return mPopulation->objectBox();
}

} // namespace marbler::ui
