#include "workbench/SessionStore.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "workbench/Session.h"
#include "workbench/Trash.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLocale>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <fstream>

namespace marbler::ui {

namespace {

const QString IdFormat = QStringLiteral("yyyyMMdd-HHmmss");
const QString Suffix = QStringLiteral(".json");

QString tr(const char* text) {
    return QCoreApplication::translate("marbler::ui::SessionStore", text);
}

/// Reads the members of a session document that come before its generations, and stops there:
/// a list of sessions reads a few hundred bytes of each, however many designs it holds.
class HeadReader : public nlohmann::json_sax<nlohmann::json> {
public:
    bool session = false;
    std::optional<long long> current;
    std::optional<long long> generation; ///< the current generation's number (version 2)
    int dimension = 0;
    std::string name;
    std::string created;

    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t value) override { return integer(value); }
    bool number_unsigned(number_unsigned_t value) override { return integer(static_cast<long long>(value)); }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t& value) override {
        if (mDepth != 1) return true;
        if (mKey == "format") session = value == "marbler-session";
        if (mKey == "name") name = value;
        if (mKey == "created") created = value;
        return true;
    }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return ++mDepth, true; }
    bool end_object() override { return --mDepth, true; }
    bool start_array(std::size_t) override { return ++mDepth, true; }
    bool end_array() override { return --mDepth, true; }
    bool key(string_t& key) override {
        if (mDepth == 1) mKey = key;
        return !(mDepth == 1 && key == "generations"); // the head ends here
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
        return false;
    }

private:
    bool integer(long long value) {
        if (mDepth != 1) return true;
        if (mKey == "current") current = value;
        if (mKey == "generation") generation = value;
        if (mKey == "dimension") dimension = value == 2 || value == 3 ? int(value) : 0;
        return true;
    }
    int mDepth = 0;
    std::string mKey;
};

/// The document's text with `name` (and `created`, when valid) set; new members go before the
/// generations, so the head reader finds them. Throws as parseSession for a file that is no
/// session document.
std::string withLabel(const QString& file, const QString& name, const QDateTime& created) {
    QFile in(file);
    if (!in.open(QIODevice::ReadOnly))
        throw RuntimeFailure("cannot read " + file.toStdString() + ": " + in.errorString().toStdString());
    const QByteArray text = in.readAll();
    nlohmann::ordered_json doc;
    try {
        doc = nlohmann::ordered_json::parse(text.constData(), text.constData() + text.size());
    } catch (const nlohmann::ordered_json::exception& e) {
        throw GenomeError(file.toStdString(), "", std::string("not valid JSON (") + e.what() + ")");
    }
    if (!doc.is_object() || !doc.contains("format") || doc["format"] != "marbler-session")
        throw GenomeError(file.toStdString(), "format", "not a Marbler session");
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    const auto put = [&](nlohmann::ordered_json& target) {
        target["name"] = name.toStdString();
        if (created.isValid() && !doc.contains("created"))
            target["created"] = created.toUTC().toString(Qt::ISODate).toStdString();
    };
    bool placed = doc.contains("name");
    for (auto& [key, value] : doc.items()) {
        if (key == "generations" && !placed) {
            put(out);
            placed = true;
        }
        if (key == "name") value = name.toStdString();
        out[key] = std::move(value);
    }
    if (!placed) put(out);
    return out.dump() + "\n";
}

/// Writes a document's text atomically, keeping the file's modification time (a label changed
/// is no change of the session, and the last changed session is the one offered next start).
/// Moves a session's generations folder (Session.h) along with its file, when it has one.
bool moveGenerations(const QString& from, const QString& to) {
    const QString folder = generationsFolder(from);
    return !QFileInfo(folder).isDir() || QDir().rename(folder, generationsFolder(to));
}

void rewriteKeepingTime(const QString& file, const std::string& text) {
    const QDateTime modified = QFileInfo(file).lastModified();
    writeFileAtomically(QFile::encodeName(file).toStdString(), text);
    QFile out(file);
    if (out.open(QIODevice::ReadWrite)) out.setFileTime(modified, QFileDevice::FileModificationTime);
}

} // namespace

QString defaultSessionName(int dimension, const QDateTime& created) {
    const QString when = QLocale().toString(created.toLocalTime(), QStringLiteral("d MMM yyyy HH:mm"));
    return dimension == 3 ? tr("Solid session, %1").arg(when) : tr("Flat session, %1").arg(when);
}

QString describeSession(const KeptSession& session) {
    QStringList parts;
    if (session.generation > 0) parts << tr("generation %1").arg(session.generation);
    if (session.dimension == 3) parts << tr("solid");
    if (session.dimension == 2) parts << tr("flat");
    if (session.modified.isValid())
        parts << tr("changed %1")
                     .arg(QLocale().toString(session.modified.toLocalTime(),
                                             QStringLiteral("d MMM yyyy HH:mm")));
    return parts.join(QStringLiteral(", "));
}

SessionStore::SessionStore(QString sessionFolder)
    : mFolder(std::move(sessionFolder)) {}

QString SessionStore::folder() const {
    return QDir(mFolder).filePath(QStringLiteral("sessions"));
}

QString SessionStore::trashFolder() const {
    return QDir(folder()).filePath(QStringLiteral(".trash"));
}

