#include "marbler/Meta.h"

#include <algorithm>
#include <cmath>

namespace marbler {

namespace {
// Named, so that a unity build's neighbours (GenomeIO's readers) cannot clash with these.
namespace metaio {

using Json = nlohmann::ordered_json;

// The readers: a value of another type reads as absent (nullopt), never a throw.
std::optional<std::string> readString(const Json& v) {
    if (!v.is_string()) return std::nullopt;
    return v.get<std::string>();
}
std::optional<std::uint64_t> readSeed(const Json& v) {
    if (v.is_number_unsigned()) return v.get<std::uint64_t>();
    if (v.is_number_integer() && v.get<std::int64_t>() >= 0) return std::uint64_t(v.get<std::int64_t>());
    return std::nullopt;
}
std::optional<int> readInt(const Json& v) {
    if (!v.is_number_integer()) return std::nullopt;
    return v.get<int>();
}
std::optional<double> readNumber(const Json& v) {
    if (!v.is_number()) return std::nullopt;
    return v.get<double>();
}
std::optional<double> readFinite(const Json& v) {
    auto x = readNumber(v);
    if (x && !std::isfinite(*x)) return std::nullopt;
    return x;
}
std::optional<bool> readBool(const Json& v) {
    if (!v.is_boolean()) return std::nullopt;
    return v.get<bool>();
}
std::optional<Json> readObject(const Json& v) {
    if (!v.is_object()) return std::nullopt;
    return v;
}

/// Reads `field` from `value` with `read`; what it cannot read goes to `other` as it is.
template <typename T, typename Read>
void take(std::optional<T>& field, const std::string& key, const Json& value, Json& other, Read read) {
    field = read(value);
    if (!field) other[key] = value;
}

template <typename T> void put(Json& out, const char* key, const std::optional<T>& field) {
    if (field) out[key] = *field;
}

/// `other`'s keys after the known ones, except keys whose field is set (a value set over an
/// unreadable one).
void putOther(Json& out, const Json& other) {
    for (auto it = other.begin(); it != other.end(); ++it)
        if (!out.contains(it.key())) out[it.key()] = it.value();
}

MetaVariation readVariation(const Json& json) {
    MetaVariation v;
    for (auto it = json.begin(); it != json.end(); ++it) {
        if (it.key() == "of")
            take(v.of, it.key(), it.value(), v.other, readString);
        else if (it.key() == "strength")
            take(v.strength, it.key(), it.value(), v.other, readNumber);
        else
            v.other[it.key()] = it.value();
    }
    return v;
}

Json writeVariation(const MetaVariation& v) {
    Json out = Json::object();
    put(out, "of", v.of);
    put(out, "strength", v.strength);
    putOther(out, v.other);
    return out;
}

MetaLineage readLineage(const Json& json) {
    MetaLineage l;
    for (auto it = json.begin(); it != json.end(); ++it) {
        const std::string& key = it.key();
        const Json& v = it.value();
        if (key == "parents") {
            if (v.is_array()) {
                l.parents.emplace();
                for (const Json& p : v)
                    if (p.is_string()) l.parents->push_back(p.get<std::string>());
            } else {
                l.other[key] = v;
            }
        } else if (key == "operator") {
            take(l.op, key, v, l.other, readString);
        } else if (key == "seed") {
            take(l.seed, key, v, l.other, readSeed);
        } else if (key == "child") {
            take(l.child, key, v, l.other, readInt);
        } else if (key == "strength") {
            take(l.strength, key, v, l.other, readNumber);
        } else if (key == "variation" && v.is_object()) {
            l.variation = readVariation(v);
        } else if (key == "redraws") {
            take(l.redraws, key, v, l.other, readInt);
        } else if (key == "generation") {
            take(l.generation, key, v, l.other, readInt);
        } else if (key == "change") {
            take(l.change, key, v, l.other, readString);
        } else {
            l.other[key] = v;
        }
    }
    return l;
}

// The order bred children have always written their lineage in.
Json writeLineage(const MetaLineage& l) {
    Json out = Json::object();
    put(out, "parents", l.parents);
    put(out, "operator", l.op);
    put(out, "seed", l.seed);
    put(out, "child", l.child);
    put(out, "strength", l.strength);
    if (l.variation) out["variation"] = writeVariation(*l.variation);
    put(out, "redraws", l.redraws);
    put(out, "generation", l.generation);
    put(out, "change", l.change);
    putOther(out, l.other);
    return out;
}

MetaEditor readEditor(const Json& json) {
    MetaEditor e;
    for (auto it = json.begin(); it != json.end(); ++it) {
        if (it.key() == "muted")
            e.muted = it.value();
        else
            e.other[it.key()] = it.value();
    }
    return e;
}

Json writeEditor(const MetaEditor& e) {
    Json out = Json::object();
    put(out, "muted", e.muted);
    putOther(out, e.other);
    return out;
}

MetaView readView(const Json& json) {
    MetaView view;
    for (auto it = json.begin(); it != json.end(); ++it) {
        if (it.key() == "yaw")
            take(view.yaw, it.key(), it.value(), view.other, readFinite);
        else if (it.key() == "pitch")
            take(view.pitch, it.key(), it.value(), view.other, readFinite);
        else
            view.other[it.key()] = it.value();
    }
    return view;
}

Json writeView(const MetaView& view) {
    Json out = Json::object();
    put(out, "yaw", view.yaw);
    put(out, "pitch", view.pitch);
    putOther(out, view.other);
    return out;
}

MetaLocks readLocks(const Json& json) {
    MetaLocks locks;
    for (auto it = json.begin(); it != json.end(); ++it) {
        if (it.key() == "palette")
            take(locks.palette, it.key(), it.value(), locks.other, readBool);
        else if (it.key() == "initial")
            take(locks.initial, it.key(), it.value(), locks.other, readBool);
        else if (it.key() == "operations")
            take(locks.operations, it.key(), it.value(), locks.other, readBool);
        else
            locks.other[it.key()] = it.value();
    }
    return locks;
}

Json writeLocks(const MetaLocks& locks) {
    Json out = Json::object();
    put(out, "palette", locks.palette);
    put(out, "initial", locks.initial);
    put(out, "operations", locks.operations);
    putOther(out, locks.other);
    return out;
}

const char* keyName(MetaKey key) {
    switch (key) {
    case MetaKey::Name:
        return "name";
    case MetaKey::Id:
        return "id";
    case MetaKey::Lineage:
        return "lineage";
    case MetaKey::Family:
        return "family";
    case MetaKey::Seed:
        return "seed";
    case MetaKey::Generator:
        return "generator";
    case MetaKey::Paper:
        return "paper";
    case MetaKey::Editor:
        return "editor";
    case MetaKey::View:
        return "view";
    case MetaKey::Locks:
        return "locks";
    case MetaKey::Note:
        return "note";
    }
    return "";
}

/// Every field as this code writes it, in the order Marbler has always set them: the
/// generators' name, seed, generator, family and paper, a child's lineage and id, then the
/// editor's and the window's notes; unknown keys last.
Json written(const Meta& m) {
    Json out = Json::object();
    put(out, "name", m.name);
    put(out, "seed", m.seed);
    put(out, "generator", m.generator);
    put(out, "family", m.family);
    put(out, "paper", m.paper);
    if (m.lineage) out["lineage"] = writeLineage(*m.lineage);
    put(out, "id", m.id);
    if (m.editor) out["editor"] = writeEditor(*m.editor);
    if (m.view) out["view"] = writeView(*m.view);
    if (m.locks) out["locks"] = writeLocks(*m.locks);
    put(out, "note", m.note);
    putOther(out, m.other);
    return out;
}

} // namespace metaio
} // namespace

Meta Meta::fromJson(const nlohmann::ordered_json& json) {
    using namespace metaio;
    Meta m;
    if (!json.is_object()) return m;
    for (auto it = json.begin(); it != json.end(); ++it) {
        const std::string& key = it.key();
        const Json& v = it.value();
        if (key == "name") {
            take(m.name, key, v, m.other, readString);
        } else if (key == "id") {
            take(m.id, key, v, m.other, readString);
        } else if (key == "note") {
            take(m.note, key, v, m.other, readString);
        } else if (key == "family") {
            take(m.family, key, v, m.other, readString);
        } else if (key == "seed") {
            take(m.seed, key, v, m.other, readSeed);
        } else if (key == "generator") {
            take(m.generator, key, v, m.other, readString);
        } else if (key == "paper") {
            take(m.paper, key, v, m.other, readObject);
        } else if (key == "lineage" && v.is_object()) {
            m.lineage = readLineage(v);
        } else if (key == "editor" && v.is_object()) {
            m.editor = readEditor(v);
        } else if (key == "view" && v.is_object()) {
            m.view = readView(v);
        } else if (key == "locks" && v.is_object()) {
            m.locks = readLocks(v);
        } else {
            m.other[key] = v;
        }
        m.mOrder.push_back(key);
    }
    m.mRead = json;
    m.mReadWritten = written(m);
    return m;
}

nlohmann::ordered_json Meta::toJson() const {
    using namespace metaio;
    const Json now = written(*this);
    if (mOrder.empty()) return now;
    Json out = Json::object();
    const auto emit = [&](const std::string& key) {
        auto value = now.find(key);
        if (value == now.end() || out.contains(key)) return;
        auto read = mRead.find(key);
        auto readWritten = mReadWritten.find(key);
        // Unchanged since reading: the bytes read (their key order, 30 rather than 30.0).
        const bool unchanged =
            read != mRead.end() && readWritten != mReadWritten.end() && *readWritten == *value;
        out[key] = unchanged ? *read : *value;
    };
    for (const std::string& key : mOrder)
        emit(key);
    for (auto it = now.begin(); it != now.end(); ++it)
        emit(it.key());
    return out;
}

bool Meta::empty() const {
    using namespace metaio;
    return written(*this).empty();
}

bool Meta::has(MetaKey key) const {
    return metaio::written(*this).contains(metaio::keyName(key));
}

void Meta::erase(MetaKey key) {
    switch (key) {
    case MetaKey::Name:
        name.reset();
        break;
    case MetaKey::Id:
        id.reset();
        break;
    case MetaKey::Lineage:
        lineage.reset();
        break;
    case MetaKey::Family:
        family.reset();
        break;
    case MetaKey::Seed:
        seed.reset();
        break;
    case MetaKey::Generator:
        generator.reset();
        break;
    case MetaKey::Paper:
        paper.reset();
        break;
    case MetaKey::Editor:
        editor.reset();
        break;
    case MetaKey::View:
        view.reset();
        break;
    case MetaKey::Locks:
        locks.reset();
        break;
    case MetaKey::Note:
        note.reset();
        break;
    }
    // Gone as from a JSON object: set again, it comes after the keys there are.
    const std::string name = metaio::keyName(key);
    other.erase(name);
    mRead.erase(name);
    mReadWritten.erase(name);
    mOrder.erase(std::remove(mOrder.begin(), mOrder.end(), name), mOrder.end());
}

Meta Meta::keptByChild() const {
    using namespace metaio;
    Meta child = *this;
    static constexpr MetaKey Dropped[] = {MetaKey::Name, MetaKey::Seed, MetaKey::Generator, MetaKey::Id,
                                          MetaKey::Lineage};
    for (MetaKey key : Dropped)
        child.erase(key);
    // The child's name first, the parent's other keys in their order, lineage and id last.
    const Json kept = child.toJson();
    child.mOrder = {keyName(MetaKey::Name)};
    for (auto it = kept.begin(); it != kept.end(); ++it)
        child.mOrder.push_back(it.key());
    child.mOrder.push_back(keyName(MetaKey::Lineage));
    child.mOrder.push_back(keyName(MetaKey::Id));
    return child;
}

} // namespace marbler
