#include "workbench/PopulationModel.h"

#include "marbler/Colourways.h"
#include "marbler/Error.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "shared/RenameDialog.h"
#include "workbench/Session.h"
#include "workbench/Trash.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>
#include <set>

namespace marbler::ui {

PopulationModel::PopulationModel(QObject* parent)
    : QObject(parent) {
    mHistory.emplace_back();
    mHistory.back().description = tr("Empty workbench");
    mStored.emplace_back();
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

int PopulationModel::selectedCount() const {
    return int(selectedCells().size());
}

void PopulationModel::toggleSelected(int index) {
    setSelected(index, !isSelected(index));
}

void PopulationModel::setSelected(int index, bool selected) {
    if (index < 0 || index >= CellCount) return;
    if (selected && !cell(index)) return;
    auto& flag = currentMutable().selected[std::size_t(index)];
    if (flag == selected) return;
    flag = selected;
    selectionEdited();
    emit selectionChanged();
}

void PopulationModel::clearSelection() {
    auto& sel = currentMutable().selected;
    if (std::none_of(sel.begin(), sel.end(), [](bool b) { return b; })) return;
    sel.fill(false);
    selectionEdited();
    emit selectionChanged();
}

QString PopulationModel::whyNot(GeneticOperator op) const {
    const QString label = operatorLabel(op);
    const auto selected = selectedCells();
    const int n = int(selected.size());
    const int least = minParents(op), most = maxParents(op);
    // What the operator takes, said the same way in every message.
    const QString needs = most == 0 ? tr("%1 needs %2 or more parents").arg(label).arg(least)
                          : least == most && least == 1
                              ? tr("%1 needs 1 parent").arg(label)
                              : tr("%1 needs exactly %2 parents").arg(label).arg(least);
    if (mEmptyStart)
        return tr("%1: there are no designs yet; make a new random population or open designs").arg(needs);
    if (n == 0)
        return least == 1
                   ? tr("%1: click a design to pick it").arg(needs)
                   : tr("%1: click %2 designs").arg(needs, least == 2 ? tr("two") : QString::number(least));
    if (n < least) return tr("%1: %2 is picked, click another design").arg(needs).arg(n);
    if (most > 0 && n > most) return tr("%1: %2 are picked, click one to let it go").arg(needs).arg(n);
    // Every cell selected leaves no room for offspring.
    if (n >= CellCount)
        return tr("%1 has no room for offspring: every design is a parent, click one to let it go")
            .arg(label);
    const int dimension = cell(selected.front())->dimension;
    if (!std::all_of(selected.begin(), selected.end(),
                     [&](int i) { return cell(i)->dimension == dimension; }))
        return n == 2 ? tr("%1 needs two parents of the same kind (flat/solid): one picked design is flat, "
                           "the other solid")
                            .arg(label)
                      : tr("%1 needs parents of the same kind (flat/solid): the picked designs mix flat and "
                           "solid ones")
                            .arg(label);
    return {};
}

std::uint64_t PopulationModel::nextBreedSeed() const {
    // The new generation's index: in a session without branches it is the generation's
    // position, as before branches existed, and it never repeats.
    return mixSeed(mSessionSeed, std::uint64_t(mHistory.size()));
}

void PopulationModel::apply(GeneticOperator op, double strength) {
    PendingBreed pending = prepareBreed(op, strength);
    breedPending(pending);
    commitBreed(std::move(pending));
}

PopulationModel::PendingBreed PopulationModel::prepareBreed(GeneticOperator op, double strength) const {
    const auto selected = selectedCells();
    PendingBreed pending;
    pending.op = op;
    BreedRequest& request = pending.steer.breed;
    request.op = op;
    request.seed = nextBreedSeed();
    request.strength = std::clamp(strength, 0.0, 1.0);
    for (int i : selected)
        request.parents.push_back(*cell(i));
    request.count = CellCount - int(selected.size());
    if (request.count <= 0)
        throw InputError("every cell is a parent: deselect one to make room for offspring");
    // The children carry the numbers the user sees: the generation they make (as the status
    // bar counts it) and the design (cell) each goes to.
    request.generation = current().number + 1;
    for (int i = 0; i < CellCount; ++i)
        if (!current().selected[std::size_t(i)]) request.childNumbers.push_back(i + 1);
    // Steering (issue 26): the offspring ranked by what the picks so far say.
    pending.steered = mSteering;
    if (mSteering) {
        pending.steer.rounds = steerRounds(request.parents);
        pending.steer.fresh = mWildcard;
    }
    pending.wildcard = mWildcard;
    pending.selected = current().selected;
    pending.current = mCurrent;
    pending.historySize = mHistory.size();
    return pending;
}

void PopulationModel::breedPending(PendingBreed& pending) {
    const BreedRequest& request = pending.steer.breed;
    std::vector<Genome> children;
    if (pending.steered) {
        SteerResult steered = steerBreed(pending.steer);
        children = std::move(steered.children);
        pending.explanation = std::move(steered.explanation);
    } else {
        children = breed(request);
    }
    if (children.size() != std::size_t(request.count))
        throw RuntimeFailure("the operator made too few offspring");
    if (pending.wildcard && children.size() > 1) children.back() = wildcardChild(request, children.back());
    pending.children = std::move(children);
}

void PopulationModel::commitBreed(PendingBreed pending) {
    if (pending.current != mCurrent || pending.historySize != mHistory.size() ||
        pending.children.size() != std::size_t(pending.steer.breed.count))
        throw RuntimeFailure("the population changed while a generation was being bred");
    const GeneticOperator op = pending.op;
    std::vector<int> selected;
    for (int i = 0; i < CellCount; ++i)
        if (pending.selected[std::size_t(i)]) selected.push_back(i);
    Generation next;
    next.selected = pending.selected;
    next.parentCells = selected;
    next.description = selected.size() == 1
                           ? tr("%1 of 1 parent").arg(operatorLabel(op))
                           : tr("%1 of %2 parents").arg(operatorLabel(op)).arg(selected.size());
    std::size_t child = 0;
    for (int i = 0; i < CellCount; ++i) {
        if (pending.selected[std::size_t(i)]) {
            next.cells[std::size_t(i)] = current().cells[std::size_t(i)];
        } else {
            next.cells[std::size_t(i)] = std::move(pending.children[child++]);
        }
    }
    if (!pending.explanation.empty())
        mExplanations[int(mHistory.size())] = QString::fromStdString(pending.explanation);
    pushGeneration(std::move(next));
}

// --- Steering (issue 26) ---
template <typename Enough> std::vector<PickRound> PopulationModel::roundsNewestFirst(Enough enough) const {
    std::vector<PickRound> rounds;
    if (mEmptyStart) return rounds;
    const auto roundOf = [&](const Generation& from, const std::vector<int>& picked) {
        PickRound round;
        for (int i = 0; i < CellCount; ++i) {
            const auto& c = from.cells[std::size_t(i)];
            if (!c) continue;
            if (std::find(picked.begin(), picked.end(), i) != picked.end())
                round.picked.push_back(*c);
            else if (mDisliked.count(genomeId(*c)))
                round.disliked.push_back(*c);
            else
                round.passed.push_back(*c);
        }
        return round;
    };
    rounds.push_back(roundOf(current(), selectedCells()));
    // The generations on the way from the root, read back when they are not in memory.
    for (int g = mCurrent; g >= 0 && mHistory[std::size_t(g)].parent >= 0 && !enough(rounds);) {
        const int parent = mHistory[std::size_t(g)].parent;
        const std::vector<int> cells = mHistory[std::size_t(g)].parentCells;
        if (!cells.empty()) rounds.push_back(roundOf(generation(parent), cells));
        g = parent;
    }
    return rounds;
}

std::vector<PickRound> PopulationModel::pickRounds() const {
    std::vector<PickRound> rounds = roundsNewestFirst([](const std::vector<PickRound>&) { return false; });
    std::reverse(rounds.begin(), rounds.end());
    return rounds;
}

std::vector<PickRound> PopulationModel::steerRounds(const std::vector<Genome>& parents) const {
    // steerBreed reads the newest MaxSteerRounds rounds, and the newest picks until it has two
    // mates besides the parents: the rounds up to there give the same offspring as all of them,
    // without reading back every generation of a long session.
    std::vector<PickRound> rounds = roundsNewestFirst([&](const std::vector<PickRound>& newest) {
        if (newest.size() < std::size_t(MaxSteerRounds)) return false;
        std::vector<Genome> mates = parents;
        for (const PickRound& round : newest) {
            if (mates.size() >= parents.size() + 2) break;
            for (const Genome& g : round.picked)
                if (g.dimension == parents.front().dimension &&
                    std::none_of(mates.begin(), mates.end(),
                                 [&](const Genome& m) { return genomeId(m) == genomeId(g); }))
                    mates.push_back(g);
        }
        return mates.size() >= parents.size() + 2;
    });
    std::reverse(rounds.begin(), rounds.end());
    return rounds;
}

void PopulationModel::setDisliked(int index, bool disliked) {
    const Genome* g = cell(index);
    if (!g) return;
    const std::string id = genomeId(*g);
    if (disliked == bool(mDisliked.count(id))) return;
    if (disliked) {
        mDisliked.insert(id);
        setSelected(index, false);
    } else {
        mDisliked.erase(id);
    }
    emit selectionChanged();
}

bool PopulationModel::isDisliked(int index) const {
    const Genome* g = cell(index);
    return g && mDisliked.count(genomeId(*g));
}

QString PopulationModel::steerExplanation() const {
    auto it = mExplanations.find(mCurrent);
    return it == mExplanations.end() ? QString() : it->second;
}
// --- end steering ---

QString PopulationModel::whyNoColourways(bool mix) const {
    if (QString why = whyNot(mix ? GeneticOperator::Recombine : GeneticOperator::Alter); !why.isEmpty())
        return why;
    for (int i : selectedCells())
        if (locksOf(*cell(i)).palette)
            return tr("Design %1's palette is locked, and colourways change only the palette: unlock it "
                      "first")
                .arg(i + 1);
    return {};
}

void PopulationModel::applyColourways(bool mix, double strength, const QString& description) {
    const auto selected = selectedCells();
    ColourwayRequest request;
    request.mix = mix;
    request.strength = std::clamp(strength, 0.0, 1.0);
    request.seed = nextBreedSeed();
    for (int i : selected)
        request.parents.push_back(*cell(i));
    request.count = CellCount - int(selected.size());
    if (request.count <= 0)
        throw InputError("every cell is a parent: deselect one to make room for colourways");
    request.generation = current().number + 1;
    for (int i = 0; i < CellCount; ++i)
        if (!current().selected[std::size_t(i)]) request.childNumbers.push_back(i + 1);
    std::vector<Genome> children = colourways(request);

    Generation next;
    next.selected = current().selected;
    next.parentCells = selected;
    next.description = !description.isEmpty() ? description
                       : selected.size() == 1 ? tr("Colourways of 1 parent")
                                              : tr("Colourways mixed from %1 parents").arg(selected.size());
    std::size_t child = 0;
    for (int i = 0; i < CellCount; ++i)
        next.cells[std::size_t(i)] =
            current().selected[std::size_t(i)] ? current().cells[std::size_t(i)] : children[child++];
    pushGeneration(std::move(next));
}

void PopulationModel::newRandomPopulation(int dimension, const std::string& family) {
    Generation next;
    const Family* only = findFamily(family);
    if (only && only->dimension != dimension) only = nullptr;
    if (only)
        next.description =
            tr("New %1 population").arg(QString::fromUtf8(only->name.data(), qsizetype(only->name.size())));
    else
        next.description = dimension == 3 ? tr("New random solid population") : tr("New random population");
    // Seeded by the index the new generation gets, which the placeholder does not take: the
    // first population and every later one draw from different seeds.
    const std::size_t number = mEmptyStart ? 0 : mHistory.size();
    const std::uint64_t base = mixSeed(mSessionSeed, std::uint64_t(number) * 1000003ULL);
    // A new population is new: no design repeats one of the grid it replaces.
    std::set<std::string> taken;
    for (const auto& c : current().cells)
        if (c) taken.insert(genomeId(*c));
    std::vector<Genome> designs = newPopulation(base, dimension, only, CellCount, std::move(taken));
    for (int i = 0; i < CellCount; ++i)
        next.cells[std::size_t(i)] = std::move(designs[std::size_t(i)]);
    pushGeneration(std::move(next));
}

std::vector<int> PopulationModel::placementCells(std::size_t count, Placement placement) const {
    std::vector<int> order;
    const auto take = [&](auto&& wanted) {
        for (int i = 0; i < CellCount; ++i)
            if (wanted(i) && std::find(order.begin(), order.end(), i) == order.end()) order.push_back(i);
    };
    if (placement == Placement::IntoSelected) {
        take([&](int i) { return isSelected(i); });
        take([&](int i) { return !cell(i); });
        take([](int) { return true; });
    } else {
        take([&](int i) { return !cell(i); });
        take([&](int i) { return !isSelected(i); });
    }
    if (order.size() > count) order.resize(count);
    return order;
}

std::vector<int> PopulationModel::placeDesigns(const std::vector<Genome>& designs, const QString& description,
                                               Placement placement) {
    const std::vector<int> used = placementCells(designs.size(), placement);
    Generation next = current();
    next.description = description;
    next.parentCells.clear(); // opened designs were not bred from the previous parents
    for (std::size_t k = 0; k < used.size(); ++k) {
        next.cells[std::size_t(used[k])] = designs[k];
        next.selected[std::size_t(used[k])] = false;
    }
    if (!used.empty()) pushGeneration(std::move(next));
    return used;
}

std::vector<int> PopulationModel::startGenerationOf(const std::vector<Genome>& designs,
                                                    const QString& description, int first) {
    Generation next;
    next.description = description;
    std::vector<int> used;
    first = std::clamp(first, 0, CellCount - 1);
    for (std::size_t k = 0; k < designs.size() && k < std::size_t(CellCount); ++k) {
        const int index = (first + int(k)) % CellCount;
        next.cells[std::size_t(index)] = designs[k];
        used.push_back(index);
    }
    if (!used.empty()) pushGeneration(std::move(next));
    return used;
}

void PopulationModel::setCell(int index, const Genome& genome, const QString& description) {
    if (index < 0 || index >= CellCount) return;
    Generation next = current();
    next.description = description;
    next.parentCells.clear(); // an opened design was not bred from the previous parents
    next.cells[std::size_t(index)] = genome;
    next.selected[std::size_t(index)] = false;
    pushGeneration(std::move(next));
}

void PopulationModel::setCellLocks(int index, const Locks& locks) {
    if (!cell(index)) return;
    setLocks(*currentMutable().cells[std::size_t(index)], locks);
    currentChangedInPlace();
    emit cellChanged(index);
    autosave();
}

void PopulationModel::setCellView(int index, const ViewAngle& view) {
    if (!cell(index)) return;
    setViewAngle(*currentMutable().cells[std::size_t(index)], view);
    currentChangedInPlace();
    emit cellChanged(index);
    autosave();
}

void PopulationModel::uniqueNames(Generation& generation) const {
    // Two different designs of a session never share a name: two branches both breed a
    // "(g4 #1)", a family draws the same words twice. The same design again keeps its name.
    // By each design's info: the generations not in memory are not read back for their names.
    std::map<std::string, std::vector<std::string>> named; ///< name: the ids of the designs so named
    const auto idOf = [](const Genome& g) { return g.meta.id ? *g.meta.id : genomeId(g); };
    const auto add = [&](const Genome& g) {
        if (g.meta.name) named[*g.meta.name].push_back(idOf(g));
    };
    for (const Generation& earlier : mHistory)
        for (const CellInfo& info : earlier.info)
            if (info.present && info.name) named[*info.name].push_back(info.id);
    for (const Favourite& f : mFavourites)
        add(f.genome);
    for (auto& design : generation.cells) {
        if (!design || !design->meta.name) continue;
        auto found = named.find(*design->meta.name);
        if (found != named.end()) {
            const std::string id = idOf(*design);
            const bool other = std::any_of(found->second.begin(), found->second.end(),
                                           [&](const std::string& g) { return g != id; });
            if (other) {
                std::set<std::string> taken;
                for (const auto& entry : named)
                    taken.insert(entry.first);
                design->meta.name = uniqueName(*design->meta.name, taken);
            }
        }
        add(*design);
    }
}

std::set<std::string> PopulationModel::sessionNames(const std::string& except) const {
    std::set<std::string> names;
    const auto add = [&](const Genome& g) {
        if (g.meta.name && (except.empty() || genomeId(g) != except)) names.insert(*g.meta.name);
    };
    for (const Generation& generation : mHistory)
        for (const CellInfo& info : generation.info)
            if (info.present && info.name && (except.empty() || info.contentId != except))
                names.insert(*info.name);
    for (const Favourite& f : mFavourites)
        add(f.genome);
    return names;
}

QString PopulationModel::renameCell(int index, const QString& name, const QString& note, bool exact) {
    if (!cell(index)) return {};
    Genome& design = *currentMutable().cells[std::size_t(index)];
    const QString given =
        exact ? name : QString::fromStdString(uniqueName(name.toStdString(), sessionNames(genomeId(design))));
    setNameAndNote(design, given, note);
    currentChangedInPlace();
    emit cellChanged(index);
    autosave();
    return given;
}

QString PopulationModel::renameFavourite(int index, const QString& name, const QString& note) {
    if (index < 0 || index >= int(mFavourites.size())) return {};
    Favourite& f = mFavourites[std::size_t(index)];
    Genome renamed = f.genome;
    const QString given =
        QString::fromStdString(uniqueName(name.toStdString(), sessionNames(genomeId(renamed))));
    setNameAndNote(renamed, given, note);
    try {
        saveGenome(renamed, f.file.toStdString());
    } catch (const Error&) {
        return {};
    }
    f.genome = std::move(renamed);
    emit favouritesChanged();
    return given;
}

void PopulationModel::pushGeneration(Generation generation) {
    uniqueNames(generation);
    if (mEmptyStart) {
        // The first designs replace the empty placeholder: they are generation 1.
        mEmptyStart = false;
        mHistory.clear();
        mStored.clear();
        mHeld.clear();
        mForwardChild.clear();
        generation.parent = -1;
    } else {
        generation.parent = mCurrent;
    }
    generation.held = true;
    describeCells(generation);
    mHistory.push_back(std::move(generation));
    mStored.emplace_back();
    numberGeneration(mHistory, mHistory.size() - 1);
    mForwardChild.resize(mHistory.size(), -1);
    setCurrent(int(mHistory.size()) - 1);
    currentGenerationChanged();
}

std::vector<int> PopulationModel::children(int index) const {
    std::vector<int> result;
    for (std::size_t k = 0; k < mHistory.size(); ++k)
        if (mHistory[k].parent == index && index >= 0) result.push_back(int(k));
    return result;
}

QString PopulationModel::generationLabel(int index) const {
    if (index < 0 || index >= int(mHistory.size())) return {};
    const Generation& g = mHistory[std::size_t(index)];
    return g.branch == 1 ? QString::number(g.number) : tr("%1 (branch %2)").arg(g.number).arg(g.branch);
}

int PopulationModel::forwardTarget() const {
    if (mEmptyStart) return -1;
    const int remembered =
        std::size_t(mCurrent) < mForwardChild.size() ? mForwardChild[std::size_t(mCurrent)] : -1;
    if (remembered >= 0) return remembered;
    const std::vector<int> next = children(mCurrent);
    return next.empty() ? -1 : next.back();
}

bool PopulationModel::bringBack(int index) {
    return generation(index).held;
}

void PopulationModel::setCurrent(int index) {
    mCurrent = index;
    touch(index);
    // Every generation on the way from the root was visited on the way here.
    for (int k = index; mHistory[std::size_t(k)].parent >= 0; k = mHistory[std::size_t(k)].parent)
        mForwardChild[std::size_t(mHistory[std::size_t(k)].parent)] = k;
}

void PopulationModel::goBack() {
    if (!canGoBack() || !bringBack(current().parent)) return;
    setCurrent(current().parent);
    currentGenerationChanged();
}

void PopulationModel::goForward() {
    const int next = forwardTarget();
    if (next < 0 || !bringBack(next)) return;
    setCurrent(next);
    currentGenerationChanged();
}

void PopulationModel::goTo(int index) {
    if (mEmptyStart || index < 0 || index >= int(mHistory.size()) || index == mCurrent) return;
    if (!bringBack(index)) return;
    setCurrent(index);
    currentGenerationChanged();
}

void PopulationModel::setSessionFile(const QString& file) {
    mSessionFile = file;
    autosave();
}

bool PopulationModel::saveSession() {
    if (mSessionFile.isEmpty() || mEmptyStart) return true;
    try {
        // Generation files first, the head last: a crash in between leaves the head naming the
        // generations written before (Session.h).
        const QString folder = generationsFolder(mSessionFile);
        if (!QDir().mkpath(folder))
            throw RuntimeFailure("cannot create the session folder " + folder.toStdString());
        if (folder != mDiskFolder) {
            // A new place (the first save, or another file): every generation is written there,
            // and those kept only in the old place are taken along.
            for (std::size_t k = 0; k < mHistory.size(); ++k) {
                Stored& stored = mStored[k];
                if (!mHistory[k].held && stored.packed.isEmpty()) {
                    const QString old = generationFile(mDiskFolder, int(k));
                    QFile in(old);
                    if (!in.open(QIODevice::ReadOnly))
                        throw RuntimeFailure("cannot read " + old.toStdString() + ": " +
                                             in.errorString().toStdString());
                    stored.packed = qCompress(in.readAll());
                }
                stored.dirty = true;
            }
            mDiskFolder = folder;
        }
        for (std::size_t k = 0; k < mHistory.size(); ++k) {
            Stored& stored = mStored[k];
            if (!stored.dirty) continue;
            const QString file = generationFile(folder, int(k));
            if (mHistory[k].held) {
                writeFileAtomically(QFile::encodeName(file).toStdString(), serializeGeneration(mHistory[k]));
            } else {
                const QByteArray text = qUncompress(stored.packed);
                writeFileAtomically(QFile::encodeName(file).toStdString(),
                                    std::string(text.constData(), std::size_t(text.size())));
                stored.packed.clear(); // on disk now: read back from there
            }
            stored.dirty = false;
        }
        writeFileAtomically(QFile::encodeName(mSessionFile).toStdString(), serializeSessionHead(*this));
        return true;
    } catch (const std::exception& e) { // also the JSON library's (a folder name that is not UTF-8)
        emit sessionSaveFailed(QString::fromStdString(e.what()));
        return false;
    }
}

void PopulationModel::autosave() {
    saveSession();
}

const Generation& PopulationModel::generation(int index) const {
    Generation& g = mHistory[std::size_t(index)];
    if (!g.held) {
        Stored& stored = mStored[std::size_t(index)];
        try {
            QString name;
            QByteArray text;
            if (!stored.packed.isEmpty()) {
                text = qUncompress(stored.packed);
                name = tr("generation %1 of the session").arg(generationLabel(index));
            } else {
                name = generationFile(mDiskFolder, index);
                QFile in(name);
                if (!in.open(QIODevice::ReadOnly))
                    throw RuntimeFailure("cannot read back generation " + std::to_string(index) + " from " +
                                         name.toStdString() + ": " + in.errorString().toStdString());
                text = in.readAll();
            }
            Generation read = parseGenerationText(
                std::string_view(text.constData(), std::size_t(text.size())), index, name.toStdString());
            g.cells = std::move(read.cells);
            g.held = true;
        } catch (const std::exception& e) {
            // Its designs stay unknown (empty cells) and the window says why.
            emit const_cast<PopulationModel*>(this)->generationUnreadable(QString::fromStdString(e.what()));
            return g;
        }
    }
    touch(index);
    return g;
}

void PopulationModel::touch(int index) const {
    mHeld.erase(std::remove(mHeld.begin(), mHeld.end(), index), mHeld.end());
    mHeld.push_back(index);
    while (mHeld.size() > std::size_t(HeldGenerations) + 1) {
        // The least recently used one, never the current generation nor the one just used.
        const auto victim =
            std::find_if(mHeld.begin(), mHeld.end(), [&](int k) { return k != mCurrent && k != index; });
        if (victim == mHeld.end()) break;
        const int k = *victim;
        mHeld.erase(victim);
        release(k);
    }
}

void PopulationModel::release(int index) const {
    Generation& g = mHistory[std::size_t(index)];
    if (!g.held || mEmptyStart) return;
    Stored& stored = mStored[std::size_t(index)];
    // Its file is current on disk: read back from there; otherwise packed in memory.
    if ((stored.dirty || mDiskFolder.isEmpty()) && stored.packed.isEmpty())
        stored.packed = qCompress(QByteArray::fromStdString(serializeGeneration(g)));
    g.cells = {};
    g.held = false;
}

void PopulationModel::selectionEdited() {
    if (std::size_t(mCurrent) >= mStored.size()) return;
    mStored[std::size_t(mCurrent)].dirty = true;
    mStored[std::size_t(mCurrent)].packed.clear();
}

void PopulationModel::currentChangedInPlace() {
    describeCells(currentMutable());
    selectionEdited();
}

std::size_t PopulationModel::historyBytes() const {
    std::size_t bytes = mHistory.capacity() * sizeof(Generation) + mStored.capacity() * sizeof(Stored);
    for (std::size_t k = 0; k < mHistory.size(); ++k) {
        const Generation& g = mHistory[k];
        bytes +=
            std::size_t(g.description.capacity()) * sizeof(QChar) + g.parentCells.capacity() * sizeof(int);
        for (const CellInfo& info : g.info)
            bytes += info.contentId.capacity() + info.id.capacity() + (info.name ? info.name->capacity() : 0);
        for (const auto& cell : g.cells)
            if (cell) bytes += toJson(*cell).dump().size(); // the design, estimated by its text
        bytes += std::size_t(mStored[k].packed.capacity());
    }
    return bytes;
}

void PopulationModel::restoreSession(SavedSession session) {
    if (session.history.empty()) return;
    mHistory = std::move(session.history);
    for (std::size_t k = 0; k < mHistory.size(); ++k) {
        // A parent that is not an earlier generation would make a cycle: a root instead.
        int& parent = mHistory[k].parent;
        if (parent < -1 || parent >= int(k)) parent = -1;
        numberGeneration(mHistory, k);
        if (mHistory[k].held) describeCells(mHistory[k]);
    }
    // The generations not held are in the session's folder, and so are the others when there is
    // one: nothing is written again until something changes.
    mDiskFolder = session.folder;
    mStored.assign(mHistory.size(), Stored{QByteArray(), session.folder.isEmpty()});
    mHeld.clear();
    mEmptyStart = false;
    mForwardChild.assign(mHistory.size(), -1);
    // The newest held generations stay in memory, the others are packed (or left on disk).
    const int current = std::clamp(session.current, 0, int(mHistory.size()) - 1);
    mCurrent = current;
    for (std::size_t k = 0; k < mHistory.size(); ++k)
        if (mHistory[k].held) touch(int(k));
    bringBack(current);
    setCurrent(current);
    mSessionSeed = session.seed;
    mMesh = session.mesh;
    mFlatMesh = session.flatMesh;
    mSessionLabel = session.label;
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

void PopulationModel::setFlatMesh(const QString& mesh) {
    if (mesh == mFlatMesh) return;
    mFlatMesh = mesh;
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
    return mFavouritesFolder.isEmpty() ? QString()
                                       : QDir(mFavouritesFolder).filePath(QStringLiteral(".trash"));
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
                mFavourites.push_back(
                    {loadGenome(info.absoluteFilePath().toStdString()), info.absoluteFilePath()});
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

void numberGeneration(std::vector<Generation>& history, std::size_t k) {
    Generation& g = history[k];
    const bool firstChild = std::none_of(history.begin(), history.begin() + std::ptrdiff_t(k),
                                         [&](const Generation& other) { return other.parent == g.parent; });
    if (g.parent >= 0 && firstChild) {
        const Generation& parent = history[std::size_t(g.parent)];
        g.number = parent.number + 1;
        g.branch = parent.branch;
        return;
    }
    g.number = g.parent >= 0 ? history[std::size_t(g.parent)].number + 1 : 1;
    int branches = 0;
    for (std::size_t j = 0; j < k; ++j)
        branches = std::max(branches, history[j].branch);
    g.branch = branches + 1;
}

void describeCells(Generation& generation) {
    for (int i = 0; i < CellCount; ++i) {
        const auto& cell = generation.cells[std::size_t(i)];
        CellInfo& info = generation.info[std::size_t(i)];
        info = CellInfo{};
        if (!cell) continue;
        info.present = true;
        info.dimension = cell->dimension;
        info.contentId = genomeId(*cell);
        info.id = cell->meta.id ? *cell->meta.id : info.contentId;
        info.name = cell->meta.name;
    }
}

void PopulationModel::currentGenerationChanged() {
    emit populationChanged();
    emit selectionChanged();
    emit historyChanged();
    autosave();
}

} // namespace marbler::ui
