#include "workbench/FavouritesShelf.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "shared/ErrorReport.h"
#include "shared/RenameDialog.h"
#include "shared/RenderService.h"
#include "workbench/DesignCell.h"
#include "workbench/LineagePanel.h"
#include "workbench/PopulationModel.h"
#include "workbench/Trash.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QListWidget>
#include <QMainWindow>
#include <QMenu>
#include <QMimeData>
#include <QPushButton>
#include <QStatusBar>

namespace marbler::ui {

namespace {

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

} // namespace

FavouritesShelf::FavouritesShelf(QMainWindow* window, PopulationModel* model, RenderService* renderer,
                                 QMenu* editMenu, std::function<QString()> mesh,
                                 std::function<void(const QString&)> noteSavedFile)
    : QObject(window)
    , mWindow(window)
    , mModel(model)
    , mRenderer(renderer)
    , mKeyBase(renderer->newKeys(KeyCount))
    , mMesh(std::move(mesh))
    , mNoteSavedFile(std::move(noteSavedFile)) {
    mRestore = editMenu->addAction(tr("&Restore removed favourite"), this, [this] { restoreRemoved(); });
    // Ctrl+Z steps back a generation, so undoing a removal has a key of its own.
    mRestore->setObjectName(QStringLiteral("restoreFavouriteAction"));
    mRestore->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    mRestore->setStatusTip(tr("Puts the favourite removed last back on the shelf"));
    mRestore->setEnabled(false);

    connect(mModel, &PopulationModel::favouritesChanged, this, &FavouritesShelf::update);
    connect(mRenderer, &RenderService::rendered, this, [this](std::uint64_t key, const QImage& image) {
        if (key < mKeyBase || key >= mKeyBase + KeyCount) return;
        if (QListWidgetItem* item = mList ? mList->item(int(key - mKeyBase)) : nullptr)
            item->setIcon(QIcon(QPixmap::fromImage(image)));
    });
}

QDockWidget* FavouritesShelf::buildDock() {
    auto* favDock = new QDockWidget(tr("Favourites"), mWindow);
    favDock->setObjectName(QStringLiteral("favouritesDock"));
    auto* list = new FavouritesList(favDock);
    list->favourites = &mModel->favourites();
    mList = list;
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
            [this](QListWidgetItem* item) { emit restoreRequested(mList->row(item)); });
    connect(list, &QWidget::customContextMenuRequested, this, &FavouritesShelf::showMenu);
    // Docks never shrink past the point where a thumbnail or the lineage columns stay usable,
    // so a small window cannot squash them (nor save a squashed layout).
    list->setMinimumSize(ThumbnailSide + 80, ThumbnailSide + 50);
    favDock->setWidget(list);
    return favDock;
}

void FavouritesShelf::addUndoButton(QStatusBar* statusBar) {
    mUndoRemove = new QPushButton(tr("Undo"), mWindow);
    mUndoRemove->setObjectName(QStringLiteral("undoRemoveFavourite"));
    mUndoRemove->setToolTip(
        tr("Put the removed favourite back (%1)")
            .arg(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R).toString(QKeySequence::NativeText)));
    // The first of the permanent widgets (index 0 is the generation summary), left of the rest.
    statusBar->insertPermanentWidget(1, mUndoRemove);
    mUndoRemove->hide();
    connect(mUndoRemove, &QPushButton::clicked, this, [this] { restoreRemoved(); });
    connect(statusBar, &QStatusBar::messageChanged, this, [this](const QString& message) {
        if (message != mUndoRemove->property("message").toString()) mUndoRemove->hide();
    });
}

void FavouritesShelf::cancelThumbnails() {
    for (std::size_t i = 0; i < mModel->favourites().size(); ++i)
        mRenderer->cancel(mKeyBase + i);
}

