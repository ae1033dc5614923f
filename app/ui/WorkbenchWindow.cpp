#include "ui/WorkbenchWindow.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "ui/DesignCell.h"
#include "ui/DesignDialog.h"
#include "ui/ErrorReport.h"
#include "ui/RenderService.h"
#include "ui/SessionStore.h"
#include "ui/SessionsDialog.h"
#include "ui/StartDialog.h"
#include "ui/Trash.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
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
#include <QSettings>
#include <QSlider>
#include <QStatusBar>
#include <QToolBar>
#include <QTreeWidget>

#include <algorithm>
#include <cmath>

namespace marbler::ui {

namespace {

/// Render keys: the grid uses 0..8, favourite thumbnails start here.
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

QString shortId(const QString& id) { return id.left(8); }

/// How a design was made, in the window's words ("Change initial state", never "reinit").
QString madeBy(const LineageInfo& info) {
    if (info.op.isEmpty()) return WorkbenchWindow::tr("(not bred)");
    const QString label = operatorLabel(info.op);
    return info.varied ? WorkbenchWindow::tr("%1, varied").arg(label) : label;
}


} // namespace

WorkbenchWindow::WorkbenchWindow(RenderService* renderer, QWidget* parent)
    : QMainWindow(parent), mRenderer(renderer), mModel(new PopulationModel(this)) {
    setWindowTitle(tr("Marbler — evolution workbench"));
    mModel->setSessionSeed(QRandomGenerator::global()->generate64());
    mYaw.fill(30.0);
    mPitch.fill(20.0);

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
        connect(cell, &DesignCell::filesDropped, this, [this](int index, const QStringList& files) {
            openFiles(files, index);
        });
        connect(cell, &DesignCell::genomeTextDropped, this, [this](int index, const QByteArray& json) {
            try {
                mModel->setCell(index, parseGenome(json.toStdString(), "dropped design"), tr("Brought back a favourite"));
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

    mBackendLabel = new QLabel(this);
    mBackendLabel->setObjectName(QStringLiteral("backendLabel"));
    statusBar()->addPermanentWidget(mBackendLabel);
    // Beside the message that a favourite was removed, while it shows.
    mUndoRemove = new QPushButton(tr("Undo"), this);
    mUndoRemove->setObjectName(QStringLiteral("undoRemoveFavourite"));
    mUndoRemove->setToolTip(tr("Put the removed favourite back (%1)")
                                .arg(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R).toString(QKeySequence::NativeText)));
    statusBar()->insertPermanentWidget(0, mUndoRemove);
    mUndoRemove->hide();
    connect(mUndoRemove, &QPushButton::clicked, this, [this] { restoreRemovedFavourite(); });
    connect(statusBar(), &QStatusBar::messageChanged, this, [this](const QString& message) {
        if (message != mUndoRemove->property("message").toString()) mUndoRemove->hide();
    });
    if (!mRenderer->backendName().isEmpty()) showBackend();
    connect(mRenderer, &RenderService::backendReady, this, [this] {
        showBackend();
        // Images from the other back end differ in the last bits: render everything anew.
        mImageCache.clear();
        requestAllRenders();
    });
    connect(mRenderer, &RenderService::rendered, this, &WorkbenchWindow::onRendered);
    connect(mRenderer, &RenderService::failed, this, &WorkbenchWindow::onRenderFailed);

    connect(mModel, &PopulationModel::populationChanged, this, [this] {
        updateCells();
        requestAllRenders();
        updateLineage();
    });
    connect(mModel, &PopulationModel::cellChanged, this, [this] {
        updateCells(); // the lock marker
        updateLineage();
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
                           "keep the designs you like as favourites.\n\n%1").arg(message));
        } else {
            statusBar()->showMessage(tr("The session could not be saved: %1").arg(message), 10000);
        }
    });

    readSettings();
    mModel->setMesh(mMesh->currentText());
    const QStringList favouriteErrors = mModel->setFavouritesFolder(PopulationModel::defaultFavouritesFolder());
    if (!favouriteErrors.isEmpty())
        statusBar()->showMessage(tr("Some favourites could not be read: %1").arg(favouriteErrors.join(QStringLiteral("; "))), 10000);
    updateCells();
    updateActions();
    updateLineage();
}

