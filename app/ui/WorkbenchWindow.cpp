#include "ui/WorkbenchWindow.h"
#include "marbler/Mesh.h"

#include "editor/EditorWindow.h"
#include "marbler/Error.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/ImageFormats.h"
#include "marbler/Paper.h"
#include "ui/DesignCell.h"
#include "ui/DesignDialog.h"
#include "ui/ErrorReport.h"
#include "ui/GenomeClipboard.h"
#include "ui/Help.h"
#include "ui/OpenPlacement.h"
#include "ui/RenderService.h"
#include "ui/SavedFiles.h"
#include "ui/StartDialog.h"
#include "ui/Trash.h"

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
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QPushButton>
#include <QRandomGenerator>
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

/// Render keys: the grid uses 0..8, favourite thumbnails start here, lineage thumbnails at
/// LineageKeyBase (the queue renders lower keys first, so the grid comes before thumbnails).
constexpr std::uint64_t FavouriteKeyBase = 100;
constexpr int ThumbnailSide = 96;

/// The favourites list hands a dragged favourite over as genome JSON, which a cell accepts.
class FavouritesList : public QListWidget {
public:
    using QListWidget::QListWidget;
    std::vector<Favourite> const* favourites = nullptr;

protected:
    QStringList mimeTypes() const override { return {QString::fromLatin1(GenomeMimeType)}; }
    QMimeData* mimeData(const QList<QListWidgetItem*>& items) const override {
        if (items.isEmpty() || !favourites) return nullptr;
        const int row = this->row(items.front());
        if (row < 0 || row >= int(favourites->size())) return nullptr;
        auto* mime = new QMimeData; // ownership passes to the drag
        mime->setData(QString::fromLatin1(GenomeMimeType),
                      QByteArray::fromStdString(serializeGenome((*favourites)[std::size_t(row)].genome)));
        return mime;
    }
};

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
    buildHelpMenu();
    setAcceptDrops(true);

    // The status bar: passing messages over the generation's summary on the left; on the right
    // the last file saved and what the window is doing. Which renderer draws is in Help ▸ About.
    mGenerationLabel = new QLabel(this);
    mGenerationLabel->setObjectName(QStringLiteral("generationLabel"));
    statusBar()->addWidget(mGenerationLabel, 1);
    mSavedNotice = new SavedFileNotice(this);
    statusBar()->addPermanentWidget(mSavedNotice);
    mTaskLabel = new QLabel(this);
    mTaskLabel->setObjectName(QStringLiteral("taskLabel"));
    mTaskLabel->setToolTip(
        tr("What the window is doing. Help ▸ About Marbler says which renderer draws the designs."));
    statusBar()->addPermanentWidget(mTaskLabel);
    // Beside the message that a favourite was removed, while it shows.
    mUndoRemove = new QPushButton(tr("Undo"), this);
    mUndoRemove->setObjectName(QStringLiteral("undoRemoveFavourite"));
    mUndoRemove->setToolTip(
        tr("Put the removed favourite back (%1)")
            .arg(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R).toString(QKeySequence::NativeText)));
    // The first of the permanent widgets (index 0 is the generation summary), left of the rest.
    statusBar()->insertPermanentWidget(1, mUndoRemove);
    mUndoRemove->hide();
    connect(mUndoRemove, &QPushButton::clicked, this, [this] { restoreRemovedFavourite(); });
    connect(statusBar(), &QStatusBar::messageChanged, this, [this](const QString& message) {
        if (message != mUndoRemove->property("message").toString()) mUndoRemove->hide();
    });
    connect(mRenderer, &RenderService::backendReady, this, [this] {
        if (mAnnounceBackend) {
            mAnnounceBackend = false;
            statusBar()->showMessage(rendererDescription(), 8000);
        }
        // Images from the other back end differ in the last bits: render everything anew.
        mImageCache.clear();
        requestAllRenders();
    });
    connect(mRenderer, &RenderService::rendered, this, &WorkbenchWindow::onRendered);
    connect(mRenderer, &RenderService::failed, this, &WorkbenchWindow::onRenderFailed);

    connect(this, &WorkbenchWindow::renderingFinished, this, &WorkbenchWindow::onRenderingFinished);
    connect(mModel, &PopulationModel::populationChanged, this, [this] {
        // Going to another generation drops a click still waiting: it was meant for this one.
        if (!mBreedingNow) mPendingOperator.reset();
        updateCells();
        requestAllRenders();
        updateLineage();
    });
    connect(mModel, &PopulationModel::cellChanged, this, [this](int index) {
        updateCells(); // the lock marker
        updateLineage();
        requestRender(index); // a new view angle (a lock change finds its image in the cache)
    });
    connect(mModel, &PopulationModel::selectionChanged, this, [this] {
        updateCells();
        updateActions();
    });
    connect(mModel, &PopulationModel::historyChanged, this, &WorkbenchWindow::updateActions);
    connect(mModel, &PopulationModel::favouritesChanged, this, &WorkbenchWindow::updateFavourites);
    connect(mModel, &PopulationModel::sessionSaveFailed, this, [this](const QString& message) {
        // Once as a message, after that on the status bar: every change would fail the same way.
        if (!mSaveFailureShown) {
            mSaveFailureShown = true;
            reportError(this, tr("Cannot save the session"),
                        tr("The breeding session could not be saved, so it would not survive a crash; "
                           "keep the designs you like as favourites.\n\n%1")
                            .arg(message));
        } else {
            statusBar()->showMessage(tr("The session could not be saved: %1").arg(message), 10000);
        }
    });

    readSettings();
    mModel->setMesh(mMesh->currentText());
    const QStringList favouriteErrors =
        mModel->setFavouritesFolder(PopulationModel::defaultFavouritesFolder());
    if (!favouriteErrors.isEmpty())
        statusBar()->showMessage(
            tr("Some favourites could not be read: %1").arg(favouriteErrors.join(QStringLiteral("; "))),
            10000);
    updateCells();
    updateActions();
    updateLineage();
}