void FavouritesShelf::update() {
    mRestore->setEnabled(!mModel->removedFavourites().isEmpty());
    if (mModel->removedFavourites().isEmpty()) mUndoRemove->hide();
    mList->clear();
    const auto& favourites = mModel->favourites();
    // Until its thumbnail is rendered, a favourite shows a blank of the thumbnail's size.
    QPixmap placeholder(ThumbnailSide, ThumbnailSide);
    placeholder.fill(mWindow->palette().color(QPalette::Mid));
    for (std::size_t i = 0; i < favourites.size(); ++i) {
        const LineageInfo info = lineageOf(favourites[i].genome);
        auto* item = new QListWidgetItem(info.displayName(), mList);
        const QString note = noteOf(favourites[i].genome);
        item->setToolTip(note.isEmpty()
                             ? QStringLiteral("%1\n%2").arg(item->text(), favourites[i].file)
                             : QStringLiteral("%1\n%2\n%3").arg(item->text(), note, favourites[i].file));
        item->setIcon(placeholder);
        RenderRequest request;
        request.genome = favourites[i].genome;
        request.size = QSize(ThumbnailSide, ThumbnailSide);
        request.mesh = mMesh();
        const ViewAngle angle = viewAngleOf(favourites[i].genome);
        request.yaw = angle.yaw;
        request.pitch = angle.pitch;
        mRenderer->request(mKeyBase + i, std::move(request));
    }
}

bool FavouritesShelf::keep(int index) {
    const Genome* g = mModel->cell(index);
    if (!g) return false;
    try {
        mModel->addFavourite(*g);
    } catch (const Error& e) {
        reportError(mWindow, tr("Cannot keep the favourite"), QString::fromStdString(e.what()));
        return false;
    }
    // Kept as a genome file: say where, as for any file the window writes.
    const QString id = QString::fromStdString(genomeId(*g));
    for (const Favourite& f : mModel->favourites())
        if (QFileInfo(f.file).fileName().startsWith(id)) mNoteSavedFile(f.file);
    mWindow->statusBar()->showMessage(tr("Design %1 kept on the favourites shelf").arg(index + 1), 4000);
    return true;
}

void FavouritesShelf::showMenu(const QPoint& pos) {
    QMenu menu(mWindow);
    if (QListWidgetItem* item = mList->itemAt(pos)) {
        const int row = mList->row(item);
        menu.addAction(tr("Put into the grid"), this, [this, row] { emit restoreRequested(row); });
        menu.addAction(tr("Rename…"), this, [this, row] { rename(row); })
            ->setShortcut(QKeySequence(Qt::Key_F2));
        menu.addAction(tr("Remove from favourites"), this, [this, row] { remove(row); });
        menu.addSeparator();
    }
    menu.addAction(mRestore);
    menu.exec(mList->viewport()->mapToGlobal(pos));
}

RenameDialog* FavouritesShelf::rename(int favourite) {
    const auto& favourites = mModel->favourites();
    if (favourite < 0 || favourite >= int(favourites.size())) return nullptr;
    const QString file = favourites[std::size_t(favourite)].file;
    return askRename(mWindow, favourites[std::size_t(favourite)].genome,
                     [this, favourite, file](const QString& name, const QString& note) {
                         const auto& now = mModel->favourites();
                         // The shelf changed meanwhile: the favourite is found by its file.
                         if (favourite >= int(now.size()) || now[std::size_t(favourite)].file != file) return;
                         if (mModel->renameFavourite(favourite, name, note).isEmpty())
                             reportError(mWindow, tr("Cannot rename the favourite"),
                                         tr("%1 could not be written").arg(QDir::toNativeSeparators(file)));
                     });
}

bool FavouritesShelf::remove(int favourite) {
    const auto& favourites = mModel->favourites();
    if (favourite < 0 || favourite >= int(favourites.size())) return false;
    const LineageInfo info = lineageOf(favourites[std::size_t(favourite)].genome);
    const QString name = info.displayName();
    try {
        mModel->removeFavourite(favourite);
    } catch (const Error& e) {
        reportError(mWindow, tr("Cannot remove the favourite"), QString::fromStdString(e.what()));
        return false;
    }
    const QString message = tr("Removed “%1” from favourites — Undo (%2)")
                                .arg(name, mRestore->shortcut().toString(QKeySequence::NativeText));
    mUndoRemove->setProperty("message", message);
    mWindow->statusBar()->showMessage(message, 15000);
    mUndoRemove->show();
    return true;
}

bool FavouritesShelf::restoreRemoved() {
    if (mModel->removedFavourites().isEmpty()) return false;
    const QString trashed = mModel->removedFavourites().back();
    const QString back = QDir(mModel->favouritesFolder()).filePath(originalTrashName(trashed));
    if (!mModel->restoreRemovedFavourite(trashed)) {
        reportError(mWindow, tr("Cannot restore the favourite"),
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
    mWindow->statusBar()->showMessage(tr("“%1” is back on the favourites shelf").arg(name), 5000);
    return true;
}

} // namespace marbler::ui
