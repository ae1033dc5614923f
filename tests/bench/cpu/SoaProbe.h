#pragma once
/// The structure-of-arrays probe: the straightforward vector loop for 2D drops and combs, as a
/// yardstick for the tile kernel. Every point runs through every operation (no early exit, no
/// compaction), one operation at a time over a block of points held as arrays of doubles, in
/// loops the compiler vectorises on its own. What it reaches on a genome's operation mix is
/// what plain vector code does on this machine; the kernel is measured against it.

#include "marbler/Tools.h"

#include <cstddef>

namespace marbler::probe {

/// Points per block: the block's arrays (x, y, colour) stay in the first-level cache, so the
/// probe measures arithmetic, not memory bandwidth.
inline constexpr std::size_t BlockSize = 2048;

/// Whether the probe handles every operation of `ops` (2D drops and combs only).
bool handles(const PreparedOp* ops, std::size_t count);

/// Traces n points (x, y; overwritten) through `ops`, which are in reverse time order, block by
/// block; writes the palette index each point shows (-1: none) to colors.
void trace(const PreparedOp* ops, std::size_t count, double* x, double* y, int* colors, std::size_t n);

} // namespace marbler::probe
