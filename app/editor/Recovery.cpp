#include "editor/Recovery.h"

#include "editor/EditorDocument.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QStandardPaths>
#include <QUuid>
#include <QtGlobal>

#include <nlohmann/json.hpp>

#include <algorithm>

namespace marbler::ui {

namespace {

const QString Suffix = QStringLiteral(".recovery.json");
const QString LockSuffix = QStringLiteral(".lock");
constexpr const char* RecoveryFormat = "marbler-recovery";

/// A lock of a recovery file that only a running process holds: no age makes it stale, a
/// holder that is gone (a crash) does.
std::unique_ptr<QLockFile> lockOf(const QString& recoveryFile) {
    auto lock = std::make_unique<QLockFile>(recoveryFile + LockSuffix);
    lock->setStaleLockTime(0);
    return lock;
}

/// Reads one recovery file. Throws Error saying what is wrong.
RecoveredDesign readRecovery(const QFileInfo& info) {
    const QString path = info.absoluteFilePath();
    const std::string name = path.toStdString();
    if (info.size() > static_cast<qint64>(2 * MaxFileBytes)) throw InputError(name + ": too large");
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        throw RuntimeFailure(name + ": cannot read: " + f.errorString().toStdString());
    const QByteArray bytes = f.readAll();
    nlohmann::ordered_json root;
    try {
        root = nlohmann::ordered_json::parse(bytes.constData(), bytes.constData() + bytes.size());
    } catch (const nlohmann::json::exception& e) {
        throw InputError(name + ": not JSON: " + e.what());
    }
    if (!root.is_object() || root.value("format", std::string()) != RecoveryFormat ||
        !root.contains("genome") || !root["genome"].is_object())
        throw InputError(name + ": not a recovery file");
    RecoveredDesign r;
    r.recoveryFile = path;
    r.design = parseGenome(root["genome"].dump(), name);
    if (root.contains("file") && root["file"].is_string())
        r.originalFile = QString::fromStdString(root["file"].get<std::string>());
    if (root.contains("baseDirectory") && root["baseDirectory"].is_string())
        r.design.baseDirectory = root["baseDirectory"].get<std::string>();
    else if (!r.originalFile.isEmpty())
        r.design.baseDirectory = QFileInfo(r.originalFile).absolutePath().toStdString();
    if (!r.originalFile.isEmpty()) r.design.fileName = r.originalFile.toStdString();
    if (root.contains("saved") && root["saved"].is_string())
        r.saved = QDateTime::fromString(QString::fromStdString(root["saved"].get<std::string>()),
                                        Qt::ISODateWithMs);
    if (!r.saved.isValid()) r.saved = info.lastModified();
    r.declined = root.value("declined", false);
    return r;
}

} // namespace

EditorAutosave::EditorAutosave(EditorDocument* doc, QString folder, QObject* parent)
    : QObject(parent)
    , mDoc(doc)
    , mFolder(std::move(folder)) {
    if (!QDir().mkpath(mFolder)) qWarning("cannot make the recovery folder %s", qPrintable(mFolder));
    const QString stamp = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss"));
    mFile = QDir(mFolder).filePath(stamp + QLatin1Char('-') +
                                   QUuid::createUuid().toString(QUuid::Id128).left(12) + Suffix);
    mLock = lockOf(mFile);
    if (!mLock->tryLock(0)) qWarning("cannot lock the recovery file %s", qPrintable(mFile));

    mTimer.setSingleShot(true);
    mTimer.setInterval(2000);
    connect(&mTimer, &QTimer::timeout, this, &EditorAutosave::flush);
    if (!doc) return;
    connect(doc, &QObject::destroyed, &mTimer, &QTimer::stop);
    connect(doc, &EditorDocument::changed, this, [this] { mTimer.start(); });
    connect(doc, &EditorDocument::modifiedChanged, this, [this](bool modified) {
        // Saved clean (or undone back to the saved state): nothing left to recover.
        if (!modified) flush();
    });
}

EditorAutosave::~EditorAutosave() = default;

void EditorAutosave::flush() {
    mTimer.stop();
    // The document gone first (its editor closing): the file is left as the editor leaves it.
    if (!mDoc) return;
    if (!mDoc->isModified()) {
        if (QFile::exists(mFile) && !QFile::remove(mFile)) qWarning("cannot remove %s", qPrintable(mFile));
        return;
    }
    nlohmann::ordered_json root;
    root["format"] = RecoveryFormat;
    root["file"] = mDoc->fileName().isEmpty() ? nlohmann::ordered_json()
                                              : nlohmann::ordered_json(mDoc->fileName().toStdString());
    root["saved"] = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs).toStdString();
    root["baseDirectory"] = mDoc->design().baseDirectory;
    root["genome"] = toJson(mDoc->fileGenome());
    try {
        QDir().mkpath(mFolder);
        writeFileAtomically(QFile::encodeName(mFile).toStdString(),
                            root.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    } catch (const Error& e) {
        // Autosave is a safety net: a failure must not disturb the editing.
        qWarning("autosave failed: %s", e.what());
    }
}

void EditorAutosave::discard() {
    mTimer.stop();
    if (QFile::exists(mFile) && !QFile::remove(mFile)) qWarning("cannot remove %s", qPrintable(mFile));
}

std::vector<RecoveredDesign> pendingRecoveries(const QString& folder, QStringList* warnings) {
    std::vector<RecoveredDesign> found;
    const QDir dir(folder);
    if (!dir.exists()) return found;
    for (const QFileInfo& info : dir.entryInfoList({QStringLiteral("*") + Suffix}, QDir::Files)) {
        // A running editor's file is its own business.
        const auto lock = lockOf(info.absoluteFilePath());
        if (!lock->tryLock(0)) continue;
        try {
            found.push_back(readRecovery(info));
        } catch (const std::exception& e) {
            const QString line =
                QObject::tr("A recovery file was skipped: %1").arg(QString::fromStdString(e.what()));
            qWarning("%s", qPrintable(line));
            if (warnings) *warnings << line;
        }
    }
    // Locks left by editors that crashed before their first autosave.
    for (const QFileInfo& info :
         dir.entryInfoList({QStringLiteral("*") + Suffix + LockSuffix}, QDir::Files)) {
        const QString recovery = info.absoluteFilePath().chopped(LockSuffix.size());
        if (QFileInfo::exists(recovery)) continue;
        const auto lock = lockOf(recovery);
        if (lock->tryLock(0)) lock->unlock();
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const RecoveredDesign& a, const RecoveredDesign& b) { return a.saved > b.saved; });
    return found;
}

bool discardRecovery(const QString& recoveryFile) {
    return QFile::remove(recoveryFile);
}

bool declineRecovery(const QString& recoveryFile) {
    QFile f(recoveryFile);
    if (!f.open(QIODevice::ReadOnly)) return false;
    const QByteArray bytes = f.readAll();
    f.close();
    try {
        auto root = nlohmann::ordered_json::parse(bytes.constData(), bytes.constData() + bytes.size());
        if (!root.is_object()) return false;
        root["declined"] = true;
        writeFileAtomically(QFile::encodeName(recoveryFile).toStdString(),
                            root.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    } catch (const std::exception& e) {
        qWarning("cannot mark %s declined: %s", qPrintable(recoveryFile), e.what());
        return false;
    }
    return true;
}

int purgeOldRecoveries(const QString& folder, int days, const QDateTime& now) {
    int removed = 0;
    for (const RecoveredDesign& r : pendingRecoveries(folder))
        if (r.saved.isValid() && r.saved.daysTo(now) > days && discardRecovery(r.recoveryFile)) ++removed;
    return removed;
}

QString defaultRecoveryFolder() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/recovery");
}

} // namespace marbler::ui
