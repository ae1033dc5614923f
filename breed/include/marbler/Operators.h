#pragma once
/// The genetic operators of the evolution workbench (after the solid marbling paper), seeded
/// and reproducible, and the lineage every child records in its `meta`.
///
/// Every child has one *home* parent: the parent whose initial state, palette and background
/// it carries (alter, reinit: the parent; swap: the parent whose initial state it takes;
/// recombine: the parent chosen for its initial state). The locks of the home parent
/// (`meta.locks`) hold for the child:
///
/// | operator  | operations unlocked                     | operations locked                      |
/// | --------- | --------------------------------------- | -------------------------------------- |
/// | alter     | every numeric parameter of every stroke | unlocked palette colours are nudged,   |
/// |           | perturbed (the tools and their order    | and unlocked initial drops moved and   |
/// |           | never change); palette, initial kept    | resized a little instead               |
/// | recombine | crossover of the parents' strokes       | the home parent's strokes, unchanged   |
/// | swap      | the other parent's strokes              | the home parent's strokes, unchanged   |
///
/// Alteration keeps every parameter valid: lengths stay > 0, a stretch's teeth in strictly
/// increasing order, a flow's steps at least the fewest its new speed, time and size need (a
/// draw that would need more than the format allows keeps the old speed, time and size), a
/// stylus's path moved (shifted, its points jittered, now and then smoothed), its pressure
/// (where it has one) nudged within [0, 1] and its steps re-timed, never below the fewest its
/// new values need (a draw that would need more than the format allows keeps the old path and
/// values); a core of 0 stays 0, so a version-1 design's children are version 1. Strokes travel
/// whole (recombine, swap: a flow with its steps, a stylus with its path and pressure), and a
/// child has its home parent's `bleed`, which belongs with the inks like the palette.
///
/// reinit draws a new initial drop pattern (randomInitial) unless the initial state is locked;
/// then it draws a new palette instead, unless that too is locked. No operator touches a locked
/// part; with everything locked a child has the home parent's content.
///
/// Every child is worth a cell: no two children of a request are equal, and none equals a
/// parent (genomes compared without `meta`, by genomeId). A draw that repeats one is drawn
/// again (alter, recombine, reinit); what still repeats (swap, which has exactly two results,
/// alter at strength 0, recombine of parents with few strokes) becomes a gentle variation of
/// itself (alterGenome at VariationStrength, more on a further repeat), recorded in
/// `meta.lineage.variation`. So swap gives the two swaps, then variations of them in turn.
/// Only a home parent with everything locked can still give copies: nothing may change.
///
/// Children worth looking at: a random operator's child (alter above strength 0, recombine,
/// reinit) that is dull (one colour covers more than DullShare of its glimpse, and more than of
/// its parents') or a near-duplicate (mean CIE76 colour difference below NearDuplicateDeltaE
/// against a parent or an earlier sibling) is drawn again, as the best fractal breeders do: at
/// most ChildRedraws times, from the child's own stream, so it is reproducible and costs no
/// more on a slow machine; if every draw fails the best one is kept (not dull first, then the
/// farthest from the others). `meta.lineage.redraws` records how many redraws a child took
/// (absent when none). Swap's two results are not filtered: drawing again cannot change them.
///
/// A family's character stays (a nonpareil's fine comb stays fine): for a design with
/// `meta.family`, alteration below FamilyKeepStrength moves lengths, shifts, sizes and a
/// stretch's teeth relative to their own size (a factor within [1/2, 2]) rather than by a
/// fraction of the design; at FamilyKeepStrength and above it alters as any design.
///
/// Colour indices that another palette does not have (swap, recombine) are clamped to its last
/// ink. Children keep the home parent's free-form `meta` (name with a generation suffix,
/// locks, author...) except `seed`, `generator`, `id` and `lineage`, which they set anew.

#include "marbler/Genome.h"
#include "marbler/Random.h"

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
/// The locks in `meta.locks` (missing or non-boolean entries read as unlocked).
Locks locksOf(const Genome& genome);
/// Writes `meta.locks` (removes it when nothing is locked).
void setLocks(Genome& genome, const Locks& locks);

/// A stable identifier of a design's content: FNV-1a 64 of the compact canonical JSON
/// (toJson) without `meta`, as 16 lower-case hex digits. Used for lineage.
std::string genomeId(const Genome& genome);

/// The generation a bred design records (`meta.lineage.generation`); 0 for one not bred.
int lineageGeneration(const Genome& genome);
/// The meta of a child, as breed() and colourways() write it: the home parent's meta without its
/// name, seed, generator, id and lineage; the name "ROOT (gG #N)" from the home parent's name
/// without an earlier "(g.. #..)"; and `lineage`, which the caller fills.
Meta childMeta(const Genome& home, int generation, int number, MetaLineage lineage);

struct BreedRequest {
    GeneticOperator op = GeneticOperator::Alter;
    std::vector<Genome> parents;
    std::uint64_t seed = 0;
    int count = 8;
    double strength = 0.5; ///< alteration strength, 0..1
    /// The generation the children record (meta.lineage.generation and the name's " (gN #K)");
    /// default 1 + the parents' largest. The window passes its own generation number.
    std::optional<int> generation;
    /// The number each child's name carries (" #K"); default 1, 2, ... (the child's index).
    /// The window passes the design (cell) number each child goes to.
    std::vector<int> childNumbers;
};

