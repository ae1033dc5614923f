#include "editor/EditorDocument.h"

#include "marbler/ChangeSummary.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"

#include <QCryptographicHash>
#include <QFile>
#include <QUndoCommand>
#include <QtGlobal>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <unordered_set>
#include <utility>

namespace marbler::ui {

/// One state of the document: the design and the muted flags. Only the present state is held
/// whole (EditorDocument::mDesign, mMuted); the history holds what each edit changed.
struct EditorState {
    Genome design;
    std::vector<bool> muted;

    bool operator==(const EditorState& o) const { return design == o.design && muted == o.muted; }
};

/// A run of a list replaced: from index `at`, `removed` gave way to `inserted`; or, for a step
/// moved (`rotated` != 0), the run of `length` from `at` turned by one, its first entry moved to
/// its end (+1) or its last to its front (-1), which holds no entries at all. Applying it to the
/// list before gives the list after, reverting it the other way, exactly.
template <class T> struct ListSplice {
    std::size_t at = 0;
    std::vector<T> removed;
    std::vector<T> inserted;
    int rotated = 0;
    std::size_t length = 0;

    /// The smallest splice from `a` to `b`: what lies between their common head and tail.
    static ListSplice between(const std::vector<T>& a, const std::vector<T>& b) {
        std::size_t head = 0;
        const std::size_t shorter = std::min(a.size(), b.size());
        while (head < shorter && a[head] == b[head])
            ++head;
        std::size_t tail = 0;
        while (tail < shorter - head && a[a.size() - 1 - tail] == b[b.size() - 1 - tail])
            ++tail;
        ListSplice s;
        s.at = head;
        const auto first = static_cast<std::ptrdiff_t>(head);
        const auto last = static_cast<std::ptrdiff_t>(tail);
        if (a.size() == b.size() && a.size() - head - tail >= 2) {
            // A step moved far turns the run between, however long: keep the turn, not the run.
            const auto run = [&](const std::vector<T>& v) {
                return std::vector<T>(v.begin() + first, v.end() - last);
            };
            std::vector<T> turned = run(a);
            std::rotate(turned.begin(), turned.begin() + 1, turned.end());
            const std::vector<T> after = run(b);
            if (turned == after)
                s.rotated = 1;
            else {
                std::rotate(turned.begin(), turned.end() - 2, turned.end());
                if (turned == after) s.rotated = -1;
            }
            if (s.rotated != 0) {
                s.length = after.size();
                return s;
            }
        }
        s.removed.assign(a.begin() + first, a.end() - last);
        s.inserted.assign(b.begin() + first, b.end() - last);
        return s;
    }
    static void replace(std::vector<T>& v, std::size_t at, const std::vector<T>& out,
                        const std::vector<T>& in) {
        const auto first = v.begin() + static_cast<std::ptrdiff_t>(at);
        v.insert(v.erase(first, first + static_cast<std::ptrdiff_t>(out.size())), in.begin(), in.end());
    }
    void turn(std::vector<T>& v, int direction) const {
        const auto first = v.begin() + static_cast<std::ptrdiff_t>(at);
        const auto last = first + static_cast<std::ptrdiff_t>(length);
        std::rotate(first, direction > 0 ? first + 1 : last - 1, last);
    }
    void apply(std::vector<T>& v) const {
        if (rotated != 0)
            turn(v, rotated);
        else
            replace(v, at, removed, inserted);
    }
    void revert(std::vector<T>& v) const {
        if (rotated != 0)
            turn(v, -rotated);
        else
            replace(v, at, inserted, removed);
    }
    bool empty() const { return rotated == 0 && removed.empty() && inserted.empty(); }
};

namespace {

/// The heap and inline bytes of one step (its vectors included).
std::size_t bytesOf(const Operation& op) {
    return sizeof(Operation) + op.teeth.capacity() * sizeof(double) +
           op.path.capacity() * sizeof(glm::dvec2) + op.pressure.capacity() * sizeof(double);
}

/// A design without its steps: everything an edit may change besides them.
Genome headerOf(const Genome& g) {
    Genome h;
    h.dimension = g.dimension;
    h.size = g.size;
    h.background = g.background;
    h.palette = g.palette;
    h.source = g.source;
    h.bleed = g.bleed;
    h.wrap = g.wrap;
    h.meta = g.meta;
    h.baseDirectory = g.baseDirectory;
    h.fileName = g.fileName;
    h.allowExternalSource = g.allowExternalSource;
    return h;
}

/// Whether two designs agree in everything but their steps (the fields that are not saved
/// included, so that undo and redo give back exactly the genome that was there).
bool sameHeader(const Genome& a, const Genome& b) {
    return a.dimension == b.dimension && a.size == b.size && a.background == b.background &&
           a.palette == b.palette && a.source == b.source && a.bleed == b.bleed && a.wrap == b.wrap &&
           a.meta == b.meta && a.baseDirectory == b.baseDirectory && a.fileName == b.fileName &&
           a.allowExternalSource == b.allowExternalSource;
}

} // namespace

/// What one edit changed, and only that: the steps and muted flags replaced (a splice of each
/// list) and, when something else changed (an ink, the background, a new design), the design's
/// other fields before and after. An edit of one step of a 10,000-step design holds two steps,
/// not two designs, so the history grows with the edits made, not with the design's size
/// (docs/performance.md, "Long editing sessions"). Immutable: commands and branches share them,
/// and a shared edit is how two lines of history are known to share a state.
struct EditorDelta {
    std::optional<Genome> headerBefore; ///< set only when the fields besides the steps changed
    std::optional<Genome> headerAfter;
    ListSplice<Operation> initial;
    ListSplice<Operation> operations;
    ListSplice<bool> muted;
    std::size_t bytes = sizeof(EditorDelta); ///< what it holds, for EditorDocument::historyBytes

