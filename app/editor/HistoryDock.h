#pragma once
/// The editor's History panel: every edit of the document (a QUndoView on its undo stack; a
/// click goes back or forward to one) and the other branches of the history, edits undone and
/// then left by making another, one click away (EditorDocument::branches).

#include <QDockWidget>

class QLabel;
class QListWidget;
class QUndoView;

namespace marbler::ui {

class EditorDocument;

class HistoryDock : public QDockWidget {
    Q_OBJECT
public:
    HistoryDock(EditorDocument* document, QWidget* parent = nullptr);

    QUndoView* historyView() const { return mHistory; }
    QListWidget* branchList() const { return mBranchList; }

signals:
    /// A line for the window's status bar, shown for `ms` milliseconds.
    void message(const QString& text, int ms);

private:
    /// Lists the document's branches; the list and its label hide when there are none.
    void fillBranchList();

    EditorDocument* mDocument;
    QUndoView* mHistory;
    QListWidget* mBranchList;
    QLabel* mBranchLabel;
};

} // namespace marbler::ui
