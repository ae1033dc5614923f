#include "workbench/Session.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "shared/StartDialog.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <optional>

#include <nlohmann/json.hpp>

namespace marbler::ui {

namespace {

constexpr const char* FormatName = "marbler-session";
/// Version 3 keeps the generations in files of their own (issue 28); version 2 records each
/// generation's parent (history is a tree) in one document; version 1, a line of generations in
/// one document. All are read; the model writes version 3, serializeSession version 2.
constexpr int SessionVersion = 3;
constexpr int DocumentVersion = 2;
/// A generation file larger than this is not read (nine very large designs).
constexpr qint64 MaxGenerationBytes = 64LL * 1024 * 1024;
/// A session larger than this is not read (it would be thousands of generations of big designs).
constexpr qint64 MaxSessionBytes = 512LL * 1024 * 1024;

[[noreturn]] void bad(const std::string& name, const std::string& location, const std::string& what) {
    throw GenomeError(name, location, what);
}

/// A list of cell indices (0..8) at `key`, or empty when absent.
std::vector<int> cellList(const nlohmann::ordered_json& object, const char* key, const std::string& name,
                          const std::string& location) {
    std::vector<int> result;
    if (!object.contains(key)) return result;
    const auto& list = object[key];
    const std::string at = location.empty() ? std::string(key) : location + "." + key;
    if (!list.is_array()) bad(name, at, "must be an array of cell numbers");
    for (const auto& v : list) {
        if (!v.is_number_integer() || v.get<int>() < 0 || v.get<int>() >= CellCount)
            bad(name, at, "cell numbers are 0 to 8");
        result.push_back(v.get<int>());
    }
    return result;
}

} // namespace

QString defaultSessionFolder() {
    const QByteArray env = qgetenv("MARBLER_SESSION_DIR");
    if (!env.isEmpty()) return QString::fromLocal8Bit(env);
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/session");
}

QString sessionFilePath(const QString& folder) {
    return QDir(folder).filePath(QStringLiteral("session.json"));
}

namespace {

/// A generation as an object: its small fields, then its designs (see Session.h).
nlohmann::ordered_json generationJson(const Generation& g) {
    nlohmann::ordered_json gen;
    gen["description"] = g.description.toStdString();
    gen["parent"] = g.parent;
    gen["parents"] = g.parentCells;
    std::vector<int> selected;
    for (int i = 0; i < CellCount; ++i)
        if (g.selected[std::size_t(i)]) selected.push_back(i);
    gen["selected"] = selected;
    auto& list = gen["cells"] = nlohmann::ordered_json::array();
    nlohmann::ordered_json bases = nlohmann::ordered_json::array();
    bool anyBase = false;
    for (const auto& cell : g.cells) {
        list.push_back(cell ? toJson(*cell) : nlohmann::ordered_json());
        anyBase = anyBase || (cell && !cell->baseDirectory.empty());
        if (cell && !cell->baseDirectory.empty())
            bases.push_back(cell->baseDirectory);
        else
            bases.push_back(nullptr);
    }
    if (anyBase) gen["bases"] = std::move(bases);
    return gen;
}

/// The members every version's head has: seed, current, kind, objects, label.
nlohmann::ordered_json headJson(const PopulationModel& model, int version) {
    nlohmann::ordered_json header;
    header["format"] = FormatName;
    header["version"] = version;
    header["seed"] = model.sessionSeed();
    header["current"] = model.currentIndex();
    // The number the window shows for the current generation, for lists that read only the head.
    if (!model.isEmptyWorkbench()) header["generation"] = model.current().number;
    header["dimension"] = model.populationDimension();
    header["mesh"] = model.mesh().toStdString();
    if (!model.flatMesh().isEmpty()) header["flatMesh"] = model.flatMesh().toStdString();
    // The label goes before the generations: lists of sessions read only the head.
    const SessionLabel& label = model.sessionLabel();
    if (!label.name.isEmpty()) header["name"] = label.name.toStdString();
    if (label.created.isValid())
        header["created"] = label.created.toUTC().toString(Qt::ISODate).toStdString();
    return header;
}

} // namespace

QString generationsFolder(const QString& sessionFile) {
    QString base = sessionFile;
    if (base.endsWith(QStringLiteral(".json"))) base.chop(5);
    return base + QStringLiteral(".generations");
}

QString generationFile(const QString& folder, int index) {
    return QDir(folder).filePath(QStringLiteral("g%1.json").arg(index, 6, 10, QLatin1Char('0')));
}

std::string serializeGeneration(const Generation& generation) {
    return generationJson(generation).dump() + "\n";
}

std::string serializeSessionHead(const PopulationModel& model) {
    nlohmann::ordered_json header = headJson(model, SessionVersion);
    header["count"] = model.history().size();
    return header.dump() + "\n";
}

std::string serializeSession(const PopulationModel& model) {
    std::string text = headJson(model, DocumentVersion).dump();
    text.pop_back(); // the closing brace
    text += ",\"generations\":[";
    for (std::size_t k = 0; k < model.history().size(); ++k) {
        if (k > 0) text += ',';
        text += generationJson(model.generation(int(k))).dump();
    }
    text += "]}\n";
    return text;
}

namespace {

nlohmann::ordered_json parseJson(std::string_view text, const std::string& name) {
    try {
        return nlohmann::ordered_json::parse(text);
    } catch (const nlohmann::ordered_json::exception& e) {
        bad(name, "", std::string("not valid JSON (") + e.what() + ")");
    }
}

/// The head of a document of any version: everything but the generations. Returns the version.
int parseHead(const nlohmann::ordered_json& doc, const std::string& name, SavedSession& session) {
    if (!doc.is_object()) bad(name, "", "a session is a JSON object");
    if (!doc.contains("format") || doc["format"] != FormatName) bad(name, "format", "not a Marbler session");
    if (!doc.contains("version") || !doc["version"].is_number_integer() ||
        doc["version"].get<long long>() < 1 || doc["version"].get<long long>() > SessionVersion)
        bad(name, "version", "only version 1, 2 and 3 sessions are read");
    const int version = doc["version"].get<int>();
    if (!doc.contains("seed") || !doc["seed"].is_number_unsigned())
        bad(name, "seed", "must be a whole number >= 0");
    session.seed = doc["seed"].get<std::uint64_t>();
    if (!doc.contains("dimension") || !doc["dimension"].is_number_integer() ||
        (doc["dimension"].get<int>() != 2 && doc["dimension"].get<int>() != 3))
        bad(name, "dimension", "must be 2 or 3");
    session.dimension = doc["dimension"].get<int>();
    // An unknown object falls back to the vase (flat designs: to flat); a file's path is kept.
    const auto object = [&](const char* key) -> std::optional<QString> {
        if (!doc.contains(key)) return std::nullopt;
        if (!doc[key].is_string()) bad(name, key, "must be a string");
        const QString mesh = QString::fromStdString(doc[key].get<std::string>());
        if (meshNames().contains(mesh) || QDir::isAbsolutePath(mesh)) return mesh;
        return std::nullopt;
    };
    if (const auto mesh = object("mesh")) session.mesh = *mesh;
    if (const auto mesh = object("flatMesh")) session.flatMesh = *mesh;

    if (doc.contains("name")) {
        if (!doc["name"].is_string()) bad(name, "name", "must be a string");
        session.label.name = QString::fromStdString(doc["name"].get<std::string>());
    }
    if (doc.contains("created")) {
        if (!doc["created"].is_string()) bad(name, "created", "must be a date and time (ISO 8601)");
        // A time that does not parse only loses the label's date, not the session.
        session.label.created =
            QDateTime::fromString(QString::fromStdString(doc["created"].get<std::string>()), Qt::ISODate);
    }
    return version;
}

/// One generation object (`at` locates it in errors: "generations[3]", or "" for a file of its
/// own). Its designs' info is set.
Generation parseGeneration(const nlohmann::ordered_json& gen, int version, std::size_t k,
                           const std::string& name, const std::string& at) {
    const auto where = [&](const std::string& member) { return at.empty() ? member : at + "." + member; };
    if (!gen.is_object()) bad(name, at, "must be an object");
    Generation g;
    if (version == 1) {
        // Version 1 sessions were a line: each generation grew from the one before.
        g.parent = int(k) - 1;
    } else {
        // Only an earlier generation can be a parent, which also rules out cycles.
        if (!gen.contains("parent") || !gen["parent"].is_number_integer() ||
            gen["parent"].get<long long>() < -1 ||
            gen["parent"].get<long long>() >= static_cast<long long>(k))
            bad(name, where("parent"),
                k == 0 ? std::string("must be -1: the first generation grows from none")
                       : "must name an earlier generation (0 to " + std::to_string(k - 1) +
                             "), or be -1 for a generation that grows from none");
        g.parent = gen["parent"].get<int>();
    }
    if (gen.contains("description")) {
        if (!gen["description"].is_string()) bad(name, where("description"), "must be a string");
        g.description = QString::fromStdString(gen["description"].get<std::string>());
    }
    g.parentCells = cellList(gen, "parents", name, at);
    if (!gen.contains("cells") || !gen["cells"].is_array() || gen["cells"].size() != std::size_t(CellCount))
        bad(name, where("cells"), "must be an array of 9 designs or nulls");
    const nlohmann::ordered_json* bases = nullptr;
    if (gen.contains("bases")) {
        bases = &gen["bases"];
        if (!bases->is_array() || bases->size() != std::size_t(CellCount))
            bad(name, where("bases"), "must be an array of 9 folders or nulls");
    }
    bool any = false;
    for (int i = 0; i < CellCount; ++i) {
        const auto& cell = gen["cells"][std::size_t(i)];
        if (cell.is_null()) continue;
        const std::string cellAt = where("cells[" + std::to_string(i) + "]");
        // The genome's own reader checks every rule of the format.
        Genome genome = parseGenome(cell.dump(), name + ": " + cellAt);
        if (bases) {
            const auto& base = (*bases)[std::size_t(i)];
            if (base.is_string())
                genome.baseDirectory = base.get<std::string>();
            else if (!base.is_null())
                bad(name, where("bases[" + std::to_string(i) + "]"), "must be a folder name or null");
        }
        g.cells[std::size_t(i)] = std::move(genome);
        any = true;
    }
    if (!any) bad(name, where("cells"), "a generation holds at least one design");
    for (int i : cellList(gen, "selected", name, at))
        if (g.cells[std::size_t(i)]) g.selected[std::size_t(i)] = true;
    describeCells(g);
    return g;
}

void parseCurrent(const nlohmann::ordered_json& doc, const std::string& name, SavedSession& session) {
    if (!doc.contains("current") || !doc["current"].is_number_integer() ||
        doc["current"].get<long long>() < 0 ||
        doc["current"].get<long long>() >= static_cast<long long>(session.history.size()))
        bad(name, "current", "must name one of the generations");
    session.current = doc["current"].get<int>();
}

QByteArray readFile(const QString& file, qint64 limit, const char* what) {
    const std::string name = file.toStdString();
    QFile in(file);
    if (!in.open(QIODevice::ReadOnly))
        throw RuntimeFailure("cannot read " + name + ": " + in.errorString().toStdString());
    if (in.size() > limit) bad(name, "", std::string("the file is too large to be ") + what);
    const QByteArray text = in.readAll();
    if (in.error() != QFileDevice::NoError)
        throw RuntimeFailure("cannot read " + name + ": " + in.errorString().toStdString());
    return text;
}

} // namespace

namespace {

/// A whole document (version 1 or 2).
SavedSession parseDocument(const nlohmann::ordered_json& doc, const std::string& name) {
    SavedSession session;
    const int version = parseHead(doc, name, session);
    if (version >= 3)
        bad(name, "generations",
            "a version 3 session keeps its generations in a folder beside it: open the file, not its text");
    if (!doc.contains("generations") || !doc["generations"].is_array() || doc["generations"].empty())
        bad(name, "generations", "must be a non-empty array");
    const auto& generations = doc["generations"];
    for (std::size_t k = 0; k < generations.size(); ++k) {
        session.history.push_back(
            parseGeneration(generations[k], version, k, name, "generations[" + std::to_string(k) + "]"));
        numberGeneration(session.history, k);
    }
    parseCurrent(doc, name, session);
    return session;
}

} // namespace

SavedSession parseSession(std::string_view text, const std::string& name) {
    return parseDocument(parseJson(text, name), name);
}

Generation readGeneration(const QString& folder, int index) {
    const QString file = generationFile(folder, index);
    const QByteArray text = readFile(file, MaxGenerationBytes, "a generation");
    return parseGenerationText(std::string_view(text.constData(), std::size_t(text.size())), index,
                               file.toStdString());
}

Generation parseGenerationText(std::string_view text, int index, const std::string& name) {
    return parseGeneration(parseJson(text, name), SessionVersion, std::size_t(index), name, "");
}

SavedSession loadSession(const QString& file) {
    const std::string name = file.toStdString();
    const QByteArray text = readFile(file, MaxSessionBytes, "a session");
    const std::string_view view(text.constData(), std::size_t(text.size()));
    // A head says its version before its generations; only version 3 has a count.
    const nlohmann::ordered_json doc = parseJson(view, name);
    if (!doc.is_object() || !doc.contains("version") || doc["version"] != SessionVersion)
        return parseDocument(doc, name);
    SavedSession session;
    parseHead(doc, name, session);
    if (!doc["count"].is_number_unsigned() || doc["count"].get<std::uint64_t>() == 0 ||
        doc["count"].get<std::uint64_t>() > 1000000)
        bad(name, "count", "must be the number of generations (1 or more)");
    const int count = doc["count"].get<int>();
    if (!doc.contains("current") || !doc["current"].is_number_integer() ||
        doc["current"].get<long long>() < 0 || doc["current"].get<long long>() >= count)
        bad(name, "current", "must name one of the generations");
    const int current = doc["current"].get<int>();
    session.folder = generationsFolder(file);
    // Every generation is read (and checked) once; only the current one and the newest few stay
    // in memory, the others are read back from the folder when they are wanted.
    for (int k = 0; k < count; ++k) {
        Generation g = readGeneration(session.folder, k);
        if (k != current && k < count - PopulationModel::HeldGenerations) {
            g.cells = {};
            g.held = false;
        }
        session.history.push_back(std::move(g));
        numberGeneration(session.history, std::size_t(k));
    }
    session.current = current;
    return session;
}

QString keepBadSession(const QString& file) {
    for (int n = 1; n < 1000; ++n) {
        const QString aside =
            n == 1 ? file + QStringLiteral(".bad") : QStringLiteral("%1.%2.bad").arg(file).arg(n);
        if (QFileInfo::exists(aside)) continue;
        return QFile::rename(file, aside) ? aside : QString();
    }
    return {};
}

} // namespace marbler::ui