WorkbenchWindow::~WorkbenchWindow() {
    // Results for this window's keys may still arrive after it is gone; the service simply
    // has no receiver then, but the work itself is wasted, so drop it.
    for (int i = 0; i < CellCount; ++i) mRenderer->cancel(std::uint64_t(i));
    for (std::size_t i = 0; i < mModel->favourites().size(); ++i) mRenderer->cancel(FavouriteKeyBase + i);
}

void WorkbenchWindow::buildActions() {
    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    QMenu* editMenu = menuBar()->addMenu(tr("&Edit"));
    QMenu* breedMenu = menuBar()->addMenu(tr("&Breed"));
    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->setObjectName(QStringLiteral("viewMenu"));

    QToolBar* bar = addToolBar(tr("Breeding"));
    bar->setObjectName(QStringLiteral("breedingToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);

    QAction* open = fileMenu->addAction(tr("&Open designs…"), this, &WorkbenchWindow::openFileDialog);
    open->setShortcut(QKeySequence::Open);
    open->setStatusTip(tr("Load genome files into the selected cells, then free ones"));
    QAction* newRandom = fileMenu->addAction(tr("&New random population"), this, [this] {
        newRandomPopulation(mDimension->currentData().toInt());
    });
    newRandom->setShortcut(QKeySequence::New);
    newRandom->setIconText(tr("New random"));
    newRandom->setToolTip(tr("Nine new random designs of the kind chosen beside (Ctrl+N)"));
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
    mBack->setToolTip(tr("Back to the previous generation (Ctrl+Z)"));
    mForward = editMenu->addAction(style()->standardIcon(QStyle::SP_ArrowForward), tr("&Forward a generation"),
                                   mModel, &PopulationModel::goForward);
    mForward->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z));
    mForward->setIconText(tr("Forward ▶"));
    mForward->setToolTip(tr("Forward to the next generation (Ctrl+Shift+Z)"));
    editMenu->addSeparator();
    editMenu->addAction(tr("Clear &selection"), mModel, &PopulationModel::clearSelection)
        ->setShortcut(QKeySequence(Qt::Key_Escape));
    editMenu->addSeparator();
    mRestoreFavourite = editMenu->addAction(tr("&Restore removed favourite"), this, [this] { restoreRemovedFavourite(); });
    // Ctrl+Z steps back a generation, so undoing a removal has a key of its own.
    mRestoreFavourite->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    mRestoreFavourite->setStatusTip(tr("Puts the favourite removed last back on the shelf"));
    mRestoreFavourite->setEnabled(false);

    const auto makeOperator = [&](GeneticOperator op, const QString& text, const QString& tip, QKeySequence key) {
        QAction* action = breedMenu->addAction(text, this, [this, op] { applyOperator(op); });
        action->setShortcut(key);
        action->setToolTip(QStringLiteral("%1 (%2)").arg(tip, key.toString(QKeySequence::NativeText)));
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

    bar->addAction(mBack);
    bar->addAction(mForward);
    bar->addSeparator();
    for (QAction* a : {mAlter, mRecombine, mSwap, mReinit}) bar->addAction(a);

    auto* strengthLabel = new QLabel(tr(" Strength "), bar);
    mStrength = new QSlider(Qt::Horizontal, bar);
    mStrength->setRange(0, 100);
    mStrength->setValue(50);
    mStrength->setMaximumWidth(120);
    mStrength->setToolTip(tr("How far Alter moves the strokes: 0 barely, 1 a lot"));
    connect(mStrength, &QSlider::valueChanged, this, [this](int value) {
        statusBar()->showMessage(tr("Alteration strength %1").arg(value / 100.0, 0, 'f', 2), 2000);
    });
    bar->addWidget(strengthLabel);
    bar->addWidget(mStrength);
    bar->addSeparator();

    mDimension = new QComboBox(bar);
    mDimension->addItem(tr("2D designs"), 2);
    mDimension->addItem(tr("Solid designs"), 3);
    mDimension->setToolTip(tr("What a new random population holds: flat marbling or solid (volume) marbling"));
    bar->addWidget(mDimension);
    bar->addAction(newRandom);

    mMesh = new QComboBox(bar);
    mMesh->addItems(meshNames());
    mMesh->setToolTip(tr("The object solid designs are shown on (drag in a cell to turn it)"));
    connect(mMesh, &QComboBox::currentTextChanged, this, [this](const QString& mesh) {
        QSettings().setValue(QStringLiteral("view/mesh"), mesh);
        mModel->setMesh(mesh);
        requestAllRenders();
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
    list->setToolTip(tr("Designs kept aside (F on a cell). Double-click or drag one onto a cell to bring it back."));
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
    mLineageTree->setToolTip(tr("How the current designs came to be. Double-click a generation to go to it."));
    connect(mLineageTree, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
        const QVariant generation = item->data(0, Qt::UserRole);
        if (generation.isValid()) mModel->goTo(generation.toInt());
    });
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
    addChoice(gl::BackendPreference::Auto, tr("Renderer: &Automatic"),
              tr("OpenGL on a graphics card; the CPU where OpenGL is a software rasteriser (such as llvmpipe) or "
                 "missing, since the CPU renderer is faster there"));
    addChoice(gl::BackendPreference::Gpu, tr("Renderer: &GPU"),
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
    if (preference != mRenderer->preference()) mRenderer->setPreference(preference);
}

QAction* WorkbenchWindow::rendererAction(gl::BackendPreference preference) const {
    return mRendererActions[std::size_t(preference)];
}

void WorkbenchWindow::showBackend() {
    const QString where = mRenderer->usesGl() ? tr("Rendering with %1").arg(mRenderer->backendName())
                                              : tr("Rendering on the %1").arg(mRenderer->backendName());
    const QString why = mRenderer->backendReason();
    mBackendLabel->setText(why.isEmpty() ? where : tr("%1: %2").arg(where, why));
    mBackendLabel->setToolTip(tr("%1.\nChoose the renderer in View ▸ Renderer (the environment variable %2=auto|gpu|cpu "
                                 "overrides it).")
                                  .arg(why.isEmpty() ? where : why, QString::fromLatin1(gl::BackendEnvironmentVariable)));
}

void WorkbenchWindow::readSettings() {
    QSettings settings;
    if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray())) resize(1180, 860);
    if (!restoreState(settings.value(QStringLiteral("window/state")).toByteArray())) {
        // First start: docks wide enough for the lineage columns, the shelf above the lineage.
        const auto docks = findChildren<QDockWidget*>();
        resizeDocks(QList<QDockWidget*>(docks.begin(), docks.end()), QList<int>(docks.size(), 380), Qt::Horizontal);
    }
    const int dimension = settings.value(QStringLiteral("population/dimension"), 2).toInt();
    mDimension->setCurrentIndex(dimension == 3 ? 1 : 0);
    mStrength->setValue(settings.value(QStringLiteral("breed/strength"), 50).toInt());
    const QString mesh = settings.value(QStringLiteral("view/mesh"), QStringLiteral("vase")).toString();
    if (mMesh->findText(mesh) >= 0) mMesh->setCurrentText(mesh);
}

void WorkbenchWindow::closeEvent(QCloseEvent* event) {
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    settings.setValue(QStringLiteral("breed/strength"), mStrength->value());
    QMainWindow::closeEvent(event);
}

QAction* WorkbenchWindow::operatorAction(GeneticOperator op) const {
    switch (op) {
    case GeneticOperator::Alter: return mAlter;
    case GeneticOperator::Recombine: return mRecombine;
    case GeneticOperator::Swap: return mSwap;
    case GeneticOperator::Reinit: return mReinit;
    }
    return nullptr;
}

double WorkbenchWindow::strength() const { return mStrength->value() / 100.0; }
void WorkbenchWindow::setStrength(double strength) { mStrength->setValue(int(std::lround(strength * 100.0))); }

void WorkbenchWindow::updateCells() {
    for (int i = 0; i < CellCount; ++i) {
        DesignCell* c = mCells[std::size_t(i)];
        const Genome* g = mModel->cell(i);
        c->setHasDesign(g != nullptr);
        c->setSelectedParent(mModel->isSelected(i));
        c->setOrbitEnabled(g && g->dimension == 3);
        if (!g) {
            c->setCaption({});
            continue;
        }
        c->setCaption(designCaption(*g));
        const Locks locks = locksOf(*g);
        c->setLocked(locks.palette || locks.initial || locks.operations);
    }
}

void WorkbenchWindow::updateActions() {
    const int n = mModel->selectedCount();
    for (GeneticOperator op : {GeneticOperator::Alter, GeneticOperator::Recombine, GeneticOperator::Swap,
                               GeneticOperator::Reinit})
        operatorAction(op)->setEnabled(mModel->canApply(op));
    mBack->setEnabled(mModel->canGoBack());
    mForward->setEnabled(mModel->canGoForward());
    const auto& gen = mModel->current();
    if (mModel->isEmptyWorkbench()) {
        statusBar()->showMessage(tr("No designs yet: make a new random population (Ctrl+N) or open designs (Ctrl+O)"));
        return;
    }
    statusBar()->showMessage(tr("Generation %1 of %2: %3 — %4 selected")
                                 .arg(displayNumber(mModel->currentIndex()))
                                 .arg(mModel->history().size())
                                 .arg(gen.description)
                                 .arg(n == 1 ? tr("1 parent") : tr("%1 parents").arg(n)));
}

void WorkbenchWindow::updateLineage() {
    mLineageTree->clear();
    auto* designs = new QTreeWidgetItem(mLineageTree, {tr("Current designs")});
    for (int i = 0; i < CellCount; ++i) {
        const Genome* g = mModel->cell(i);
        if (!g) continue;
        const LineageInfo info = lineageOf(*g);
        QStringList parents;
        for (const QString& p : info.parents) parents << shortId(p);
        auto* item = new QTreeWidgetItem(designs, {tr("Design %1: %2").arg(i + 1).arg(info.name.isEmpty() ? shortId(info.id) : info.name),
                                                   madeBy(info), parents.join(QStringLiteral(", ")),
                                                   info.op.isEmpty() ? QString() : QString::number(info.generation)});
        item->setToolTip(0, info.id);
        item->setToolTip(2, info.parents.join(QLatin1Char('\n')));
    }
    auto* generations = new QTreeWidgetItem(mLineageTree, {tr("Generations")});
    const auto& history = mModel->history();
    // The empty placeholder before the first designs is no generation.
    for (std::size_t k = 0; k < history.size() && !mModel->isEmptyWorkbench(); ++k) {
        QStringList parents;
        for (int i : history[k].parentCells) parents << tr("design %1").arg(i + 1);
        auto* item = new QTreeWidgetItem(generations, {tr("Generation %1").arg(displayNumber(int(k))), history[k].description,
                                                       parents.join(QStringLiteral(", ")), QString()});
        item->setData(0, Qt::UserRole, int(k));
        if (int(k) == mModel->currentIndex()) {
            QFont f = item->font(0);
            f.setBold(true);
            for (int c = 0; c < 4; ++c) item->setFont(c, f);
        }
    }
    mLineageTree->expandAll();
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
        auto* item = new QListWidgetItem(info.name.isEmpty() ? shortId(info.id) : info.name, mFavouritesList);
        item->setToolTip(QStringLiteral("%1\n%2").arg(item->text(), favourites[i].file));
        item->setIcon(placeholder);
        RenderRequest request;
        request.genome = favourites[i].genome;
        request.size = QSize(ThumbnailSide, ThumbnailSide);
        request.mesh = mMesh->currentText();
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
        .arg(g->dimension == 3 ? mYaw[std::size_t(index)] : 0.0)
        .arg(g->dimension == 3 ? mPitch[std::size_t(index)] : 0.0);
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
            mFinal[std::size_t(index)] = true;
            return;
        }
    }
    RenderRequest request;
    request.genome = *g;
    const int margin = 12;
    request.size = ((c->size() - QSize(margin, margin)) * c->devicePixelRatioF()).expandedTo(QSize(16, 16));
    request.mesh = mMesh->currentText();
    request.yaw = mYaw[std::size_t(index)];
    request.pitch = mPitch[std::size_t(index)];
    request.previewOnly = previewOnly;
    mPendingCacheKey[std::size_t(index)] = previewOnly ? QString() : key;
    mFinal[std::size_t(index)] = false;
    mRenderer->request(std::uint64_t(index), std::move(request));
}