WorkbenchWindow::~WorkbenchWindow() {
    // Results for this window's keys may still arrive after it is gone; the service simply
    // has no receiver then, but the work itself is wasted, so drop it.
    for (int i = 0; i < CellCount; ++i)
        mRenderer->cancel(std::uint64_t(i));
    for (std::size_t i = 0; i < mModel->favourites().size(); ++i)
        mRenderer->cancel(FavouriteKeyBase + i);
    for (auto it = mLineageRequests.cbegin(); it != mLineageRequests.cend(); ++it)
        mRenderer->cancel(it.key());
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
                        openEditor(randomGenome(QRandomGenerator::global()->generate64(),
                                                mDimension->currentData().toInt()));
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
    QAction* newRandom = fileMenu->addAction(tr("&New random population"), this, [this] {
        newRandomPopulation(mDimension->currentData().toInt());
    });
    newRandom->setShortcut(QKeySequence::New);
    newRandom->setIconText(tr("New random"));
    newRandom->setToolTip(tr("Nine new random designs of the kind chosen beside (Ctrl+N)"));
    QAction* picture =
        fileMenu->addAction(tr("&Marble a picture…"), this, &WorkbenchWindow::marblePictureDialog);
    picture->setObjectName(QStringLiteral("marblePictureAction"));
    picture->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M));
    picture->setStatusTip(
        tr("Nine flat designs whose bath is a picture you pick: flows and strokes carry its colours"));
    QAction* newPaperAction = fileMenu->addAction(
        tr("New marbled &paper"), this, [this] { newPaper(QRandomGenerator::global()->generate64()); });
    newPaperAction->setObjectName(QStringLiteral("newPaperAction"));
    newPaperAction->setStatusTip(
        tr("A procedural marbled paper (as marbler paper makes) into the grid, to breed from"));
    fileMenu->addSeparator();
    mSessionsAction = fileMenu->addAction(tr("&Sessions…"), this, [this] { openSessionsDialog(); });
    mSessionsAction->setStatusTip(tr("Every breeding session is kept: resume, rename or delete one"));
    mRecentSessions = fileMenu->addMenu(tr("&Resume session"));
    mRecentSessions->setObjectName(QStringLiteral("recentSessionsMenu"));
    connect(mRecentSessions, &QMenu::aboutToShow, this, &WorkbenchWindow::fillRecentSessions);
    // Until startSession names the session folder there is no store to show.
    mSessionsAction->setEnabled(false);
    mRecentSessions->setEnabled(false);
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
    editMenu->addSeparator();
    QAction* clearSelection =
        editMenu->addAction(tr("Clear &selection"), mModel, &PopulationModel::clearSelection);
    clearSelection->setObjectName(QStringLiteral("clearSelectionAction"));
    clearSelection->setShortcut(QKeySequence(Qt::Key_Escape));
    editMenu->addSeparator();
    mRestoreFavourite =
        editMenu->addAction(tr("&Restore removed favourite"), this, [this] { restoreRemovedFavourite(); });
    // Ctrl+Z steps back a generation, so undoing a removal has a key of its own.
    mRestoreFavourite->setObjectName(QStringLiteral("restoreFavouriteAction"));
    mRestoreFavourite->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    mRestoreFavourite->setStatusTip(tr("Puts the favourite removed last back on the shelf"));
    mRestoreFavourite->setEnabled(false);

    const auto makeOperator = [&](GeneticOperator op, const QString& text, const QString& tip,
                                  QKeySequence key) {
        QAction* action = breedMenu->addAction(text, this, [this, op] { requestOperator(op); });
        action->setShortcut(key);
        action->setToolTip(QStringLiteral("%1 (%2)").arg(tip, key.toString(QKeySequence::NativeText)));
        // The tooltip when the operator can run; updateActions() says why when it cannot.
        action->setProperty("readyTip", action->toolTip());
        action->setStatusTip(tip);
        return action;
    };
    mAlter = makeOperator(GeneticOperator::Alter, tr("Alter (1 parent)"),
                          tr("Offspring with the parent's strokes perturbed; the slider sets how much"),
                          QKeySequence(Qt::CTRL | Qt::Key_1));
    mRecombine = makeOperator(GeneticOperator::Recombine, tr("Recombine (2+ parents)"),
                              tr("Offspring that take strokes from each of the parents"),
                              QKeySequence(Qt::CTRL | Qt::Key_2));
    mSwap = makeOperator(GeneticOperator::Swap, tr("Swap (2 parents)"),
                         tr("One parent's initial drops with the other's strokes, both ways"),
                         QKeySequence(Qt::CTRL | Qt::Key_3));
    mReinit = makeOperator(GeneticOperator::Reinit, tr("Change initial state (1 parent)"),
                           tr("Offspring with new initial drops under the same strokes"),
                           QKeySequence(Qt::CTRL | Qt::Key_4));

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
    for (QAction* a : {mAlter, mRecombine, mSwap, mReinit})
        bar->addAction(a);
    buildColourwayActions(breedMenu, bar);

    mStrength = new QSlider(Qt::Horizontal, bar);
    mStrength->setObjectName(QStringLiteral("strengthSlider"));
    mStrength->setRange(0, 100);
    mStrength->setMaximumWidth(120);
    mStrength->setToolTip(tr("How far %1 moves the strokes: 0 % barely, 100 % a lot")
                              .arg(operatorLabel(GeneticOperator::Alter)));
    // The value is always in sight, not only while the slider is dragged.
    mStrengthLabel = new QLabel(bar);
    mStrengthLabel->setObjectName(QStringLiteral("strengthLabel"));
    mStrengthLabel->setToolTip(mStrength->toolTip());
    // Wide enough for "Strength 100 %", so the toolbar does not shift as the value changes.
    mStrengthLabel->setMinimumWidth(
        mStrengthLabel->fontMetrics().horizontalAdvance(tr(" Strength %1 % ").arg(100)));
    mStrengthLabel->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    mStrengthLabel->setBuddy(mStrength);
    connect(mStrength, &QSlider::valueChanged, this,
            [this](int value) { mStrengthLabel->setText(tr(" Strength %1 % ").arg(value)); });
    mStrength->setValue(50);
    mStrengthLabel->setText(tr(" Strength %1 % ").arg(mStrength->value()));
    bar->addWidget(mStrengthLabel);
    bar->addWidget(mStrength);

    // New populations on a row of their own: on one row the family box, New random and the
    // object box hid behind the bar's ›› at the default width, and on a 1,366-pixel screen.
    addToolBarBreak();
    bar = addToolBar(tr("New population"));
    bar->setObjectName(QStringLiteral("populationToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    auto* kindLabel = new QLabel(tr(" New population: "), bar);
    bar->addWidget(kindLabel);

    mDimension = new QComboBox(bar);
    mDimension->addItem(tr("2D designs"), 2);
    mDimension->addItem(tr("Solid designs"), 3);
    mDimension->setToolTip(
        tr("What a new random population holds: flat marbling or solid (volume) marbling"));
    bar->addWidget(mDimension);
    kindLabel->setBuddy(mDimension);
    kindLabel->setToolTip(tr("What File ▸ New random population (%1) makes")
                              .arg(newRandom->shortcut().toString(QKeySequence::NativeText)));
    mFamily = new QComboBox(bar);
    mFamily->setObjectName(QStringLiteral("familyCombo"));
    mFamily->setToolTip(
        tr("The pattern family of a new random population, or a mix of the craft's families"));
    bar->addWidget(mFamily);
    fillFamilies();
    connect(mDimension, &QComboBox::currentIndexChanged, this, &WorkbenchWindow::fillFamilies);
    bar->addAction(newRandom);
    bar->addSeparator();

    auto* meshLabel = new QLabel(tr(" Solids on: "), bar);
    bar->addWidget(meshLabel);
    mMesh = new QComboBox(bar);
    mMesh->addItems(meshNames());
    mMesh->setToolTip(tr("The object solid designs are shown on (drag in a cell to turn it)"));
    meshLabel->setBuddy(mMesh);
    meshLabel->setToolTip(mMesh->toolTip());
    connect(mMesh, &QComboBox::currentTextChanged, this, [this](const QString& mesh) {
        QSettings().setValue(QStringLiteral("view/mesh"), mesh);
        mModel->setMesh(mesh);
        requestAllRenders();
        updateLineage(); // solid designs' thumbnails show the object
    });
    bar->addWidget(mMesh);
}

void WorkbenchWindow::buildDocks() {
    QMenu* viewMenu = menuBar()->findChild<QMenu*>(QStringLiteral("viewMenu"));

    auto* favDock = new QDockWidget(tr("Favourites"), this);
    favDock->setObjectName(QStringLiteral("favouritesDock"));
    auto* list = new FavouritesList(favDock);
    list->favourites = &mModel->favourites();
    mFavouritesList = list;
    list->setViewMode(QListView::IconMode);
    list->setIconSize(QSize(ThumbnailSide, ThumbnailSide));
    list->setResizeMode(QListView::Adjust);
    list->setMovement(QListView::Static);
    // A fixed grid: thumbnails arrive after the items, and the names vary in length, so items
    // laid out by their own size would overlap.
    list->setGridSize(QSize(ThumbnailSide + 56, ThumbnailSide + 30));
    list->setUniformItemSizes(true);
    list->setWordWrap(false);
    list->setTextElideMode(Qt::ElideRight);
    list->setDragEnabled(true);
    list->setDragDropMode(QAbstractItemView::DragOnly);
    list->setContextMenuPolicy(Qt::CustomContextMenu);
    list->setToolTip(
        tr("Designs kept aside (F on a cell). Double-click or drag one onto a cell to bring it back."));
    connect(list, &QListWidget::itemDoubleClicked, this,
            [this](QListWidgetItem* item) { restoreFavourite(mFavouritesList->row(item)); });
    connect(list, &QWidget::customContextMenuRequested, this, &WorkbenchWindow::showFavouriteMenu);
    // Docks never shrink past the point where a thumbnail or the lineage columns stay usable,
    // so a small window cannot squash them (nor save a squashed layout).
    list->setMinimumSize(ThumbnailSide + 80, ThumbnailSide + 50);
    favDock->setWidget(list);
    addDockWidget(Qt::RightDockWidgetArea, favDock);

    auto* lineageDock = new QDockWidget(tr("Lineage"), this);
    lineageDock->setObjectName(QStringLiteral("lineageDock"));
    mLineageTree = new QTreeWidget(lineageDock);
    mLineageTree->setColumnCount(4);
    mLineageTree->setHeaderLabels({tr("Design"), tr("Made by"), tr("Parents"), tr("Generation")});
    mLineageTree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    mLineageTree->setIconSize(QSize(LineageIconSide, LineageIconSide));
    // A double-click goes to a generation; it must not also fold it.
    mLineageTree->setExpandsOnDoubleClick(false);
    mLineageTree->setToolTip(
        tr("Every generation, branches included, and how the designs came to be. Click a "
           "design to select it; double-click a generation to go back to it, or a design of "
           "another generation to bring it back into the grid."));
    mLineageClickTimer.setSingleShot(true);
    mLineageClickTimer.setInterval(QApplication::doubleClickInterval());
    connect(&mLineageClickTimer, &QTimer::timeout, this,
            [this] { selectLineageDesign(mLineageClickGeneration, mLineageClickCell); });
    connect(mLineageTree, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) {
        const QVariant cell = item->data(0, LineageCellRole);
        if (!cell.isValid()) return;
        mLineageClickGeneration = item->data(0, LineageGenerationRole).toInt();
        mLineageClickCell = cell.toInt();
        mLineageClickTimer.start();
    });
    connect(mLineageTree, &QTreeWidget::itemDoubleClicked, this, &WorkbenchWindow::onLineageDoubleClicked);
    connect(mLineageTree, &QTreeWidget::itemExpanded, this, [this](QTreeWidgetItem* item) {
        const QVariant generation = item->data(0, LineageGenerationRole);
        if (generation.isValid() && !item->data(0, LineageCellRole).isValid()) {
            mExpandedGenerations.insert(generation.toInt());
            populateLineageGeneration(item);
        }
        const QVariant branch = item->data(0, LineageBranchRole);
        if (branch.isValid()) mCollapsedBranches.remove(branch.toInt());
        if (item == mLineageTree->topLevelItem(0)) mCurrentDesignsFolded = false;
        mLineageThumbnailTimer.start();
    });
    connect(mLineageTree, &QTreeWidget::itemCollapsed, this, [this](QTreeWidgetItem* item) {
        const QVariant generation = item->data(0, LineageGenerationRole);
        if (generation.isValid()) mExpandedGenerations.remove(generation.toInt());
        const QVariant branch = item->data(0, LineageBranchRole);
        if (branch.isValid()) mCollapsedBranches.insert(branch.toInt());
        if (item == mLineageTree->topLevelItem(0)) mCurrentDesignsFolded = true;
    });
    // Thumbnails are rendered for what comes into view: after scrolling, resizing, showing.
    mLineageThumbnailTimer.setSingleShot(true);
    mLineageThumbnailTimer.setInterval(30);
    connect(&mLineageThumbnailTimer, &QTimer::timeout, this, &WorkbenchWindow::requestLineageThumbnails);
    // The timer is the receiver: the dock hides as the window is destroyed, after the timer.
    const auto scheduleThumbnails = [this] { mLineageThumbnailTimer.start(); };
    connect(mLineageTree->verticalScrollBar(), &QScrollBar::valueChanged, &mLineageThumbnailTimer,
            scheduleThumbnails);
    connect(mLineageTree->verticalScrollBar(), &QScrollBar::rangeChanged, &mLineageThumbnailTimer,
            scheduleThumbnails);
    connect(lineageDock, &QDockWidget::visibilityChanged, &mLineageThumbnailTimer, scheduleThumbnails);
    mLineageTree->setMinimumSize(260, 140);
    lineageDock->setWidget(mLineageTree);
    addDockWidget(Qt::RightDockWidgetArea, lineageDock);

    viewMenu->addAction(favDock->toggleViewAction());
    viewMenu->addAction(lineageDock->toggleViewAction());
    favDock->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    lineageDock->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L));

    viewMenu->addSeparator();
    QMenu* rendererMenu = viewMenu->addMenu(tr("&Renderer"));
    rendererMenu->setObjectName(QStringLiteral("rendererMenu"));
    rendererMenu->setToolTipsVisible(true);
    auto* group = new QActionGroup(rendererMenu);
    const auto addChoice = [&](gl::BackendPreference preference, const QString& text, const QString& tip) {
        QAction* action = rendererMenu->addAction(text);
        action->setCheckable(true);
        action->setChecked(mRenderer->preference() == preference);
        action->setToolTip(tip);
        action->setStatusTip(tip);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, preference] { setRendererPreference(preference); });
        mRendererActions[std::size_t(preference)] = action;
    };
    addChoice(
        gl::BackendPreference::Auto, tr("Renderer: &Automatic"),
        tr("OpenGL on a graphics card; the CPU where OpenGL is a software rasteriser (such as llvmpipe) or "
           "missing, since the CPU renderer is faster there"));
    addChoice(
        gl::BackendPreference::Gpu, tr("Renderer: &GPU"),
        tr("Always render with OpenGL shaders, even on a software rasteriser (the CPU where there is no "
           "OpenGL at all)"));
    addChoice(gl::BackendPreference::Cpu, tr("Renderer: &CPU"),
              tr("Always render with the CPU renderer on every core; solid objects are still rasterised by "
                 "OpenGL where it exists, and coloured by the CPU"));
    std::string problem;
    if (!gl::environmentBackendPreference(&problem) && !problem.empty())
        statusBar()->showMessage(QString::fromStdString(problem), 10000);
    if (const auto forced = RenderService::environmentPreference()) {
        // The environment wins over the setting, so the menu only shows what it forces.
        const QString why = tr("%1=%2 is set, which overrides this setting")
                                .arg(QString::fromLatin1(gl::BackendEnvironmentVariable),
                                     QString::fromLatin1(gl::backendPreferenceName(*forced).data()));
        for (QAction* action : group->actions()) {
            action->setEnabled(false);
            action->setToolTip(why);
        }
        mRendererActions[std::size_t(*forced)]->setChecked(true);
    }
}

