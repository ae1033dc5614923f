#pragma once
/// The sprays of a wrapping bath binned on a grid (internal to render/): the fast path of the
/// CPU renderer for `marbler paper`'s hundreds of painted circles. The kernel visits every
/// operation for every point; a point that falls through a layer of small circles visits them
/// all. Here the points, once the kernel has pulled them back through the operations before
/// the sprays, look up only the sprays whose (soft) disc reaches their grid cell, newest first,
/// with the kernel's arithmetic (Kernel.cpp sprayWrapped2 and bleedInk), so the result is the
/// same to the bit.

#include "marbler/Tools.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace marbler::kernel {

struct Bleed;

/// A trailing run of sprays of a wrapped design's reversed operations, binned.
struct SprayGrid {
    std::size_t first = 0;            ///< the index in the reversed operations where the run starts
    double width = 0.0, height = 0.0; ///< the design's size (the wrap's periods)
    glm::dvec2 shift{0.0};            ///< the lattice (PreparedOp::wrapShift): 0 for straight
    int cols = 1, rows = 1;
    double cellWidth = 1.0, cellHeight = 1.0;
    struct Spray {
        double cx, cy, r, rr; ///< the wrapped centre, radius and its square
        int color;
    };
    std::vector<Spray> sprays; ///< newest first (the reversed order)
    std::vector<std::uint32_t>
        start; ///< per cell (row-major), its first entry in `items`; one more at the end
    std::vector<std::uint32_t> items; ///< indices into `sprays`, ascending (newest first) per cell
};

/// The grid of `reversed`'s trailing sprays where the design wraps and they are many enough to
/// pay for it (null otherwise). `bleed` widens each disc by half the bleed (where its coverage
/// ends).
std::shared_ptr<const SprayGrid> makeSprayGrid(const std::vector<PreparedOp>& reversed, double bleed);

/// Continues the colour rule of points that traceTile left on the bath after the operations
/// before `grid.first`: for each k < n with colors[k] == -1 (and, under bleed, weight > 0), from
/// (whereX[k], whereY[k]) through the sprays, newest first. Writes colors[k] where an ink of
/// coverage 1 stops it, and under `bleed` its weight and rgb as traceTile would.
void traceSprays(const SprayGrid& grid, int n, int* colors, const double* whereX, const double* whereY,
                 const Bleed* bleed);

} // namespace marbler::kernel