void WorkbenchWindow::requestAllRenders() {
    for (int i = 0; i < CellCount; ++i) requestRender(i);
    if (renderingDone()) emit renderingFinished();
}

bool WorkbenchWindow::renderingDone() const {
    return std::all_of(mFinal.begin(), mFinal.end(), [](bool b) { return b; });
}

void WorkbenchWindow::onRendered(std::uint64_t key, const QImage& image, bool final) {
    if (key < std::uint64_t(CellCount)) {
        const auto index = std::size_t(key);
        mCells[index]->setImage(image);
        if (final) {
            if (!mPendingCacheKey[index].isEmpty()) mImageCache.insert(mPendingCacheKey[index], new QImage(image));
            mFinal[index] = true;
            if (renderingDone()) emit renderingFinished();
        }
        return;
    }
    if (key >= FavouriteKeyBase) {
        const int row = int(key - FavouriteKeyBase);
        if (QListWidgetItem* item = mFavouritesList->item(row)) item->setIcon(QIcon(QPixmap::fromImage(image)));
    }
}

void WorkbenchWindow::onRenderFailed(std::uint64_t key, const QString& message) {
    if (key < std::uint64_t(CellCount)) {
        mCells[std::size_t(key)]->setError(message);
        mFinal[std::size_t(key)] = true;
        statusBar()->showMessage(tr("Design %1 cannot be rendered: %2").arg(key + 1).arg(message), 10000);
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
    const auto i = std::size_t(index);
    mYaw[i] = std::fmod(mYaw[i] + delta.x() * 0.5, 360.0);
    mPitch[i] = std::clamp(mPitch[i] + delta.y() * 0.5, -89.0, 89.0);
    // While dragging only previews are worth rendering; the release asks for the final image.
    requestRender(index, !finished);
}

bool WorkbenchWindow::applyOperator(GeneticOperator op) {
    if (!mModel->canApply(op)) {
        statusBar()->showMessage(tr("%1 needs %2 parents of one kind")
                                     .arg(operatorLabel(op))
                                     .arg(maxParents(op) == 0 ? tr("%1 or more").arg(minParents(op))
                                                              : QString::number(minParents(op))),
                                 5000);
        return false;
    }
    try {
        mModel->apply(op, strength());
    } catch (const Error& e) {
        reportError(this, tr("Cannot breed"), QString::fromStdString(e.what()));
        return false;
    }
    statusBar()->showMessage(tr("%1: generation %2").arg(operatorLabel(op)).arg(displayNumber(mModel->currentIndex())), 5000);
    return true;
}

void WorkbenchWindow::newRandomPopulation(int dimension) {
    QSettings().setValue(QStringLiteral("population/dimension"), dimension);
    mDimension->setCurrentIndex(dimension == 3 ? 1 : 0);
    try {
        mModel->newRandomPopulation(dimension);
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
            designs.push_back(loadGenome(file.toStdString(), &warnings));
            names << QFileInfo(file).fileName();
            if (!warnings.empty())
                statusBar()->showMessage(QString::fromStdString(warnings.front()), 8000);
        } catch (const Error& e) {
            errors << QString::fromStdString(e.what());
        }
    }
    if (!designs.empty()) {
        const QString description = tr("Opened %1").arg(names.join(QStringLiteral(", ")));
        if (cell >= 0 && designs.size() == 1) {
            mModel->setCell(cell, designs.front(), description);
        } else {
            mModel->placeDesigns(designs, description);
        }
        statusBar()->showMessage(description, 5000);
    }
    if (!errors.isEmpty()) {
        reportError(this, tr("Cannot open a design"),
                    tr("These files could not be loaded; the population is unchanged by them.\n\n%1")
                        .arg(errors.join(QStringLiteral("\n"))));
        return false;
    }
    return true;
}