void WorkbenchWindow::setRendererPreference(gl::BackendPreference preference) {
    QSettings().setValue(QStringLiteral("view/renderer"),
                         QString::fromLatin1(gl::backendPreferenceName(preference).data()));
    mRendererActions[std::size_t(preference)]->setChecked(true);
    if (preference != mRenderer->preference()) {
        mAnnounceBackend = true;
        mRenderer->setPreference(preference);
    }
}

QAction* WorkbenchWindow::rendererAction(gl::BackendPreference preference) const {
    return mRendererActions[std::size_t(preference)];
}

QString WorkbenchWindow::rendererDescription() const {
    if (mRenderer->backendName().isEmpty()) return {};
    const QString where = mRenderer->usesGl() ? tr("Rendering with %1").arg(mRenderer->backendName())
                                              : tr("Rendering on the %1").arg(mRenderer->backendName());
    const QString why = mRenderer->backendReason();
    return why.isEmpty() ? where : tr("%1: %2").arg(where, why);
}

void WorkbenchWindow::buildHelpMenu() {
    QMenu* helpMenu = menuBar()->addMenu(tr("&Help"));
    helpMenu->setObjectName(QStringLiteral("helpMenu"));
    mGuideAction = helpMenu->addAction(tr("Marbler &guide"), this, &WorkbenchWindow::showGuide);
    mGuideAction->setShortcut(QKeySequence::HelpContents);
    mGuideAction->setStatusTip(tr("What the operators do, how to breed, and every keyboard shortcut"));
    helpMenu->addSeparator();
    mAboutAction = helpMenu->addAction(tr("&About Marbler"), this, &WorkbenchWindow::showAbout);
    mAboutAction->setStatusTip(tr("Marbler's version, the libraries it runs with and the renderer in use"));
    mAboutQtAction = helpMenu->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
    mAboutQtAction->setStatusTip(tr("The Qt toolkit Marbler is built with"));
}