    static EditorDelta between(const EditorState& a, const EditorState& b) {
        EditorDelta d;
        if (!sameHeader(a.design, b.design)) {
            d.headerBefore = headerOf(a.design);
            d.headerAfter = headerOf(b.design);
            for (const Genome* h : {&*d.headerBefore, &*d.headerAfter})
                d.bytes += sizeof(Genome) + h->palette.capacity() * sizeof(Color) +
                           (h->source ? h->source->image.capacity() : 0) + h->baseDirectory.capacity() +
                           h->fileName.capacity() + toJson(*h).dump().size(); // meta, roughly
        }
        d.initial = ListSplice<Operation>::between(a.design.initial, b.design.initial);
        d.operations = ListSplice<Operation>::between(a.design.operations, b.design.operations);
        d.muted = ListSplice<bool>::between(a.muted, b.muted);
        for (const auto* list :
             {&d.initial.removed, &d.initial.inserted, &d.operations.removed, &d.operations.inserted})
            for (const Operation& op : *list)
                d.bytes += bytesOf(op);
        d.bytes += (d.muted.removed.size() + d.muted.inserted.size() + 7) / 8;
        return d;
    }

    /// Turns the state before the edit into the one after it (forward) or back.
    void step(EditorState& s, bool forward) const {
        if (headerAfter) {
            Genome h = forward ? *headerAfter : *headerBefore;
            h.initial = std::move(s.design.initial);
            h.operations = std::move(s.design.operations);
            s.design = std::move(h);
        }
        if (forward) {
            initial.apply(s.design.initial);
            operations.apply(s.design.operations);
            muted.apply(s.muted);
        } else {
            initial.revert(s.design.initial);
            operations.revert(s.design.operations);
            muted.revert(s.muted);
        }
    }

