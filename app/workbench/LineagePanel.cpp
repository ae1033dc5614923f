#include "workbench/LineagePanel.h"

#include "marbler/GenomeIO.h"
#include "shared/RenderService.h"

#include <QApplication>
#include <QDockWidget>
#include <QFont>
#include <QHeaderView>
#include <QPainter>
#include <QScrollBar>
#include <QTreeWidget>

#include <algorithm>

namespace marbler::ui {

LineagePanel::LineagePanel(QWidget* window, PopulationModel* model, RenderService* renderer,
                           std::function<QString()> mesh)
    : QObject(window)
    , mWindow(window)
    , mModel(model)
    , mRenderer(renderer)
    , mMesh(std::move(mesh)) {
    mDock = new QDockWidget(tr("Lineage"), window);
    mDock->setObjectName(QStringLiteral("lineageDock"));
    mTree = new QTreeWidget(mDock);
    mTree->setColumnCount(4);
    mTree->setHeaderLabels({tr("Design"), tr("Made by"), tr("Parents"), tr("Generation")});
    mTree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    mTree->setIconSize(QSize(IconSide, IconSide));
    // A double-click goes to a generation; it must not also fold it.
    mTree->setExpandsOnDoubleClick(false);
    mTree->setToolTip(tr("Every generation, branches included, and how the designs came to be. Click a "
                         "design to select it; double-click a generation to go back to it, or a design of "
                         "another generation to bring it back into the grid."));
    mClickTimer.setSingleShot(true);
    mClickTimer.setInterval(QApplication::doubleClickInterval());
    connect(&mClickTimer, &QTimer::timeout, this, [this] { selectDesign(mClickGeneration, mClickCell); });
    connect(mTree, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) {
        const QVariant cell = item->data(0, CellRole);
        if (!cell.isValid()) return;
        mClickGeneration = item->data(0, GenerationRole).toInt();
        mClickCell = cell.toInt();
        mClickTimer.start();
    });
    connect(mTree, &QTreeWidget::itemDoubleClicked, this, &LineagePanel::onDoubleClicked);
    connect(mTree, &QTreeWidget::itemExpanded, this, [this](QTreeWidgetItem* item) {
        const QVariant generation = item->data(0, GenerationRole);
        if (generation.isValid() && !item->data(0, CellRole).isValid()) {
            mExpandedGenerations.insert(generation.toInt());
            populateGeneration(item);
        }
        const QVariant branch = item->data(0, BranchRole);
        if (branch.isValid()) mCollapsedBranches.remove(branch.toInt());
        if (item == mTree->topLevelItem(0)) mCurrentDesignsFolded = false;
        mThumbnailTimer.start();
    });
    connect(mTree, &QTreeWidget::itemCollapsed, this, [this](QTreeWidgetItem* item) {
        const QVariant generation = item->data(0, GenerationRole);
        if (generation.isValid()) mExpandedGenerations.remove(generation.toInt());
        const QVariant branch = item->data(0, BranchRole);
        if (branch.isValid()) mCollapsedBranches.insert(branch.toInt());
        if (item == mTree->topLevelItem(0)) mCurrentDesignsFolded = true;
    });
    // Thumbnails are rendered for what comes into view: after scrolling, resizing, showing.
    mThumbnailTimer.setSingleShot(true);
    mThumbnailTimer.setInterval(30);
    connect(&mThumbnailTimer, &QTimer::timeout, this, &LineagePanel::requestThumbnails);
    // The timer is the receiver: the dock hides as the window is destroyed, after the timer.
    const auto scheduleThumbnails = [this] { mThumbnailTimer.start(); };
    connect(mTree->verticalScrollBar(), &QScrollBar::valueChanged, &mThumbnailTimer, scheduleThumbnails);
    connect(mTree->verticalScrollBar(), &QScrollBar::rangeChanged, &mThumbnailTimer, scheduleThumbnails);
    connect(mDock, &QDockWidget::visibilityChanged, &mThumbnailTimer, scheduleThumbnails);
    mTree->setMinimumSize(260, 140);
    mDock->setWidget(mTree);