/// How far a child is altered when the operator's own result repeats a design already in the
/// generation (see above): gentle, so it stays recognisably that result.
inline constexpr double VariationStrength = 0.12;

/// The child filter (see above). A glimpse is GlimpseSide x GlimpseSide cell centres of the
/// design (for a solid, the slice halfway up z) coloured by the hard colour rule traceColor:
/// enough to see a comb's lines or a dominant ink, about a millisecond a design.
inline constexpr int GlimpseSide = 32;
/// The most draws a child gets beyond its first; a fixed count, not a time, so children never
/// depend on the machine.
inline constexpr int ChildRedraws = 8;
/// A child is dull when one colour (an ink or the ground) covers more than this share of its
/// glimpse, and more than it covers of every parent's: a plain sheet of ink, or a sheet of bare
/// ground, has nothing to choose between (what the parents already had is no fault of the child).
inline constexpr double DullShare = 0.97;
/// A child is a near-duplicate when its glimpse's mean CIE76 ΔE against a parent's or an earlier
/// sibling's is below this: about one just-noticeable difference (ΔE 2.3) spread over the whole
/// image, or 3 % of the cells changed between two distinct inks (ΔE ~50), which at a glance
/// reads as the same design.
inline constexpr double NearDuplicateDeltaE = 1.5;
/// Alteration below this strength keeps a family's character (relative length changes).
inline constexpr double FamilyKeepStrength = 0.7;
/// The relative spread of a family design's lengths at strength 1 (a factor 1 + N(0, 1) times
/// this times the strength, held within [1/2, 2]).
inline constexpr double FamilyRelativeScale = 0.25;

/// A small look at a design: per cell its colour in CIE L*a*b* (D65), and the largest share any
/// one colour covers. A source image cannot be read in genome/, so where the source shows the
/// glimpse sees the background colour; bleed is ignored (the hard rule). Only IEEE basic
/// operations (roots by bisection), so the same on every machine.
struct Glimpse {
    std::vector<double> lab; ///< L, a, b per cell, row by row
    double dominantShare = 0.0;
};
Glimpse glimpseOf(const Genome& genome);
/// The same look over side x side cell centres (steering's features use a 16 x 16 one).
Glimpse glimpseOf(const Genome& genome, int side);
/// The mean CIE76 ΔE between two glimpses (of the same size).
double meanDeltaE(const Glimpse& a, const Glimpse& b);

/// The most children one request may ask for.
inline constexpr int MaxChildren = 1000;

/// The children of a request. Each child's `meta.lineage` holds {parents: [ids], operator,
/// seed, child (1-based index), generation (1 + the parents' largest), change (what differs
/// from its home parent, in words: describeChange(parents, home, child), ChangeSummary.h; for
/// a varied child what differs from the design it varies: "a variation of #3: …" for a sibling
/// numbered as childNumbers number it, "a variation of parent 1: …")} (alter adds strength; a
/// varied child adds variation: {of: the id of the repeated design, strength}; a redrawn one
/// redraws: the number of redraws) and `meta.id`
/// its own id. Child i draws from a Pcg32 stream derived from (seed, i) alone (and is checked
/// against the children before it), so the same request gives the same children and asking
/// for more children keeps the first ones. Every child passes validateGenome. Throws
/// InputError for a wrong parent count, mixed dimensions, an invalid parent, a count outside
/// [1, MaxChildren], a strength outside [0, 1], a generation below 1 or childNumbers that are
/// neither empty nor one per child.
std::vector<Genome> breed(const BreedRequest& request);
/// The window's wildcard cell and `marbler breed --wildcard`, against breeding fatigue: a fresh
/// design of the parents' family (the first parent that names one, when it is of the parents'
/// dimension; else a free random design), drawn again (16 draws at most) while it equals a
/// parent. It takes `replaced`'s place in the lineage: operator "wildcard", the draw's seed,
/// `replaced`'s generation and number, and its name's " (gN #K)" with K the request's last child
/// number. Reproducible from the request's seed.
Genome wildcardChild(const BreedRequest& request, const Genome& replaced);
/// A wrapping bath (docs/genome-format.md) stays one only while every step can wrap: a child
/// given a drop or a comb becomes a plain design, without a lattice (issue 29).
void keepWrapValid(Genome& child);
/// What breed() refuses, refused the same way (InputError), without breeding.
void checkBreedRequest(const BreedRequest& request);

/// The single operators, without lineage (breed adds it). Each returns a new genome whose
/// meta is the home parent's; they honour the home parent's locks as described above.
Genome alterGenome(const Genome& parent, double strength, Pcg32& rng);
/// The parts of a design alterPart varies on its own.
enum class DesignPart { Palette, Initial, Strokes };
/// Alteration of one part only (steered breeding's small, separate steps): Palette nudges one
/// ink by about 90 x `strength` sRGB levels and each other ink and the background now and
/// then; Initial perturbs each initial entry with probability 0.3 (at least one); Strokes
/// perturbs about the square root of the strokes' count of them (at least one). A locked part,
/// or one with nothing in it, is returned unchanged.
Genome alterPart(const Genome& parent, DesignPart part, double strength, Pcg32& rng);
/// `home` indexes the parent whose initial state, palette and background the child keeps.
Genome recombineGenomes(const std::vector<Genome>& parents, std::size_t home, Pcg32& rng);
/// The initial state (and palette, background) of `home` with the operations of `other`.
Genome swapGenomes(const Genome& home, const Genome& other);
Genome reinitGenome(const Genome& parent, Pcg32& rng);

} // namespace marbler