    /// Whether the list of steps must be rebuilt after it (EditorDocument::stepsChanged): steps
    /// added, removed, moved or muted, or a step's tool changed; not for a parameter edit of one
    /// step.
    bool structural() const {
        if (!muted.empty() || initial.rotated != 0 || operations.rotated != 0 ||
            initial.removed.size() != initial.inserted.size() ||
            operations.removed.size() != operations.inserted.size())
            return true;
        int changed = 0;
        for (const auto* part : {&initial, &operations})
            for (std::size_t i = 0; i < part->removed.size(); ++i) {
                if (part->removed[i] == part->inserted[i]) continue;
                if (part->removed[i].tool != part->inserted[i].tool) changed += 2;
                ++changed;
            }
        return changed > 1;
    }
};

using EditPtr = std::shared_ptr<const EditorDelta>;

struct EditorDocument::Line {
    struct Edit {
        QString text;
        EditPtr edit;
    };
    std::vector<Edit> edits;
};

namespace {

/// How a merged command names the change from its first state to its last.
using Describe = std::function<QString(const EditorState& before, const EditorState& after)>;

QString fromView(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}
QString hexName(Color c) {
    return QString::fromStdString(toHex(c));
}
/// A number as the history shows it: up to four significant figures, no locale.
QString number(double v) {
    return QString::number(v, 'g', 4);
}

const Operation& stepOf(const Genome& g, std::size_t i) {
    return i < g.initial.size() ? g.initial.at(i) : g.operations.at(i - g.initial.size());
}

QString stepLabel(const Genome& g, std::size_t i) {
    return QStringLiteral("%1 %2").arg(fromView(toolSpec(stepOf(g, i).tool).name)).arg(i + 1);
}

/// A genome holding only `op`, in `initial` or `operations`, with the dimension, size and palette
/// of `design`: the form in which the file's serializer and parser see one step.
Genome holder(const Genome& design, const std::optional<Operation>& op, bool initial) {
    Genome h;
    h.dimension = design.dimension;
    h.size = design.size;
    h.background = design.background;
    h.palette = design.palette;
    if (op) (initial ? h.initial : h.operations).push_back(*op);
    return h;
}

/// One step as its file form writes it.
nlohmann::ordered_json stepJson(const Genome& design, const Operation& op, bool initial) {
    return toJson(holder(design, op, initial)).at(initial ? "initial" : "operations").at(0);
}

/// The step a file form gives, read by the genome parser (every rule checked). Throws Error.
Operation parseStep(const Genome& design, const nlohmann::ordered_json& json, bool initial,
                    const std::string& name) {
    nlohmann::ordered_json j = toJson(holder(design, std::nullopt, initial));
    j["version"] = FormatVersion;
    j[initial ? "initial" : "operations"] = nlohmann::ordered_json::array({json});
    const Genome g = parseGenome(j.dump(), name);
    const auto& part = initial ? g.initial : g.operations;
    if (part.size() != 1) throw InputError(name + ": not one step");
    return part.front();
}

/// A step as it reads back from a file (vectors normalised, fields its tool lacks at their
/// defaults), so that what the editor holds is exactly what a save and a reload give, and a
/// recovered design equals the one being edited. A step the format refuses stays as it is.
Operation canonicalStep(const Genome& design, const Operation& op, bool initial) {
    try {
        return parseStep(design, stepJson(design, op, initial), initial, "step");
    } catch (const std::exception&) {
        return op;
    }
}

/// Inserts a step at full index `index` (Growth.h numbering) into the part given.
void insertStep(EditorState& s, std::size_t index, const Operation& op, bool initial, bool muted) {
    auto& g = s.design;
    if (initial) {
        index = std::min(index, g.initial.size());
        g.initial.insert(g.initial.begin() + static_cast<std::ptrdiff_t>(index), op);
    } else {
        index = std::clamp(index, g.initial.size(), g.initial.size() + g.operations.size());
        g.operations.insert(g.operations.begin() + static_cast<std::ptrdiff_t>(index - g.initial.size()), op);
    }
    s.muted.insert(s.muted.begin() + static_cast<std::ptrdiff_t>(index), muted);
}

/// Where a step of `tool` added as step `at` of `g` goes: its index, and whether in `initial`.
/// A tool that may stand in `initial` goes there when `at` is within it or at its end (the
/// same place in the design's order, and `initial` is where a design's inks are read).
struct Place {
    std::size_t index;
    bool initial;
};
Place placeFor(const Genome& g, Tool tool, std::size_t at) {
    const std::size_t initialCount = g.initial.size();
    const std::size_t n = initialCount + g.operations.size();
    at = std::min(at, n);
    const bool initial = allowedInInitial(tool, g.dimension) && at <= initialCount;
    return {initial ? at : std::max(at, initialCount), initial};
}

/// Removes step i; returns it.
Operation takeStep(EditorState& s, std::size_t i) {
    auto& g = s.design;
    Operation op = stepOf(g, i);
    if (i < g.initial.size())
        g.initial.erase(g.initial.begin() + static_cast<std::ptrdiff_t>(i));
    else
        g.operations.erase(g.operations.begin() + static_cast<std::ptrdiff_t>(i - g.initial.size()));
    s.muted.erase(s.muted.begin() + static_cast<std::ptrdiff_t>(i));
    return op;
}

/// A design as the editor holds it: read back as a file gives it (see canonicalStep), with the
/// steps kept aside in meta.editor.muted back in the list, muted, and meta without "editor".
EditorState unpack(Genome design) {
    try {
        Genome canonical =
            parseGenome(serializeGenome(design), design.fileName.empty() ? "design" : design.fileName);
        canonical.baseDirectory = design.baseDirectory;
        canonical.fileName = design.fileName;
        canonical.allowExternalSource = design.allowExternalSource;
        design = std::move(canonical);
    } catch (const std::exception&) {
        // A design the format refuses is edited as it is; saving it reports why.
    }
    EditorState s{std::move(design), {}};
    s.muted.assign(s.design.initial.size() + s.design.operations.size(), false);
    auto& meta = s.design.meta;
    if (!meta.editor) {
        meta.erase(MetaKey::Editor); // one that is not an object holds no muted steps
        return s;
    }

    struct Entry {
        std::size_t step;
        bool initial;
        Operation op;
    };
    std::vector<Entry> entries;
    if (meta.editor->muted) {
        const auto& muted = *meta.editor->muted;
        if (!muted.is_array())
            qWarning("meta.editor.muted is not a list: muted steps left out");
        else
            for (std::size_t k = 0; k < muted.size(); ++k) {
                const std::string where = "meta.editor.muted[" + std::to_string(k) + "]";
                try {
                    const auto& e = muted[k];
                    if (!e.is_object() || !e.contains("step") || !e["step"].is_number_unsigned() ||
                        !e.contains("part") || !e["part"].is_string() || !e.contains("operation"))
                        throw InputError(where + ": needs \"step\", \"part\" and \"operation\"");
                    const std::string part = e["part"].get<std::string>();
                    if (part != "initial" && part != "operations")
                        throw InputError(where + ".part: must be \"initial\" or \"operations\"");
                    const bool initial = part == "initial";
                    entries.push_back({e["step"].get<std::size_t>(), initial,
                                       parseStep(s.design, e["operation"], initial, where)});
                } catch (const std::exception& error) {
                    qWarning("muted step left out: %s", error.what());
                }
            }
    }
    meta.erase(MetaKey::Editor);
    // In the order of their steps, each goes where it was: the ones before it are in place.
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        return a.initial != b.initial ? a.initial : a.step < b.step;
    });
    for (const Entry& e : entries)
        insertStep(s, e.step, e.op, e.initial, true);
    return s;
}