namespace {

/// A text window with a Close button: the guide and the About box.
QDialog* makeTextDialog(QWidget* parent, const QString& name, const QString& title, QWidget* body,
                        QSize size) {
    auto* dialog = new QDialog(parent);
    dialog->setObjectName(name);
    dialog->setWindowTitle(title);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    body->setParent(dialog);
    layout->addWidget(body, 1);
    layout->addWidget(buttons);
    dialog->resize(size);
    return dialog;
}

} // namespace

QDialog* WorkbenchWindow::showGuide() {
    if (!mGuide) {
        auto* browser = new QTextBrowser;
        browser->setObjectName(QStringLiteral("guideBrowser"));
        browser->setOpenLinks(false);
        mGuide = makeTextDialog(this, QStringLiteral("guideDialog"), tr("Marbler guide"), browser,
                                QSize(640, 720));
    }
    // Built each time it is shown, from the actions as they are now.
    mGuide->findChild<QTextBrowser*>(QStringLiteral("guideBrowser"))->setHtml(guideHtml(*this));
    mGuide->show();
    mGuide->raise();
    mGuide->activateWindow();
    return mGuide;
}

QString WorkbenchWindow::aboutText() const {
    AboutFacts facts;
    facts.version = marblerVersion();
    facts.qt = QString::fromLatin1(qVersion());
    if (facts.qt != QStringLiteral(QT_VERSION_STR))
        facts.qt = tr("%1 (built with %2)").arg(facts.qt, QStringLiteral(QT_VERSION_STR));
    if (const auto imageIo = loadedOpenImageIoVersion()) facts.imageIo = QString::fromStdString(*imageIo);
    facts.renderer = rendererDescription();
    return aboutHtml(facts);
}

