#pragma once
/// The genetic operators of the evolution workbench (after the solid marbling paper), seeded
/// and reproducible, and the lineage every child records in its `meta`.

#include "marbler/Genome.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace marbler {

enum class GeneticOperator : std::uint8_t {
    Alter,     ///< one parent: perturb its deformation parameters (strength 0..1)
    Recombine, ///< two or more parents: children take operations from the parents' lists
    Swap,      ///< two parents: one's initial state with the other's operations, both ways
    Reinit,    ///< one parent: a new initial drop pattern, the same operations
};

/// `alter`, `recombine`, `swap`, `reinit`.
std::string_view operatorName(GeneticOperator op);
std::optional<GeneticOperator> parseOperator(std::string_view name);
/// How many parents an operator takes: [min, max] (max 0: no upper bound).
int minParents(GeneticOperator op);
int maxParents(GeneticOperator op);

/// What a user has locked on a design; operators never change what is locked. Kept in
/// `meta.locks` ({"palette": true, ...}) so locks travel with the file.
struct Locks {
    bool palette = false;
    bool initial = false;
    bool operations = false;
    friend bool operator==(const Locks&, const Locks&) = default;
};
Locks locksOf(const Genome& genome);
void setLocks(Genome& genome, const Locks& locks);

/// A stable identifier of a design's content (hex of a 64-bit hash of its JSON without
/// `meta`), used for lineage.
std::string genomeId(const Genome& genome);

struct BreedRequest {
    GeneticOperator op = GeneticOperator::Alter;
    std::vector<Genome> parents;
    std::uint64_t seed = 0;
    int count = 8;
    double strength = 0.5; ///< alteration strength, 0..1
};

/// The children of a request. Each child's `meta.lineage` holds {parents: [ids], operator,
/// seed, generation (1 + the parents' largest)} and `meta.id` its own id. Throws InputError
/// for a wrong parent count, mixed dimensions, or a strength outside [0, 1].
std::vector<Genome> breed(const BreedRequest& request);

} // namespace marbler