/// "comb 3: spacing 18 → 23": the parameter changes of step i (ChangeSummary's words).
QString describeStepEdit(const Genome& before, const Genome& after, std::size_t i) {
    const Operation& a = stepOf(before, i);
    const Operation& b = stepOf(after, i);
    const QString label = stepLabel(before, i);
    if (a.tool != b.tool) return QStringLiteral("%1 → %2").arg(label, fromView(toolSpec(b.tool).name));
    const bool initial = i < before.initial.size();
    const std::string text = describeChange(holder(before, a, initial), holder(after, b, initial));
    // The holders hold one step, which ChangeSummary calls "<tool> 1".
    const std::string prefix = std::string(toolSpec(a.tool).name) + " 1: ";
    if (text.rfind(prefix, 0) == 0)
        return label + QStringLiteral(": ") + QString::fromStdString(text.substr(prefix.size()));
    return label + QStringLiteral(": ") + QString::fromStdString(text);
}

} // namespace

/// One edit: what it changed (EditorDelta), applied to the document's present state by redo
/// and taken back by undo. Consecutive edits with the same merge id and target (one drag of a
/// slider or a handle) merge into one, named by the change from the first state to the last.
class EditorCommand : public QUndoCommand {
public:
    EditorCommand(EditorDocument* doc, EditPtr edit, const QString& text, int mergeId, QString mergeKey,
                  Describe describe)
        : QUndoCommand(text)
        , mDoc(doc)
        , mEdit(std::move(edit))
        , mMergeId(mergeId < 0 ? -1 : mergeId)
        , mMergeKey(std::move(mergeKey))
        , mDescribe(std::move(describe)) {}

    void undo() override { mDoc->applyEdit(*mEdit, false); }
    void redo() override { mDoc->applyEdit(*mEdit, true); }
    int id() const override { return mMergeId; }

    bool mergeWith(const QUndoCommand* other) override {
        const auto* o = dynamic_cast<const EditorCommand*>(other);
        if (!o || o->mMergeId != mMergeId || o->mMergeKey != mMergeKey || mMergeKey.isEmpty()) return false;
        // QUndoStack::push has applied `other`: the document is at the merged edit's end, and
        // its start is found by taking both edits back.
        const EditorState after{mDoc->mDesign, mDoc->mMuted};
        EditorState before = after;
        o->mEdit->step(before, false);
        mEdit->step(before, false);
        mEdit = std::make_shared<const EditorDelta>(EditorDelta::between(before, after));
        setText(mDescribe ? mDescribe(before, after) : o->text());
        // A drag that ends where it began (a colour dialog cancelled) leaves no entry behind,
        // and the design as clean as it was.
        setObsolete(before == after);
        return true;
    }

    /// Pushes an edit of `doc` from its present state `before` to `after` (applying it); an
    /// edit that changes nothing is no command. Undone edits the push drops are kept as a
    /// branch first.
    static void push(EditorDocument* doc, QUndoStack* stack, const EditorState& before,
                     const EditorState& after, const QString& text, int mergeId = -1, QString mergeKey = {},
                     Describe describe = {}) {
        if (before == after) return;
        // A bath that wraps holds only steps that commute with the wrap: the file would not load
        // again otherwise (docs/genome-format.md, "Wrapping bath").
        if (after.design.wrap) {
            const std::string why = wrapProblem(after.design);
            if (!why.empty()) {
                emit doc->editRefused(
                    EditorDocument::tr("Not done: this design's bath wraps (it is a repeat tile), and "
                                       "%1. Edit ▸ Bath wraps turns the wrap off and allows every tool.")
                        .arg(QString::fromStdString(why)));
                return;
            }
        }
        doc->keepRedoBranch();
        stack->push(
            new EditorCommand(doc, std::make_shared<const EditorDelta>(EditorDelta::between(before, after)),
                              text, mergeId, std::move(mergeKey), std::move(describe)));
    }