void WorkbenchWindow::openFileDialog() {
    const QString dir = QSettings().value(QStringLiteral("files/lastDir")).toString();
    const QStringList files = QFileDialog::getOpenFileNames(this, tr("Open designs"), dir,
                                                            tr("Marbler genomes (*.marble.json *.json);;All files (*)"));
    if (files.isEmpty()) return;
    QSettings().setValue(QStringLiteral("files/lastDir"), QFileInfo(files.front()).absolutePath());
    openFiles(files);
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
    statusBar()->showMessage(tr("Design %1 kept on the favourites shelf").arg(index + 1), 4000);
    return true;
}

void WorkbenchWindow::restoreFavourite(int favourite, int index) {
    const auto& favourites = mModel->favourites();
    if (favourite < 0 || favourite >= int(favourites.size())) return;
    const Genome genome = favourites[std::size_t(favourite)].genome;
    const QString description = tr("Brought back a favourite");
    if (index >= 0)
        mModel->setCell(index, genome, description);
    else
        mModel->placeDesigns({genome}, description);
}

void WorkbenchWindow::showCellMenu(int index, const QPoint& globalPos) {
    const Genome* g = mModel->cell(index);
    QMenu menu(this);
    if (!g) {
        menu.addAction(tr("Open a design here…"), this, [this, index] {
            const QString file = QFileDialog::getOpenFileName(this, tr("Open a design"), QString(),
                                                              tr("Marbler genomes (*.marble.json *.json)"));
            if (!file.isEmpty()) openFiles({file}, index);
        });
        menu.exec(globalPos);
        return;
    }
    menu.addAction(mModel->isSelected(index) ? tr("Deselect parent") : tr("Select as parent"), this,
                   [this, index] { mModel->toggleSelected(index); });
    menu.addAction(tr("Open large…"), this, [this, index] { openDesign(index); });
    menu.addAction(tr("Keep as favourite"), this, [this, index] { keepFavourite(index); })
        ->setShortcut(QKeySequence(Qt::Key_F));
    menu.addAction(tr("Save design…"), this, [this, index] { saveDesign(index); });
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
    const QString name = info.name.isEmpty() ? shortId(info.id) : info.name;
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
            name = info.name.isEmpty() ? shortId(info.id) : info.name;
        }
    statusBar()->showMessage(tr("“%1” is back on the favourites shelf").arg(name), 5000);
    return true;
}

