#pragma once
/// Procedural marbled paper (`marbler paper`), after the well-known small generator: layers of
/// drops, one colour each, laid at Poisson-disk spaced points with radii that shrink for each
/// later colour, then a few `stretch` passes along x or y whose teeth are Poisson-disk spaced,
/// each pass weaker than the one before, and a slight `bleed`. Unlike that generator the result
/// is a genome, so the paper is exact at any resolution and can be bred further.
///
/// Design units are millimetres of the paper, so every length of the recipe is a length on
/// the sheet. Determinism as for randomGenome (Generator.h): every draw comes from Pcg32 and
/// the recipe uses only IEEE basic operations and square roots, so a seed gives the same
/// genome on every machine.

#include "marbler/Genome.h"
#include "marbler/Random.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace marbler {

/// What `meta.generator` says of a paper; bump it when the same options start giving another
/// design.
inline constexpr const char* PaperGeneratorVersion = "marbler-paper-1";

/// Bounds of the options (the command line refuses others).
inline constexpr int MaxPaperColors = 16;
inline constexpr int MaxPaperPasses = 10;

/// What `meta.generator` says of a paper of the post's recipe (PaperRecipe::Post).
inline constexpr const char* PaperPostGeneratorVersion = "marbler-paper-post-1";

/// Which recipe makes the paper (docs/paper.md): the procedural marbled-paper post's, as
/// published (the default), or Marbler's first one.
enum class PaperRecipe {
    Post,    ///< painted circles on the first colour, golden-ratio ranges, a bath that wraps
    Classic, ///< drops that push each other, on a cream bath, with no wrap ("marbler-paper-1")
};

/// The golden ratio, by which the post's drop radii shrink per colour, its shifts per pass and
/// by which its tooth gaps grow per pass.
inline constexpr double GoldenRatio = 1.6180339887498948482;

/// What a paper is made of. Sizes in millimetres.
struct PaperOptions {
    PaperRecipe recipe = PaperRecipe::Post;
    double width = 210.0; ///< A4 by default
    double height = 297.0;
    int colors = 5;      ///< 1 to MaxPaperColors inks, one layer of drops each
    int passes = 3;      ///< 0 to MaxPaperPasses stretch passes
    bool pastel = false; ///< pale, soft inks on a white bath instead of random ones
    /// The post's wrap lattice (docs/genome-format.md, "Half-drop and brick repeats"): its passes'
    /// teeth span the period the lattice needs. Only the post's recipe wraps.
    Lattice lattice = Lattice::Straight;
};

/// The smallest distance between two drop centres of one colour, in millimetres, for a sheet of
/// w x h millimetres: 28 mm at A4, growing as the fourth root of the sheet's area (halfway, in
/// scale, between a fixed distance and one proportional to the sheet; README "Marbled paper"
/// says why), and never so small that the drops would exceed the format's entry limit.
double paperSpacing(double width, double height, int colors);

/// The radii of the drops of the colour layer `layer` (0 first): [lo, hi] = [0.4, 0.6] x
/// spacing x 0.8^layer, so every later colour's drops are smaller.
glm::dvec2 paperRadii(double spacing, int layer);

/// The post's recipe: the smallest distance between two drop centres of one colour, 20 mm at A4
/// (the post's 2 cm), growing as the fourth root of the sheet's area as paperSpacing does, and
/// kept within the format's entry limit.
double paperPostSpacing(double width, double height, int colors);

/// The post's recipe: the radii of the drops of palette colour `color` (1 first; colour 0 is
/// the bath): [0.75, 1.0] x spacing / phi^(color - 1).
glm::dvec2 paperPostRadii(double spacing, int color);

/// The post's recipe: the range of the first pass's shift, [2, 7] x spacing; pass k's shift is
/// the first's / phi^k.
glm::dvec2 paperPostFirstShift(double spacing);

/// The post's recipe: the range of pass k's tooth gap, [0.5, 1.0] x spacing x phi^k.
glm::dvec2 paperPostToothGap(double spacing, int pass);

/// The marbled paper of a seed. Throws InputError for options out of range (a size not
/// positive or above 100 m, colours or passes outside their bounds).
Genome paperGenome(std::uint64_t seed, const PaperOptions& options);

/// Points of [x0, x1] x [y0, y1] no two closer than `minDistance` (Bridson's Poisson-disk
/// sampling, candidates drawn in the annulus [d, 2d] by rejection), each coordinate rounded
/// to a hundredth before the distance is checked, in the order they were accepted; at most
/// `maxCount` of them.
std::vector<glm::dvec2> poissonDisk(Pcg32& rng, double x0, double y0, double x1, double y1,
                                    double minDistance, std::size_t maxCount);

/// The inks of a paper and its bath: random (any hue, vivid to muted, on a cream bath) or
/// pastel (pale and soft, on a white bath), each ink kept apart from the others and the bath.
std::vector<Color> paperPalette(Pcg32& rng, int count, bool pastel, Color* background);

} // namespace marbler