    const EditPtr& edit() const { return mEdit; }

private:
    EditorDocument* mDoc;
    EditPtr mEdit;
    int mMergeId;
    QString mMergeKey; ///< what the edit changes ("step:3"): only edits of one target merge
    Describe mDescribe;
};

EditorDocument::EditorDocument(Genome design, QObject* parent)
    : QObject(parent) {
    EditorState s = unpack(std::move(design));
    mDesign = std::move(s.design);
    mMuted = std::move(s.muted);
    mOpened = std::make_shared<const EditorDelta>();
    mSaved = mOpened;
    connect(&mUndo, &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (!mQuiet) emit modifiedChanged(!clean);
    });
}

EditorDocument::~EditorDocument() {
    // The commands hold a pointer back to the document: drop them before it goes.
    mUndo.blockSignals(true);
    mUndo.clear();
}

Genome EditorDocument::renderedDesign() const {
    Genome g = mDesign;
    g.initial.clear();
    g.operations.clear();
    const std::size_t n = mDesign.initial.size();
    for (std::size_t i = 0; i < n; ++i)
        if (!mMuted[i]) g.initial.push_back(mDesign.initial[i]);
    for (std::size_t i = 0; i < mDesign.operations.size(); ++i)
        if (!mMuted[n + i]) g.operations.push_back(mDesign.operations[i]);
    return g;
}

Genome EditorDocument::fileGenome() const {
    Genome g = renderedDesign();
    auto muted = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < mMuted.size(); ++i) {
        if (!mMuted[i]) continue;
        const bool initial = isInitial(i);
        nlohmann::ordered_json entry;
        entry["step"] = i;
        entry["part"] = initial ? "initial" : "operations";
        entry["operation"] = stepJson(mDesign, step(i), initial);
        muted.push_back(std::move(entry));
    }
    if (!muted.empty()) g.meta.editor = MetaEditor{std::move(muted), {}};
    return g;
}

std::size_t EditorDocument::stepCount() const {
    return mDesign.initial.size() + mDesign.operations.size();
}

const Operation& EditorDocument::step(std::size_t i) const {
    return stepOf(mDesign, i);
}

bool EditorDocument::isMuted(std::size_t i) const {
    return i < mMuted.size() && mMuted[i];
}

QString EditorDocument::stepName(std::size_t i) const {
    return stepLabel(mDesign, i);
}

std::size_t EditorDocument::insertionIndex(Tool tool, std::optional<std::size_t> at) const {
    return placeFor(mDesign, tool, at.value_or(stepCount())).index;
}

std::size_t EditorDocument::addStep(const Operation& op, std::optional<std::size_t> at) {
    const Place place = placeFor(mDesign, op.tool, at.value_or(stepCount()));
    EditorState after{mDesign, mMuted};
    insertStep(after, place.index, canonicalStep(mDesign, op, place.initial), place.initial, false);
    const QString text = tr("Add %1").arg(stepLabel(after.design, place.index));
    EditorCommand::push(this, &mUndo, {mDesign, mMuted}, std::move(after), text);
    return place.index;
}

std::size_t EditorDocument::addSteps(const std::vector<Operation>& ops, const QString& text,
                                     std::optional<std::size_t> at) {
    EditorState after{mDesign, mMuted};
    std::optional<std::size_t> first;
    std::size_t next = at.value_or(stepCount());
    for (const Operation& op : ops) {
        // Each goes after the one before, placed by addStep's rule in the design as it grows.
        const Place place = placeFor(after.design, op.tool, next);
        insertStep(after, place.index, canonicalStep(mDesign, op, place.initial), place.initial, false);
        if (!first) first = place.index;
        next = place.index + 1;
    }
    EditorCommand::push(this, &mUndo, {mDesign, mMuted}, std::move(after), text);
    return first.value_or(stepCount());
}

void EditorDocument::setStep(std::size_t i, const Operation& op, int mergeId) {
    if (i >= stepCount()) return;
    const bool initial = isInitial(i);
    if (initial && !allowedInInitial(op.tool, mDesign.dimension)) {
        qWarning("a %s cannot be part of the initial state", std::string(toolSpec(op.tool).name).c_str());
        return;
    }
    EditorState after{mDesign, mMuted};
    (initial ? after.design.initial[i] : after.design.operations[i - mDesign.initial.size()]) =
        canonicalStep(mDesign, op, initial);
    const QString text = describeStepEdit(mDesign, after.design, i);
    EditorCommand::push(
        this, &mUndo, {mDesign, mMuted}, std::move(after), text, mergeId, QStringLiteral("step:%1").arg(i),
        [i](const EditorState& a, const EditorState& b) { return describeStepEdit(a.design, b.design, i); });
}

