#pragma once
/// The seeded random genome generator: designs people would keep. A bath covered with drops
/// the way marblers lay a stone pattern (a harmonious palette, some drops inside others), then
/// a few strokes of the traditional families (combed, chevron/nonpareil, waved, swirled,
/// vortices). The same seed gives the same genome on every machine.

#include "marbler/Genome.h"
#include "marbler/Random.h"

#include <cstdint>

namespace marbler {

/// A complete random genome of dimension 2 or 3 (1000 units a side).
Genome randomGenome(std::uint64_t seed, int dimension);

/// A harmonious palette of 3 to 6 inks and a background that sets them off.
std::vector<Color> randomPalette(Pcg32& rng, Color* background = nullptr);

/// A new initial state (stone pattern of drops, and in 3D ink columns) for a genome with the
/// given dimension, size and palette size.
std::vector<Operation> randomInitial(Pcg32& rng, int dimension, const glm::dvec3& size, int paletteSize);

/// A few strokes from the traditional families.
std::vector<Operation> randomStrokes(Pcg32& rng, int dimension, const glm::dvec3& size);

} // namespace marbler
