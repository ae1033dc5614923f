// The editor's list of steps (StepList.h).

#include "editor/StepList.h"
#include "shared/Language.h"

#include <QAction>
#include <QComboBox>
#include <QDropEvent>
#include <QKeyEvent>
#include <QListWidget>
#include <QMenu>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace marbler::ui {
namespace {

/// "drops", "vortices", "stretches": a tool's name for a count of its steps.
QString plural(const QString& tool, std::size_t count) {
    if (count == 1) return registryText(tool.toStdString()); // issue 25: in the window's language
    if (tool == QStringLiteral("vortex")) return registryText("vortices");
    if (tool.endsWith(QLatin1Char('s')) || tool.endsWith(QLatin1Char('x')) ||
        tool.endsWith(QStringLiteral("ch")) || tool.endsWith(QStringLiteral("sh")))
        return registryText((tool + QStringLiteral("es")).toStdString());
    return registryText((tool + QStringLiteral("s")).toStdString());
}

} // namespace

/// A list whose drops move nothing themselves: a drop of a row asks the StepList to move it, and
/// the window answers with new rows (a move it refuses leaves the list as it was).
class StepListView : public QListWidget {
public:
    explicit StepListView(StepList* owner)
        : QListWidget(owner)
        , mOwner(owner) {
        setDragDropMode(QAbstractItemView::InternalMove);
        setDefaultDropAction(Qt::MoveAction);
        setSelectionMode(QAbstractItemView::SingleSelection);
        viewport()->setAcceptDrops(true);
    }

protected:
    /// → or + opens the current step's group, ← or - folds it.
    void keyPressEvent(QKeyEvent* event) override {
        const int key = event->key();
        const bool open = key == Qt::Key_Right || key == Qt::Key_Plus;
        const bool fold = key == Qt::Key_Left || key == Qt::Key_Minus;
        const int row = currentRow();
        if ((open || fold) && row >= 0 && mOwner->groupOf(std::size_t(row))) {
            mOwner->setGroupExpanded(std::size_t(row), open);
            event->accept();
            return;
        }
        QListWidget::keyPressEvent(event);
    }

    void dropEvent(QDropEvent* event) override {
        const int from = currentRow();
        QListWidgetItem* target = itemAt(event->position().toPoint());
        int to = target ? row(target) : count() - 1;
        // Take no Qt move: the item stays put until the window sets the rows again.
        event->setDropAction(Qt::IgnoreAction);
        event->accept();
        if (from < 0 || to < 0 || from == to) return;
        mOwner->requestMove(std::size_t(from), std::size_t(to));
    }

private:
    StepList* mOwner;
};

StepList::StepList(QWidget* parent)
    : QWidget(parent)
    , mList(new StepListView(this))
    , mFilter(new QComboBox(this)) {
    setObjectName(QStringLiteral("stepList"));
    mFilter->setObjectName(QStringLiteral("stepFilter"));
    mFilter->setToolTip(tr("Show the steps of one tool only"));
    mFilter->addItem(tr("All steps"), QString());
    mList->setObjectName(QStringLiteral("stepListView"));
    mList->setToolTip(
        tr("The steps of the design, first to last: the inks laid at the start, then the strokes. "
           "Drag a step to reorder; untick it to mute it; Ctrl+D duplicates, Del deletes, M mutes. "
           "A run of steps of one tool is one row: double-click it or press → to open it, ← to fold it."));
    mList->setContextMenuPolicy(Qt::CustomContextMenu);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(mFilter);
    layout->addWidget(mList);

    auto* duplicate = new QAction(tr("&Duplicate step"), this);
    duplicate->setObjectName(QStringLiteral("duplicateStepAction"));
    duplicate->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    duplicate->setToolTip(tr("Add a copy of the selected step after it (Ctrl+D)"));
    auto* remove = new QAction(tr("De&lete step"), this);
    remove->setObjectName(QStringLiteral("deleteStepAction"));
    remove->setShortcut(QKeySequence(Qt::Key_Delete));
    remove->setToolTip(tr("Delete the selected step (Del)"));
    auto* mute = new QAction(tr("&Mute step"), this);
    mute->setObjectName(QStringLiteral("muteStepAction"));
    mute->setShortcut(QKeySequence(Qt::Key_M));
    mute->setToolTip(tr("Leave the selected step out of the design, or put it back (M)"));
    for (QAction* action : {duplicate, remove, mute}) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        addAction(action);
    }
    connect(duplicate, &QAction::triggered, this, [this] {
        if (auto row = current()) emit duplicateRequested(*row);
    });
    connect(remove, &QAction::triggered, this, [this] {
        if (auto row = current()) emit deleteRequested(*row);
    });
    connect(mute, &QAction::triggered, this, &StepList::toggleMuteOfCurrent);

    connect(mList, &QListWidget::currentRowChanged, this, [this](int row) {
        if (mUpdating) return;
        emit currentChanged(row < 0 ? std::nullopt : std::optional<std::size_t>(row));
    });
    connect(mList, &QListWidget::itemChanged, this, [this](QListWidgetItem* item) {
        if (mUpdating) return;
        const auto row = std::size_t(mList->row(item));
        const bool muted = item->checkState() != Qt::Checked;
        const Group* group = groupOf(row);
        if (group && !isGroupExpanded(row)) {
            // A folded group's box stands for all its steps.
            emit rangeMutedToggled(group->first, std::min(group->last, mRows.size() - 1), muted);
            return;
        }
        emit mutedToggled(row, muted);
    });
    connect(mList, &QListWidget::itemDoubleClicked, this, [this](QListWidgetItem* item) {
        const auto row = std::size_t(mList->row(item));
        if (isGroupHead(row)) setGroupExpanded(row, !isGroupExpanded(row));
    });
    connect(mFilter, &QComboBox::currentIndexChanged, this, [this] {
        if (mUpdating) return;
        updateVisibility();
        scrollToCurrent();
    });
    connect(mList, &QWidget::customContextMenuRequested, this, &StepList::showMenu);
}