    connect(mRenderer, &RenderService::rendered, this,
            [this](std::uint64_t key, const QImage& image, bool final) {
                // Other keys are other views' (the grid, the favourites, a large view, an editor).
                if (final && mRequests.contains(key)) onThumbnail(key, image);
            });
    connect(mRenderer, &RenderService::failed, this, [this](std::uint64_t key) {
        if (mRequests.contains(key)) onThumbnail(key, QImage());
    });
}

LineagePanel::~LineagePanel() {
    // Results may still arrive after the panel is gone; the work itself is wasted, so drop it.
    for (auto it = mRequests.cbegin(); it != mRequests.cend(); ++it)
        mRenderer->cancel(it.key());
}

void LineagePanel::update() {
    mDesignItems.clear();
    mGenerationItems.clear();
    mTree->clear();
    const int current = mModel->currentIndex();
    auto* designs = new QTreeWidgetItem(mTree, {tr("Current designs")});
    for (int i = 0; i < CellCount && !mModel->isEmptyWorkbench(); ++i)
        if (mModel->cell(i)) addDesign(designs, current, i);
    auto* generations = new QTreeWidgetItem(mTree, {tr("Generations")});
    designs->setExpanded(!mCurrentDesignsFolded);
    generations->setExpanded(true);
    // The empty placeholder before the first designs is no generation.
    if (mModel->isEmptyWorkbench()) return;

    const auto& history = mModel->history();
    std::vector<std::vector<int>> children(history.size());
    std::vector<int> roots;
    for (std::size_t k = 0; k < history.size(); ++k) {
        const int parent = history[k].parent;
        (parent >= 0 ? children[std::size_t(parent)] : roots).push_back(int(k));
    }
    QTreeWidgetItem* currentItem = nullptr;
    const auto addGeneration = [&](QTreeWidgetItem* container, int k) {
        const Generation& g = history[std::size_t(k)];
        QStringList parents;
        for (int i : g.parentCells)
            parents << tr("design %1").arg(i + 1);
        auto* item =
            new QTreeWidgetItem(container, {tr("Generation %1").arg(mModel->generationLabel(k)),
                                            g.description, parents.join(QStringLiteral(", ")), QString()});
        item->setData(0, GenerationRole, k);
        for (const CellInfo& cell : g.info)
            if (cell.present) mGenerationItems.insert(thumbnailKey(cell), item);
        item->setIcon(0, mosaic(k));
        // Designs are added when the generation is first expanded.
        item->setChildIndicatorPolicy(QTreeWidgetItem::ShowIndicator);
        if (mExpandedGenerations.contains(k)) item->setExpanded(true);
        if (k == current) {
            currentItem = item;
            QFont f = item->font(0);
            f.setBold(true);
            QColor mark = mWindow->palette().color(QPalette::Highlight);
            mark.setAlpha(60);
            for (int c = 0; c < 4; ++c) {
                item->setFont(c, f);
                item->setBackground(c, mark);
            }
            item->setToolTip(0, tr("The current generation: its designs are in the grid"));
        }
    };
    // A branch's generations in order, each followed by the branches that grew from it, in
    // the order they were started; the generation's first child continues its branch.
    const auto addBranch = [&](auto& self, QTreeWidgetItem* container, int first) -> void {
        for (int k = first; k >= 0;) {
            addGeneration(container, k);
            int next = -1;
            for (int child : children[std::size_t(k)]) {
                if (history[std::size_t(child)].branch == history[std::size_t(k)].branch) {
                    next = child;
                    continue;
                }
                const int branch = history[std::size_t(child)].branch;
                auto* branchItem = new QTreeWidgetItem(
                    container,
                    {tr("Branch %1").arg(branch), tr("from generation %1").arg(mModel->generationLabel(k))});
                branchItem->setData(0, BranchRole, branch);
                self(self, branchItem, child);
                branchItem->setExpanded(!mCollapsedBranches.contains(branch));
            }
            k = next;
        }
    };
    for (int root : roots) {
        if (root == roots.front()) {
            addBranch(addBranch, generations, root);
            continue;
        }
        const int branch = history[std::size_t(root)].branch;
        auto* branchItem = new QTreeWidgetItem(generations, {tr("Branch %1").arg(branch), tr("a new start")});
        branchItem->setData(0, BranchRole, branch);
        addBranch(addBranch, branchItem, root);
        branchItem->setExpanded(!mCollapsedBranches.contains(branch));
    }
    if (currentItem) {
        for (QTreeWidgetItem* up = currentItem->parent(); up; up = up->parent())
            up->setExpanded(true);
        mTree->scrollToItem(currentItem);
    }
    mThumbnailTimer.start();
}

