#pragma once
/// Autosave of an editor's design and recovery after a crash.
///
/// Each open editor has a recovery file in a folder (defaultRecoveryFolder()), written
/// atomically a short while after each change and at once by flush(), and removed when the
/// document is saved clean or the editor closes normally (discard()). The file is a JSON object
/// {"format": "marbler-recovery", "file": the design's file or null, "saved": ISO time,
/// "baseDirectory": ..., "genome": the document's fileGenome()}, so the muted steps come back too;
/// "declined": true once the user said No to it (kept, listed by File ▸ Recover unsaved designs,
/// not offered at start again), until discarded or RecoveryKeepDays old.
///
/// While its editor runs, a recovery file is locked (a QLockFile beside it): only the files of
/// editors that are gone (a crash) are offered by pendingRecoveries, never those of an editor
/// open in this or another running Marbler.

#include "marbler/Genome.h"

#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <memory>
#include <vector>

class QLockFile;

namespace marbler::ui {

class EditorDocument;

/// Keeps a recovery file of one editor's design up to date.
class EditorAutosave : public QObject {
    Q_OBJECT
public:
    /// Watches `doc` and keeps its recovery file in `folder` (created when needed). Nothing is
    /// written until the design has unsaved changes.
    EditorAutosave(EditorDocument* doc, QString folder, QObject* parent = nullptr);
    /// Leaves the recovery file where it is (after a crash it is what the next start offers);
    /// discard() removes it.
    ~EditorAutosave() override;

    /// Writes the recovery file now when the design has unsaved changes; removes it when it has
    /// none.
    void flush();
    /// Removes the recovery file: the editor closes normally (its design saved or let go).
    void discard();
    /// The recovery file's path (it exists only while there are unsaved changes).
    QString file() const { return mFile; }
    /// How long after a change the file is written, in milliseconds (2000 unless set).
    void setDelay(int milliseconds) { mTimer.setInterval(milliseconds); }

private:
    QPointer<EditorDocument> mDoc;
    QString mFolder;
    QString mFile;
    QTimer mTimer;
    std::unique_ptr<QLockFile> mLock;
};

/// A design an editor left behind when it did not close normally.
struct RecoveredDesign {
    QString recoveryFile; ///< the recovery file (discardRecovery removes it)
    QString originalFile; ///< the file the design was opened from or saved to; may be empty
    /// The design as its file would hold it (fileGenome form: muted steps kept in meta.editor);
    /// an EditorDocument made from it shows the design that was being edited, exactly.
    Genome design;
    QDateTime saved; ///< when the recovery file was written
    /// The user said No when it was offered: kept (File ▸ Recover unsaved designs…) but not
    /// offered again at start.
    bool declined = false;
};

/// The recovery files in `folder` whose editors are gone, newest first. A file that cannot be
/// read or is not a valid recovery is skipped (and left in place); a line saying why is appended
/// to `warnings` when given, and logged.
std::vector<RecoveredDesign> pendingRecoveries(const QString& folder, QStringList* warnings = nullptr);

/// Removes a recovery file once its design was taken back or discarded; false when it could not.
bool discardRecovery(const QString& recoveryFile);
/// Marks a recovery file declined (see RecoveredDesign::declined); false when it could not.
bool declineRecovery(const QString& recoveryFile);
/// How long a recovery file is kept after it was written: then it is old, and purged.
inline constexpr int RecoveryKeepDays = 30;
/// Removes the recovery files in `folder` whose editors are gone and that were written more than
/// `days` days before `now`; returns how many went.
int purgeOldRecoveries(const QString& folder, int days = RecoveryKeepDays,
                       const QDateTime& now = QDateTime::currentDateTimeUtc());

/// Where editors keep their recovery files: the application data folder + "/recovery".
QString defaultRecoveryFolder();

} // namespace marbler::ui