void StepList::setRows(const std::vector<StepRow>& rows) {
    const std::optional<std::size_t> keep = current();
    mRows = rows;
    mGroups.clear();
    for (std::size_t i = 0; i < rows.size();) {
        std::size_t last = i;
        while (!rows[i].tool.isEmpty() && last + 1 < rows.size() && rows[last + 1].tool == rows[i].tool &&
               rows[last + 1].initial == rows[i].initial)
            ++last;
        if (last - i + 1 >= MinGroupSize) mGroups.push_back(Group{i, last});
        i = last + 1;
    }
    // Groups stay open where one still starts.
    std::erase_if(mExpanded, [this](std::size_t first) { return !isGroupHead(first); });
    mUpdating = true;
    mList->clear();
    for (std::size_t i = 0; i < rows.size(); ++i) {
        auto* item = new QListWidgetItem(mList);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable |
                       Qt::ItemIsDragEnabled);
    }
    fillFilter();
    updateTexts();
    updateVisibility();
    if (keep && *keep < rows.size()) mList->setCurrentRow(int(*keep));
    mUpdating = false;
}

const StepList::Group* StepList::groupOf(std::size_t row) const {
    auto it = std::find_if(mGroups.begin(), mGroups.end(),
                           [row](const Group& g) { return row >= g.first && row <= g.last; });
    return it == mGroups.end() ? nullptr : &*it;
}

bool StepList::isGroupHead(std::size_t row) const {
    const Group* group = groupOf(row);
    return group && group->first == row;
}

bool StepList::isGroupExpanded(std::size_t row) const {
    const Group* group = groupOf(row);
    return group && std::find(mExpanded.begin(), mExpanded.end(), group->first) != mExpanded.end();
}

bool StepList::isRowShown(std::size_t row) const {
    return row < rowCount() && !mList->item(int(row))->isHidden();
}

void StepList::setGroupExpanded(std::size_t row, bool expanded) {
    const Group* group = groupOf(row);
    if (!group || isGroupExpanded(row) == expanded) return;
    const Group g = *group;
    if (expanded)
        mExpanded.push_back(g.first);
    else
        std::erase(mExpanded, g.first);
    const bool was = mUpdating;
    mUpdating = true;
    updateTexts();
    updateVisibility();
    mUpdating = was;
    // A step folded away leaves the group's row selected: it stands for them all.
    if (!expanded) {
        if (auto at = current(); at && *at > g.first && *at <= g.last) mList->setCurrentRow(int(g.first));
    }
    scrollToCurrent();
}

void StepList::setFilter(const QString& tool) {
    const int index = mFilter->findData(tool);
    mFilter->setCurrentIndex(std::max(index, 0));
}

void StepList::fillFilter() {
    const QString chosen = mFilter->currentData().toString();
    std::vector<std::pair<QString, std::size_t>> tools; // in order of first appearance
    for (const StepRow& r : mRows) {
        if (r.tool.isEmpty()) continue;
        auto it = std::find_if(tools.begin(), tools.end(), [&r](const auto& t) { return t.first == r.tool; });
        if (it == tools.end())
            tools.emplace_back(r.tool, 1);
        else
            ++it->second;
    }
    const bool was = mUpdating;
    mUpdating = true;
    while (mFilter->count() > 1)
        mFilter->removeItem(1);
    for (const auto& [tool, count] : tools)
        mFilter->addItem(tr("%1 (%2)").arg(plural(tool, 2)).arg(count), tool);
    // The chosen tool stays chosen while the design has any of its steps.
    mFilter->setCurrentIndex(std::max(mFilter->findData(chosen), 0));
    mFilter->setVisible(!tools.empty());
    mUpdating = was;
}

