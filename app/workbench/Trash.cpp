#include "workbench/Trash.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTimeZone>

namespace marbler::ui {

namespace {

const QString StampFormat = QStringLiteral("yyyyMMdd'T'HHmmss'Z'");
/// The stamp's length ("20261202T140512Z"); a second file of a name trashed within the same
/// second gets ".2", ".3", ... after it. The original name follows the first dash.
constexpr int StampLength = 16;

} // namespace

QString moveToTrash(const QString& file, const QString& trashFolder) {
    if (!QFileInfo(file).isFile() || !QDir().mkpath(trashFolder)) return {};
    const QString stamp = QDateTime::currentDateTimeUtc().toString(StampFormat);
    const QString name = QFileInfo(file).fileName();
    for (int n = 1; n < 1000; ++n) {
        // The same name trashed twice within a second gets a second stamp, not a collision.
        const QString trashed =
            QDir(trashFolder)
                .filePath(n == 1 ? QStringLiteral("%1-%2").arg(stamp, name)
                                 : QStringLiteral("%1.%2-%3").arg(stamp).arg(n).arg(name));
        if (QFileInfo::exists(trashed)) continue;
        return QFile::rename(file, trashed) ? trashed : QString();
    }
    return {};
}

QString originalTrashName(const QString& trashed) {
    const QString name = QFileInfo(trashed).fileName();
    return name.mid(name.indexOf(QLatin1Char('-')) + 1);
}

QString restoreFromTrash(const QString& trashed, const QString& folder) {
    if (!QFileInfo(trashed).isFile() || !QDir().mkpath(folder)) return {};
    const QString target = QDir(folder).filePath(originalTrashName(trashed));
    // Never over a file that took the name meanwhile.
    if (QFileInfo::exists(target)) return {};
    return QFile::rename(trashed, target) ? target : QString();
}

int emptyTrash(const QString& trashFolder, int days) {
    const QDateTime limit = QDateTime::currentDateTimeUtc().addDays(-days);
    int deleted = 0;
    const QDir dir(trashFolder);
    for (const QString& name : dir.entryList(QDir::Files | QDir::Hidden, QDir::Name)) {
        QDateTime trashed = QDateTime::fromString(name.left(StampLength), StampFormat);
        trashed.setTimeZone(QTimeZone::utc());
        // A file whose name carries no stamp was not put there by moveToTrash: leave it.
        if (!trashed.isValid() || trashed >= limit) continue;
        if (QFile::remove(dir.filePath(name))) ++deleted;
    }
    return deleted;
}

} // namespace marbler::ui