void EditorDocument::removeStep(std::size_t i) {
    if (i >= stepCount()) return;
    EditorState after{mDesign, mMuted};
    takeStep(after, i);
    EditorCommand::push(this, &mUndo, {mDesign, mMuted}, std::move(after), tr("Delete %1").arg(stepName(i)));
}

std::size_t EditorDocument::duplicateStep(std::size_t i) {
    if (i >= stepCount()) return i;
    EditorState after{mDesign, mMuted};
    insertStep(after, i + 1, step(i), isInitial(i), isMuted(i));
    EditorCommand::push(this, &mUndo, {mDesign, mMuted}, std::move(after),
                        tr("Duplicate %1").arg(stepName(i)));
    return i + 1;
}

bool EditorDocument::moveStep(std::size_t from, std::size_t to) {
    const std::size_t n = stepCount();
    if (from >= n || to >= n) return false;
    if (from == to) return true;
    EditorState after{mDesign, mMuted};
    const bool wasInitial = isInitial(from);
    const bool muted = isMuted(from);
    const Operation op = takeStep(after, from);
    // At the boundary between the parts the step stays in its own.
    const std::size_t initialCount = after.design.initial.size();
    const bool toInitial = to < initialCount || (to == initialCount && wasInitial);
    if (toInitial && !allowedInInitial(op.tool, mDesign.dimension)) return false;
    insertStep(after, to, op, toInitial, muted);
    EditorCommand::push(this, &mUndo, {mDesign, mMuted}, std::move(after),
                        tr("Move %1 to %2").arg(stepName(from)).arg(to + 1));
    return true;
}

void EditorDocument::setMuted(std::size_t i, bool muted) {
    if (i >= stepCount() || isMuted(i) == muted) return;
    EditorState after{mDesign, mMuted};
    after.muted[i] = muted;
    EditorCommand::push(this, &mUndo, {mDesign, mMuted}, std::move(after),
                        (muted ? tr("Mute %1") : tr("Unmute %1")).arg(stepName(i)));
}

void EditorDocument::setMuted(std::size_t first, std::size_t last, bool muted) {
    if (first > last || last >= stepCount()) return;
    EditorState after{mDesign, mMuted};
    for (std::size_t i = first; i <= last; ++i)
        after.muted[i] = muted;
    EditorCommand::push(
        this, &mUndo, {mDesign, mMuted}, std::move(after),
        (muted ? tr("Mute steps %1–%2") : tr("Unmute steps %1–%2")).arg(first + 1).arg(last + 1));
}

void EditorDocument::setPaletteColor(int index, Color color, int mergeId) {
    if (index < 0 || index >= static_cast<int>(mDesign.palette.size())) return;
    const auto idx = static_cast<std::size_t>(index);
    const auto describe = [idx](const EditorState& a, const EditorState& b) {
        return tr("Ink %1: %2 → %3")
            .arg(idx + 1)
            .arg(hexName(a.design.palette[idx]), hexName(b.design.palette[idx]));
    };
    EditorState after{mDesign, mMuted};
    after.design.palette[idx] = color;
    EditorState before{mDesign, mMuted};
    const QString text = describe(before, after);
    EditorCommand::push(this, &mUndo, std::move(before), std::move(after), text, mergeId,
                        QStringLiteral("ink:%1").arg(index), describe);
}

int EditorDocument::addPaletteColor(Color color) {
    if (mDesign.palette.size() >= MaxPaletteSize) return -1;
    EditorState after{mDesign, mMuted};
    after.design.palette.push_back(color);
    const int index = static_cast<int>(mDesign.palette.size());
    EditorCommand::push(this, &mUndo, {mDesign, mMuted}, std::move(after),
                        tr("Add ink %1: %2").arg(index + 1).arg(hexName(color)));
    return index;
}

void EditorDocument::setBackground(Color color, int mergeId) {
    const auto describe = [](const EditorState& a, const EditorState& b) {
        return tr("Background: %1 → %2").arg(hexName(a.design.background), hexName(b.design.background));
    };
    EditorState before{mDesign, mMuted};
    EditorState after = before;
    after.design.background = color;
    const QString text = describe(before, after);
    EditorCommand::push(this, &mUndo, std::move(before), std::move(after), text, mergeId,
                        QStringLiteral("background"), describe);
}

void EditorDocument::setBleed(double bleed, int mergeId) {
    if (!std::isfinite(bleed) || bleed < 0.0) return;
    const auto describe = [](const EditorState& a, const EditorState& b) {
        return tr("Bleed: %1 → %2").arg(number(a.design.bleed), number(b.design.bleed));
    };
    EditorState before{mDesign, mMuted};
    EditorState after = before;
    after.design.bleed = bleed;
    const QString text = describe(before, after);
    EditorCommand::push(this, &mUndo, std::move(before), std::move(after), text, mergeId,
                        QStringLiteral("bleed"), describe);
}