QDialog* WorkbenchWindow::showAbout() {
    if (!mAbout) {
        auto* text = new QLabel;
        text->setObjectName(QStringLiteral("aboutText"));
        text->setWordWrap(true);
        text->setTextInteractionFlags(Qt::TextSelectableByMouse);
        text->setAlignment(Qt::AlignTop | Qt::AlignLeft);
        mAbout =
            makeTextDialog(this, QStringLiteral("aboutDialog"), tr("About Marbler"), text, QSize(520, 340));
        // The renderer may still be choosing, or change while the box is open.
        connect(mRenderer, &RenderService::backendReady, text, [this, text] { text->setText(aboutText()); });
    }
    // Filled each time it is shown: OpenImageIO may have loaded since.
    mAbout->findChild<QLabel*>(QStringLiteral("aboutText"))->setText(aboutText());
    mAbout->show();
    mAbout->raise();
    mAbout->activateWindow();
    return mAbout;
}

void WorkbenchWindow::noteSavedFile(const QString& file) {
    // The notice holds the full path, long enough to reach "Show in folder"; a passing message
    // would only say it twice.
    mSavedNotice->showFile(file);
}

void WorkbenchWindow::updateTask() {
    int pending = 0;
    for (int i = 0; i < CellCount; ++i)
        if (!mFinal[std::size_t(i)] && mModel->cell(i)) ++pending;
    if (pending == 0) {
        mRenderBatch = 0;
        mTaskLabel->setText(tr("Ready"));
        return;
    }
    // A batch counts every cell asked for since the window was last idle.
    mRenderBatch = std::max(mRenderBatch, pending);
    mTaskLabel->setText(tr("Rendering %1 of %2…").arg(mRenderBatch - pending + 1).arg(mRenderBatch));
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
    mDimension->setCurrentIndex(dimension == 3 ? 1 : 0);
    setPopulationFamily(settings.value(QStringLiteral("population/family")).toString());
    mStrength->setValue(settings.value(QStringLiteral("breed/strength"), 50).toInt());
    const QString mesh =
        settings.value(QStringLiteral("view/mesh"), QString::fromLatin1(DefaultMesh)).toString();
    if (mMesh->findText(mesh) >= 0) mMesh->setCurrentText(mesh);
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
    settings.setValue(QStringLiteral("breed/strength"), mStrength->value());
    QMainWindow::closeEvent(event);
}

