#pragma once
/// File ▸ Sessions: every kept breeding session (SessionStore.h), the most recently changed
/// first, with its name, generation, kind and dates. Resume one (double-click), rename one (edit
/// its name in place, F2), delete one (into the trash; Undo brings it back while the dialog is
/// open, and the trash keeps it 30 days). The session being bred can be renamed, not deleted.

#include <QDialog>
#include <QStringList>

class QLabel;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace marbler::ui {

class WorkbenchWindow;

class SessionsDialog : public QDialog {
    Q_OBJECT
public:
    explicit SessionsDialog(WorkbenchWindow* window);

    /// Reads the store again.
    void refresh();
    /// Makes a session the selected one; false when it is not listed.
    bool select(const QString& id);
    /// The selected session's id (empty: none).
    QString selectedId() const;

    QTreeWidget* list() const { return mList; }
    QPushButton* resumeButton() const { return mResume; }
    QPushButton* deleteButton() const { return mDelete; }
    QPushButton* undoDeleteButton() const { return mUndoDelete; }
    QLabel* messageLabel() const { return mMessage; }

private:
    void updateButtons();
    void onItemChanged(QTreeWidgetItem* item, int column);

    WorkbenchWindow* mWindow;
    QTreeWidget* mList;
    QPushButton* mResume;
    QPushButton* mRename;
    QPushButton* mDelete;
    QPushButton* mUndoDelete;
    QLabel* mMessage;
    QStringList mDeleted; ///< trashed files, the last deleted last
    bool mFilling = false;
};

} // namespace marbler::ui
