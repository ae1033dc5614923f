#pragma once
/// The traditional pattern families of marbling, each a recipe of what a marbler does at the
/// bath (a ground of drops laid in a known way, then a known order of strokes), generated with
/// seeded variation: `marbler random --family NAME` and the window's new populations. Recipes
/// in the words of the craft are in docs/families.md.
///
/// Determinism as in Generator.h: every draw comes from Pcg32 and only IEEE basic operations
/// and square roots are used, so a seed gives the same design on every machine.

#include "marbler/Genome.h"

#include <cstdint>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace marbler {

/// What `meta.generator` says of a family's design; bump it when a seed's design changes.
inline constexpr const char* FamiliesVersion = "marbler-family-3";

/// One family of the craft.
struct Family {
    std::string_view name;    ///< as `--family` takes it and `meta.family` records it
    int dimension;            ///< 2 (paper) or 3 (solid)
    std::string_view summary; ///< one line, for `--families` and tooltips
};

/// Every family, flat ones first.
std::span<const Family> allFamilies();
/// The family of a name; nullptr when there is none.
const Family* findFamily(std::string_view name);
/// The family of a set of parents (the wildcard's, steering's fresh designs'): that of the first
/// parent that names one, when it is of the first parent's dimension; nullptr otherwise.
const Family* parentsFamily(std::span<const Genome> parents);

/// A design of the family from the seed: meta {"name", "seed", "generator", "family"}. The
/// family is kept by breeding (children copy `meta.family`), so the lineage records it.
Genome familyGenome(const Family& family, std::uint64_t seed);

/// A new population as the window draws one (New Population, the first grid, and the simulated
/// breeder's first nine): `count` designs, each of another generator while there are enough of
/// them (the dimension's families and the free generator, in an order drawn from the seed, so a
/// mixed grid shows the craft's range), or all of `only`'s. No design repeats one whose genomeId
/// is in `taken`, nor another (after a thousand draws one may). Each records its seed.
std::vector<Genome> newPopulation(std::uint64_t seed, int dimension, const Family* only, int count,
                                  std::set<std::string> taken = {});

/// One of marbling's traditional palettes: the paper and the inks laid on it.
struct TraditionalPalette {
    std::string_view name;
    Color paper;
    std::span<const Color> inks;
};
std::span<const TraditionalPalette> traditionalPalettes();

} // namespace marbler
