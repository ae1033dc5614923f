// The workbench window's kept sessions: File ▸ Sessions and the recent-sessions menu
// (WorkbenchWindow.h declares these members; the rest of the window is in WorkbenchWindow.cpp).
#include "workbench/WorkbenchWindow.h"

#include "shared/ErrorReport.h"
#include "workbench/SessionStore.h"
#include "workbench/SessionsDialog.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QStatusBar>

namespace marbler::ui {

void WorkbenchWindow::setSessionStore(const QString& sessionFolder) {
    mSessionFolder = sessionFolder;
    mSessionsAction->setEnabled(!sessionFolder.isEmpty());
    mRecentSessions->setEnabled(!sessionFolder.isEmpty());
}

QString WorkbenchWindow::currentSessionId() const {
    const QString file = mModel->sessionFile();
    return file.isEmpty() ? QString() : QFileInfo(file).completeBaseName();
}

void WorkbenchWindow::fillRecentSessions() {
    mRecentSessions->clear();
    if (mSessionFolder.isEmpty()) return;
    const QString current = currentSessionId();
    int shown = 0;
    for (const KeptSession& session : SessionStore(mSessionFolder).list()) {
        if (session.id == current) continue;
        if (++shown > 9) break;
        QAction* action = mRecentSessions->addAction(
            QStringLiteral("&%1 %2 — %3").arg(shown).arg(session.name, describeSession(session)), this,
            [this, id = session.id] { resumeKeptSession(id); });
        action->setData(session.id);
    }
    if (shown == 0) mRecentSessions->addAction(tr("No other sessions"))->setEnabled(false);
    mRecentSessions->addSeparator();
    mRecentSessions->addAction(mSessionsAction);
}

bool WorkbenchWindow::resumeKeptSession(const QString& id) {
    if (mSessionFolder.isEmpty() || id.isEmpty() || id == currentSessionId()) return false;
    const std::optional<KeptSession> kept = SessionStore(mSessionFolder).find(id);
    if (!kept) {
        reportError(this, tr("Cannot resume the session"),
                    tr("There is no kept session %1 any more.").arg(id));
        return false;
    }
    SavedSession saved;
    try {
        saved = loadSession(kept->file);
    } catch (const std::exception& e) {
        reportBadSession(this, kept->file, QString::fromStdString(e.what()));
        return false;
    }
    // The current session was saved with its last change, so switching loses nothing; no file
    // is set while the other one comes in, so nothing is written over either.
    const QString previous = mModel->sessionLabel().name;
    mModel->setSessionFile({});
    resumeSession(std::move(saved));
    mModel->setSessionFile(kept->file);
    statusBar()->showMessage(previous.isEmpty()
                                 ? tr("Resumed “%1” at generation %2")
                                       .arg(kept->name)
                                       .arg(mModel->generationLabel(mModel->currentIndex()))
                                 : tr("Resumed “%1” at generation %2; “%3” is kept under File ▸ Sessions")
                                       .arg(kept->name)
                                       .arg(mModel->generationLabel(mModel->currentIndex()))
                                       .arg(previous),
                             15000);
    return true;
}

bool WorkbenchWindow::renameSession(const QString& id, const QString& name) {
    const QString trimmed = name.trimmed();
    if (mSessionFolder.isEmpty() || id.isEmpty() || trimmed.isEmpty()) return false;
    if (id == currentSessionId()) {
        SessionLabel label = mModel->sessionLabel();
        label.name = trimmed;
        mModel->setSessionLabel(label); // saved with the session
        return true;
    }
    try {
        SessionStore(mSessionFolder).rename(id, trimmed);
    } catch (const std::exception& e) {
        reportError(this, tr("Cannot rename the session"), QString::fromStdString(e.what()));
        return false;
    }
    return true;
}

QString WorkbenchWindow::deleteSession(const QString& id) {
    if (mSessionFolder.isEmpty() || id.isEmpty()) return {};
    if (id == currentSessionId()) {
        statusBar()->showMessage(tr("The session being bred cannot be deleted; resume another one first"),
                                 8000);
        return {};
    }
    try {
        return SessionStore(mSessionFolder).remove(id);
    } catch (const std::exception& e) {
        reportError(this, tr("Cannot delete the session"), QString::fromStdString(e.what()));
        return {};
    }
}

bool WorkbenchWindow::restoreDeletedSession(const QString& trashed) {
    try {
        SessionStore(mSessionFolder).restore(trashed);
    } catch (const std::exception& e) {
        reportError(this, tr("Cannot bring back the session"), QString::fromStdString(e.what()));
        return false;
    }
    return true;
}

SessionsDialog* WorkbenchWindow::openSessionsDialog() {
    if (mSessionFolder.isEmpty()) return nullptr;
    if (!mSessionsDialog) {
        mSessionsDialog = new SessionsDialog(this);
        mSessionsDialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    mSessionsDialog->refresh();
    mSessionsDialog->show();
    mSessionsDialog->raise();
    return mSessionsDialog;
}

void reportBadSession(QWidget* parent, const QString& file, const QString& what) {
    const QString aside = keepBadSession(file);
    reportError(parent, WorkbenchWindow::tr("Cannot resume the last session"),
                WorkbenchWindow::tr("The session could not be read, so it is not resumed.\n\n%1\n\n%2")
                    .arg(what, aside.isEmpty() ? WorkbenchWindow::tr("The file could not be moved aside.")
                                               : WorkbenchWindow::tr("The file is kept as %1.").arg(aside)));
}

} // namespace marbler::ui
