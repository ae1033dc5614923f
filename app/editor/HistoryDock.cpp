// The editor's History panel (HistoryDock.h).

#include "editor/HistoryDock.h"

#include "editor/EditorDocument.h"

#include <QLabel>
#include <QListWidget>
#include <QUndoView>
#include <QVBoxLayout>

namespace marbler::ui {

HistoryDock::HistoryDock(EditorDocument* document, QWidget* parent)
    : QDockWidget(tr("History"), parent)
    , mDocument(document) {
    setObjectName(QStringLiteral("historyDock"));
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
        emit message(tr("Switched to another branch of the history"), 4000);
    });
    setWidget(historyPanel);
    connect(mDocument, &EditorDocument::branchesChanged, this, &HistoryDock::fillBranchList);
    connect(mDocument->undoStack(), &QUndoStack::indexChanged, this, &HistoryDock::fillBranchList);
    fillBranchList();
}

void HistoryDock::fillBranchList() {
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

} // namespace marbler::ui