QAction* WorkbenchWindow::operatorAction(GeneticOperator op) const {
    switch (op) {
    case GeneticOperator::Alter:
        return mAlter;
    case GeneticOperator::Recombine:
        return mRecombine;
    case GeneticOperator::Swap:
        return mSwap;
    case GeneticOperator::Reinit:
        return mReinit;
    }
    return nullptr;
}

double WorkbenchWindow::strength() const {
    return mStrength->value() / 100.0;
}
void WorkbenchWindow::setStrength(double strength) {
    mStrength->setValue(int(std::lround(strength * 100.0)));
}

void WorkbenchWindow::updateCells() {
    for (int i = 0; i < CellCount; ++i) {
        DesignCell* c = mCells[std::size_t(i)];
        const Genome* g = mModel->cell(i);
        c->setHasDesign(g != nullptr);
        c->setSelectedParent(mModel->isSelected(i));
        c->setOrbitEnabled(g && g->dimension == 3);
        if (!g) {
            c->setCaption({});
            c->setChange({});
            continue;
        }
        c->setCaption(designCaption(*g));
        c->setChange(lineageOf(*g).change);
        const Locks locks = locksOf(*g);
        c->setLocked(locks.palette || locks.initial || locks.operations);
    }
}

void WorkbenchWindow::updateActions() {
    const int n = mModel->selectedCount();
    for (GeneticOperator op : {GeneticOperator::Alter, GeneticOperator::Recombine, GeneticOperator::Swap,
                               GeneticOperator::Reinit}) {
        // A greyed-out operator says what it needs, so it is never disabled without a reason.
        QAction* action = operatorAction(op);
        const QString why = mModel->whyNot(op);
        action->setEnabled(why.isEmpty());
        action->setToolTip(why.isEmpty() ? action->property("readyTip").toString() : why);
    }
    updateColourwayActions();
    mBack->setEnabled(mModel->canGoBack());
    mForward->setEnabled(mModel->canGoForward());
    const auto& gen = mModel->current();
    if (mModel->isEmptyWorkbench()) {
        mGenerationLabel->setText(
            tr("No designs yet: make a new random population (Ctrl+N) or open designs (Ctrl+O)"));
        return;
    }
    mGenerationLabel->setText(tr("Generation %1: %2 — %3 selected")
                                  .arg(mModel->generationLabel(mModel->currentIndex()))
                                  .arg(gen.description)
                                  .arg(n == 1 ? tr("1 parent") : tr("%1 parents").arg(n)));
}

void WorkbenchWindow::updateFavourites() {
    mRestoreFavourite->setEnabled(!mModel->removedFavourites().isEmpty());
    if (mModel->removedFavourites().isEmpty()) mUndoRemove->hide();
    mFavouritesList->clear();
    const auto& favourites = mModel->favourites();
    // Until its thumbnail is rendered, a favourite shows a blank of the thumbnail's size.
    QPixmap placeholder(ThumbnailSide, ThumbnailSide);
    placeholder.fill(palette().color(QPalette::Mid));
    for (std::size_t i = 0; i < favourites.size(); ++i) {
        const LineageInfo info = lineageOf(favourites[i].genome);
        auto* item = new QListWidgetItem(info.displayName(), mFavouritesList);
        item->setToolTip(QStringLiteral("%1\n%2").arg(item->text(), favourites[i].file));
        item->setIcon(placeholder);
        RenderRequest request;
        request.genome = favourites[i].genome;
        request.size = QSize(ThumbnailSide, ThumbnailSide);
        request.mesh = mMesh->currentText();
        const ViewAngle angle = viewAngleOf(favourites[i].genome);
        request.yaw = angle.yaw;
        request.pitch = angle.pitch;
        mRenderer->request(FavouriteKeyBase + i, std::move(request));
    }
}