void WorkbenchWindow::setSessionStore(const QString& sessionFolder) {
    mSessionFolder = sessionFolder;
    mSessionsAction->setEnabled(!sessionFolder.isEmpty());
    mRecentSessions->setEnabled(!sessionFolder.isEmpty());
}

QString WorkbenchWindow::currentSessionId() const {
    const QString file = mModel->sessionFile();
    return file.isEmpty() ? QString() : QFileInfo(file).completeBaseName();
}

void WorkbenchWindow::fillRecentSessions() {
    mRecentSessions->clear();
    if (mSessionFolder.isEmpty()) return;
    const QString current = currentSessionId();
    int shown = 0;
    for (const KeptSession& session : SessionStore(mSessionFolder).list()) {
        if (session.id == current) continue;
        if (++shown > 9) break;
        QAction* action = mRecentSessions->addAction(
            QStringLiteral("&%1 %2 — %3").arg(shown).arg(session.name, describeSession(session)),
            this, [this, id = session.id] { resumeKeptSession(id); });
        action->setData(session.id);
    }
    if (shown == 0) mRecentSessions->addAction(tr("No other sessions"))->setEnabled(false);
    mRecentSessions->addSeparator();
    mRecentSessions->addAction(mSessionsAction);
}

bool WorkbenchWindow::resumeKeptSession(const QString& id) {
    if (mSessionFolder.isEmpty() || id.isEmpty() || id == currentSessionId()) return false;
    const std::optional<KeptSession> kept = SessionStore(mSessionFolder).find(id);
    if (!kept) {
        reportError(this, tr("Cannot resume the session"), tr("There is no kept session %1 any more.").arg(id));
        return false;
    }
    SavedSession saved;
    try {
        saved = loadSession(kept->file);
    } catch (const std::exception& e) {
        reportBadSession(this, kept->file, QString::fromStdString(e.what()));
        return false;
    }
    // The current session was saved with its last change, so switching loses nothing; no file
    // is set while the other one comes in, so nothing is written over either.
    const QString previous = mModel->sessionLabel().name;
    mModel->setSessionFile({});
    resumeSession(std::move(saved));
    mModel->setSessionFile(kept->file);
    statusBar()->showMessage(previous.isEmpty()
                                 ? tr("Resumed “%1” at generation %2").arg(kept->name).arg(displayNumber(mModel->currentIndex()))
                                 : tr("Resumed “%1” at generation %2; “%3” is kept under File ▸ Sessions")
                                       .arg(kept->name)
                                       .arg(displayNumber(mModel->currentIndex()))
                                       .arg(previous),
                             15000);
    return true;
}

