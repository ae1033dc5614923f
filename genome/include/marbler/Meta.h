#pragma once
/// A genome's `meta`: what Marbler records about a design beside the design itself (its name,
/// where it came from, the editor's and the window's notes). The one place that names meta's
/// keys: everyone else reads and writes these fields.
///
/// Reading never throws: a known key whose value has a type Marbler cannot read is left out of
/// its field (absent, as every reader always treated it) and kept as it is in `other`, with the
/// keys Marbler does not know, so a stranger's file round-trips untouched. A meta written back
/// unchanged is written as it was read, key order and number forms included (nlohmann's
/// ordered_json keeps insertion order, and 30 and 30.0 are different bytes).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace marbler {

/// `meta.lineage.variation`: a child that repeated a design and was varied gently instead.
struct MetaVariation {
    std::optional<std::string> of;  ///< the id of the design it repeated
    std::optional<double> strength; ///< the alteration strength that varied it
    nlohmann::ordered_json other = nlohmann::ordered_json::object();
};

/// `meta.lineage`: how a bred design was made (Operators.h, Colourways.h, the wildcard).
struct MetaLineage {
    std::optional<std::vector<std::string>> parents; ///< the parents' ids (non-text entries skipped)
    std::optional<std::string> op;                   ///< "operator": alter, recombine, ..., wildcard
    std::optional<std::uint64_t> seed;               ///< the breeding (or wildcard) seed
    std::optional<int> child;                        ///< its number among the children, from 1
    std::optional<double> strength;                  ///< alter and colourway strength
    std::optional<MetaVariation> variation;          ///< set when it is a variation of a repeat
    std::optional<int> redraws;                      ///< redraws the child filter took
    std::optional<int> generation;                   ///< the generation it was bred in
    std::optional<std::string> change;               ///< what changed from its home parent, in words
    nlohmann::ordered_json other = nlohmann::ordered_json::object(); ///< keys not known, kept
};

/// `meta.editor`: the manual editor's notes.
struct MetaEditor {
    /// Steps muted in the editor, kept out of the design (EditorDocument.h). Any JSON: the
    /// editor says what it cannot read of it.
    std::optional<nlohmann::ordered_json> muted;
    nlohmann::ordered_json other = nlohmann::ordered_json::object();
};

/// `meta.view`: the angle a solid is seen from, in degrees (ViewController.h).
struct MetaView {
    std::optional<double> yaw;   ///< finite numbers only
    std::optional<double> pitch; ///< finite numbers only
    nlohmann::ordered_json other = nlohmann::ordered_json::object();
};

/// `meta.locks`: the parts breeding leaves alone (Operators.h).
struct MetaLocks {
    std::optional<bool> palette;
    std::optional<bool> initial;
    std::optional<bool> operations;
    nlohmann::ordered_json other = nlohmann::ordered_json::object();
};

/// The keys Meta knows, for erase().
enum class MetaKey { Name, Id, Lineage, Family, Seed, Generator, Paper, Editor, View, Locks, Note };

/// A genome's `meta`, typed.
class Meta {
public:
    std::optional<std::string> name;
    std::optional<std::string> id; ///< genomeId of the design, as bred designs record it
    std::optional<MetaLineage> lineage;
    std::optional<std::string> family;           ///< the pattern family (Families.h), kept by breeding
    std::optional<std::uint64_t> seed;           ///< the generator's seed
    std::optional<std::string> generator;        ///< the generator and its version
    std::optional<nlohmann::ordered_json> paper; ///< a paper's options (Paper.h); an object
    std::optional<MetaEditor> editor;
    std::optional<MetaView> view;
    std::optional<MetaLocks> locks;
    std::optional<std::string> note; ///< the user's note on the design (the window's tooltip)
    /// Keys Meta does not know, and known keys whose value it cannot read, as they were.
    nlohmann::ordered_json other = nlohmann::ordered_json::object();

    /// Reads a meta object; never throws. Anything but an object reads as an empty meta.
    static Meta fromJson(const nlohmann::ordered_json& json);
    /// The meta object: a key read and not changed is written as it was read, in its place;
    /// keys set since come after, in a fixed order (name, seed, generator, family, paper,
    /// lineage, id, editor, view, locks, note), then unknown keys added since.
    nlohmann::ordered_json toJson() const;
    /// Whether there is nothing to write.
    bool empty() const;
    /// Whether the key is there at all, readable or not.
    bool has(MetaKey key) const;
    /// Removes a key as from a JSON object: its field, any unreadable value kept for it in
    /// `other`, and its place (set again, it comes after the keys there are). Setting a field
    /// needs no erase: a value set is written in the key's place, over an unreadable one.
    void erase(MetaKey key);
    /// What a bred child keeps of its home parent's meta: everything but name, seed, generator,
    /// id and lineage, in its order; the child's name comes first, its lineage and id last.
    Meta keptByChild() const;

    friend bool operator==(const Meta& a, const Meta& b) { return a.toJson() == b.toJson(); }

private:
    /// The object it was read from, its keys in their order, and those keys as this code writes
    /// them back: where a field still writes as it did when read, the value read is written.
    nlohmann::ordered_json mRead = nlohmann::ordered_json::object();
    nlohmann::ordered_json mReadWritten = nlohmann::ordered_json::object();
    /// Key order to keep (the file's, or a child's); keys not in it follow.
    std::vector<std::string> mOrder;
};

} // namespace marbler
