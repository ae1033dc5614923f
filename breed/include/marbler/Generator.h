#pragma once
/// The seeded random genome generator: designs people would keep. A bath covered with drops
/// the way marblers lay a stone pattern (a harmonious palette, some drops inside others), then
/// a few strokes of the traditional families (combed, chevron/nonpareil, waved, swirled,
/// vortices). A flat design now and then has version 2's touches: stretch passes (the
/// marbled-paper look), swirls with a finite core, a flow, a slight bleed; about one in seven
/// has version 3's free-hand stroke (a stylus or a small rake along a wandering path, with the
/// fewest steps the format allows); a solid one none of these. The same seed gives the same
/// genome on every machine.
///
/// Determinism: every draw comes from Pcg32 and the generator itself uses only IEEE basic
/// operations and square roots (correctly rounded everywhere): directions are drawn by
/// rejection instead of from sines and cosines, colours are mixed in HSL (piecewise linear)
/// and the 3D volume law uses a Newton cube root, so no libm difference can change a file.

#include "marbler/Genome.h"
#include "marbler/Random.h"

#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace marbler {

/// What `meta.generator` says of a genome made by randomGenome; bump it when the same seed
/// starts giving a different design.
inline constexpr const char* GeneratorVersion = "marbler-random-4";

/// A complete random genome of dimension 2 or 3 (1000 units a side), with
/// meta {"name", "seed", "generator"}. Throws InputError for another dimension.
Genome randomGenome(std::uint64_t seed, int dimension);

/// A harmonious palette of 3 to 6 inks (analogous, complementary, split-complementary, triadic
/// or monochrome-with-accent around a random base hue) and a background that sets them off.
std::vector<Color> randomPalette(Pcg32& rng, Color* background = nullptr);

/// A new initial state (stone pattern of drops, bull's-eyes, occasional sprays, and in 3D ink
/// columns) for a genome with the given dimension, size and palette size (>= 1).
std::vector<Operation> randomInitial(Pcg32& rng, int dimension, const glm::dvec3& size, int paletteSize);

/// A few strokes from the traditional families (at least one, at most about ten).
std::vector<Operation> randomStrokes(Pcg32& rng, int dimension, const glm::dvec3& size);

/// The colour word nearest an sRGB colour ("Cobalt", "Saffron", "Slate", ...), from a fixed
/// table of pigment and stone names.
std::string colorWord(Color color);
/// The palette index of a design's main ink: the one covering the most of its initial state
/// (-1 for an empty palette).
int mainInk(const Genome& genome);
/// An evocative name for a design: the colour word of its main ink and a noun drawn from the
/// seed among its family's own words ("Cobalt Peacock"; Families.h names the families; none:
/// words of no family), so names never contradict colours or pattern.
std::string randomName(std::uint64_t seed, const Genome& genome, std::string_view family = {});
/// The nouns a family's designs are named with (words of no family for an unknown one).
std::vector<std::string> familyNouns(std::string_view family);
/// A palette in words: the colour words of the inks covering the most (distinct, at most `most`,
/// the main ink first), "Purple", "Russet and Harbour Green", "Ochre, Slate and Ivory".
std::string paletteWords(const Genome& genome, int most = 2);
/// The name of a colourway of `parent` (whose name, without a bred suffix, is `name`): the
/// colourway's own colour word in place of the parent's ("Russet Current" in purple is "Purple
/// Current"); a name that is only the parent's colour becomes the colourway's palette words.
std::string recolouredName(const std::string& name, const Genome& parent, const Genome& colourway);
/// `name` made unique among `taken` (the names a session has given): itself when free, else
/// "name 2", "name 3", ... so two different designs never share a name.
std::string uniqueName(const std::string& name, const std::set<std::string>& taken);

} // namespace marbler