void LineagePanel::populateGeneration(QTreeWidgetItem* item) {
    if (item->childCount() > 0) return;
    const int generation = item->data(0, GenerationRole).toInt();
    if (generation < 0 || generation >= int(mModel->history().size())) return;
    // Read back when the generation is not in memory.
    const Generation& g = mModel->generation(generation);
    for (int i = 0; i < CellCount; ++i)
        if (g.cells[std::size_t(i)]) addDesign(item, generation, i);
}

void LineagePanel::addDesign(QTreeWidgetItem* parent, int generation, int cell) {
    const auto& design = mModel->generation(generation).cells[std::size_t(cell)];
    if (!design) return; // could not be read back (the model said why)
    const Genome& g = *design;
    const LineageInfo info = lineageOf(g);
    QStringList parents;
    for (const QString& p : info.parents)
        parents << p.left(8);
    auto* item =
        new QTreeWidgetItem(parent, {tr("Design %1: %2").arg(cell + 1).arg(info.displayName()), info.madeBy(),
                                     parents.join(QStringLiteral(", ")),
                                     info.op.isEmpty() ? QString() : QString::number(info.generation)});
    item->setToolTip(0, info.family.isEmpty() ? info.id : tr("%1\nFamily: %2").arg(info.id, info.family));
    item->setToolTip(1, info.change.isEmpty() ? QString() : tr("Changed: %1").arg(info.change));
    item->setToolTip(2, info.parents.join(QLatin1Char('\n')));
    item->setData(0, GenerationRole, generation);
    item->setData(0, CellRole, cell);
    const QString key = thumbnailKey(g);
    item->setIcon(0, icon(key));
    mDesignItems.insert(key, item);
}

QString LineagePanel::thumbnailKey(const CellInfo& info) const {
    return QString::fromStdString(info.contentId) + QLatin1Char('/') +
           (info.dimension == 3 ? mMesh() : QString());
}

QString LineagePanel::thumbnailKey(const Genome& genome) const {
    return QString::fromStdString(genomeId(genome)) + QLatin1Char('/') +
           (genome.dimension == 3 ? mMesh() : QString());
}

bool LineagePanel::hasThumbnail(const Genome& genome) const {
    return mThumbnails.contains(thumbnailKey(genome));
}

QPixmap LineagePanel::icon(const QString& key) const {
    if (const QImage* image = mThumbnails.object(key)) return QPixmap::fromImage(*image);
    QPixmap blank(IconSide, IconSide);
    blank.fill(mWindow->palette().color(QPalette::Mid));
    return blank;
}

QPixmap LineagePanel::mosaic(int generation) const {
    QPixmap mosaic(IconSide, IconSide);
    mosaic.fill(Qt::transparent);
    QPainter painter(&mosaic);
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    const int tile = (IconSide - 2) / 3;
    const auto& cells = mModel->history()[std::size_t(generation)].info;
    for (int i = 0; i < CellCount; ++i) {
        const CellInfo& cell = cells[std::size_t(i)];
        if (!cell.present) continue;
        const QRect rect((i % 3) * (tile + 1), (i / 3) * (tile + 1), tile, tile);
        if (const QImage* image = mThumbnails.object(thumbnailKey(cell)))
            painter.drawImage(rect, *image);
        else
            painter.fillRect(rect, mWindow->palette().color(QPalette::Mid));
    }
    return mosaic;
}

