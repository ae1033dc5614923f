#include "workbench/SessionsController.h"

#include "shared/ErrorReport.h"
#include "shared/Help.h"
#include "workbench/PopulationModel.h"
#include "workbench/Session.h"
#include "workbench/SessionStore.h"
#include "workbench/SessionsDialog.h"
#include "workbench/WorkbenchWindow.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QRandomGenerator>
#include <QStatusBar>

namespace marbler::ui {

SessionsController::SessionsController(WorkbenchWindow* window, PopulationModel* model, QMenu* fileMenu)
    : QObject(window)
    , mWindow(window)
    , mModel(model) {
    // Issue 29: File ▸ Sessions had no way to start afresh but quitting and answering the start
    // question differently.
    mNewSession = fileMenu->addAction(tr("&New session"), this, [this] { newSession(); });
    mNewSession->setObjectName(QStringLiteral("newSessionAction"));
    mNewSession->setStatusTip(tr("Start a new breeding session with a random population of the kind "
                                 "shown; this one stays kept under File ▸ Sessions"));
    mNewSession->setToolTip(mNewSession->statusTip());
    mSessionsAction = fileMenu->addAction(tr("&Sessions…"), this, [this] { openDialog(); });
    mSessionsAction->setStatusTip(tr("Every breeding session is kept: resume, rename or delete one"));
    mRecent = fileMenu->addMenu(tr("&Resume session"));
    mRecent->setObjectName(QStringLiteral("recentSessionsMenu"));
    connect(mRecent, &QMenu::aboutToShow, this, &SessionsController::fillRecent);
    // Until startSession names the session folder there is no store to show.
    mSessionsAction->setEnabled(false);
    mRecent->setEnabled(false);
    mNewSession->setEnabled(false);

    connect(mModel, &PopulationModel::generationUnreadable, this, [this](const QString& message) {
        mWindow->statusBar()->showMessage(
            tr("A generation of the session could not be read back: %1").arg(message), 15000);
    });
    connect(mModel, &PopulationModel::sessionSaveFailed, this, [this](const QString& message) {
        // Once as a message, after that on the status bar: every change would fail the same way.
        if (!mSaveFailureShown) {
            mSaveFailureShown = true;
            reportError(mWindow, tr("Cannot save the session"),
                        tr("The breeding session could not be saved, so it would not survive a crash; "
                           "keep the designs you like as favourites.\n\n%1")
                            .arg(message));
        } else {
            mWindow->statusBar()->showMessage(tr("The session could not be saved: %1").arg(message), 10000);
        }
    });
}

void SessionsController::setStore(const QString& sessionFolder) {
    mFolder = sessionFolder;
    mSessionsAction->setEnabled(!sessionFolder.isEmpty());
    mRecent->setEnabled(!sessionFolder.isEmpty());
    mNewSession->setEnabled(!sessionFolder.isEmpty());
}

bool SessionsController::newSession() {
    if (mFolder.isEmpty()) return false;
    const int dimension = mModel->populationDimension();
    // The new population is drawn in a model of its own, from a fresh seed, and comes in as a
    // resumed session does: the current one was saved with its last change and stays kept.
    PopulationModel fresh;
    fresh.setSessionSeed(QRandomGenerator::global()->generate64());
    KeptSession kept;
    try {
        fresh.newRandomPopulation(dimension, mWindow->populationFamily().toStdString());
        kept = SessionStore(mFolder).create(dimension);
    } catch (const std::exception& e) {
        reportError(mWindow, tr("Cannot start a new session"), QString::fromStdString(e.what()));
        return false;
    }
    SavedSession session;
    session.history = fresh.history();
    session.current = int(session.history.size()) - 1;
    session.seed = fresh.sessionSeed();
    session.dimension = dimension;
    session.mesh = mWindow->mesh();
    session.flatMesh = mWindow->flatMesh();
    session.label = {kept.name, kept.created};
    const QString previous = mModel->sessionLabel().name;
    mModel->setSessionFile({});
    mWindow->resumeSession(std::move(session));
    mModel->setSessionFile(kept.file);
    mWindow->statusBar()->showMessage(
        previous.isEmpty()
            ? tr("Started a new session “%1”").arg(kept.name)
            : tr("Started a new session “%1”; “%2” is kept under File ▸ Sessions").arg(kept.name, previous),
        15000);
    return true;
}

QString SessionsController::currentId() const {
    const QString file = mModel->sessionFile();
    return file.isEmpty() ? QString() : QFileInfo(file).completeBaseName();
}

void SessionsController::fillRecent() {
    mRecent->clear();
    if (mFolder.isEmpty()) return;
    const QString current = currentId();
    int shown = 0;
    for (const KeptSession& session : SessionStore(mFolder).list()) {
        if (session.id == current) continue;
        if (++shown > 9) break;
        QAction* action = mRecent->addAction(
            QStringLiteral("&%1 %2 — %3").arg(shown).arg(labelSafe(session.name), describeSession(session)),
            this, [this, id = session.id] { resume(id); });
        action->setData(session.id);
    }
    if (shown == 0) mRecent->addAction(tr("No other sessions"))->setEnabled(false);
    mRecent->addSeparator();
    mRecent->addAction(mSessionsAction);
}

bool SessionsController::resume(const QString& id) {
    if (mFolder.isEmpty() || id.isEmpty() || id == currentId()) return false;
    const std::optional<KeptSession> kept = SessionStore(mFolder).find(id);
    if (!kept) {
        reportError(mWindow, tr("Cannot resume the session"),
                    tr("There is no kept session %1 any more.").arg(id));
        return false;
    }
    SavedSession saved;
    try {
        saved = loadSession(kept->file);
    } catch (const std::exception& e) {
        reportBadSession(mWindow, kept->file, QString::fromStdString(e.what()));
        return false;
    }
    // The current session was saved with its last change, so switching loses nothing; no file
    // is set while the other one comes in, so nothing is written over either.
    const QString previous = mModel->sessionLabel().name;
    mModel->setSessionFile({});
    mWindow->resumeSession(std::move(saved));
    mModel->setSessionFile(kept->file);
    mWindow->statusBar()->showMessage(
        previous.isEmpty() ? tr("Resumed “%1” at generation %2")
                                 .arg(kept->name)
                                 .arg(mModel->generationLabel(mModel->currentIndex()))
                           : tr("Resumed “%1” at generation %2; “%3” is kept under File ▸ Sessions")
                                 .arg(kept->name)
                                 .arg(mModel->generationLabel(mModel->currentIndex()))
                                 .arg(previous),
        15000);
    return true;
}

bool SessionsController::rename(const QString& id, const QString& name) {
    const QString trimmed = name.trimmed();
    if (mFolder.isEmpty() || id.isEmpty() || trimmed.isEmpty()) return false;
    if (id == currentId()) {
        SessionLabel label = mModel->sessionLabel();
        label.name = trimmed;
        mModel->setSessionLabel(label); // saved with the session
        return true;
    }
    try {
        SessionStore(mFolder).rename(id, trimmed);
    } catch (const std::exception& e) {
        reportError(mWindow, tr("Cannot rename the session"), QString::fromStdString(e.what()));
        return false;
    }
    return true;
}

QString SessionsController::remove(const QString& id) {
    if (mFolder.isEmpty() || id.isEmpty()) return {};
    if (id == currentId()) {
        mWindow->statusBar()->showMessage(
            tr("The session being bred cannot be deleted; resume another one first"), 8000);
        return {};
    }
    try {
        return SessionStore(mFolder).remove(id);
    } catch (const std::exception& e) {
        reportError(mWindow, tr("Cannot delete the session"), QString::fromStdString(e.what()));
        return {};
    }
}

bool SessionsController::restoreDeleted(const QString& trashed) {
    try {
        SessionStore(mFolder).restore(trashed);
    } catch (const std::exception& e) {
        reportError(mWindow, tr("Cannot bring back the session"), QString::fromStdString(e.what()));
        return false;
    }
    return true;
}

SessionsDialog* SessionsController::openDialog() {
    if (mFolder.isEmpty()) return nullptr;
    if (!mDialog) {
        mDialog = new SessionsDialog(mWindow);
        mDialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    mDialog->refresh();
    mDialog->show();
    mDialog->raise();
    return mDialog;
}

void reportBadSession(QWidget* parent, const QString& file, const QString& what) {
    const QString aside = keepBadSession(file);
    reportError(parent, WorkbenchWindow::tr("Cannot resume the last session"),
                WorkbenchWindow::tr("The session could not be read, so it is not resumed.\n\n%1\n\n%2")
                    .arg(what, aside.isEmpty() ? WorkbenchWindow::tr("The file could not be moved aside.")
                                               : WorkbenchWindow::tr("The file is kept as %1.").arg(aside)));
}

} // namespace marbler::ui
