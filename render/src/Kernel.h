#pragma once
/// The tile kernel of the CPU renderer (internal to render/). A tile is a few hundred sample
/// points in structure-of-arrays form; the genome's operations are applied to the whole tile one
/// at a time, backward, so each loop is branch-free and vectorises, and points that find their
/// ink are swapped out so later operations skip them.

#include "marbler/Tools.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace marbler::kernel {

/// Points per tile: large enough to amortise the per-operation dispatch, small enough that the
/// tile's arrays stay in L1.
inline constexpr int TileSize = 512;

/// The working arrays of one tile. x, y, z hold the points being traced; id their index in the
/// caller's arrays; the t arrays are scratch.
struct alignas(64) Tile {
    double x[TileSize];
    double y[TileSize];
    double z[TileSize];
    double t0[TileSize];
    double t1[TileSize];
    double t2[TileSize];
    double t3[TileSize];
    std::int64_t flag[TileSize];
    int id[TileSize];
    // Bleed only (traceTile with a Bleed): the weight left for what lies beneath each point,
    // and the linear colour of the inks met so far, each already weighted.
    double w[TileSize];
    double r[TileSize];
    double g[TileSize];
    double b[TileSize];
};

/// Version 2's soft ink edges (genome-format.md, `bleed`): what traceTile needs to composite
/// the inks it meets, and where it leaves the result.
struct Bleed {
    double width = 0.0;                  ///< the genome's bleed b > 0
    const glm::dvec3* palette = nullptr; ///< the inks' linear colours
    /// Per caller index: the weight of what lies beneath the inks met (0 where the search
    /// stopped on an ink of coverage 1; then colors[] holds that ink), and the linear colour
    /// those inks add (3 doubles: sum of weight * coverage * ink).
    double* weight = nullptr;
    double* rgb = nullptr;
};

/// Traces the first `n` points of `tile` through `ops`, which hold a genome's prepared
/// operations in reverse time order (`count` of them, all of `dimension`). Writes the palette
/// index seen by point k (-1: none) to colors[tile.id[k]]; for points that find no ink, when
/// `whereX` is given, writes where they map back to into whereX/whereY[tile.id[k]]. Returns the
/// number of sample-operations traversed. The tile's arrays are clobbered. Runs the active
/// variant (activeChoice). With `bleed`, an ink of coverage 0 < c < 1 does not stop a point
/// (Tools.h traceCovers): colors[] receives the ink a point stopped on (coverage 1) or -1,
/// and bleed->weight and bleed->rgb what the inks met add up to; whereX/whereY are written
/// for the points that reach the bath (weight > 0).
std::uint64_t traceTile(const PreparedOp* ops, std::size_t count, int dimension, Tile& tile, int n,
                        int* colors, double* whereX, double* whereY, const Bleed* bleed = nullptr);

/// The compiled variants of traceTile, best first. Avx512 (x86-64-v4) also replaces the
/// divides and roots of drops, lines and combs by refined hardware estimates (a few ulps from
/// the reference); Avx2 (x86-64-v3) and Baseline (x86-64) round exactly like the reference
/// outside sine, cosine and cube root.
enum class Variant { Avx512, Avx2, Baseline };
inline constexpr Variant AllVariants[] = {Variant::Avx512, Variant::Avx2, Variant::Baseline};

/// "avx512", "avx2", "baseline": the names MARBLER_KERNEL takes.
const char* variantName(Variant v);
std::optional<Variant> variantNamed(std::string_view name);
/// Whether the running CPU (and operating system) can execute the variant.
bool cpuRuns(Variant v);
/// The variants the CPU runs, best first (never empty: Baseline runs everywhere).
std::vector<Variant> supportedVariants();

/// A variant and why it was picked.
struct Choice {
    Variant variant;
    std::string reason;
};
/// The variant for a value of MARBLER_KERNEL (null, "" or "auto": the best the CPU runs). A
/// name that is not a variant, or a variant the CPU cannot run, falls back to the best, and
/// the reason says so; nothing is refused, so a stale setting never stops a render.
Choice chooseVariant(const char* requested);
/// As chooseVariant, for a CPU that runs `supported` (best first, not empty): for tests.
Choice chooseVariant(const char* requested, const std::vector<Variant>& supported);
/// The variant traceTile uses: chosen from MARBLER_KERNEL on first use, or set.
Choice activeChoice();
/// Makes traceTile use `choice.variant` from now on, in every thread (the caller checks that
/// the CPU runs it).
void setActiveChoice(const Choice& choice);

/// The variant that ran the last traceTile on the calling thread.
Variant lastVariantRunForTest();

/// The point-steps the stylus kernel has run on the calling thread (one point through one
/// integration step counts one): lets the tests see that it skips the steps that cannot move
/// a point.
std::uint64_t stylusStepsRunForTest();

/// sin and cos of x as the kernel computes them (for tests): Cody-Waite reduction by pi/2 and
/// the fdlibm polynomials, within about 1 ulp of std::sin/std::cos for |x| <= 1e6.
void sinCosForTest(double x, double& s, double& c);

/// The kernel's cube root on [0, 1] (for tests).
double cbrtForTest(double x);

} // namespace marbler::kernel
