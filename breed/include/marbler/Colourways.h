#pragma once
/// Colourways, as textile designers make them: one design's structure (dimension, size,
/// initial state, strokes, source, bleed) kept exactly, and only its palette and background
/// bred. The window's Colourways mode fills a generation with a design and eight colourways of
/// it; Alter then varies palettes and Recombine mixes the parents' palettes.
///
/// Every palette a colourway gets keeps its inks readable: each ink stands apart from the
/// background and from the ink before it (their neighbour in a stone ground, where each colour
/// is dropped on the ones before) by a squared redmean distance of at least MinInkContrast2,
/// the rule of the pattern families (Families.cpp). A palette keeps its size, so the drops keep
/// their colour indices.
///
/// Determinism as in Generator.h: every draw comes from Pcg32 and only IEEE basic operations
/// are used, so a seed gives the same colourways on every machine.

#include "marbler/Genome.h"
#include "marbler/Random.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace marbler {

/// What `meta.lineage.operator` says of a colourway.
inline constexpr const char* ColourwayOperator = "colourway";

/// Inks this far apart (squared) read against each other: 90^2.
inline constexpr double MinInkContrast2 = 90.0 * 90.0;
/// Whether every ink of a palette stands apart from the background and from the ink before it.
bool paletteHasContrast(const std::vector<Color>& palette, Color background);

/// Whether two designs share a structure: everything but palette, background and meta equal.
bool sameStructure(const Genome& a, const Genome& b);

/// A colourway of a design: its structure with a palette of as many inks and a background
/// changed by `strength` (0..1): at 1 a palette of its own (traditional or a harmony), below
/// it a variation of the design's own (hues turned, values shifted, inks reordered). The
/// result always has contrast (paletteHasContrast), the meta is the design's.
Genome colourwayOf(const Genome& design, double strength, Pcg32& rng);
/// A colourway of parents[home] whose inks and background are drawn from the parents' palettes.
Genome mixedColourway(const std::vector<Genome>& parents, std::size_t home, Pcg32& rng);

struct ColourwayRequest {
    std::vector<Genome> parents;
    bool mix = false;      ///< false: colourwayOf parents[0]; true: mixedColourway of all
    double strength = 1.0; ///< colourwayOf's strength
    std::uint64_t seed = 0;
    int count = 8;
    /// As BreedRequest (Operators.h): the generation children record and their names' numbers.
    std::optional<int> generation;
    std::vector<int> childNumbers;
};

/// The colourways of a request, with lineage as breed gives it (operator "colourway", and
/// `strength` unless mixed). Child i draws from a stream of (seed, i) alone; no child equals
/// another or a parent where a redraw can avoid it. Throws InputError for no parent, a parent
/// that is invalid or whose palette is locked (meta.locks), a count outside [1, MaxChildren], a
/// strength outside [0, 1], or childNumbers that are neither empty nor one per child.
std::vector<Genome> colourways(const ColourwayRequest& request);

} // namespace marbler
