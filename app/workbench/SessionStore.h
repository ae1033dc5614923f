#pragma once
/// Kept breeding sessions. Starting differently (`--flat`, `--solid`, genome files, or "breed
/// flat/solid" instead of resuming) starts a new session and never discards one: every session
/// lives in a file of its own in the store, is listed with its name and dates, and can be
/// resumed, renamed or deleted (into a trash, so a deletion can be undone) from File ▸ Sessions
/// and the start question.
///
///     <session folder>/sessions/20261202-140512.json        a session document (Session.h)
///     <session folder>/sessions/20261202-140512.json.bad    one that did not load, moved aside
///     <session folder>/sessions/.trash/...                  deleted sessions (Trash.h)
///
/// A session's id is its file's base name, made from its creation time (UTC), so ids sort by
/// age. Its name and creation time are kept in the document (the optional "name" and "created"
/// members); its modification time is the file's, as every change of the population rewrites the
/// file. The most recently modified session is "the last session", the one a start offers to
/// resume. The session folder of the single-session layout before the store held `session.json`
/// and `session.previous.json`: migrate() moves them in.

#include <QDateTime>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace marbler::ui {

/// One kept session as lists show it, read from the head of its file (quick, whatever the
/// session's size: the designs are not read).
struct KeptSession {
    QString id;         ///< the file's base name ("20261202-140512")
    QString file;       ///< the file's absolute path
    QString name;       ///< as named by the user or by default at creation; the id when unknown
    QDateTime created;  ///< invalid when unknown
    QDateTime modified; ///< the file's modification time: the session's last change
    int generation = 0; ///< the current generation as the window counts (from 1); 0: unknown
    int dimension = 0;  ///< 2: flat, 3: solid; 0: unknown
};

/// The default name of a session: "Flat session, 2 Dec 2026 14:05" (or "Solid session, ...").
QString defaultSessionName(int dimension, const QDateTime& created);
/// "generation 12, solid, changed 2 Dec 2026 14:05": what a list says of a session besides
/// its name.
QString describeSession(const KeptSession& session);

class SessionStore {
public:
    /// The store of a session folder (defaultSessionFolder() for the window).
    explicit SessionStore(QString sessionFolder);

    QString sessionFolder() const { return mFolder; }
    /// The folder the session files are in.
    QString folder() const;
    /// Where deleted sessions go until they are restored or the trash is emptied.
    QString trashFolder() const;

    /// Moves the single-session layout's `session.json` and `session.previous.json` (the older)
    /// into the store, each named by its kind and the time it was last changed, keeping that
    /// time. A file that cannot be moved stays where it is (and is described in `problems`);
    /// nothing is ever deleted. Returns the ids of the sessions moved in, newest first.
    QStringList migrate(QStringList* problems = nullptr);

    /// The kept sessions, the most recently changed first (files moved aside as `.bad` and the
    /// trash are not listed).
    std::vector<KeptSession> list() const;
    /// One kept session by id.
    std::optional<KeptSession> find(const QString& id) const;
    /// Reads the head of a session file (nothing but its name when it is not a session).
    static KeptSession describe(const QString& file);

    /// A new session's id, file (not written yet: the model writes it, and makes the folder,
    /// reporting when it cannot), default name and creation time.
    KeptSession create(int dimension, const QDateTime& now = QDateTime::currentDateTime());

    /// Renames a kept session that no window is saving to (the model's own session is renamed
    /// through PopulationModel::setSessionLabel). Rewrites the document atomically and keeps
    /// its modification time, so renaming does not make it the last session. Throws
    /// InputError/GenomeError for a file that is not a session, RuntimeFailure when it cannot
    /// be read or written.
    void rename(const QString& id, const QString& name);

    /// Moves a kept session into the trash; returns the trashed file (for restore()). Throws
    /// RuntimeFailure when it cannot be moved.
    QString remove(const QString& id);
    /// Brings a deleted session back from the trash; returns its id. Throws RuntimeFailure.
    QString restore(const QString& trashed);
    /// Deletes the sessions trashed more than `days` days ago (done at each start).
    int emptyTrash(int days = 30);

private:
    QString mFolder;
};

} // namespace marbler::ui
