// The straightforward SoA loop (see SoaProbe.h). Built with -O3 -fno-math-errno
// -fno-trapping-math (so that sqrt and floor vectorise); the block loop is compiled for
// AVX-512, AVX2 and baseline x86-64, the loader picking the best, as a plain program built for
// this machine would be. The formulas are genome-format.md's, written the obvious way.

#include "SoaProbe.h"

#include <algorithm>
#include <cmath>

namespace marbler::probe {
namespace {

/// Inverse 2D drop: the ink test, then the push; points already coloured keep their colour.
[[gnu::always_inline]] inline void drop(const PreparedOp& op, double* __restrict x, double* __restrict y,
                                        int* __restrict colors, std::size_t n) {
    const double cx = op.c.x, cy = op.c.y, rr = op.r * op.r, r2 = op.rPow;
    const int color = op.color;
    for (std::size_t i = 0; i < n; ++i) {
        double dx = x[i] - cx, dy = y[i] - cy;
        double len2 = dx * dx + dy * dy;
        colors[i] = colors[i] < 0 && len2 < rr ? color : colors[i];
        double factor = std::sqrt(std::max(0.0, 1.0 - r2 / len2));
        x[i] = len2 > 0.0 ? cx + dx * factor : x[i];
        y[i] = len2 > 0.0 ? cy + dy * factor : y[i];
    }
}

/// Inverse 2D comb: shift back along M by l(d), d the distance to the nearest tine.
[[gnu::always_inline]] inline void comb(const PreparedOp& op, double* __restrict x, double* __restrict y,
                                        std::size_t n) {
    const double cx = op.c.x, cy = op.c.y, nx = op.n.x, ny = op.n.y, mx = op.m.x, my = op.m.y;
    const double al = op.alphaLambda, lambda = op.lambda, s = op.spacing;
    for (std::size_t i = 0; i < n; ++i) {
        double t = (x[i] - cx) * nx + (y[i] - cy) * ny;
        double m = t - s * std::floor(t / s);
        double d = 0.5 * s - std::abs(m - 0.5 * s);
        double l = al / (d + lambda);
        x[i] -= l * mx;
        y[i] -= l * my;
    }
}

__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void
traceBlock(const PreparedOp* ops, std::size_t count, double* x, double* y, int* colors, std::size_t n) {
    std::fill(colors, colors + n, -1);
    for (std::size_t k = 0; k < count; ++k) {
        if (ops[k].tool == Tool::Drop)
            drop(ops[k], x, y, colors, n);
        else
            comb(ops[k], x, y, n);
    }
}

} // namespace

bool handles(const PreparedOp* ops, std::size_t count) {
    return std::all_of(ops, ops + count, [](const PreparedOp& op) {
        return op.dimension == 2 && (op.tool == Tool::Drop || op.tool == Tool::Comb);
    });
}

void trace(const PreparedOp* ops, std::size_t count, double* x, double* y, int* colors, std::size_t n) {
    for (std::size_t at = 0; at < n; at += BlockSize)
        traceBlock(ops, count, x + at, y + at, colors + at, std::min(BlockSize, n - at));
}

} // namespace marbler::probe