KeptSession SessionStore::describe(const QString& file) {
    const QFileInfo info(file);
    KeptSession session;
    session.file = info.absoluteFilePath();
    session.id = info.fileName().endsWith(Suffix) ? info.fileName().chopped(Suffix.size()) : info.fileName();
    session.name = session.id;
    session.modified = info.lastModified();
    std::ifstream in(QFile::encodeName(file).toStdString(), std::ios::binary);
    HeadReader head;
    if (in) nlohmann::json::sax_parse(in, &head);
    if (!head.session) return session;
    if (!head.name.empty()) session.name = QString::fromStdString(head.name);
    session.created = QDateTime::fromString(QString::fromStdString(head.created), Qt::ISODate);
    // Version 2 names the current generation's number (its depth in the tree); in version 1
    // the history is a line, so the number follows from the index.
    if (head.generation && *head.generation > 0)
        session.generation = int(*head.generation);
    else if (head.current && *head.current >= 0)
        session.generation = int(*head.current) + 1;
    session.dimension = head.dimension;
    return session;
}

std::vector<KeptSession> SessionStore::list() const {
    std::vector<KeptSession> sessions;
    const QDir dir(folder());
    // Hidden files are excluded: an atomic write's temporary is one.
    for (const QFileInfo& info : dir.entryInfoList({QStringLiteral("*.json")}, QDir::Files))
        sessions.push_back(describe(info.absoluteFilePath()));
    std::sort(sessions.begin(), sessions.end(), [](const KeptSession& a, const KeptSession& b) {
        if (a.modified != b.modified) return a.modified > b.modified;
        return a.id > b.id; // ids sort by creation
    });
    return sessions;
}

std::optional<KeptSession> SessionStore::find(const QString& id) const {
    const QString file = QDir(folder()).filePath(id + Suffix);
    if (id.isEmpty() || !QFileInfo(file).isFile()) return std::nullopt;
    return describe(file);
}

KeptSession SessionStore::create(int dimension, const QDateTime& now) {
    const QString base = now.toUTC().toString(IdFormat);
    KeptSession session;
    for (int n = 1;; ++n) {
        session.id = n == 1 ? base : QStringLiteral("%1-%2").arg(base).arg(n);
        session.file = QDir(folder()).filePath(session.id + Suffix);
        if (!QFileInfo::exists(session.file) && !QFileInfo::exists(session.file + QStringLiteral(".bad")))
            break;
    }
    session.name = defaultSessionName(dimension, now);
    session.created = now;
    session.dimension = dimension;
    return session;
}

QStringList SessionStore::migrate(QStringList* problems) {
    QStringList moved;
    // session.json is the newer of the two; both keep their times, so the list orders them so.
    for (const QString& file :
         {sessionFilePath(mFolder), QDir(mFolder).filePath(QStringLiteral("session.previous.json"))}) {
        if (!QFileInfo(file).isFile()) continue;
        const KeptSession head = describe(file);
        // The time it was last changed is the best known creation time of an old session.
        const KeptSession kept = create(head.dimension, head.modified);
        if (!QDir().mkpath(folder()) || !QFile::rename(file, kept.file) ||
            !moveGenerations(file, kept.file)) {
            if (problems)
                *problems << tr("%1 could not be moved to %2; it stays where it is").arg(file, kept.file);
            continue;
        }
        moved << kept.id;
        if (head.name != head.id) continue; // already named
        try {
            rewriteKeepingTime(kept.file, withLabel(kept.file, kept.name, kept.created));
        } catch (const std::exception&) {
            // Not a readable session: it is moved in all the same, and reported (and moved
            // aside as .bad) when someone resumes it.
        }
    }
    return moved;
}

void SessionStore::rename(const QString& id, const QString& name) {
    const std::optional<KeptSession> session = find(id);
    if (!session) throw RuntimeFailure("there is no kept session " + id.toStdString());
    rewriteKeepingTime(session->file, withLabel(session->file, name, session->created));
}

QString SessionStore::remove(const QString& id) {
    const std::optional<KeptSession> session = find(id);
    if (!session) throw RuntimeFailure("there is no kept session " + id.toStdString());
    const QString trashed = moveToTrash(session->file, trashFolder());
    if (trashed.isEmpty())
        throw RuntimeFailure("cannot move " + session->file.toStdString() + " to the trash");
    if (!moveGenerations(session->file, trashed))
        throw RuntimeFailure("cannot move " + generationsFolder(session->file).toStdString() +
                             " to the trash");
    return trashed;
}

QString SessionStore::restore(const QString& trashed) {
    const QString file = restoreFromTrash(trashed, folder());
    if (file.isEmpty())
        throw RuntimeFailure("cannot bring back " + trashed.toStdString() + " from the trash");
    if (!moveGenerations(trashed, file))
        throw RuntimeFailure("cannot bring back " + generationsFolder(trashed).toStdString() +
                             " from the trash");
    return QFileInfo(file).fileName().chopped(Suffix.size());
}

int SessionStore::emptyTrash(int days) {
    const int deleted = ui::emptyTrash(trashFolder(), days);
    // A deleted session's generations folder goes with its file.
    const QDir trash(trashFolder());
    for (const QString& name :
         trash.entryList({QStringLiteral("*.generations")}, QDir::Dirs | QDir::Hidden)) {
        const QString file = trash.filePath(name.chopped(int(std::strlen(".generations"))) + Suffix);
        if (!QFileInfo::exists(file)) QDir(trash.filePath(name)).removeRecursively();
    }
    return deleted;
}

} // namespace marbler::ui
