#include "workbench/SessionsDialog.h"

#include "workbench/SessionStore.h"
#include "workbench/WorkbenchWindow.h"

#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace marbler::ui {

namespace {

constexpr int IdRole = Qt::UserRole;

} // namespace

SessionsDialog::SessionsDialog(WorkbenchWindow* window)
    : QDialog(window)
    , mWindow(window) {
    setWindowTitle(tr("Marbler — sessions"));
    auto* intro =
        new QLabel(tr("Every breeding session is kept, however Marbler was started. Resume one to go on "
                      "where it was left; the one being bred stays kept."),
                   this);
    intro->setWordWrap(true);

    mList = new QTreeWidget(this);
    mList->setColumnCount(2);
    mList->setHeaderLabels({tr("Name"), tr("Session")});
    mList->setRootIsDecorated(false);
    // Names in full; the details (generation, kind, last change) take the rest.
    mList->header()->setStretchLastSection(true);
    mList->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    // Double-click resumes, so a name is edited with F2, a slow second click or Rename.
    mList->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::SelectedClicked);
    mList->setMinimumSize(640, 220);

    mResume = new QPushButton(tr("&Resume"), this);
    mRename = new QPushButton(tr("Re&name"), this);
    mDelete = new QPushButton(tr("&Delete"), this);
    mUndoDelete = new QPushButton(tr("&Undo delete"), this);
    mMessage = new QLabel(this);
    mMessage->setWordWrap(true);
    auto* close = new QDialogButtonBox(QDialogButtonBox::Close, this);

    connect(mList, &QTreeWidget::itemSelectionChanged, this, &SessionsDialog::updateButtons);
    connect(mList, &QTreeWidget::itemChanged, this, &SessionsDialog::onItemChanged);
    connect(mList, &QTreeWidget::itemDoubleClicked, this, [this] { mResume->click(); });
    connect(mResume, &QPushButton::clicked, this, [this] {
        const QString id = selectedId();
        if (id.isEmpty() || id == mWindow->currentSessionId()) return;
        if (mWindow->resumeKeptSession(id)) {
            accept();
            return;
        }
        refresh(); // a session that did not load is moved aside
    });
    connect(mRename, &QPushButton::clicked, this, [this] {
        if (QTreeWidgetItem* item = mList->currentItem()) mList->editItem(item, 0);
    });
    connect(mDelete, &QPushButton::clicked, this, [this] {
        const QTreeWidgetItem* item = mList->currentItem();
        if (!item) return;
        const QString name = item->text(0);
        const QString trashed = mWindow->deleteSession(selectedId());
        if (trashed.isEmpty()) return;
        mDeleted << trashed;
        mMessage->setText(tr("Deleted “%1”. Undo delete brings it back.").arg(name));
        refresh();
    });
    connect(mUndoDelete, &QPushButton::clicked, this, [this] {
        if (mDeleted.isEmpty()) return;
        const QString trashed = mDeleted.takeLast();
        if (mWindow->restoreDeletedSession(trashed)) mMessage->setText(tr("The session is back."));
        refresh();
    });
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* buttons = new QHBoxLayout;
    for (QPushButton* b : {mResume, mRename, mDelete, mUndoDelete})
        buttons->addWidget(b);
    buttons->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(mList, 1);
    layout->addLayout(buttons);
    layout->addWidget(mMessage);
    layout->addWidget(close);
    refresh();
}

void SessionsDialog::refresh() {
    const QString keep = selectedId();
    const QString current = mWindow->currentSessionId();
    mFilling = true;
    mList->clear();
    for (const KeptSession& session : SessionStore(mWindow->sessionStoreFolder()).list()) {
        const bool isCurrent = session.id == current;
        QString details = describeSession(session);
        if (isCurrent) details = tr("being bred now — %1").arg(details);
        auto* item = new QTreeWidgetItem(mList, {session.name, details});
        item->setData(0, IdRole, session.id);
        item->setFlags(item->flags() | Qt::ItemIsEditable);
        item->setToolTip(0, session.file);
        if (isCurrent) {
            QFont bold = item->font(0);
            bold.setBold(true);
            item->setFont(0, bold);
            item->setFont(1, bold);
        }
    }
    mFilling = false;
    if (!select(keep) && mList->topLevelItemCount() > 0) mList->setCurrentItem(mList->topLevelItem(0));
    updateButtons();
}

bool SessionsDialog::select(const QString& id) {
    for (int i = 0; i < mList->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = mList->topLevelItem(i);
        if (!id.isEmpty() && item->data(0, IdRole).toString() == id) {
            mList->setCurrentItem(item);
            return true;
        }
    }
    return false;
}

QString SessionsDialog::selectedId() const {
    const QTreeWidgetItem* item = mList->currentItem();
    return item ? item->data(0, IdRole).toString() : QString();
}

void SessionsDialog::updateButtons() {
    const QString id = selectedId();
    const bool isCurrent = !id.isEmpty() && id == mWindow->currentSessionId();
    mResume->setEnabled(!id.isEmpty() && !isCurrent);
    mRename->setEnabled(!id.isEmpty());
    mDelete->setEnabled(!id.isEmpty() && !isCurrent);
    mDelete->setToolTip(isCurrent ? tr("The session being bred cannot be deleted; resume another one first")
                                  : tr("Moves the session to the trash; Undo delete brings it back"));
    mUndoDelete->setEnabled(!mDeleted.isEmpty());
}

void SessionsDialog::onItemChanged(QTreeWidgetItem* item, int column) {
    if (mFilling || column != 0) return;
    mWindow->renameSession(item->data(0, IdRole).toString(), item->text(0));
    // Shows the name kept (an empty one is refused); later, as the item is still being edited.
    QMetaObject::invokeMethod(this, &SessionsDialog::refresh, Qt::QueuedConnection);
}

} // namespace marbler::ui