void LineagePanel::requestThumbnails() {
    if (!mTree->isVisible() || mModel->isEmptyWorkbench()) return;
    const int bottom = mTree->viewport()->height();
    const auto& history = mModel->history();
    // The rows in view, top to bottom (itemBelow skips what is folded away).
    for (QTreeWidgetItem* item = mTree->itemAt(QPoint(0, 0));
         item && mTree->visualItemRect(item).top() < bottom; item = mTree->itemBelow(item)) {
        const QVariant generation = item->data(0, GenerationRole);
        if (!generation.isValid()) continue;
        const int k = generation.toInt();
        const QVariant cell = item->data(0, CellRole);
        const auto wanted = [&](int i) { return !cell.isValid() || cell.toInt() == i; };
        // A generation not in memory is read back only when a thumbnail it shows is missing.
        const auto& info = history[std::size_t(k)].info;
        bool missing = false;
        for (int i = 0; i < CellCount; ++i)
            if (info[std::size_t(i)].present && wanted(i)) {
                const QString key = thumbnailKey(info[std::size_t(i)]);
                missing = missing || (!mPending.contains(key) && !mThumbnails.contains(key));
            }
        if (!missing) continue;
        const auto& cells = mModel->generation(k).cells;
        for (int i = 0; i < CellCount; ++i)
            if (cells[std::size_t(i)] && wanted(i)) requestThumbnail(*cells[std::size_t(i)]);
    }
}

void LineagePanel::requestThumbnail(const Genome& genome) {
    const QString key = thumbnailKey(genome);
    if (mPending.contains(key) || mThumbnails.contains(key)) return;
    RenderRequest request;
    request.genome = genome;
    request.size = QSize(IconSide, IconSide);
    request.mesh = mMesh();
    // A key of its own from the render service (after the grid's and the favourites', which
    // the queue renders first), so windows sharing the service never take each other's results.
    const std::uint64_t renderKey = mRenderer->newKey();
    mRequests.insert(renderKey, key);
    mPending.insert(key);
    mRenderer->request(renderKey, std::move(request));
}

void LineagePanel::onThumbnail(std::uint64_t key, const QImage& image) {
    const QString thumbnail = mRequests.take(key);
    mPending.remove(thumbnail);
    if (thumbnail.isEmpty()) return;
    // A failed render gets a dark blank, so it is not asked for again and again.
    QImage shown = image;
    if (shown.isNull()) {
        shown = QImage(IconSide, IconSide, QImage::Format_RGB888);
        shown.fill(mWindow->palette().color(QPalette::Dark));
    }
    mThumbnails.insert(thumbnail, new QImage(shown));
    const QPixmap shownIcon = icon(thumbnail);
    for (QTreeWidgetItem* item : mDesignItems.values(thumbnail))
        item->setIcon(0, shownIcon);
    for (QTreeWidgetItem* item : mGenerationItems.values(thumbnail))
        item->setIcon(0, mosaic(item->data(0, GenerationRole).toInt()));
}

void LineagePanel::selectDesign(int generation, int cell) {
    const auto& history = mModel->history();
    if (generation < 0 || generation >= int(history.size())) return;
    if (generation != mModel->currentIndex()) mModel->goTo(generation);
    mModel->setSelected(cell, true);
}

void LineagePanel::onDoubleClicked(QTreeWidgetItem* item) {
    mClickTimer.stop();
    const QVariant generation = item->data(0, GenerationRole);
    if (!generation.isValid()) return;
    const int index = generation.toInt();
    const QVariant cell = item->data(0, CellRole);
    // Changing the generation rebuilds the tree, which must not happen while the view is
    // still handling the double-click on one of its items.
    QTimer::singleShot(0, this, [this, index, cell] {
        if (!cell.isValid())
            mModel->goTo(index);
        else if (index == mModel->currentIndex())
            emit openDesignRequested(cell.toInt());
        else
            emit bringBackRequested(index, cell.toInt());
    });
}

} // namespace marbler::ui
