#pragma once
/// The workbench's kept sessions (SessionStore.h): File ▸ Sessions… (the SessionsDialog), File ▸
/// Resume session, switching to, renaming, deleting and restoring kept sessions, and telling the
/// user when the session being bred cannot be saved. Owns the two menu entries, the store's
/// folder and the dialog; the window resumes a session's designs (resumeSession).

#include <QObject>
#include <QPointer>
#include <QString>

class QAction;
class QMenu;

namespace marbler::ui {

class PopulationModel;
class SessionsDialog;
class WorkbenchWindow;

class SessionsController : public QObject {
    Q_OBJECT
public:
    /// Adds Sessions… and Resume session to `fileMenu` (disabled until setStore names a folder).
    SessionsController(WorkbenchWindow* window, PopulationModel* model, QMenu* fileMenu);

    QAction* sessionsAction() const { return mSessionsAction; }
    QMenu* recentMenu() const { return mRecent; }

    /// See the WorkbenchWindow functions of the same names.
    void setStore(const QString& sessionFolder);
    QString storeFolder() const { return mFolder; }
    QString currentId() const;
    /// File ▸ New session: a random population of the kind shown, in a session of its own; the
    /// current one stays kept. Returns false (reported) when none could be started.
    bool newSession();
    QAction* newSessionAction() const { return mNewSession; }
    bool resume(const QString& id);
    bool rename(const QString& id, const QString& name);
    QString remove(const QString& id);
    bool restoreDeleted(const QString& trashed);
    SessionsDialog* openDialog();

private:
    void fillRecent();

    WorkbenchWindow* mWindow;
    PopulationModel* mModel;
    QString mFolder;
    QAction* mSessionsAction = nullptr;
    QAction* mNewSession = nullptr;
    QMenu* mRecent = nullptr;
    QPointer<SessionsDialog> mDialog;
    bool mSaveFailureShown = false;
};

/// Reports a session file that does not load (once), moving it aside as `.bad` first.
void reportBadSession(QWidget* parent, const QString& file, const QString& what);

} // namespace marbler::ui
