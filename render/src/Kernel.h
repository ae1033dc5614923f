#pragma once
/// The tile kernel of the CPU renderer (internal to render/). A tile is a few hundred sample
/// points in structure-of-arrays form; the genome's operations are applied to the whole tile one
/// at a time, backward, so each loop is branch-free and vectorises, and points that find their
/// ink are swapped out so later operations skip them.

#include "marbler/Tools.h"

#include <cstddef>
#include <cstdint>

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
};

/// Traces the first `n` points of `tile` through `ops`, which hold a genome's prepared
/// operations in reverse time order (`count` of them, all of `dimension`). Writes the palette
/// index seen by point k (-1: none) to colors[tile.id[k]]; for points that find no ink, when
/// `whereX` is given, writes where they map back to into whereX/whereY[tile.id[k]]. Returns the
/// number of sample-operations traversed. The tile's arrays are clobbered.
std::uint64_t traceTile(const PreparedOp* ops, std::size_t count, int dimension, Tile& tile, int n, int* colors,
                        double* whereX, double* whereY);

/// sin and cos of x as the kernel computes them (for tests): Cody-Waite reduction by pi/2 and
/// the fdlibm polynomials, within about 1 ulp of std::sin/std::cos for |x| <= 1e6.
void sinCosForTest(double x, double& s, double& c);

/// The kernel's cube root on [0, 1] (for tests).
double cbrtForTest(double x);

} // namespace marbler::kernel