void EditorDocument::setWrap(bool wrap) {
    EditorState after{mDesign, mMuted};
    after.design.wrap = wrap;
    if (!wrap) after.design.lattice = Lattice::Straight; // a bath that does not wrap has no lattice
    EditorCommand::push(this, &mUndo, {mDesign, mMuted}, std::move(after),
                        wrap ? tr("Wrap the bath") : tr("Unwrap the bath"));
}

void EditorDocument::replaceDesign(const Genome& design, const QString& text) {
    EditorCommand::push(this, &mUndo, {mDesign, mMuted}, unpack(design), text);
}

void EditorDocument::setFileName(const QString& file) {
    if (file == mFileName) return;
    mFileName = file;
    emit fileNameChanged(mFileName);
}

bool EditorDocument::saveAs(const QString& file, QString* error) {
    try {
        const Genome g = fileGenome();
        // A file the format refuses would not open again: say why instead of writing it.
        validateGenome(g, file.toStdString());
        saveGenome(g, QFile::encodeName(file).toStdString());
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    markSaved(file);
    return true;
}

void EditorDocument::markSaved(const QString& file) {
    mUndo.setClean();
    mSaved = currentState();
    setFileName(file);
    noteFileOnDisk();
}

void EditorDocument::markModified() {
    mUndo.resetClean();
    mSaved.reset();
}

namespace {

/// What the document remembers of a file's bytes: their hash, or empty when it cannot be read.
QByteArray hashOfFile(const QString& file) {
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) return {};
    QCryptographicHash hash(QCryptographicHash::Sha256);
    if (!hash.addData(&f)) return {};
    return hash.result();
}

} // namespace

bool EditorDocument::fileChangedOnDisk() const {
    if (mFileName.isEmpty() || mDiskHash.isEmpty()) return false;
    return hashOfFile(mFileName) != mDiskHash;
}

void EditorDocument::noteFileOnDisk() {
    mDiskHash = mFileName.isEmpty() ? QByteArray() : hashOfFile(mFileName);
}

void EditorDocument::applyEdit(const EditorDelta& edit, bool forward) {
    // A history switch sets the state itself, at its end.
    if (mQuiet) return;
    EditorState s{std::move(mDesign), std::move(mMuted)};
    edit.step(s, forward);
    mDesign = std::move(s.design);
    mMuted = std::move(s.muted);
    emit changed();
    if (edit.structural()) emit stepsChanged();
}

std::size_t EditorDocument::historyBytes() const {
    std::unordered_set<const EditorDelta*> seen;
    std::size_t bytes = 0;
    const auto count = [&](const EditPtr& e, const QString& text) {
        bytes += sizeof(Line::Edit) + static_cast<std::size_t>(text.capacity()) * sizeof(QChar);
        if (seen.insert(e.get()).second) bytes += e->bytes;
    };
    for (int k = 0; k < mUndo.count(); ++k) {
        const auto* c = static_cast<const EditorCommand*>(mUndo.command(k));
        count(c->edit(), c->text());
    }
    for (const auto& branch : mBranches)
        for (const Line::Edit& e : branch->edits)
            count(e.edit, e.text);
    return bytes;
}

// ---- history as a tree ------------------------------------------------------------------------

EditPtr EditorDocument::currentState() const {
    const int index = mUndo.index();
    if (index == 0) return mOpened;
    return static_cast<const EditorCommand*>(mUndo.command(index - 1))->edit();
}

EditorDocument::Line EditorDocument::currentLine() const {
    Line line;
    for (int k = 0; k < mUndo.count(); ++k) {
        const auto* c = static_cast<const EditorCommand*>(mUndo.command(k));
        line.edits.push_back({c->text(), c->edit()});
    }
    return line;
}

namespace {

/// How many edits two lines share from their start (their states are shared, not copied).
std::size_t sharedEdits(const EditorDocument::Line& a, const EditorDocument::Line& b) {
    std::size_t k = 0;
    while (k < a.edits.size() && k < b.edits.size() && a.edits[k].edit == b.edits[k].edit)
        ++k;
    return k;
}

} // namespace

void EditorDocument::keepRedoBranch() {
    if (mQuiet || mUndo.index() >= mUndo.count()) return;
    mBranches.push_back(std::make_shared<Line>(currentLine()));
    emit branchesChanged();
}

std::vector<EditorDocument::BranchInfo> EditorDocument::branches() const {
    const Line current = currentLine();
    std::vector<BranchInfo> infos;
    for (const auto& branch : mBranches) {
        const std::size_t fork = sharedEdits(*branch, current);
        BranchInfo info;
        info.forkAt = static_cast<int>(fork);
        info.length = static_cast<int>(branch->edits.size() - fork);
        info.forkText = fork == 0 ? QString() : branch->edits[fork - 1].text;
        info.lastText = branch->edits.empty() ? QString() : branch->edits.back().text;
        infos.push_back(info);
    }
    return infos;
}