void StepList::updateTexts() {
    const bool was = mUpdating;
    mUpdating = true;
    for (std::size_t i = 0; i < mRows.size(); ++i) {
        const StepRow& r = mRows[i];
        QListWidgetItem* item = mList->item(int(i));
        const Group* group = groupOf(i);
        const bool folded = group && group->first == i && !isGroupExpanded(i);
        QString text = QStringLiteral("%1. %2").arg(i + 1).arg(r.name);
        QString tip =
            r.initial ? tr("Step %1: an ink laid at the start").arg(i + 1) : tr("Step %1").arg(i + 1);
        if (!r.detail.isEmpty()) tip += QStringLiteral("\n") + r.detail;
        bool muted = r.muted;
        Qt::CheckState check = r.muted ? Qt::Unchecked : Qt::Checked;
        if (folded) {
            const std::size_t count = group->last - group->first + 1;
            text = QStringLiteral("▸ ") + tr("%1 %2 (steps %3–%4)")
                                              .arg(count)
                                              .arg(plural(r.tool, count))
                                              .arg(group->first + 1)
                                              .arg(group->last + 1);
            std::size_t mutedCount = 0;
            for (std::size_t k = group->first; k <= group->last; ++k)
                mutedCount += mRows[k].muted ? 1 : 0;
            muted = mutedCount == count;
            check = mutedCount == 0 ? Qt::Checked : muted ? Qt::Unchecked : Qt::PartiallyChecked;
            tip = tr("Steps %1–%2: %3 %4, shown as one row (double-click or press → to see them); "
                     "selecting it selects step %1, its box mutes them all")
                      .arg(group->first + 1)
                      .arg(group->last + 1)
                      .arg(count)
                      .arg(plural(r.tool, count));
        } else if (group && group->first == i) {
            text = QStringLiteral("▾ ") + text;
            tip += QStringLiteral("\n") + tr("The first of %1 %2 (double-click or press ← to fold them)")
                                              .arg(group->last - group->first + 1)
                                              .arg(plural(r.tool, group->last - group->first + 1));
        } else if (group) {
            text = QStringLiteral("      ") + text;
        }
        if (muted) tip += QStringLiteral("\n") + tr("Muted: left out of the design (tick to put it back)");
        item->setText(text);
        item->setCheckState(check);
        QFont font = item->font();
        font.setItalic(r.initial);
        font.setStrikeOut(muted);
        item->setFont(font);
        item->setToolTip(tip);
    }
    mUpdating = was;
}

void StepList::updateVisibility() {
    const QString tool = mFilter->currentData().toString();
    for (std::size_t i = 0; i < mRows.size(); ++i) {
        bool shown = tool.isEmpty() || mRows[i].tool == tool;
        if (const Group* group = groupOf(i); group && group->first != i && !isGroupExpanded(i)) shown = false;
        mList->item(int(i))->setHidden(!shown);
    }
}

std::size_t StepList::rowCount() const {
    return std::size_t(mList->count());
}

void StepList::scrollToCurrent() {
    if (QListWidgetItem* item = mList->currentItem())
        mList->scrollToItem(item, QAbstractItemView::PositionAtCenter);
}

void StepList::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // Only when the row would be hidden: a resize does not move a list the user scrolled about.
    QTimer::singleShot(0, this, [this] {
        if (QListWidgetItem* item = mList->currentItem())
            mList->scrollToItem(item, QAbstractItemView::EnsureVisible);
    });
}

void StepList::setCurrent(std::optional<std::size_t> row) {
    mUpdating = true;
    if (row && *row < rowCount()) {
        // The step is shown: its group opened, the filter cleared if it hides the step.
        if (!isGroupHead(*row)) setGroupExpanded(*row, true);
        if (!isRowShown(*row)) {
            setFilter(QString());
            updateVisibility();
        }
        mList->setCurrentRow(int(*row));
        scrollToCurrent();
    } else {
        mList->setCurrentRow(-1);
        mList->clearSelection();
    }
    mUpdating = false;
}

std::optional<std::size_t> StepList::current() const {
    const int row = mList->currentRow();
    if (row < 0) return std::nullopt;
    return std::size_t(row);
}

QListWidget* StepList::list() const {
    return mList;
}

void StepList::requestMove(std::size_t from, std::size_t to) {
    if (from >= rowCount() || to >= rowCount() || from == to) return;
    emit moveRequested(from, to);
}

void StepList::toggleMuteOfCurrent() {
    const auto row = current();
    if (!row) return;
    QListWidgetItem* item = mList->item(int(*row));
    // itemChanged emits mutedToggled.
    item->setCheckState(item->checkState() == Qt::Checked ? Qt::Unchecked : Qt::Checked);
}

void StepList::showMenu(const QPoint& pos) {
    if (QListWidgetItem* item = mList->itemAt(pos)) mList->setCurrentItem(item);
    if (!current()) return;
    QMenu menu(this);
    for (QAction* action : actions())
        menu.addAction(action);
    const std::size_t row = *current();
    if (groupOf(row)) {
        menu.addSeparator();
        const bool open = isGroupExpanded(row);
        menu.addAction(open ? tr("&Fold the group (←)") : tr("&Open the group (→)"), this,
                       [this, row, open] { setGroupExpanded(row, !open); });
    }
    menu.exec(mList->viewport()->mapToGlobal(pos));
}

} // namespace marbler::ui

// The moc output here, not in marbler_ui's mocs_compilation: a test of the panels links only them.
#include "moc_StepList.cpp"