QString WorkbenchWindow::renderCacheKey(int index) const {
    const Genome* g = mModel->cell(index);
    if (!g) return {};
    const QSize size = mCells[std::size_t(index)]->size() * mCells[std::size_t(index)]->devicePixelRatioF();
    // Locks live in meta, and genomeId ignores meta, so a lock change keeps the image.
    return QStringLiteral("%1/%2x%3/%4/%5/%6")
        .arg(QString::fromStdString(genomeId(*g)))
        .arg(size.width())
        .arg(size.height())
        .arg(g->dimension == 3 ? mMesh->currentText() : QString())
        .arg(g->dimension == 3 ? cellViewAngle(index).yaw : 0.0)
        .arg(g->dimension == 3 ? cellViewAngle(index).pitch : 0.0);
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
        mRenderer->cancel(std::uint64_t(index));
        mFinal[std::size_t(index)] = true;
        return;
    }
    const QString key = renderCacheKey(index);
    if (!previewOnly) {
        if (const QImage* cached = mImageCache.object(key)) {
            mRenderer->cancel(std::uint64_t(index));
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
    request.mesh = mMesh->currentText();
    const ViewAngle angle = cellViewAngle(index);
    request.yaw = angle.yaw;
    request.pitch = angle.pitch;
    request.previewOnly = previewOnly;
    mPendingCacheKey[std::size_t(index)] = previewOnly ? QString() : key;
    mFinal[std::size_t(index)] = false;
    mRenderer->request(std::uint64_t(index), std::move(request));
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
    if (key >= RenderService::ViewKeyBase) return; // a view's of its own (large view, editor)
    if (key < std::uint64_t(CellCount)) {
        const auto index = std::size_t(key);
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
    if (key >= LineageKeyBase) {
        if (final) onLineageThumbnail(key, image);
        return;
    }
    if (key >= FavouriteKeyBase) {
        const int row = int(key - FavouriteKeyBase);
        if (QListWidgetItem* item = mFavouritesList->item(row))
            item->setIcon(QIcon(QPixmap::fromImage(image)));
    }
}

void WorkbenchWindow::onRenderFailed(std::uint64_t key, const QString& message) {
    if (key < std::uint64_t(CellCount)) {
        mCells[std::size_t(key)]->setError(message);
        mFinal[std::size_t(key)] = true;
        statusBar()->showMessage(tr("Design %1 cannot be rendered: %2").arg(key + 1).arg(message), 10000);
        updateTask();
        if (renderingDone()) emit renderingFinished();
    } else if (key >= LineageKeyBase) {
        onLineageThumbnail(key, QImage());
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
    if (colourwaysMode()) return applyColourwayOperator(op);
    if (const QString why = mModel->whyNot(op); !why.isEmpty()) {
        statusBar()->showMessage(why, 5000);
        return false;
    }
    try {
        mModel->apply(op, strength());
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
    if (mBredRendering) {
        // Breeding is quick, its nine renders are not: clicks made meanwhile would queue
        // generations that keep arriving for seconds. The last click waits for the renders.
        mPendingOperator = op;
        statusBar()->showMessage(tr("%1 follows when this generation has rendered").arg(operatorLabel(op)),
                                 5000);
        return;
    }
    mBreedingNow = true;
    const bool bred = applyOperator(op);
    mBreedingNow = false;
    mBredRendering = bred && !renderingDone();
}

void WorkbenchWindow::onRenderingFinished() {
    mBredRendering = false;
    if (!mPendingOperator) return;
    const GeneticOperator op = *mPendingOperator;
    mPendingOperator.reset();
    // Not inside the render result's handler, which is still updating the cells.
    QTimer::singleShot(0, this, [this, op] { requestOperator(op); });
}

void WorkbenchWindow::fillFamilies() {
    const int dimension = mDimension->currentData().toInt();
    const QString chosen = mFamily->currentData().toString();
    const QSignalBlocker quiet(mFamily);
    mFamily->clear();
    mFamily->addItem(tr("Mixed families"), QString());
    mFamily->setItemData(0, tr("Every cell a different family of the craft (and some free designs)"),
                         Qt::ToolTipRole);
    for (const Family& f : allFamilies()) {
        if (f.dimension != dimension) continue;
        QString label = QString::fromUtf8(f.name.data(), qsizetype(f.name.size()));
        label.replace(QLatin1Char('-'), QLatin1Char(' '));
        label[0] = label[0].toUpper();
        mFamily->addItem(label, QString::fromUtf8(f.name.data(), qsizetype(f.name.size())));
        mFamily->setItemData(mFamily->count() - 1,
                             QString::fromUtf8(f.summary.data(), qsizetype(f.summary.size())),
                             Qt::ToolTipRole);
    }
    mFamily->setCurrentIndex(std::max(0, mFamily->findData(chosen)));
}

void WorkbenchWindow::setPopulationFamily(const QString& family) {
    mFamily->setCurrentIndex(std::max(0, mFamily->findData(family)));
}

QString WorkbenchWindow::populationFamily() const {
    return mFamily->currentData().toString();
}

void WorkbenchWindow::newRandomPopulation(int dimension) {
    QSettings().setValue(QStringLiteral("population/dimension"), dimension);
    mDimension->setCurrentIndex(dimension == 3 ? 1 : 0);
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
    for (const QString& file : files) {
        try {
            std::vector<std::string> warnings;
            // A genome file or an image that carries one: the command line's loader.
            designs.push_back(loadDesign(file.toStdString(), &warnings));
            names << QFileInfo(file).fileName();
            if (!warnings.empty()) statusBar()->showMessage(QString::fromStdString(warnings.front()), 8000);
        } catch (const Error& e) {
            errors << QString::fromStdString(e.what());
        }
    }
    // Several files dropped on one cell have no single target: they go where opened files go.
    placeOpened(designs, names, designs.size() == 1 ? cell : -1);
    if (!errors.isEmpty()) {
        reportError(this, tr("Cannot open a design"),
                    tr("These files could not be loaded; the population is unchanged by them.\n\n%1")
                        .arg(errors.join(QStringLiteral("\n"))));
        return false;
    }
    return true;
}

std::vector<int> WorkbenchWindow::placeOpened(const std::vector<Genome>& opened, const QStringList& names,
                                              int cell, const QString& describe) {
    if (opened.empty()) return {};
    // One kind per generation: flat and solid designs cannot breed together, and the grid's
    // object, previews and operators all assume one kind. The first design decides.
    const int kind = opened.front().dimension;
    std::vector<Genome> designs;
    QStringList accepted, refused;
    for (std::size_t k = 0; k < opened.size(); ++k) {
        const QString name = int(k) < names.size() ? names[int(k)] : tr("design %1").arg(k + 1);
        if (opened[k].dimension == kind) {
            designs.push_back(opened[k]);
            accepted << name;
        } else {
            refused << name;
        }
    }
    if (!refused.isEmpty())
        reportError(
            this, tr("Some designs were not opened"),
            tr("A generation holds one kind of design, and %1 is %2, so these %3 designs were not opened; "
               "open them on their own:\n\n%4")
                .arg(names.value(0), kind == 3 ? tr("solid") : tr("flat"),
                     kind == 3 ? tr("flat") : tr("solid"), refused.join(QStringLiteral("\n"))));
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
    mDimension->setCurrentIndex(kind == 3 ? 1 : 0);
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
    const Genome paper = paperGenome(seed, PaperOptions{});
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
    const Genome* g = mModel->cell(index);
    if (!g) return false;
    try {
        mModel->addFavourite(*g);
    } catch (const Error& e) {
        reportError(this, tr("Cannot keep the favourite"), QString::fromStdString(e.what()));
        return false;
    }
    // Kept as a genome file: say where, as for any file the window writes.
    const QString id = QString::fromStdString(genomeId(*g));
    for (const Favourite& f : mModel->favourites())
        if (QFileInfo(f.file).fileName().startsWith(id)) mSavedNotice->showFile(f.file);
    statusBar()->showMessage(tr("Design %1 kept on the favourites shelf").arg(index + 1), 4000);
    return true;
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
    menu.addAction(tr("Open large…"), this, [this, index] { openDesign(index); });
    menu.addAction(tr("Open in editor"), this, [this, index] {
        if (const Genome* design = mModel->cell(index)) openEditor(*design);
    });
    menu.addAction(tr("Keep as favourite"), this, [this, index] { keepFavourite(index); })
        ->setShortcut(QKeySequence(Qt::Key_F));
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

void WorkbenchWindow::showFavouriteMenu(const QPoint& pos) {
    QMenu menu(this);
    if (QListWidgetItem* item = mFavouritesList->itemAt(pos)) {
        const int row = mFavouritesList->row(item);
        menu.addAction(tr("Put into the grid"), this, [this, row] { restoreFavourite(row); });
        menu.addAction(tr("Remove from favourites"), this, [this, row] { removeFavourite(row); });
        menu.addSeparator();
    }
    menu.addAction(mRestoreFavourite);
    menu.exec(mFavouritesList->viewport()->mapToGlobal(pos));
}

bool WorkbenchWindow::removeFavourite(int favourite) {
    const auto& favourites = mModel->favourites();
    if (favourite < 0 || favourite >= int(favourites.size())) return false;
    const LineageInfo info = lineageOf(favourites[std::size_t(favourite)].genome);
    const QString name = info.displayName();
    try {
        mModel->removeFavourite(favourite);
    } catch (const Error& e) {
        reportError(this, tr("Cannot remove the favourite"), QString::fromStdString(e.what()));
        return false;
    }
    const QString message = tr("Removed “%1” from favourites — Undo (%2)")
                                .arg(name, mRestoreFavourite->shortcut().toString(QKeySequence::NativeText));
    mUndoRemove->setProperty("message", message);
    statusBar()->showMessage(message, 15000);
    mUndoRemove->show();
    return true;
}

bool WorkbenchWindow::restoreRemovedFavourite() {
    if (mModel->removedFavourites().isEmpty()) return false;
    const QString trashed = mModel->removedFavourites().back();
    const QString back = QDir(mModel->favouritesFolder()).filePath(originalTrashName(trashed));
    if (!mModel->restoreRemovedFavourite(trashed)) {
        reportError(this, tr("Cannot restore the favourite"),
                    tr("The removed favourite could not be put back from %1 to %2.").arg(trashed, back));
        return false;
    }
    mUndoRemove->hide();
    QString name = QFileInfo(back).fileName();
    for (const Favourite& f : mModel->favourites())
        if (QFileInfo(f.file) == QFileInfo(back)) {
            const LineageInfo info = lineageOf(f.genome);
            name = info.displayName();
        }
    statusBar()->showMessage(tr("“%1” is back on the favourites shelf").arg(name), 5000);
    return true;
}

void WorkbenchWindow::saveDesign(int index) {
    const Genome* g = mModel->cell(index);
    if (!g) return;
    if (const QString file = saveGenomeWithDialog(this, *g); !file.isEmpty()) noteSavedFile(file);
}

DesignDialog* WorkbenchWindow::openDesign(int index) {
    const Genome* g = mModel->cell(index);
    if (!g) return nullptr;
    auto* dialog = new DesignDialog(*g, mRenderer, mMesh->currentText(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    // Turning the object in the large view turns the design, where the cell still holds it.
    const std::string id = genomeId(*g);
    connect(dialog, &DesignDialog::viewAngleChanged, this, [this, index, id](const ViewAngle& angle) {
        const Genome* shown = mModel->cell(index);
        if (shown && genomeId(*shown) == id) mModel->setCellView(index, angle);
    });
    connect(dialog, &DesignDialog::fileSaved, this, &WorkbenchWindow::noteSavedFile);
    connect(dialog, &DesignDialog::openInEditorRequested, this,
            [this](const Genome& design) { openEditor(design); });
    connect(dialog, &DesignDialog::genomeCopied, this, [this](const QString& name) {
        statusBar()->showMessage(tr("Copied %1 to the clipboard as genome text").arg(name), 5000);
    });
    dialog->show();
    emit designOpened(dialog);
    return dialog;
}

void WorkbenchWindow::resumeSession(SavedSession session) {
    const int dimension = session.dimension;
    mModel->restoreSession(std::move(session));
    mDimension->setCurrentIndex(dimension == 3 ? 1 : 0);
    setMesh(mModel->mesh());
    statusBar()->showMessage(
        tr("Resumed the last session at generation %1").arg(mModel->generationLabel(mModel->currentIndex())),
        5000);
}

QString WorkbenchWindow::mesh() const {
    return mMesh->currentText();
}

QString designCaption(const Genome& genome) {
    const LineageInfo info = lineageOf(genome);
    QString caption = info.displayName();
    if (!info.op.isEmpty()) caption += QStringLiteral(" · ") + info.madeBy();
    return caption;
}

void WorkbenchWindow::setMesh(const QString& mesh) {
    if (mMesh->findText(mesh) >= 0) mMesh->setCurrentText(mesh);
}

} // namespace marbler::ui
