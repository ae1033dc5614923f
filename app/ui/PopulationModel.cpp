#include "ui/PopulationModel.h"

#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "ui/Session.h"
#include "ui/Trash.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>
#include <set>

namespace marbler::ui {

namespace {

/// SplitMix64: turns (session seed, counter) into well-spread seeds, so neighbouring
/// generations do not get neighbouring seeds.
std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t counter) {
    std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (counter + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

} // namespace

PopulationModel::PopulationModel(QObject* parent) : QObject(parent) {
    mHistory.emplace_back();
    mHistory.back().description = tr("Empty workbench");
}

const Genome* PopulationModel::cell(int index) const {
    if (index < 0 || index >= CellCount) return nullptr;
    const auto& c = current().cells[std::size_t(index)];
    return c ? &*c : nullptr;
}

bool PopulationModel::isSelected(int index) const {
    return index >= 0 && index < CellCount && current().selected[std::size_t(index)];
}

std::vector<int> PopulationModel::selectedCells() const {
    std::vector<int> result;
    for (int i = 0; i < CellCount; ++i)
        if (isSelected(i)) result.push_back(i);
    return result;
}

int PopulationModel::selectedCount() const { return int(selectedCells().size()); }

void PopulationModel::toggleSelected(int index) { setSelected(index, !isSelected(index)); }

void PopulationModel::setSelected(int index, bool selected) {
    if (index < 0 || index >= CellCount) return;
    if (selected && !cell(index)) return;
    auto& flag = currentMutable().selected[std::size_t(index)];
    if (flag == selected) return;
    flag = selected;
    emit selectionChanged();
}

void PopulationModel::clearSelection() {
    auto& sel = currentMutable().selected;
    if (std::none_of(sel.begin(), sel.end(), [](bool b) { return b; })) return;
    sel.fill(false);
    emit selectionChanged();
}

bool PopulationModel::canApply(GeneticOperator op) const {
    const auto selected = selectedCells();
    const int n = int(selected.size());
    if (n < minParents(op)) return false;
    if (maxParents(op) > 0 && n > maxParents(op)) return false;
    // Every cell selected leaves no room for offspring.
    if (n >= CellCount) return false;
    const int dimension = cell(selected.front())->dimension;
    return std::all_of(selected.begin(), selected.end(), [&](int i) { return cell(i)->dimension == dimension; });
}

std::uint64_t PopulationModel::nextBreedSeed() const {
    return mixSeed(mSessionSeed, std::uint64_t(mCurrent + 1));
}

void PopulationModel::apply(GeneticOperator op, double strength) {
    const auto selected = selectedCells();
    BreedRequest request;
    request.op = op;
    request.seed = nextBreedSeed();
    request.strength = std::clamp(strength, 0.0, 1.0);
    for (int i : selected) request.parents.push_back(*cell(i));
    request.count = CellCount - int(selected.size());
    if (request.count <= 0) throw InputError("every cell is a parent: deselect one to make room for offspring");
    // The children carry the numbers the user sees: the generation they make (as the status
    // bar counts it) and the design (cell) each goes to.
    request.generation = displayNumber(mCurrent + 1);
    for (int i = 0; i < CellCount; ++i)
        if (!current().selected[std::size_t(i)]) request.childNumbers.push_back(i + 1);
    std::vector<Genome> children = breed(request);
    if (children.size() != std::size_t(request.count)) throw RuntimeFailure("the operator made too few offspring");

    Generation next;
    next.selected = current().selected;
    next.parentCells = selected;
    next.description = selected.size() == 1
        ? tr("%1 of 1 parent").arg(operatorLabel(op))
        : tr("%1 of %2 parents").arg(operatorLabel(op)).arg(selected.size());
    std::size_t child = 0;
    for (int i = 0; i < CellCount; ++i) {
        if (current().selected[std::size_t(i)]) {
            next.cells[std::size_t(i)] = current().cells[std::size_t(i)];
        } else {
            next.cells[std::size_t(i)] = children[child++];
        }
    }
    pushGeneration(std::move(next));
}

void PopulationModel::newRandomPopulation(int dimension) {
    Generation next;
    next.description = dimension == 3 ? tr("New random solid population") : tr("New random population");
    // Seeded by the number the new generation gets, which the placeholder does not take: the
    // first population (generation 1) and the next one (2) draw from different seeds.
    const int number = mEmptyStart ? 0 : mCurrent + 1;
    const std::uint64_t base = mixSeed(mSessionSeed, std::uint64_t(number) * 1000003ULL);
    // A new population is new: no design repeats one of the grid it replaces, or another.
    std::set<std::string> taken;
    for (const auto& c : current().cells)
        if (c) taken.insert(genomeId(*c));
    std::uint64_t draw = 0;
    for (int i = 0; i < CellCount; ++i) {
        for (;;) {
            const std::uint64_t seed = mixSeed(base, draw++) & 0xffffffffULL;
            Genome g = randomGenome(seed, dimension);
            if (!taken.insert(genomeId(g)).second && draw < 1000) continue;
            if (!g.meta.contains("seed")) g.meta["seed"] = seed;
            next.cells[std::size_t(i)] = std::move(g);
            break;
        }
    }
    pushGeneration(std::move(next));
}

std::vector<int> PopulationModel::placeDesigns(const std::vector<Genome>& designs, const QString& description) {
    std::vector<int> order = selectedCells();
    for (int i = 0; i < CellCount; ++i)
        if (!cell(i) && std::find(order.begin(), order.end(), i) == order.end()) order.push_back(i);
    for (int i = 0; i < CellCount; ++i)
        if (std::find(order.begin(), order.end(), i) == order.end()) order.push_back(i);

    Generation next = current();
    next.description = description;
    std::vector<int> used;
    for (std::size_t k = 0; k < designs.size() && k < order.size(); ++k) {
        const int index = order[k];
        next.cells[std::size_t(index)] = designs[k];
        next.selected[std::size_t(index)] = false;
        used.push_back(index);
    }
    if (!used.empty()) pushGeneration(std::move(next));
    return used;
}

void PopulationModel::setCell(int index, const Genome& genome, const QString& description) {
    if (index < 0 || index >= CellCount) return;
    Generation next = current();
    next.description = description;
    next.cells[std::size_t(index)] = genome;
    next.selected[std::size_t(index)] = false;
    pushGeneration(std::move(next));
}

void PopulationModel::setCellLocks(int index, const Locks& locks) {
    if (!cell(index)) return;
    setLocks(*currentMutable().cells[std::size_t(index)], locks);
    if (std::size_t(mCurrent) < mSessionCells.size()) mSessionCells[std::size_t(mCurrent)].clear();
    emit cellChanged(index);
    autosave();
}

void PopulationModel::pushGeneration(Generation generation) {
    if (mEmptyStart) {
        // The first designs replace the empty placeholder: they are generation 1.
        mEmptyStart = false;
        mCurrent = -1;
    }
    mHistory.resize(std::size_t(mCurrent + 1));
    if (mSessionCells.size() > mHistory.size()) mSessionCells.resize(mHistory.size());
    generation.number = mCurrent + 1;
    mHistory.push_back(std::move(generation));
    mCurrent = int(mHistory.size()) - 1;
    currentGenerationChanged();
}

void PopulationModel::goBack() {
    if (!canGoBack()) return;
    --mCurrent;
    currentGenerationChanged();
}

void PopulationModel::goForward() {
    if (!canGoForward()) return;
    ++mCurrent;
    currentGenerationChanged();
}

void PopulationModel::goTo(int index) {
    if (index < 0 || index >= int(mHistory.size()) || index == mCurrent) return;
    mCurrent = index;
    currentGenerationChanged();
}

void PopulationModel::setSessionFile(const QString& file) {
    mSessionFile = file;
    autosave();
}

bool PopulationModel::saveSession() {
    if (mSessionFile.isEmpty() || mEmptyStart) return true;
    try {
        const QString folder = QFileInfo(mSessionFile).absolutePath();
        if (!QDir().mkpath(folder)) throw RuntimeFailure("cannot create the session folder " + folder.toStdString());
        writeFileAtomically(mSessionFile.toStdString(), serializeSession(*this, &mSessionCells));
        return true;
    } catch (const std::exception& e) { // also the JSON library's (a folder name that is not UTF-8)
        emit sessionSaveFailed(QString::fromStdString(e.what()));
        return false;
    }
}

void PopulationModel::autosave() { saveSession(); }

void PopulationModel::restoreSession(SavedSession session) {
    if (session.history.empty()) return;
    mHistory = std::move(session.history);
    mSessionCells.clear();
    for (std::size_t k = 0; k < mHistory.size(); ++k) mHistory[k].number = int(k);
    mCurrent = std::clamp(session.current, 0, int(mHistory.size()) - 1);
    mSessionSeed = session.seed;
    mMesh = session.mesh;
    mSessionLabel = session.label;
    mEmptyStart = false;
    currentGenerationChanged();
}

void PopulationModel::setSessionLabel(const SessionLabel& label) {
    if (label == mSessionLabel) return;
    mSessionLabel = label;
    autosave();
}

void PopulationModel::setMesh(const QString& mesh) {
    if (mesh == mMesh) return;
    mMesh = mesh;
    autosave();
}

int PopulationModel::populationDimension() const {
    for (const auto& c : current().cells)
        if (c) return c->dimension;
    return 2;
}

QString PopulationModel::defaultFavouritesFolder() {
    const QByteArray env = qgetenv("MARBLER_FAVOURITES_DIR");
    if (!env.isEmpty()) return QString::fromLocal8Bit(env);
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/favourites");
}

QStringList PopulationModel::setFavouritesFolder(const QString& folder) {
    mFavouritesFolder = folder;
    mRemovedFavourites.clear();
    // Removed favourites stay restorable for 30 days; older ones are deleted when the folder is
    // set, which is at each start of the window.
    if (!folder.isEmpty()) emptyTrash(favouritesTrashFolder(), 30);
    return reloadFavourites();
}

QString PopulationModel::favouritesTrashFolder() const {
    return mFavouritesFolder.isEmpty() ? QString() : QDir(mFavouritesFolder).filePath(QStringLiteral(".trash"));
}

QStringList PopulationModel::reloadFavourites() {
    mFavourites.clear();
    QStringList errors;
    QDir dir(mFavouritesFolder);
    if (!mFavouritesFolder.isEmpty() && dir.exists()) {
        // Files only, and not hidden ones: the trash (.trash) and an atomic write's temporary
        // are not favourites.
        const auto files = dir.entryInfoList({QStringLiteral("*.marble.json")}, QDir::Files, QDir::Name);
        for (const QFileInfo& info : files) {
            try {
                mFavourites.push_back({loadGenome(info.absoluteFilePath().toStdString()), info.absoluteFilePath()});
            } catch (const Error& e) {
                errors << QString::fromStdString(e.what());
            }
        }
    }
    emit favouritesChanged();
    return errors;
}

void PopulationModel::addFavourite(const Genome& genome) {
    if (mFavouritesFolder.isEmpty()) throw RuntimeFailure("no favourites folder is set");
    if (!QDir().mkpath(mFavouritesFolder))
        throw RuntimeFailure("cannot create the favourites folder " + mFavouritesFolder.toStdString());
    const QString id = QString::fromStdString(genomeId(genome));
    const QString file = QDir(mFavouritesFolder).filePath(id + QStringLiteral(".marble.json"));
    // The same design kept twice stays one favourite (the file name is its content id).
    for (const auto& f : mFavourites)
        if (QFileInfo(f.file) == QFileInfo(file)) return;
    saveGenome(genome, file.toStdString());
    mFavourites.push_back({genome, file});
    emit favouritesChanged();
}

QString PopulationModel::removeFavourite(int index) {
    if (index < 0 || index >= int(mFavourites.size())) return {};
    const QString file = mFavourites[std::size_t(index)].file;
    const QString trashed = moveToTrash(file, favouritesTrashFolder());
    if (trashed.isEmpty())
        throw RuntimeFailure("cannot move " + file.toStdString() + " to the favourites' trash " +
                             favouritesTrashFolder().toStdString());
    mFavourites.erase(mFavourites.begin() + index);
    mRemovedFavourites << trashed;
    emit favouritesChanged();
    return trashed;
}

bool PopulationModel::restoreRemovedFavourite(const QString& trashed) {
    const QString file = restoreFromTrash(trashed, mFavouritesFolder);
    mRemovedFavourites.removeAll(trashed);
    if (file.isEmpty()) {
        emit favouritesChanged(); // the list of removed ones changed
        // Kept anew meanwhile (a favourite's file is named by its content): it is on the shelf.
        return QFileInfo::exists(QDir(mFavouritesFolder).filePath(originalTrashName(trashed)));
    }
    reloadFavourites(); // in its place in name order, as the next start shows it
    return true;
}

QString operatorLabel(GeneticOperator op) {
    switch (op) {
    case GeneticOperator::Alter: return PopulationModel::tr("Alter");
    case GeneticOperator::Recombine: return PopulationModel::tr("Recombine");
    case GeneticOperator::Swap: return PopulationModel::tr("Swap");
    case GeneticOperator::Reinit: return PopulationModel::tr("Change initial state");
    }
    return {};
}

QString operatorLabel(const QString& name) {
    const std::optional<GeneticOperator> op = parseOperator(name.toStdString());
    return op ? operatorLabel(*op) : name;
}

int displayNumber(int index) { return index + 1; }

LineageInfo lineageOf(const Genome& genome) {
    LineageInfo info;
    const auto& meta = genome.meta;
    if (meta.contains("id") && meta["id"].is_string())
        info.id = QString::fromStdString(meta["id"].get<std::string>());
    else
        info.id = QString::fromStdString(genomeId(genome));
    if (meta.contains("name") && meta["name"].is_string()) info.name = QString::fromStdString(meta["name"].get<std::string>());
    if (meta.contains("lineage") && meta["lineage"].is_object()) {
        const auto& lineage = meta["lineage"];
        if (lineage.contains("operator") && lineage["operator"].is_string())
            info.op = QString::fromStdString(lineage["operator"].get<std::string>());
        if (lineage.contains("parents") && lineage["parents"].is_array())
            for (const auto& p : lineage["parents"])
                if (p.is_string()) info.parents << QString::fromStdString(p.get<std::string>());
        if (lineage.contains("generation") && lineage["generation"].is_number_integer())
            info.generation = lineage["generation"].get<int>();
        info.varied = lineage.contains("variation") && lineage["variation"].is_object();
    }
    return info;
}

void PopulationModel::currentGenerationChanged() {
    emit populationChanged();
    emit selectionChanged();
    emit historyChanged();
    autosave();
}

} // namespace marbler::ui