bool WorkbenchWindow::renameSession(const QString& id, const QString& name) {
    const QString trimmed = name.trimmed();
    if (mSessionFolder.isEmpty() || id.isEmpty() || trimmed.isEmpty()) return false;
    if (id == currentSessionId()) {
        SessionLabel label = mModel->sessionLabel();
        label.name = trimmed;
        mModel->setSessionLabel(label); // saved with the session
        return true;
    }
    try {
        SessionStore(mSessionFolder).rename(id, trimmed);
    } catch (const std::exception& e) {
        reportError(this, tr("Cannot rename the session"), QString::fromStdString(e.what()));
        return false;
    }
    return true;
}

QString WorkbenchWindow::deleteSession(const QString& id) {
    if (mSessionFolder.isEmpty() || id.isEmpty()) return {};
    if (id == currentSessionId()) {
        statusBar()->showMessage(tr("The session being bred cannot be deleted; resume another one first"), 8000);
        return {};
    }
    try {
        return SessionStore(mSessionFolder).remove(id);
    } catch (const std::exception& e) {
        reportError(this, tr("Cannot delete the session"), QString::fromStdString(e.what()));
        return {};
    }
}

bool WorkbenchWindow::restoreDeletedSession(const QString& trashed) {
    try {
        SessionStore(mSessionFolder).restore(trashed);
    } catch (const std::exception& e) {
        reportError(this, tr("Cannot bring back the session"), QString::fromStdString(e.what()));
        return false;
    }
    return true;
}

