// The editor's list of steps (StepList.h).

#include "editor/StepList.h"

#include <QAction>
#include <QDropEvent>
#include <QListWidget>
#include <QMenu>
#include <QTimer>
#include <QVBoxLayout>

namespace marbler::ui {

/// A list whose drops move nothing themselves: a drop of a row asks the StepList to move it, and
/// the window answers with new rows (a move it refuses leaves the list as it was).
class StepListView : public QListWidget {
public:
    explicit StepListView(StepList* owner) : QListWidget(owner), mOwner(owner) {
        setDragDropMode(QAbstractItemView::InternalMove);
        setDefaultDropAction(Qt::MoveAction);
        setSelectionMode(QAbstractItemView::SingleSelection);
        viewport()->setAcceptDrops(true);
    }

protected:
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

StepList::StepList(QWidget* parent) : QWidget(parent), mList(new StepListView(this)) {
    setObjectName(QStringLiteral("stepList"));
    mList->setObjectName(QStringLiteral("stepListView"));
    mList->setToolTip(tr("The steps of the design, first to last: the inks laid at the start, then the strokes. "
                         "Drag a step to reorder; untick it to mute it; Ctrl+D duplicates, Del deletes, M mutes."));
    mList->setContextMenuPolicy(Qt::CustomContextMenu);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
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
        emit mutedToggled(std::size_t(mList->row(item)), item->checkState() != Qt::Checked);
    });
    connect(mList, &QWidget::customContextMenuRequested, this, &StepList::showMenu);
}

void StepList::setRows(const std::vector<StepRow>& rows) {
    const std::optional<std::size_t> keep = current();
    mUpdating = true;
    mList->clear();
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const StepRow& r = rows[i];
        auto* item = new QListWidgetItem(QStringLiteral("%1. %2").arg(i + 1).arg(r.name), mList);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable | Qt::ItemIsDragEnabled);
        item->setCheckState(r.muted ? Qt::Unchecked : Qt::Checked);
        QFont font = item->font();
        font.setItalic(r.initial);
        font.setStrikeOut(r.muted);
        item->setFont(font);
        QString tip = r.initial ? tr("Step %1: an ink laid at the start").arg(i + 1) : tr("Step %1").arg(i + 1);
        if (!r.detail.isEmpty()) tip += QStringLiteral("\n") + r.detail;
        if (r.muted) tip += QStringLiteral("\n") + tr("Muted: left out of the design (tick to put it back)");
        item->setToolTip(tip);
    }
    if (keep && *keep < rows.size()) mList->setCurrentRow(int(*keep));
    mUpdating = false;
}

std::size_t StepList::rowCount() const { return std::size_t(mList->count()); }

void StepList::scrollToCurrent() {
    if (QListWidgetItem* item = mList->currentItem()) mList->scrollToItem(item, QAbstractItemView::PositionAtCenter);
}

void StepList::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // Only when the row would be hidden: a resize does not move a list the user scrolled about.
    QTimer::singleShot(0, this, [this] {
        if (QListWidgetItem* item = mList->currentItem()) mList->scrollToItem(item, QAbstractItemView::EnsureVisible);
    });
}

void StepList::setCurrent(std::optional<std::size_t> row) {
    mUpdating = true;
    if (row && *row < rowCount()) {
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

QListWidget* StepList::list() const { return mList; }

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
    for (QAction* action : actions()) menu.addAction(action);
    menu.exec(mList->viewport()->mapToGlobal(pos));
}

} // namespace marbler::ui

// The moc output here, not in marbler_ui's mocs_compilation: a test of the panels links only them.
#include "moc_StepList.cpp"
