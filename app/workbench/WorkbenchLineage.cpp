// The workbench window's lineage dock: the generation tree with thumbnails of its designs
// (WorkbenchWindow.h declares these members; the rest of the window is in WorkbenchWindow.cpp).
#include "workbench/WorkbenchWindow.h"

#include "marbler/GenomeIO.h"
#include "shared/RenderService.h"

#include <QComboBox>
#include <QFont>
#include <QPainter>
#include <QStatusBar>
#include <QTreeWidget>

#include <algorithm>

namespace marbler::ui {

namespace {

/// Lineage thumbnails get keys of their own, unique in the process, so windows sharing one
/// render service never take each other's results.
std::uint64_t nextLineageKey() {
    static std::uint64_t next = WorkbenchWindow::LineageKeyBase;
    return next++;
}

} // namespace

void WorkbenchWindow::updateLineage() {
    mLineageDesignItems.clear();
    mLineageGenerationItems.clear();
    mLineageTree->clear();
    const int current = mModel->currentIndex();
    auto* designs = new QTreeWidgetItem(mLineageTree, {tr("Current designs")});
    for (int i = 0; i < CellCount && !mModel->isEmptyWorkbench(); ++i)
        if (mModel->cell(i)) addLineageDesign(designs, current, i);
    auto* generations = new QTreeWidgetItem(mLineageTree, {tr("Generations")});
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
        item->setData(0, LineageGenerationRole, k);
        for (const auto& cell : g.cells)
            if (cell) mLineageGenerationItems.insert(lineageThumbnailKey(*cell), item);
        item->setIcon(0, lineageMosaic(k));
        // Designs are added when the generation is first expanded.
        item->setChildIndicatorPolicy(QTreeWidgetItem::ShowIndicator);
        if (mExpandedGenerations.contains(k)) item->setExpanded(true);
        if (k == current) {
            currentItem = item;
            QFont f = item->font(0);
            f.setBold(true);
            QColor mark = palette().color(QPalette::Highlight);
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
                branchItem->setData(0, LineageBranchRole, branch);
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
        branchItem->setData(0, LineageBranchRole, branch);
        addBranch(addBranch, branchItem, root);
        branchItem->setExpanded(!mCollapsedBranches.contains(branch));
    }
    if (currentItem) {
        for (QTreeWidgetItem* up = currentItem->parent(); up; up = up->parent())
            up->setExpanded(true);
        mLineageTree->scrollToItem(currentItem);
    }
    mLineageThumbnailTimer.start();
}

void WorkbenchWindow::populateLineageGeneration(QTreeWidgetItem* item) {
    if (item->childCount() > 0) return;
    const int generation = item->data(0, LineageGenerationRole).toInt();
    const auto& history = mModel->history();
    if (generation < 0 || generation >= int(history.size())) return;
    for (int i = 0; i < CellCount; ++i)
        if (history[std::size_t(generation)].cells[std::size_t(i)]) addLineageDesign(item, generation, i);
}

void WorkbenchWindow::addLineageDesign(QTreeWidgetItem* parent, int generation, int cell) {
    const Genome& g = *mModel->history()[std::size_t(generation)].cells[std::size_t(cell)];
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
    item->setData(0, LineageGenerationRole, generation);
    item->setData(0, LineageCellRole, cell);
    const QString key = lineageThumbnailKey(g);
    item->setIcon(0, lineageIcon(key));
    mLineageDesignItems.insert(key, item);
}

QString WorkbenchWindow::lineageThumbnailKey(const Genome& genome) const {
    return QString::fromStdString(genomeId(genome)) + QLatin1Char('/') +
           (genome.dimension == 3 ? mMesh->currentText() : QString());
}

bool WorkbenchWindow::hasLineageThumbnail(const Genome& genome) const {
    return mLineageThumbnails.contains(lineageThumbnailKey(genome));
}

QPixmap WorkbenchWindow::lineageIcon(const QString& key) const {
    if (const QImage* image = mLineageThumbnails.object(key)) return QPixmap::fromImage(*image);
    QPixmap blank(LineageIconSide, LineageIconSide);
    blank.fill(palette().color(QPalette::Mid));
    return blank;
}

QPixmap WorkbenchWindow::lineageMosaic(int generation) const {
    QPixmap mosaic(LineageIconSide, LineageIconSide);
    mosaic.fill(Qt::transparent);
    QPainter painter(&mosaic);
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    const int tile = (LineageIconSide - 2) / 3;
    const auto& cells = mModel->history()[std::size_t(generation)].cells;
    for (int i = 0; i < CellCount; ++i) {
        const auto& cell = cells[std::size_t(i)];
        if (!cell) continue;
        const QRect rect((i % 3) * (tile + 1), (i / 3) * (tile + 1), tile, tile);
        if (const QImage* image = mLineageThumbnails.object(lineageThumbnailKey(*cell)))
            painter.drawImage(rect, *image);
        else
            painter.fillRect(rect, palette().color(QPalette::Mid));
    }
    return mosaic;
}

void WorkbenchWindow::requestLineageThumbnails() {
    if (!mLineageTree->isVisible() || mModel->isEmptyWorkbench()) return;
    const int bottom = mLineageTree->viewport()->height();
    const auto& history = mModel->history();
    // The rows in view, top to bottom (itemBelow skips what is folded away).
    for (QTreeWidgetItem* item = mLineageTree->itemAt(QPoint(0, 0));
         item && mLineageTree->visualItemRect(item).top() < bottom; item = mLineageTree->itemBelow(item)) {
        const QVariant generation = item->data(0, LineageGenerationRole);
        if (!generation.isValid()) continue;
        const auto& cells = history[std::size_t(generation.toInt())].cells;
        const QVariant cell = item->data(0, LineageCellRole);
        for (int i = 0; i < CellCount; ++i)
            if (cells[std::size_t(i)] && (!cell.isValid() || cell.toInt() == i))
                requestLineageThumbnail(*cells[std::size_t(i)]);
    }
}

void WorkbenchWindow::requestLineageThumbnail(const Genome& genome) {
    const QString key = lineageThumbnailKey(genome);
    if (mLineagePending.contains(key) || mLineageThumbnails.contains(key)) return;
    RenderRequest request;
    request.genome = genome;
    request.size = QSize(LineageIconSide, LineageIconSide);
    request.mesh = mMesh->currentText();
    const std::uint64_t renderKey = nextLineageKey();
    mLineageRequests.insert(renderKey, key);
    mLineagePending.insert(key);
    mRenderer->request(renderKey, std::move(request));
}

void WorkbenchWindow::onLineageThumbnail(std::uint64_t key, const QImage& image) {
    const QString thumbnail = mLineageRequests.take(key);
    mLineagePending.remove(thumbnail);
    if (thumbnail.isEmpty()) return;
    // A failed render gets a dark blank, so it is not asked for again and again.
    QImage shown = image;
    if (shown.isNull()) {
        shown = QImage(LineageIconSide, LineageIconSide, QImage::Format_RGB888);
        shown.fill(palette().color(QPalette::Dark));
    }
    mLineageThumbnails.insert(thumbnail, new QImage(shown));
    const QPixmap icon = lineageIcon(thumbnail);
    for (QTreeWidgetItem* item : mLineageDesignItems.values(thumbnail))
        item->setIcon(0, icon);
    for (QTreeWidgetItem* item : mLineageGenerationItems.values(thumbnail))
        item->setIcon(0, lineageMosaic(item->data(0, LineageGenerationRole).toInt()));
}

void WorkbenchWindow::selectLineageDesign(int generation, int cell) {
    const auto& history = mModel->history();
    if (generation < 0 || generation >= int(history.size())) return;
    if (generation != mModel->currentIndex()) mModel->goTo(generation);
    mModel->setSelected(cell, true);
}

void WorkbenchWindow::onLineageDoubleClicked(QTreeWidgetItem* item) {
    mLineageClickTimer.stop();
    const QVariant generation = item->data(0, LineageGenerationRole);
    if (!generation.isValid()) return;
    const int index = generation.toInt();
    const QVariant cell = item->data(0, LineageCellRole);
    // Changing the generation rebuilds the tree, which must not happen while the view is
    // still handling the double-click on one of its items.
    QTimer::singleShot(0, this, [this, index, cell] {
        if (!cell.isValid())
            mModel->goTo(index);
        else if (index == mModel->currentIndex())
            openDesign(cell.toInt());
        else
            bringBackDesign(index, cell.toInt());
    });
}

void WorkbenchWindow::bringBackDesign(int generation, int cell) {
    const auto& history = mModel->history();
    if (generation < 0 || generation >= int(history.size()) || cell < 0 || cell >= CellCount) return;
    const auto& design = history[std::size_t(generation)].cells[std::size_t(cell)];
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

} // namespace marbler::ui