void EditorDocument::switchToBranch(std::size_t k) {
    if (k >= mBranches.size()) return;
    const std::shared_ptr<Line> target = mBranches[k];
    mBranches.erase(mBranches.begin() + static_cast<std::ptrdiff_t>(k));
    // The line left stays reachable, unless all of it is in the line switched to.
    const Line left = currentLine();
    if (sharedEdits(left, *target) < left.edits.size()) mBranches.push_back(std::make_shared<Line>(left));

    // The branch's newest state: back from the present one to where the lines part, then
    // forward along the branch.
    EditorState s{std::move(mDesign), std::move(mMuted)};
    const std::size_t fork = sharedEdits(left, *target);
    std::size_t at = static_cast<std::size_t>(mUndo.index());
    while (at > fork)
        left.edits[--at].edit->step(s, false);
    for (; at < target->edits.size(); ++at)
        target->edits[at].edit->step(s, true);

    // The stack is made anew from the branch's edits (shared, not copied), at its newest edit,
    // clean where the saved state is on it; one change is signalled at the end.
    const bool wasModified = isModified();
    mQuiet = true;
    mUndo.clear();
    int cleanAt = mSaved == mOpened ? 0 : -1;
    for (const Line::Edit& e : target->edits) {
        mUndo.push(new EditorCommand(this, e.edit, e.text, -1, {}, {}));
        if (mSaved && e.edit == mSaved) cleanAt = mUndo.index();
    }
    if (cleanAt >= 0) {
        const int tip = mUndo.index();
        mUndo.setIndex(cleanAt);
        mUndo.setClean();
        mUndo.setIndex(tip);
    } else {
        mUndo.resetClean();
    }
    mQuiet = false;
    mDesign = std::move(s.design);
    mMuted = std::move(s.muted);
    emit changed();
    emit stepsChanged();
    if (wasModified != isModified()) emit modifiedChanged(isModified());
    emit branchesChanged();
}

// ---- Removing an ink (appended; issue 27) -----------------------------------------------------

std::size_t EditorDocument::inkUseCount(int index) const {
    std::size_t n = 0;
    for (const auto* part : {&mDesign.initial, &mDesign.operations})
        for (const Operation& op : *part)
            if (toolSpec(op.tool).laysInk && op.color == index) ++n;
    return n;
}

bool EditorDocument::removePaletteColor(int index, int replacement) {
    const int size = static_cast<int>(mDesign.palette.size());
    if (index < 0 || index >= size) return false;
    const bool valid = replacement >= 0 && replacement < size && replacement != index;
    if (inkUseCount(index) > 0 && !valid) return false;
    EditorState after{mDesign, mMuted};
    after.design.palette.erase(after.design.palette.begin() + index);
    // Only ink-laying steps carry a meaningful colour; the others keep theirs.
    const int mapped = valid ? (replacement > index ? replacement - 1 : replacement) : 0;
    for (auto* part : {&after.design.initial, &after.design.operations})
        for (Operation& op : *part) {
            if (!toolSpec(op.tool).laysInk) continue;
            if (op.color == index)
                op.color = mapped;
            else if (op.color > index)
                --op.color;
        }
    QString text = tr("Delete ink %1: %2").arg(index + 1).arg(hexName(mDesign.palette[std::size_t(index)]));
    if (inkUseCount(index) > 0) text += tr(", its steps in ink %1").arg(replacement + 1);
    EditorCommand::push(this, &mUndo, {mDesign, mMuted}, std::move(after), text);
    return true;
}

// ---- Issue 22 (editor): numbering and drag merging.

std::optional<std::size_t> EditorDocument::documentIndex(std::size_t rendered) const {
    std::size_t seen = 0;
    for (std::size_t i = 0; i < stepCount(); ++i) {
        if (isMuted(i)) continue;
        if (seen == rendered) return i;
        ++seen;
    }
    return std::nullopt;
}

std::optional<std::size_t> EditorDocument::renderedIndex(std::size_t step) const {
    if (step >= stepCount() || isMuted(step)) return std::nullopt;
    std::size_t rendered = 0;
    for (std::size_t i = 0; i < step; ++i)
        if (!isMuted(i)) ++rendered;
    return rendered;
}

int EditorDocument::mergeFor(bool dragging) {
    if (dragging) {
        if (!mDragMerge.active) {
            mDragMerge.active = true;
            mDragMerge.id = mDragMerge.next++;
        }
        return mDragMerge.id;
    }
    if (mDragMerge.active) {
        mDragMerge.active = false; // the release closes the drag's step
        return mDragMerge.id;
    }
    return -1;
}

} // namespace marbler::ui