SessionsDialog* WorkbenchWindow::openSessionsDialog() {
    if (mSessionFolder.isEmpty()) return nullptr;
    if (!mSessionsDialog) {
        mSessionsDialog = new SessionsDialog(this);
        mSessionsDialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    mSessionsDialog->refresh();
    mSessionsDialog->show();
    mSessionsDialog->raise();
    return mSessionsDialog;
}

void reportBadSession(QWidget* parent, const QString& file, const QString& what) {
    const QString aside = keepBadSession(file);
    reportError(parent, WorkbenchWindow::tr("Cannot resume the last session"),
                WorkbenchWindow::tr("The session could not be read, so it is not resumed.\n\n%1\n\n%2")
                    .arg(what, aside.isEmpty() ? WorkbenchWindow::tr("The file could not be moved aside.")
                                               : WorkbenchWindow::tr("The file is kept as %1.").arg(aside)));
}

void WorkbenchWindow::saveDesign(int index) {
    const Genome* g = mModel->cell(index);
    if (!g) return;
    saveGenomeWithDialog(this, *g);
}

DesignDialog* WorkbenchWindow::openDesign(int index) {
    const Genome* g = mModel->cell(index);
    if (!g) return nullptr;
    auto* dialog = new DesignDialog(*g, mRenderer, mMesh->currentText(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    emit designOpened(dialog);
    return dialog;
}

void WorkbenchWindow::resumeSession(SavedSession session) {
    const int dimension = session.dimension;
    mModel->restoreSession(std::move(session));
    mDimension->setCurrentIndex(dimension == 3 ? 1 : 0);
    setMesh(mModel->mesh());
    statusBar()->showMessage(tr("Resumed the last session at generation %1").arg(displayNumber(mModel->currentIndex())), 5000);
}

QString WorkbenchWindow::mesh() const { return mMesh->currentText(); }

QString designCaption(const Genome& genome) {
    const LineageInfo info = lineageOf(genome);
    QString caption = info.name.isEmpty() ? shortId(info.id) : info.name;
    if (!info.op.isEmpty()) caption += QStringLiteral(" · ") + madeBy(info);
    return caption;
}

void WorkbenchWindow::setMesh(const QString& mesh) {
    if (mMesh->findText(mesh) >= 0) mMesh->setCurrentText(mesh);
}

} // namespace marbler::ui
