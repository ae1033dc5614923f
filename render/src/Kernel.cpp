// The tile kernel. Every loop here computes the formulas of genome/src/Tools.cpp (the scalar
// reference), in the same order of operations, so that the renderer and the reference agree to
// the last bit wherever no sine, cosine, cube root or AVX-512 variant is involved, and within
// an ulp or a few where one is (the AVX-512 variant's drops replace the divides, square roots
// and cube root by refined reciprocal square roots and a multiply-only cube root, and fold the
// compaction into the same pass: see dropAvx512; its lines and combs replace their divides by
// refined reciprocals: see lineAvx512). This file is built with -O3
// -fno-math-errno -fno-trapping-math -ffp-contract=off: the first two let GCC vectorise sqrt
// and floor, the last keeps it from fusing multiply-adds, which would round differently from
// the reference.
//
// The body of traceTile is compiled three times, as explicit variants (AVX-512 with the
// hand-written drops, lines and combs, AVX2+FMA, baseline x86-64); traceTile calls the one chosen once per
// process: the best the CPU runs, or the one MARBLER_KERNEL names (see chooseVariant), so the
// binary runs anywhere, uses the widest vectors it can, and every variant can be tested on a
// machine that runs it.

#include "Kernel.h"

#include "marbler/Atan.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <numbers>
#include <utility>
#include <vector>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#endif

// "These loop iterations are independent": GCC and clang spell it differently, and each warns
// about the other's pragma. The hint is a request: where clang cannot honour it (the sanitised
// fuzz build instruments every load), the loop is still right, only scalar, so it is not warned of.
#if defined(__clang__)
#define MARBLER_IVDEP _Pragma("clang loop vectorize(assume_safety)")
#pragma clang diagnostic ignored "-Wpass-failed"
#elif defined(__GNUC__)
#define MARBLER_IVDEP _Pragma("GCC ivdep")
#else
#define MARBLER_IVDEP
#endif

namespace marbler::kernel {
namespace {

/// The variant that ran the last traceTile on this thread: lets the tests see which code a
/// selection actually runs, for the price of one store per tile.
thread_local Variant lastVariantRun = Variant::Baseline;
/// The point-steps the stylus kernel ran on this thread (stylusStepsRunForTest).
thread_local std::uint64_t stylusStepsRun = 0;

// Cody-Waite split of pi/2 (fdlibm e_rem_pio2.c): the first two parts have 33 significant bits,
// so q * part is exact for |q| < 2^20, which covers |x| <= SinCosLimit.
constexpr double TwoOverPi = 6.36619772367581382433e-01;
constexpr double Pio2_1 = 1.57079632673412561417e+00;
constexpr double Pio2_2 = 6.07710050630396597660e-11;
constexpr double Pio2_3 = 2.02226624871116645580e-21;
// Adding 1.5 * 2^52 rounds a double of magnitude < 2^51 to an integer, left in the low mantissa bits.
constexpr double RoundShifter = 6755399441055744.0;
// Beyond this the reduction loses accuracy; such angles go through std::sin/std::cos.
constexpr double SinCosLimit = 1.0e6;

// fdlibm k_sin.c / k_cos.c minimax polynomials on [-pi/4, pi/4].
constexpr double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                 S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                 S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
constexpr double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                 C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                 C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;

/// sin and cos, branch-free so that a loop calling it vectorises. Accurate for |x| <= SinCosLimit.
[[gnu::always_inline]] inline void sinCos(double x, double& sinOut, double& cosOut) {
    double shifted = x * TwoOverPi + RoundShifter;
    double q = shifted - RoundShifter;
    std::uint64_t quadrant = std::bit_cast<std::uint64_t>(shifted);
    double r = ((x - q * Pio2_1) - q * Pio2_2) - q * Pio2_3;
    double z = r * r;
    double sr = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
    double sinR = r + (z * r) * (S1 + z * sr);
    double cr = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
    double hz = 0.5 * z;
    double w = 1.0 - hz;
    double cosR = w + (((1.0 - w) - hz) + z * cr);
    // Quadrant k: sin = (s, c, -s, -c)[k], cos = (c, -s, -c, s)[k].
    bool swap = (quadrant & 1) != 0;
    double s = swap ? cosR : sinR;
    double c = swap ? sinR : cosR;
    std::uint64_t sinSign = (quadrant & 2) << 62;
    std::uint64_t cosSign = ((quadrant + 1) & 2) << 62;
    sinOut = std::bit_cast<double>(std::bit_cast<std::uint64_t>(s) ^ sinSign);
    cosOut = std::bit_cast<double>(std::bit_cast<std::uint64_t>(c) ^ cosSign);
}

/// Cube root of x in [0, 1]: a float bit-trick first guess, then three Halley steps (cubic
/// convergence: 3e-2, 3e-5, 3e-14, rounding).
[[gnu::always_inline]] inline double cbrtUnit(double x) {
    float xf = static_cast<float>(x);
    auto bits = std::bit_cast<std::int32_t>(xf);
    bits = static_cast<std::int32_t>(static_cast<double>(bits) * (1.0 / 3.0)) + 0x2a514067;
    double y = static_cast<double>(std::bit_cast<float>(bits));
    for (int i = 0; i < 3; ++i) {
        double y3 = y * y * y;
        y = y * (y3 + 2.0 * x) / (y3 + y3 + x);
    }
    // The guess is meaningless below float's range; no point outside an ink gets there but
    // one exactly on the boundary (x == 0).
    return x < 1e-30 ? 0.0 : y;
}

/// The comb's distance to the nearest tine (Tools.cpp combDistance).
[[gnu::always_inline]] inline double combDistance(double t, double s) {
    double m = t - s * std::floor(t / s);
    return 0.5 * s - std::abs(m - 0.5 * s);
}

/// Fills sinOut/cosOut for the first n angles; angles too large for the fast reduction are
/// redone with the library (rare: near a vortex centre, or a tiny wavelength).
[[gnu::always_inline]] inline void sinCosArray(const double* __restrict angle, double* __restrict sinOut,
                                               double* __restrict cosOut, int n) {
    std::int64_t large = 0;
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double s, c;
        sinCos(angle[i], s, c);
        sinOut[i] = s;
        cosOut[i] = c;
        large += std::abs(angle[i]) > SinCosLimit;
    }
    if (large == 0) return;
    for (int i = 0; i < n; ++i)
        if (std::abs(angle[i]) > SinCosLimit) {
            sinOut[i] = std::sin(angle[i]);
            cosOut[i] = std::cos(angle[i]);
        }
}

[[gnu::always_inline]] inline void sinArray(const double* __restrict angle, double* __restrict sinOut,
                                            double* __restrict scratch, int n) {
    sinCosArray(angle, sinOut, scratch, n);
}

/// Moves `count` entries from `from` down to `to` (to < from; the ranges may overlap). Copying
/// forward in blocks is safe when moving down: a block is read before any later block's
/// destination, which lies below that block's source, is written.
template <typename T> [[gnu::always_inline]] inline void slide(T* a, int to, int from, int count) {
    constexpr int Block = 64 / sizeof(T);
    int k = 0;
    for (; k + Block <= count; k += Block) {
        T block[Block];
        std::memcpy(block, a + from + k, sizeof(block));
        std::memcpy(a + to + k, block, sizeof(block));
    }
    for (; k < count; ++k)
        a[to + k] = a[from + k];
}

/// Whether the 8 flags from i are all clear (or all set).
[[gnu::always_inline]] inline bool noneSet8(const std::int64_t* f) {
    return (f[0] | f[1] | f[2] | f[3] | f[4] | f[5] | f[6] | f[7]) == 0;
}
[[gnu::always_inline]] inline bool allSet8(const std::int64_t* f) {
    return (f[0] & f[1] & f[2] & f[3] & f[4] & f[5] & f[6] & f[7]) != 0;
}

/// Removes the points whose flag (0 or 1) is set (they found ink), recording their colour; the
/// others keep their order. Ink lies in runs along a tile (a tile is a stretch of a pixel row),
/// so this walks the runs, eight flags at a time where it can, and slides each run of
/// survivors down in blocks instead of testing and copying point by point; the points before
/// the first hit stay where they are.
[[gnu::always_inline]] inline int compact(Tile& t, int n, int dimension, int color, int* colors) {
    const std::int64_t* __restrict flag = t.flag;
    const int* __restrict id = t.id;
    int i = 0;
    while (i + 8 <= n && noneSet8(flag + i))
        i += 8;
    while (i < n && !flag[i])
        ++i;
    int j = i;
    while (i < n) {
        while (i + 8 <= n && allSet8(flag + i)) {
            for (int k = 0; k < 8; ++k)
                colors[id[i + k]] = color;
            i += 8;
        }
        while (i < n && flag[i]) {
            colors[id[i]] = color;
            ++i;
        }
        const int start = i;
        while (i + 8 <= n && noneSet8(flag + i))
            i += 8;
        while (i < n && !flag[i])
            ++i;
        const int count = i - start;
        slide(t.x, j, start, count);
        slide(t.y, j, start, count);
        if (dimension == 3) slide(t.z, j, start, count);
        slide(t.id, j, start, count);
        j += count;
    }
    return j;
}

// ---- 2D -------------------------------------------------------------------------------------

/// Drop (2D area law) or spray: ink test, then (drop) the inverse push. Points inside the ink
/// are pushed too (to the centre); they are removed right after.
[[gnu::always_inline]] inline std::int64_t ink2(const PreparedOp& op, Tile& t, int n, bool pushes) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    std::int64_t* __restrict flag = t.flag;
    const double cx = op.c.x, cy = op.c.y, rr = op.r * op.r, r2 = op.rPow;
    std::int64_t inside = 0;
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double dx = x[i] - cx, dy = y[i] - cy;
        double len2 = dx * dx + dy * dy;
        std::int64_t in = len2 < rr;
        flag[i] = in;
        inside += in;
        if (pushes) {
            double factor = std::sqrt(std::max(0.0, 1.0 - r2 / len2));
            bool moves = len2 > 0.0;
            x[i] = moves ? x[i] + dx * (factor - 1.0) : x[i];
            y[i] = moves ? y[i] + dy * (factor - 1.0) : y[i];
        }
    }
    return inside;
}

// ---- Wrapping bath (docs/genome-format.md, "Wrapping bath") --------------------------------

/// Takes the tile's points into [0, w) x [0, h) (Tools.h wrapInto): at the start of a wrapped
/// design's trace and after each step that moves them, so a spray needs one image only.
[[gnu::always_inline]] inline void wrapTile(Tile& t, int n, const glm::dvec2& size, const glm::dvec2& shift) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    const double w = size.x, h = size.y;
    if (shift.x > 0.0 || shift.y > 0.0) {
        // A half-drop or brick lattice (Tools.h wrapPoint).
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 q = wrapPoint(x[i], y[i], size, shift);
            x[i] = q.x;
            y[i] = q.y;
        }
        return;
    }
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        x[i] = x[i] - w * std::floor(x[i] / w);
        y[i] = y[i] - h * std::floor(y[i] / h);
    }
}

/// A spray in a wrapping bath: the ink test against the nearest image of its (wrapped) centre
/// (Tools.cpp fromCentre); the points are already wrapped (wrapTile).
[[gnu::always_inline]] inline std::int64_t sprayWrapped2(const PreparedOp& op, Tile& t, int n) {
    const double* __restrict x = t.x;
    const double* __restrict y = t.y;
    std::int64_t* __restrict flag = t.flag;
    const double cx = op.c.x, cy = op.c.y, rr = op.r * op.r, w = op.wrap.x, h = op.wrap.y;
    const double hw = 0.5 * w, hh = 0.5 * h;
    std::int64_t inside = 0;
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double dx = x[i] - cx, dy = y[i] - cy;
        dx = dx > hw ? dx - w : (dx < -hw ? dx + w : dx);
        dy = dy > hh ? dy - h : (dy < -hh ? dy + h : dy);
        std::int64_t in = dx * dx + dy * dy < rr;
        flag[i] = in;
        inside += in;
    }
    return inside;
}

/// sprayWrapped2 on a half-drop or brick lattice: the nearest of the images of three columns
/// or rows (Tools.h nearestImage).
inline std::int64_t sprayLattice2(const PreparedOp& op, Tile& t, int n) {
    const double cx = op.c.x, cy = op.c.y, rr = op.r * op.r;
    std::int64_t inside = 0;
    for (int i = 0; i < n; ++i) {
        const glm::dvec2 d = nearestImage(glm::dvec2(t.x[i] - cx, t.y[i] - cy), op.wrap, op.wrapShift);
        std::int64_t in = d.x * d.x + d.y * d.y < rr;
        t.flag[i] = in;
        inside += in;
    }
    return inside;
}

// ---- end wrapping bath ----

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
// x86-64: the AVX-512 drops, lines and combs below, and the AVX-512 and AVX2 variants.
#define MARBLER_X86_VARIANTS 1

/// The exact 3D drop factor (ink3's formula) for the lanes of `len2`: the fallback of
/// dropAvx512 where its fast form's inputs are out of range.
[[gnu::noinline, gnu::cold]] void dropFactor3Exact(const double* len2, double r2, double* factor) {
    for (int k = 0; k < 8; ++k) {
        double len3 = len2[k] * std::sqrt(len2[k]);
        factor[k] = cbrtUnit(std::max(0.0, 1.0 - r2 / len3));
    }
}

/// The 3D drop factor cbrt(1 - r^3/len^3) without a divide or a square root: g = 1/len from
/// the 14-bit reciprocal square root and two Newton steps, x = 1 - r^3 g^3 in one rounding,
/// then y = x^(-1/3) from a float bit-trick guess (3.5%) and two third-order steps
/// y += y h (1/3 + 2h/9 + 14h^2/81), h = 1 - x y^3 (error 2e-5, then below an ulp), and the
/// cube root as x y^2: within a few ulps of the reference. Sets `bad` for the live lanes that
/// need the exact form: len2 not a moderate normal double, or a point outside the ink with x
/// below 1e-30 (float's range for the guess; only a hair from the ink's edge).
[[gnu::always_inline]] __attribute__((target("avx512f,fma"))) inline __m512d
dropFactor3(__m512d len2, __m512d r3, __mmask8 live, __mmask8 in, __mmask8& bad) {
    const __m512d half = _mm512_set1_pd(0.5), one = _mm512_set1_pd(1.0);
    const __m512d hp = _mm512_mul_pd(len2, half);
    __m512d g = _mm512_maskz_rsqrt14_pd(0xFF, len2);
    for (int k = 0; k < 2; ++k) {
        const __m512d e = _mm512_fnmadd_pd(_mm512_mul_pd(hp, g), g, half);
        g = _mm512_fmadd_pd(g, e, g);
    }
    const __m512d g3 = _mm512_mul_pd(_mm512_mul_pd(g, g), g);
    const __m512d x = _mm512_fnmadd_pd(r3, g3, one);
    bad = live & ~(_mm512_cmp_pd_mask(len2, _mm512_set1_pd(1e-200), _CMP_GE_OQ) &
                   _mm512_cmp_pd_mask(len2, _mm512_set1_pd(1e200), _CMP_LE_OQ));
    bad |= live & ~in & ~_mm512_cmp_pd_mask(x, _mm512_set1_pd(1e-30), _CMP_GE_OQ);
    // Guess: the float's bits b give x^(-1/3) ~ bits magic - b/3 (b/3 in double: exact enough).
    const __m256i bits = _mm256_castps_si256(_mm512_maskz_cvtpd_ps(0xFF, x));
    const __m256i third = _mm512_maskz_cvttpd_epi32(
        0xFF, _mm512_mul_pd(_mm512_maskz_cvtepi32_pd(0xFF, bits), _mm512_set1_pd(1.0 / 3.0)));
    __m512d y = _mm512_maskz_cvtps_pd(
        0xFF, _mm256_castsi256_ps(_mm256_sub_epi32(_mm256_set1_epi32(0x54a21d2a), third)));
    const __m512d c1 = _mm512_set1_pd(1.0 / 3.0), c2 = _mm512_set1_pd(2.0 / 9.0),
                  c3 = _mm512_set1_pd(14.0 / 81.0);
    for (int k = 0; k < 2; ++k) {
        const __m512d y3 = _mm512_mul_pd(_mm512_mul_pd(y, y), y);
        const __m512d h = _mm512_fnmadd_pd(x, y3, one);
        const __m512d poly = _mm512_fmadd_pd(_mm512_fmadd_pd(c3, h, c2), h, c1);
        y = _mm512_fmadd_pd(_mm512_mul_pd(y, h), poly, y);
    }
    // Points in the ink get 0, as max(0, .) gives the reference (they are removed anyway).
    return _mm512_maskz_mul_pd(~in, x, _mm512_mul_pd(y, y));
}

/// One step of dropAvx512: 8 points from i (`live` masks those past n in the last step).
/// Traces them through the drop and writes the survivors, compressed, from j; records the
/// colour of those in the ink.
template <int Dim>
[[gnu::always_inline]] __attribute__((target("avx512f,fma"))) inline void
dropStep(Tile& t, int i, int& j, __mmask8 live, __m512d cx, __m512d cy, __m512d cz, __m512d rr, __m512d r2,
         double r2s, int color, int* __restrict colors) {
    const __m512d zero = _mm512_setzero_pd(), half = _mm512_set1_pd(0.5), one = _mm512_set1_pd(1.0);
    const bool full = live == 0xFF;
    __m512d px = full ? _mm512_loadu_pd(t.x + i) : _mm512_maskz_loadu_pd(live, t.x + i);
    __m512d py = full ? _mm512_loadu_pd(t.y + i) : _mm512_maskz_loadu_pd(live, t.y + i);
    __m512d pz = zero;
    if (Dim == 3) pz = full ? _mm512_loadu_pd(t.z + i) : _mm512_maskz_loadu_pd(live, t.z + i);
    const __m512d dx = _mm512_sub_pd(px, cx), dy = _mm512_sub_pd(py, cy);
    const __m512d dz = Dim == 3 ? _mm512_sub_pd(pz, cz) : zero;
    __m512d len2 = _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
    if (Dim == 3) len2 = _mm512_add_pd(len2, _mm512_mul_pd(dz, dz));
    const __mmask8 in = _mm512_mask_cmp_pd_mask(live, len2, rr, _CMP_LT_OQ);
    __m512d factor;
    if (Dim == 2) {
        // sqrt(1 - r^2/len2) as w / sqrt(len2 w), w = len2 - r^2 (see dropAvx512).
        const __m512d w = _mm512_sub_pd(len2, r2);
        const __mmask8 outside = _mm512_cmp_pd_mask(w, zero, _CMP_GT_OQ);
        const __m512d prod = _mm512_mul_pd(len2, w);
        const __mmask8 normal = _mm512_cmp_pd_mask(prod, _mm512_set1_pd(1e-290), _CMP_GE_OQ) &
                                _mm512_cmp_pd_mask(prod, _mm512_set1_pd(1e290), _CMP_LE_OQ);
        if ((outside & live & ~normal) == 0) [[likely]] {
            const __m512d hp = _mm512_mul_pd(prod, half);
            __m512d g = _mm512_maskz_rsqrt14_pd(0xFF, prod);
            for (int k = 0; k < 2; ++k) {
                const __m512d e = _mm512_fnmadd_pd(_mm512_mul_pd(hp, g), g, half);
                g = _mm512_fmadd_pd(g, e, g);
            }
            factor = _mm512_maskz_mul_pd(outside, w, g);
        } else {
            factor = _mm512_maskz_sqrt_pd(
                0xFF, _mm512_maskz_max_pd(0xFF, zero, _mm512_sub_pd(one, _mm512_div_pd(r2, len2))));
        }
    } else {
        __mmask8 bad;
        factor = dropFactor3(len2, r2, live, in, bad);
        if (bad != 0) [[unlikely]] {
            alignas(64) double l[8], f[8];
            _mm512_store_pd(l, len2);
            dropFactor3Exact(l, r2s, f);
            factor = _mm512_load_pd(f);
        }
    }
    const __m512d fm1 = _mm512_sub_pd(factor, one);
    const __mmask8 moves = _mm512_mask_cmp_pd_mask(live, len2, zero, _CMP_GT_OQ);
    px = _mm512_mask_add_pd(px, moves, px, _mm512_mul_pd(dx, fm1));
    py = _mm512_mask_add_pd(py, moves, py, _mm512_mul_pd(dy, fm1));
    if (Dim == 3) pz = _mm512_mask_add_pd(pz, moves, pz, _mm512_mul_pd(dz, fm1));
    const __mmask8 keep = live & ~in;
    if (j == i && keep == live) {
        // Nothing removed so far: the points stay where they are.
        if (full) {
            _mm512_storeu_pd(t.x + i, px);
            _mm512_storeu_pd(t.y + i, py);
            if (Dim == 3) _mm512_storeu_pd(t.z + i, pz);
        } else {
            _mm512_mask_storeu_pd(t.x + i, live, px);
            _mm512_mask_storeu_pd(t.y + i, live, py);
            if (Dim == 3) _mm512_mask_storeu_pd(t.z + i, live, pz);
        }
        j += __builtin_popcount(unsigned(live));
        return;
    }
    for (unsigned m = in; m != 0; m &= m - 1)
        colors[t.id[i + __builtin_ctz(m)]] = color;
    // Compress in registers and store whole vectors: j <= i, so the 8 slots from j lie below
    // i + 8 (within the tile) and hold nothing not yet read; those past the survivors are junk
    // beyond the new count.
    const __m512i ids = _mm512_maskz_loadu_epi32(0xFF, t.id + i);
    _mm512_storeu_pd(t.x + j, _mm512_maskz_compress_pd(keep, px));
    _mm512_storeu_pd(t.y + j, _mm512_maskz_compress_pd(keep, py));
    if (Dim == 3) _mm512_storeu_pd(t.z + j, _mm512_maskz_compress_pd(keep, pz));
    _mm512_mask_storeu_epi32(t.id + j, 0xFF, _mm512_maskz_compress_epi32(__mmask16(keep), ids));
    j += __builtin_popcount(unsigned(keep));
}

/// The drop with AVX-512 (see ink2 and ink3), with the compaction folded in: returns the number
/// of points left. The push's factor has no divide and no square root, which share one slow
/// unit and bound the exact form. In 2D, sqrt(1 - r^2/len2) is w / sqrt(len2 w), w = len2 -
/// r^2, from the hardware's 14-bit reciprocal square root and two Newton steps; in 3D see
/// dropFactor3. Both are a few ulps from the correctly rounded value (the test against the
/// reference allows 1e-9); vectors with absurdly large or tiny distances use the exact form.
/// The ink test itself is the reference's, bit for bit.
template <int Dim>
__attribute__((target("avx512f,fma"))) int dropAvx512(const PreparedOp& op, Tile& t, int n, int* colors) {
    const __m512d cx = _mm512_set1_pd(op.c.x), cy = _mm512_set1_pd(op.c.y), cz = _mm512_set1_pd(op.c.z);
    const __m512d rr = _mm512_set1_pd(op.r * op.r), r2 = _mm512_set1_pd(op.rPow);
    int i = 0, j = 0;
    for (; i + 8 <= n; i += 8)
        dropStep<Dim>(t, i, j, __mmask8(0xFF), cx, cy, cz, rr, r2, op.rPow, op.color, colors);
    if (i < n)
        dropStep<Dim>(t, i, j, __mmask8((1u << (n - i)) - 1u), cx, cy, cz, rr, r2, op.rPow, op.color, colors);
    return j;
}

/// One step of lineAvx512: 8 points from i, `live` masking those past n in the last step.
template <int Dim, bool Comb, bool Full>
[[gnu::always_inline]] __attribute__((target("avx512f,fma"))) inline void
lineStep(Tile& t, int i, __mmask8 live, const __m512d (&c)[3], const __m512d (&nrm)[3],
         const __m512d (&alm)[3], __m512d s, __m512d invS, __m512d halfS, __m512d lambda) {
    double* const axes[3] = {t.x, t.y, t.z};
    __m512d p[3];
    for (int a = 0; a < Dim; ++a)
        p[a] = Full ? _mm512_loadu_pd(axes[a] + i) : _mm512_maskz_loadu_pd(live, axes[a] + i);
    __m512d along = _mm512_mul_pd(_mm512_sub_pd(p[0], c[0]), nrm[0]);
    for (int a = 1; a < Dim; ++a)
        along = _mm512_fmadd_pd(_mm512_sub_pd(p[a], c[a]), nrm[a], along);
    __m512d d;
    // (The zero-masked forms of roundscale and rcp14: the plain ones trip GCC 12's
    // -Wmaybe-uninitialized in its own header.)
    if (Comb) {
        const __m512d k = _mm512_maskz_roundscale_pd(0xFF, _mm512_mul_pd(along, invS),
                                                     _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
        const __m512d rem = _mm512_fnmadd_pd(s, k, along);
        d = _mm512_sub_pd(halfS, _mm512_abs_pd(_mm512_sub_pd(rem, halfS)));
    } else {
        d = _mm512_abs_pd(along);
    }
    const __m512d den = _mm512_add_pd(d, lambda);
    const __m512d one = _mm512_set1_pd(1.0);
    __m512d r = _mm512_maskz_rcp14_pd(0xFF, den);
    for (int step = 0; step < 2; ++step)
        r = _mm512_fmadd_pd(r, _mm512_fnmadd_pd(den, r, one), r);
    for (int a = 0; a < Dim; ++a) {
        const __m512d moved = _mm512_fnmadd_pd(r, alm[a], p[a]);
        if (Full)
            _mm512_storeu_pd(axes[a] + i, moved);
        else
            _mm512_mask_storeu_pd(axes[a] + i, live, moved);
    }
}

/// Line and comb with AVX-512 (see line2 and line3) without a divide, as the drops: t / s is
/// t (1/s), 1 / (d + lambda) comes from the 14-bit reciprocal and two Newton steps, and the
/// shift l M is that times alpha lambda M: a few ulps from the reference's quotient. d stays continuous
/// across the tines' midlines, so where t (1/s) rounds to the other side of an integer, d still moves by an
/// ulp or so.
template <int Dim, bool Comb>
__attribute__((target("avx512f,fma"))) void lineAvx512(const PreparedOp& op, Tile& t, int n) {
    const __m512d c[3] = {_mm512_set1_pd(op.c.x), _mm512_set1_pd(op.c.y), _mm512_set1_pd(op.c.z)};
    const __m512d nrm[3] = {_mm512_set1_pd(op.n.x), _mm512_set1_pd(op.n.y), _mm512_set1_pd(op.n.z)};
    const double al = op.alphaLambda;
    const __m512d alm[3] = {_mm512_set1_pd(al * op.m.x), _mm512_set1_pd(al * op.m.y),
                            _mm512_set1_pd(al * op.m.z)};
    const __m512d s = _mm512_set1_pd(op.spacing), invS = _mm512_set1_pd(1.0 / op.spacing);
    const __m512d halfS = _mm512_set1_pd(0.5 * op.spacing), lambda = _mm512_set1_pd(op.lambda);
    int i = 0;
    for (; i + 8 <= n; i += 8)
        lineStep<Dim, Comb, true>(t, i, 0xFF, c, nrm, alm, s, invS, halfS, lambda);
    if (i < n)
        lineStep<Dim, Comb, false>(t, i, __mmask8((1u << (n - i)) - 1u), c, nrm, alm, s, invS, halfS, lambda);
}
#endif

[[gnu::always_inline]] inline void line2(const PreparedOp& op, Tile& t, int n, bool comb) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    const double cx = op.c.x, cy = op.c.y, nx = op.n.x, ny = op.n.y, mx = op.m.x, my = op.m.y;
    const double al = op.alphaLambda, lambda = op.lambda, s = op.spacing;
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double along = (x[i] - cx) * nx + (y[i] - cy) * ny;
        double d = comb ? combDistance(along, s) : std::abs(along);
        double l = al / (d + lambda);
        x[i] = x[i] - l * mx;
        y[i] = y[i] - l * my;
    }
}

[[gnu::always_inline]] inline void wave2(const PreparedOp& op, Tile& t, int n) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict arg = t.t0;
    double* __restrict sn = t.t1;
    const double cx = op.c.x, cy = op.c.y, nx = op.n.x, ny = op.n.y, mx = op.m.x, my = op.m.y;
    const double amp = op.amp[0], freq = op.freq[0], phase = op.phase[0];
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i)
        arg[i] = freq * ((x[i] - cx) * nx + (y[i] - cy) * ny) + phase;
    sinArray(arg, sn, t.t2, n);
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double f = amp * sn[i];
        x[i] = x[i] - f * mx;
        y[i] = y[i] - f * my;
    }
}

/// Circle and vortex in 2D: turn by -theta about the centre.
[[gnu::always_inline]] inline void swirl2(const PreparedOp& op, Tile& t, int n, bool vortex) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict theta = t.t0;
    double* __restrict sn = t.t1;
    double* __restrict cs = t.t2;
    const double cx = op.c.x, cy = op.c.y, r = op.r, al = op.alphaLambda, lambda = op.lambda,
                 core2 = op.core2;
    const bool cored = core2 > 0.0;
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double dx = x[i] - cx, dy = y[i] - cy;
        double rho = std::sqrt(dx * dx + dy * dy);
        double d = vortex ? rho : std::abs(rho - r);
        // Version 2's core: l / sqrt(rho^2 + c^2) (Tools.cpp swirl).
        double across = cored ? std::sqrt(rho * rho + core2) : rho;
        theta[i] = -(al / (d + lambda)) / across;
    }
    sinCosArray(theta, sn, cs, n);
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double dx = x[i] - cx, dy = y[i] - cy;
        bool moves = dx * dx + dy * dy > 0.0;
        double c = cs[i], s = sn[i];
        double nxv = cx + (c * dx - s * dy);
        double nyv = cy + (s * dx + c * dy);
        x[i] = moves ? nxv : x[i];
        y[i] = moves ? nyv : y[i];
    }
}

// ---- 3D -------------------------------------------------------------------------------------

/// What an ink-laying tool does in 3D besides its ink test.
enum class Push3 {
    VolumeLaw, ///< drop: the volume law from the centre
    Column,    ///< cylinder: the area law across the axis (and the ink test across it too)
    None,      ///< spray: nothing
};

/// Drop (volume law), spray and cylinder (area law across the axis): ink test, then the push.
[[gnu::always_inline]] inline std::int64_t ink3(const PreparedOp& op, Tile& t, int n, Push3 push) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict z = t.z;
    std::int64_t* __restrict flag = t.flag;
    const double cx = op.c.x, cy = op.c.y, cz = op.c.z, rr = op.r * op.r, r2 = op.rPow;
    const double ax = op.a.x, ay = op.a.y, az = op.a.z;
    std::int64_t inside = 0;
    if (push == Push3::Column) {
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i) {
            double dx = x[i] - cx, dy = y[i] - cy, dz = z[i] - cz;
            double along = dx * ax + dy * ay + dz * az;
            dx = dx - along * ax;
            dy = dy - along * ay;
            dz = dz - along * az;
            double len2 = dx * dx + dy * dy + dz * dz;
            std::int64_t in = len2 < rr;
            flag[i] = in;
            inside += in;
            double factor = std::sqrt(std::max(0.0, 1.0 - r2 / len2));
            bool moves = len2 > 0.0;
            x[i] = moves ? x[i] + dx * (factor - 1.0) : x[i];
            y[i] = moves ? y[i] + dy * (factor - 1.0) : y[i];
            z[i] = moves ? z[i] + dz * (factor - 1.0) : z[i];
        }
    } else if (push == Push3::VolumeLaw) {
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i) {
            double dx = x[i] - cx, dy = y[i] - cy, dz = z[i] - cz;
            double len2 = dx * dx + dy * dy + dz * dz;
            std::int64_t in = len2 < rr;
            flag[i] = in;
            inside += in;
            double len3 = len2 * std::sqrt(len2);
            double factor = cbrtUnit(std::max(0.0, 1.0 - r2 / len3));
            bool moves = len2 > 0.0;
            x[i] = moves ? x[i] + dx * (factor - 1.0) : x[i];
            y[i] = moves ? y[i] + dy * (factor - 1.0) : y[i];
            z[i] = moves ? z[i] + dz * (factor - 1.0) : z[i];
        }
    } else { // spray
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i) {
            double dx = x[i] - cx, dy = y[i] - cy, dz = z[i] - cz;
            std::int64_t in = dx * dx + dy * dy + dz * dz < rr;
            flag[i] = in;
            inside += in;
        }
    }
    return inside;
}

[[gnu::always_inline]] inline void line3(const PreparedOp& op, Tile& t, int n, bool comb) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict z = t.z;
    const double cx = op.c.x, cy = op.c.y, cz = op.c.z, nx = op.n.x, ny = op.n.y, nz = op.n.z;
    const double mx = op.m.x, my = op.m.y, mz = op.m.z;
    const double al = op.alphaLambda, lambda = op.lambda, s = op.spacing;
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double along = (x[i] - cx) * nx + (y[i] - cy) * ny + (z[i] - cz) * nz;
        double d = comb ? combDistance(along, s) : std::abs(along);
        double l = al / (d + lambda);
        x[i] = x[i] - l * mx;
        y[i] = y[i] - l * my;
        z[i] = z[i] - l * mz;
    }
}

[[gnu::always_inline]] inline void wave3(const PreparedOp& op, Tile& t, int n) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict z = t.z;
    double* __restrict arg0 = t.t0;
    double* __restrict arg1 = t.t1;
    double* __restrict sn = t.t2;
    const double cx = op.c.x, cy = op.c.y, cz = op.c.z;
    const double ux = op.m.x, uy = op.m.y, uz = op.m.z, vx = op.v.x, vy = op.v.y, vz = op.v.z;
    const double wx = op.n.x, wy = op.n.y, wz = op.n.z;
    const bool ripple = op.shape == WaveShape::Ripple;
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double dx = x[i] - cx, dy = y[i] - cy, dz = z[i] - cz;
        double a = dx * ux + dy * uy + dz * uz;
        double b = dx * vx + dy * vy + dz * vz;
        if (ripple) {
            arg0[i] = op.freq[0] * std::sqrt(a * a + b * b) + op.phase[0];
        } else {
            arg0[i] = op.freq[0] * a + op.phase[0];
            arg1[i] = op.freq[1] * b + op.phase[1];
        }
    }
    double* __restrict scratch = t.t3;
    sinArray(arg0, sn, scratch, n);
    if (ripple) {
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i)
            arg0[i] = op.amp[0] * sn[i];
    } else {
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i)
            arg0[i] = op.amp[0] * sn[i];
        sinArray(arg1, sn, scratch, n);
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i)
            arg0[i] = arg0[i] + op.amp[1] * sn[i];
    }
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double shift = arg0[i];
        x[i] = x[i] - shift * wx;
        y[i] = y[i] - shift * wy;
        z[i] = z[i] - shift * wz;
    }
}

/// Circle (about the axis line: `cylindrical`), sphere and vortex (distance to the centre; a
/// `vortex` has d = rho) in 3D: turn by -theta about the line through the centre along the axis
/// (Tools.cpp rotateAbout).
[[gnu::always_inline]] inline void swirl3(const PreparedOp& op, Tile& t, int n, bool cylindrical,
                                          bool vortex) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict z = t.z;
    double* __restrict theta = t.t0;
    double* __restrict sn = t.t1;
    double* __restrict cs = t.t2;
    const double cx = op.c.x, cy = op.c.y, cz = op.c.z, ax = op.a.x, ay = op.a.y, az = op.a.z;
    const double r = op.r, al = op.alphaLambda, lambda = op.lambda, core2 = op.core2;
    const bool cored = core2 > 0.0;
    std::int64_t* __restrict moves = t.flag;
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double dx = x[i] - cx, dy = y[i] - cy, dz = z[i] - cz;
        double rho;
        if (cylindrical) {
            double along = dx * ax + dy * ay + dz * az;
            double ex = dx - along * ax, ey = dy - along * ay, ez = dz - along * az;
            rho = std::sqrt(ex * ex + ey * ey + ez * ez);
        } else {
            rho = std::sqrt(dx * dx + dy * dy + dz * dz);
        }
        double d = vortex ? rho : std::abs(rho - r);
        double across = cored ? std::sqrt(rho * rho + core2) : rho;
        double th = -(al / (d + lambda)) / across;
        // The centre (or axis) stays where it is; 0 keeps the sine pass off a NaN.
        theta[i] = rho > 0.0 ? th : 0.0;
        moves[i] = rho > 0.0;
    }
    sinCosArray(theta, sn, cs, n);
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double dx = x[i] - cx, dy = y[i] - cy, dz = z[i] - cz;
        double along = dx * ax + dy * ay + dz * az;
        double lx = along * ax, ly = along * ay, lz = along * az;
        double ex = dx - lx, ey = dy - ly, ez = dz - lz;
        // cross(a, across), as glm::cross computes it
        double kx = ay * ez - ey * az, ky = az * ex - ez * ax, kz = ax * ey - ex * ay;
        double c = cs[i], s = sn[i];
        double rx = (lx + ex * c) + kx * s, ry = (ly + ey * c) + ky * s, rz = (lz + ez * c) + kz * s;
        x[i] = moves[i] ? cx + rx : x[i];
        y[i] = moves[i] ? cy + ry : y[i];
        z[i] = moves[i] ? cz + rz : z[i];
    }
}

/// Line (`Comb` false) or comb in `Dim` dimensions: the AVX-512 variant's divide-free form, the
/// others' exact one.
template <Variant V, int Dim, bool Comb>
[[gnu::always_inline]] inline void lineOrComb(const PreparedOp& op, Tile& tile, int n) {
#ifdef MARBLER_X86_VARIANTS
    if constexpr (V == Variant::Avx512) {
        lineAvx512<Dim, Comb>(op, tile, n);
        return;
    }
#endif
    if constexpr (Dim == 2)
        line2(op, tile, n, Comb);
    else
        line3(op, tile, n, Comb);
}

/// The drop in `Dim` dimensions: the AVX-512 variant's hand-written form (the compaction folded
/// in), the others' exact one. Returns the number of points left.
template <Variant V, int Dim>
[[gnu::always_inline]] inline int drop(const PreparedOp& op, Tile& tile, int n, int* colors) {
#ifdef MARBLER_X86_VARIANTS
    if constexpr (V == Variant::Avx512) return dropAvx512<Dim>(op, tile, n, colors);
#endif
    std::int64_t inside;
    if constexpr (Dim == 2)
        inside = ink2(op, tile, n, true);
    else
        inside = ink3(op, tile, n, Push3::VolumeLaw);
    return inside != 0 ? compact(tile, n, Dim, op.color, colors) : n;
}

// ---- Version 2: stretch, flow (2D) ---------------------------------------------------------

/// Stretch (Tools.cpp stretchShift): u along N, the tooth interval t_i <= u < t_(i+1) by a
/// binary search of a fixed number of halvings (the same for every point, so the loop stays
/// branch-free), then x -= s sin(pi tau)^p M. sin^p: p = 1, 2 and 1/2 exactly as pow rounds
/// them (to the nearest double), any other p through std::pow, a point at a time.
[[gnu::always_inline]] inline void stretch2(const PreparedOp& op, Tile& t, int n) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict arg = t.t0;
    double* __restrict sn = t.t1;
    double* __restrict inside = t.t3;
    double* __restrict along = t.t2; // u, until the sines use it as scratch
    std::int64_t* __restrict below = t.flag;
    const double* __restrict teeth = op.teeth.data();
    const int count = static_cast<int>(op.teeth.size());
    if (count < 2) return;
    const int intervals = count - 1;
    const int top = static_cast<int>(std::bit_floor(static_cast<unsigned>(intervals)));
    const double cx = op.c.x, cy = op.c.y, nx = op.n.x, ny = op.n.y, mx = op.m.x, my = op.m.y;
    const double first = teeth[0], last = teeth[count - 1], shift = op.shift, power = op.power;
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        along[i] = (x[i] - cx) * nx + (y[i] - cy) * ny;
        below[i] = 0;
    }
    if (op.wrap.x > 0.0) {
        // A wrapping bath (Tools.cpp stretch): u modulo the period, into the teeth's span.
        const double period = std::abs(ny) > 0.5 ? op.wrap.y - op.wrapShift.y : op.wrap.x - op.wrapShift.x;
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i)
            along[i] = along[i] - period * std::floor((along[i] - first) / period);
    }
    // The last tooth at or below u: the largest k < intervals with teeth[k] <= u, a halving
    // at a time over the whole tile (a gather per point and halving).
    for (int step = top; step > 0; step >>= 1) {
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i) {
            std::int64_t probe = std::min<std::int64_t>(below[i] + step, intervals - 1);
            below[i] = teeth[probe] <= along[i] ? probe : below[i];
        }
    }
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double u = along[i];
        double lo = teeth[below[i]], hi = teeth[below[i] + 1];
        double tau = (u - lo) / (hi - lo);
        bool in = (u >= first) & (u < last);
        arg[i] = std::numbers::pi * tau;
        inside[i] = double(in);
    }
    // Outside the teeth tau means nothing: 0 keeps the sines off a NaN or a huge angle (a pass
    // of its own: GCC 12 vectorises neither loop with the select folded into the first).
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i)
        arg[i] = inside[i] != 0.0 ? arg[i] : 0.0;
    sinArray(arg, sn, t.t2, n);
    if (power == 1.0) {
    } else if (power == 2.0) {
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i)
            sn[i] = sn[i] * sn[i];
    } else if (power == 0.5) {
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i)
            sn[i] = std::sqrt(sn[i]);
    } else {
        for (int i = 0; i < n; ++i)
            sn[i] = inside[i] != 0.0 ? std::pow(sn[i], power) : 0.0;
    }
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double f = inside[i] != 0.0 ? shift * sn[i] : 0.0;
        x[i] = x[i] - f * mx;
        y[i] = y[i] - f * my;
    }
}

/// A flow's velocity at local (px, py) (Tools.cpp flowVelocity, in its order of operations).
template <bool Cavity>
[[gnu::always_inline]] inline void flowVelocity2(double px, double py, double lx, double ly, double u,
                                                 double piOverLx, double piOverLy, double& vx, double& vy) {
    (void)piOverLx;
    (void)piOverLy;
    if constexpr (Cavity) {
        double s = px / lx, t = py / ly;
        bool in = s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0;
        double f = 16.0 * s * s * (1.0 - s) * (1.0 - s), df = 32.0 * s * (1.0 - s) * (1.0 - 2.0 * s);
        double g = 7.5 * t * t * (1.0 - t) * (1.0 - t) * (1.0 - t),
               dg = 7.5 * t * (1.0 - t) * (1.0 - t) * (2.0 - 5.0 * t);
        double dpsiDy = u * f * dg;
        double dpsiDx = u * (ly / lx) * df * g;
        vx = in ? dpsiDy : 0.0;
        vy = in ? -dpsiDx : 0.0;
    } else {
        double ax = std::numbers::pi * px / lx, ay = std::numbers::pi * py / ly;
        double sx, cxv, sy, cyv;
        sinCos(ax, sx, cxv);
        sinCos(ay, sy, cyv);
        double dpsiDy = u * sx * cyv;
        double dpsiDx = u * (ly / lx) * cxv * sy;
        vx = dpsiDy;
        vy = -dpsiDx;
    }
}

/// Flow (Tools.cpp flow) backward: in local coordinates, n implicit midpoint steps of -h, each
/// solved by fixed-point iteration for the whole tile at once; a point that has settled (its
/// last iterate moved less than the tolerance, or 100 iterations) keeps its value while the
/// others go on, so every point takes exactly the iterations the reference takes. The kernel's
/// sine and cosine are good to an ulp only for |angle| <= SinCosLimit: points that could get
/// further (a design point some 1e5 cells from the field's origin) go through the reference.
template <bool Cavity> [[gnu::always_inline]] inline void flow2(const PreparedOp& op, Tile& t, int n) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict nextX = t.t0;
    double* __restrict nextY = t.t1;
    std::int64_t* __restrict active = t.flag;
    const double cx = op.c.x, cy = op.c.y, mx = op.m.x, my = op.m.y, nx = op.n.x, ny = op.n.y;
    const double lx = op.size[0], ly = op.size[1], u = op.speed, h = -op.step, tolerance = op.tolerance;
    const double piOverLx = std::numbers::pi / lx, piOverLy = std::numbers::pi / ly;
    // How far a point can travel in the flow's time, and where the fast sine stops.
    const double travel = std::abs(u) * std::abs(op.step) * op.steps * (1.0 + ly / lx + lx / ly);
    const double farX = 1e5 * lx - travel, farY = 1e5 * ly - travel;
    std::vector<std::pair<int, glm::dvec3>> far;
    for (int i = 0; i < n; ++i) {
        // Local coordinates (Tools.cpp: glm::dot(rel, m) with rel.z = 0).
        double rx = x[i] - cx, ry = y[i] - cy;
        double px = rx * mx + ry * my, py = rx * nx + ry * ny;
        if (!Cavity && !(std::abs(px) < farX && std::abs(py) < farY)) [[unlikely]]
            far.emplace_back(i, glm::dvec3(x[i], y[i], 0.0));
        x[i] = px;
        y[i] = py;
    }
    for (int k = 0; k < op.steps; ++k) {
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i) {
            double vx, vy;
            flowVelocity2<Cavity>(x[i], y[i], lx, ly, u, piOverLx, piOverLy, vx, vy);
            nextX[i] = x[i] + h * vx;
            nextY[i] = y[i] + h * vy;
            active[i] = 1;
        }
        std::int64_t left = n;
        for (int iteration = 0; iteration < 100 && left != 0; ++iteration) {
            left = 0;
            MARBLER_IVDEP
            for (int i = 0; i < n; ++i) {
                double vx, vy;
                flowVelocity2<Cavity>(0.5 * (x[i] + nextX[i]), 0.5 * (y[i] + nextY[i]), lx, ly, u, piOverLx,
                                      piOverLy, vx, vy);
                double againX = x[i] + h * vx, againY = y[i] + h * vy;
                double dx = againX - nextX[i], dy = againY - nextY[i];
                bool settled = std::sqrt(dx * dx + dy * dy) < tolerance;
                bool moving = active[i] != 0;
                nextX[i] = moving ? againX : nextX[i];
                nextY[i] = moving ? againY : nextY[i];
                std::int64_t still = moving && !settled;
                active[i] = still;
                left += still;
            }
        }
        MARBLER_IVDEP
        for (int i = 0; i < n; ++i) {
            x[i] = nextX[i];
            y[i] = nextY[i];
        }
    }
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double px = x[i], py = y[i];
        x[i] = (cx + px * mx) + py * nx;
        y[i] = (cy + px * my) + py * ny;
    }
    for (const auto& [i, p] : far) {
        glm::dvec3 q = inverseMap(op, p);
        x[i] = q.x;
        y[i] = q.y;
    }
}

// ---- Version 3: the stylus (2D) ------------------------------------------------------------

/// Stylus (Tools.cpp stylus) backward: each point runs the reference's steps (stylusStep),
/// newest first, but only those that can move it. A step moves a point only while the stylus is
/// within reach of it along the track (|(P - S(tau_i)) . T| < l; the tines are offset along N,
/// so this holds for all or none of them); otherwise the velocity at P is exactly zero, the
/// step's first guess and every iterate are P itself, and the step leaves it bit for bit
/// unchanged. On a segment m = (P - S(tau)) . T falls linearly with tau, so the steps that can
/// move a resting point form an interval found in closed form, widened by a margin far above
/// the rounding of m (and by a step at each end): a step is skipped only where the reference
/// surely leaves the point alone, and a point jumps from one such interval to the next. The
/// steps it does run are the reference's to the last bit (same formulas, same order, the
/// stations S(tau_i), c(tau_i) precomputed by the same code: Tools.cpp stylusStation).
///
/// The steps then run for all the points waiting on them at once, in lanes (as flow2 does),
/// which hides the long chain of divides of one point's iteration behind the others'.
///
/// The segments a tile's points can reach are found first, from the box around the points
/// grown by the farthest any point can travel in the whole stroke (L times the largest speed),
/// so that a point far from most of a long path does not test every segment.
[[gnu::always_inline]] inline void stylus2(const PreparedOp& op, Tile& t, int n) {
    const int steps = op.steps;
    if (steps <= 0 || op.stations.size() != static_cast<std::size_t>(steps) || op.path.size() < 2 ||
        op.tines < 1 || op.tines > 64) {
        // Not prepared by prepare(), or more tines than a file may hold: the reference itself.
        for (int i = 0; i < n; ++i) {
            glm::dvec3 p = inverseMap(op, {t.x[i], t.y[i], 0.0});
            t.x[i] = p.x;
            t.y[i] = p.y;
        }
        return;
    }
    const int tines = op.tines;
    double offset[64];
    double widest = 0.0;
    for (int j = 0; j < tines; ++j) {
        offset[j] = (j - 0.5 * (op.tines - 1)) * op.spacing;
        widest = std::max(widest, std::abs(offset[j]));
    }
    const double h = -op.step, step = op.step, tolerance = op.tolerance, lambda = op.lambda, reach = op.reach;
    const double toU = 1.0 / reach, toQ = 1.0 / lambda; // as stylusVelocity divides
    const StylusStation* stations = op.stations.data();
    const glm::dvec2* along = op.along.data();
    const glm::dvec2* path = op.path.data();
    const double* cum = op.cum.data();
    const int* first = op.firstStep.data();
    const int segments = static_cast<int>(op.along.size());
    // The scale of every coordinate the reference's m is made of: its rounding is a few ulps of
    // this (plus the point's own size); the margin is 1e-9 of it.
    double farthest = 0.0;
    for (const glm::dvec2& p : op.path)
        farthest = std::max(farthest, std::abs(p.x) + std::abs(p.y));
    const double scale = op.length + reach + widest + farthest;
    // The fastest any point moves: each tine's |v| <= |c| (1 + lambda (pi / 2) max|w'| / l) with
    // max|w'| = 8 / (3 sqrt 3); over the stroke a point travels at most L times that.
    double largestPull = 0.0;
    for (double p : op.pressure)
        largestPull = std::max(largestPull, std::abs(op.pull * p));
    const double travel = 1.01 * op.length * tines * largestPull *
                          (1.0 + lambda * 1.5707963267948966 * 1.5396007178390021 / reach);

    // The box around the tile's points, and the segments whose reach it can get into.
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    bool finite = true;
    for (int i = 0; i < n; ++i) {
        x0 = std::min(x0, t.x[i]);
        x1 = std::max(x1, t.x[i]);
        y0 = std::min(y0, t.y[i]);
        y1 = std::max(y1, t.y[i]);
        finite = finite && std::abs(t.x[i]) < 1e150 && std::abs(t.y[i]) < 1e150;
    }
    const double grow = travel + 1e-9 * (scale + std::abs(x0) + std::abs(x1) + std::abs(y0) + std::abs(y1));
    x0 -= grow;
    x1 += grow;
    y0 -= grow;
    y1 += grow;
    int candidates[1024];
    std::vector<int> manyCandidates;
    int* candidate = candidates;
    if (segments > 1024) {
        manyCandidates.resize(static_cast<std::size_t>(segments));
        candidate = manyCandidates.data();
    }
    int count = 0;
    for (int s = 0; s < segments; ++s) {
        if (first[s] >= first[s + 1]) continue; // no step's time lies on it
        const double tx = along[s].x, ty = along[s].y;
        // m0 = (P - path_s) . T over the box's corners.
        const double ax = (x0 - path[s].x) * tx, bx = (x1 - path[s].x) * tx;
        const double ay = (y0 - path[s].y) * ty, by = (y1 - path[s].y) * ty;
        const double lo = std::min(ax, bx) + std::min(ay, by), hi = std::max(ax, bx) + std::max(ay, by);
        const double length = cum[s + 1] - cum[s];
        if (!finite || (hi > -reach - grow && lo < length + reach + grow)) candidate[count++] = s;
    }

    // The newest step at or below k that can move point i where it rests (-1: none), its cursor
    // in the candidate segments carried from call to call.
    int cursor[TileSize];
    auto nextStep = [&](int i, int k) {
        const double px = t.x[i], py = t.y[i];
        // Beyond 1e150 m0 could overflow: such a point runs every step.
        if (!(std::abs(px) < 1e150 && std::abs(py) < 1e150)) return k;
        const double margin = 1e-9 * (scale + std::abs(px) + std::abs(py));
        int c = cursor[i];
        while (c >= 0 && k >= 0) {
            const int s = candidate[c];
            if (first[s] > k) {
                --c;
                continue;
            }
            const double m0 = (px - path[s].x) * along[s].x + (py - path[s].y) * along[s].y;
            // Moving while |m0 - (tau - cum_s)| < l, tau = (k + 1/2) h.
            const double top = (cum[s] + m0 + reach + margin) / step - 0.5;
            const double bottom = (cum[s] + m0 - reach - margin) / step - 0.5;
            const int last = std::min(k, first[s + 1] - 1);
            const int hi = top >= last ? last : top < first[s] - 1 ? first[s] - 2 : int(std::floor(top)) + 1;
            const int lo = bottom <= first[s]  ? first[s]
                           : bottom > last + 1 ? last + 2
                                               : int(std::ceil(bottom)) - 1;
            if (hi >= lo && hi >= first[s]) {
                cursor[i] = c;
                return hi;
            }
            k = first[s] - 1;
            --c;
        }
        cursor[i] = c;
        return -1;
    };
    // The points waiting for each step: a list through `link`, headed in `head`.
    thread_local std::vector<int> head;
    head.assign(static_cast<std::size_t>(steps), -1);
    int link[TileSize];
    auto wait = [&](int i, int k) {
        const int at = nextStep(i, k);
        if (at < 0) return;
        link[i] = head[static_cast<std::size_t>(at)];
        head[static_cast<std::size_t>(at)] = i;
    };
    for (int i = 0; i < n; ++i) {
        cursor[i] = count - 1;
        wait(i, steps - 1);
    }

    // Each step runs for the points waiting on it together, lane by lane as flow2 does: the
    // velocity a tine at a time (its arctangents too: vectorAtan, Atan.h, as the reference), and the
    // fixed-point iteration until every lane has settled, a settled lane keeping its value.
    alignas(64) double px[TileSize], py[TileSize], nextX[TileSize], nextY[TileSize], vx[TileSize],
        vy[TileSize], ex[TileSize], ey[TileSize], us[TileSize], qs[TileSize];
    alignas(64) std::int64_t alive[TileSize], reached[TileSize];
    int lane[TileSize];
    for (int k = steps; k-- > 0;) {
        int m = 0;
        for (int i = head[static_cast<std::size_t>(k)]; i >= 0; i = link[i])
            lane[m++] = i;
        if (m == 0) continue;
        stylusStepsRun += static_cast<std::uint64_t>(m);
        const StylusStation& station = stations[k];
        const double tx = along[station.segment].x, ty = along[station.segment].y, nx = -ty, ny = tx;
        const double sx = station.s.x, sy = station.s.y, c = station.c, side = c * lambda * toU;
        for (int j = 0; j < m; ++j) {
            px[j] = t.x[lane[j]];
            py[j] = t.y[lane[j]];
            alive[j] = 1;
        }
        // v at (ex, ey) for the alive lanes (Tools.cpp stylusVelocity, in its order of operations).
        auto velocity = [&](const double* __restrict qx, const double* __restrict qy)
            __attribute__((always_inline)) {
            MARBLER_IVDEP
            for (int j = 0; j < m; ++j) {
                vx[j] = 0.0;
                vy[j] = 0.0;
            }
            for (int tine = 0; tine < tines; ++tine) {
                const double o = offset[tine];
                std::int64_t any = 0;
                MARBLER_IVDEP
                for (int j = 0; j < m; ++j) {
                    const double rx = (qx[j] - sx) - o * nx, ry = (qy[j] - sy) - o * ny;
                    const double u = (rx * tx + ry * ty) * toU;
                    const std::int64_t in = (std::abs(u) < 1.0) & (alive[j] != 0);
                    us[j] = u;
                    qs[j] = (rx * nx + ry * ny) * toQ;
                    reached[j] = in;
                    any |= in;
                }
                if (!any) continue;
                // Every lane, reached or not (the arctangent is branch-free, Atan.h), so that
                // the loop vectorises; a lane out of reach keeps its velocity below.
                MARBLER_IVDEP
                for (int j = 0; j < m; ++j) {
                    const double u = us[j], q = qs[j];
                    const double w = (1.0 - u * u) * (1.0 - u * u), dw = -4.0 * u * (1.0 - u * u);
                    const double a = c * w / (1.0 + q * q), b = side * vectorAtan(q) * dw;
                    const bool in = reached[j] != 0;
                    vx[j] = in ? vx[j] + (a * tx - b * nx) : vx[j];
                    vy[j] = in ? vy[j] + (a * ty - b * ny) : vy[j];
                }
            }
        };
        velocity(px, py);
        MARBLER_IVDEP
        for (int j = 0; j < m; ++j) {
            nextX[j] = px[j] + h * vx[j];
            nextY[j] = py[j] + h * vy[j];
        }
        std::int64_t left = m;
        for (int iteration = 0; iteration < 100 && left != 0; ++iteration) {
            MARBLER_IVDEP
            for (int j = 0; j < m; ++j) {
                ex[j] = 0.5 * (px[j] + nextX[j]);
                ey[j] = 0.5 * (py[j] + nextY[j]);
            }
            velocity(ex, ey);
            left = 0;
            MARBLER_IVDEP
            for (int j = 0; j < m; ++j) {
                const double againX = px[j] + h * vx[j], againY = py[j] + h * vy[j];
                const double dx = againX - nextX[j], dy = againY - nextY[j];
                const bool settled = std::sqrt(dx * dx + dy * dy) < tolerance;
                const bool moving = alive[j] != 0;
                nextX[j] = moving ? againX : nextX[j];
                nextY[j] = moving ? againY : nextY[j];
                const std::int64_t still = moving && !settled;
                alive[j] = still;
                left += still;
            }
        }
        for (int j = 0; j < m; ++j) {
            t.x[lane[j]] = nextX[j];
            t.y[lane[j]] = nextY[j];
            if (k > 0) wait(lane[j], k - 1);
        }
    }
}

// ---- Bleed ----------------------------------------------------------------------------------

/// An ink-laying tool under bleed (genome-format.md, `bleed`; Tools.cpp traceCovers): the
/// coverage c = clamp(0.5 - e / b, 0, 1) of the edge distance e adds w c ink to the point's
/// colour and leaves w (1 - c) for what lies beneath; a point of coverage 1 is flagged (it
/// stops there). Then the tool's inverse push (drop, cylinder), as in ink2 and ink3, which
/// sends a point inside the ink to the centre (the reference's clamp, which the conformance
/// renders follow). Returns the number of flagged points.
template <int Dim>
[[gnu::always_inline]] inline std::int64_t bleedInk(const PreparedOp& op, Tile& t, int n, double width,
                                                    const glm::dvec3& ink) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict z = t.z;
    double* __restrict w = t.w;
    double* __restrict cr = t.r;
    double* __restrict cg = t.g;
    double* __restrict cb = t.b;
    std::int64_t* __restrict flag = t.flag;
    const double cx = op.c.x, cy = op.c.y, cz = op.c.z, r = op.r, r2 = op.rPow;
    const double ax = op.a.x, ay = op.a.y, az = op.a.z;
    const double inkR = ink.x, inkG = ink.y, inkB = ink.z;
    const bool column = op.tool == Tool::Cylinder, volume = Dim == 3 && op.tool == Tool::Drop;
    const bool pushes = op.tool != Tool::Spray;
    // A wrapping bath: the nearest image of the (wrapped) centre; the points are wrapped.
    const bool wraps = Dim == 2 && op.wrap.x > 0.0;
    const bool lattice = wraps && (op.wrapShift.x > 0.0 || op.wrapShift.y > 0.0);
    const double ww = op.wrap.x, wh = op.wrap.y;
    std::int64_t stopped = 0;
    MARBLER_IVDEP
    for (int i = 0; i < n; ++i) {
        double dx = x[i] - cx, dy = y[i] - cy, dz = Dim == 3 ? z[i] - cz : 0.0;
        if (lattice) {
            const glm::dvec2 d = nearestImage(glm::dvec2(dx, dy), op.wrap, op.wrapShift);
            dx = d.x;
            dy = d.y;
        } else if (wraps) {
            dx = dx > 0.5 * ww ? dx - ww : (dx < -0.5 * ww ? dx + ww : dx);
            dy = dy > 0.5 * wh ? dy - wh : (dy < -0.5 * wh ? dy + wh : dy);
        }
        if (column) {
            double along = dx * ax + dy * ay + dz * az;
            dx = dx - along * ax;
            dy = dy - along * ay;
            dz = dz - along * az;
        }
        double len2 = Dim == 3 ? dx * dx + dy * dy + dz * dz : dx * dx + dy * dy;
        double e = std::sqrt(len2) - r;
        double c = std::clamp(0.5 - e / width, 0.0, 1.0);
        double wc = w[i] * c;
        cr[i] = cr[i] + wc * inkR;
        cg[i] = cg[i] + wc * inkG;
        cb[i] = cb[i] + wc * inkB;
        w[i] = w[i] - wc;
        std::int64_t full = c >= 1.0;
        flag[i] = full;
        stopped += full;
        if (pushes) {
            double factor;
            if (volume) {
                double len3 = len2 * std::sqrt(len2);
                factor = cbrtUnit(std::max(0.0, 1.0 - r2 / len3));
            } else {
                factor = std::sqrt(std::max(0.0, 1.0 - r2 / len2));
            }
            bool moves = len2 > 0.0;
            x[i] = moves ? x[i] + dx * (factor - 1.0) : x[i];
            y[i] = moves ? y[i] + dy * (factor - 1.0) : y[i];
            if (Dim == 3) z[i] = moves ? z[i] + dz * (factor - 1.0) : z[i];
        }
    }
    return stopped;
}

/// compact for a traced tile under bleed: the flagged points leave with their colour (the ink
/// they stopped on, weight 0, the inks' sum), the others slide down with their layers.
inline int compactBleed(Tile& t, int n, int dimension, int color, int* colors, const Bleed& bleed) {
    int j = 0;
    for (int i = 0; i < n; ++i) {
        if (t.flag[i]) {
            const int id = t.id[i];
            colors[id] = color;
            bleed.weight[id] = 0.0;
            bleed.rgb[3 * id] = t.r[i];
            bleed.rgb[3 * id + 1] = t.g[i];
            bleed.rgb[3 * id + 2] = t.b[i];
            continue;
        }
        t.x[j] = t.x[i];
        t.y[j] = t.y[i];
        if (dimension == 3) t.z[j] = t.z[i];
        t.id[j] = t.id[i];
        t.w[j] = t.w[i];
        t.r[j] = t.r[i];
        t.g[j] = t.g[i];
        t.b[j] = t.b[i];
        ++j;
    }
    return j;
}

/// An ink-laying tool under bleed in `Dim` dimensions. Returns the number of points left.
template <int Dim>
[[gnu::always_inline]] inline int inkUnderBleed(const PreparedOp& op, Tile& tile, int n, int* colors,
                                                const Bleed& bleed) {
    if (bleedInk<Dim>(op, tile, n, bleed.width, bleed.palette[op.color]) == 0) return n;
    return compactBleed(tile, n, Dim, op.color, colors, bleed);
}

/// The body of every variant: V says which, so only the AVX-512 variant calls the
/// hand-written drops (which need AVX-512 to run, whatever the variant is compiled for). One
/// switch per dimension over every tool, with no default: a tool added to the registry
/// (Params.h) without its kernel fails the build (-Werror=switch). Soft: under bleed (then
/// `bleed` is given); the hard body has none of its code.
template <Variant V, bool Soft>
[[gnu::always_inline]] inline std::uint64_t
traceTileBody(const PreparedOp* ops, std::size_t count, int dimension, Tile& tile, int n, int* colors,
              double* whereX, double* whereY, const Bleed* bleed) {
    lastVariantRun = V;
    std::uint64_t traversed = 0;
    if constexpr (Soft)
        for (int i = 0; i < n; ++i) {
            tile.w[i] = 1.0;
            tile.r[i] = tile.g[i] = tile.b[i] = 0.0;
        }
    const bool wraps = dimension == 2 && count > 0 && ops[0].wrap.x > 0.0;
    if (wraps) wrapTile(tile, n, ops[0].wrap, ops[0].wrapShift);
    const bool lattice = wraps && (ops[0].wrapShift.x > 0.0 || ops[0].wrapShift.y > 0.0);
    for (std::size_t k = 0; k < count && n > 0; ++k) {
        const PreparedOp& op = ops[k];
        traversed += static_cast<std::uint64_t>(n);
        if (dimension == 2) {
            if constexpr (Soft)
                if (op.color >= 0) {
                    n = inkUnderBleed<2>(op, tile, n, colors, *bleed);
                    continue;
                }
            switch (op.tool) {
            case Tool::Drop:
                n = drop<V, 2>(op, tile, n, colors);
                break;
            case Tool::Spray:
                if ((lattice ? sprayLattice2(op, tile, n)
                     : wraps ? sprayWrapped2(op, tile, n)
                             : ink2(op, tile, n, false)) != 0)
                    n = compact(tile, n, 2, op.color, colors);
                break;
            case Tool::Line:
                lineOrComb<V, 2, false>(op, tile, n);
                break;
            case Tool::Comb:
                lineOrComb<V, 2, true>(op, tile, n);
                break;
            case Tool::Wave:
                wave2(op, tile, n);
                break;
            case Tool::Circle:
                swirl2(op, tile, n, false);
                break;
            case Tool::Vortex:
                swirl2(op, tile, n, true);
                break;
            case Tool::Stretch:
                stretch2(op, tile, n);
                if (wraps) wrapTile(tile, n, op.wrap, op.wrapShift);
                break;
            case Tool::Flow:
                if (op.field == FlowField::Cavity)
                    flow2<true>(op, tile, n);
                else
                    flow2<false>(op, tile, n);
                break;
            case Tool::Stylus:
                stylus2(op, tile, n);
                break;
            case Tool::Cylinder:
            case Tool::Sphere:
                break; // not in 2D genomes (the loader refuses them)
            }
        } else {
            if constexpr (Soft)
                if (op.color >= 0) {
                    n = inkUnderBleed<3>(op, tile, n, colors, *bleed);
                    continue;
                }
            switch (op.tool) {
            case Tool::Drop:
                n = drop<V, 3>(op, tile, n, colors);
                break;
            case Tool::Spray:
                if (ink3(op, tile, n, Push3::None) != 0) n = compact(tile, n, 3, op.color, colors);
                break;
            case Tool::Cylinder:
                if (ink3(op, tile, n, Push3::Column) != 0) n = compact(tile, n, 3, op.color, colors);
                break;
            case Tool::Line:
                lineOrComb<V, 3, false>(op, tile, n);
                break;
            case Tool::Comb:
                lineOrComb<V, 3, true>(op, tile, n);
                break;
            case Tool::Wave:
                wave3(op, tile, n);
                break;
            case Tool::Circle:
                swirl3(op, tile, n, true, false);
                break;
            case Tool::Sphere:
                swirl3(op, tile, n, false, false);
                break;
            case Tool::Vortex:
                swirl3(op, tile, n, false, true);
                break;
            case Tool::Stretch:
            case Tool::Flow:
            case Tool::Stylus:
                break; // 2D only (the loader refuses them in 3D)
            }
        }
    }
    if constexpr (Soft)
        for (int i = 0; i < n; ++i) {
            const int id = tile.id[i];
            bleed->weight[id] = tile.w[i];
            bleed->rgb[3 * id] = tile.r[i];
            bleed->rgb[3 * id + 1] = tile.g[i];
            bleed->rgb[3 * id + 2] = tile.b[i];
        }
    for (int i = 0; i < n; ++i) {
        colors[tile.id[i]] = -1;
        if (whereX) {
            whereX[tile.id[i]] = tile.x[i];
            whereY[tile.id[i]] = tile.y[i];
        }
    }
    return traversed;
}

using TraceFn = std::uint64_t (*)(const PreparedOp*, std::size_t, int, Tile&, int, int*, double*, double*,
                                  const Bleed*);

// The variants. Each is the same body compiled for its instruction set; the always-inline
// helpers above are compiled into each with that variant's vectors.
#ifdef MARBLER_X86_VARIANTS
__attribute__((target("arch=x86-64-v4"))) std::uint64_t
traceTileAvx512(const PreparedOp* ops, std::size_t count, int dimension, Tile& tile, int n, int* colors,
                double* whereX, double* whereY, const Bleed* bleed) {
    return bleed ? traceTileBody<Variant::Avx512, true>(ops, count, dimension, tile, n, colors, whereX,
                                                        whereY, bleed)
                 : traceTileBody<Variant::Avx512, false>(ops, count, dimension, tile, n, colors, whereX,
                                                         whereY, nullptr);
}

__attribute__((target("arch=x86-64-v3"))) std::uint64_t
traceTileAvx2(const PreparedOp* ops, std::size_t count, int dimension, Tile& tile, int n, int* colors,
              double* whereX, double* whereY, const Bleed* bleed) {
    return bleed ? traceTileBody<Variant::Avx2, true>(ops, count, dimension, tile, n, colors, whereX, whereY,
                                                      bleed)
                 : traceTileBody<Variant::Avx2, false>(ops, count, dimension, tile, n, colors, whereX, whereY,
                                                       nullptr);
}
#endif

std::uint64_t traceTileBaseline(const PreparedOp* ops, std::size_t count, int dimension, Tile& tile, int n,
                                int* colors, double* whereX, double* whereY, const Bleed* bleed) {
    return bleed ? traceTileBody<Variant::Baseline, true>(ops, count, dimension, tile, n, colors, whereX,
                                                          whereY, bleed)
                 : traceTileBody<Variant::Baseline, false>(ops, count, dimension, tile, n, colors, whereX,
                                                           whereY, nullptr);
}

TraceFn functionOf(Variant v) {
    switch (v) {
#ifdef MARBLER_X86_VARIANTS
    case Variant::Avx512:
        return traceTileAvx512;
    case Variant::Avx2:
        return traceTileAvx2;
#else
    case Variant::Avx512:
    case Variant::Avx2:
        break;
#endif
    case Variant::Baseline:
        break;
    }
    return traceTileBaseline;
}

/// The variant in use. `trace` is read on every tile, so it is an atomic of its own; the
/// choice itself changes only at start-up and in tests.
struct Active {
    std::atomic<TraceFn> trace;
    std::mutex mutex;
    Choice choice;

    Active()
        : choice(chooseVariant(std::getenv("MARBLER_KERNEL"))) {
        trace = functionOf(choice.variant);
    }
};

Active& active() {
    static Active instance;
    return instance;
}

} // namespace

const char* variantName(Variant v) {
    switch (v) {
    case Variant::Avx512:
        return "avx512";
    case Variant::Avx2:
        return "avx2";
    case Variant::Baseline:
        return "baseline";
    }
    return "baseline";
}

std::optional<Variant> variantNamed(std::string_view name) {
    for (Variant v : AllVariants)
        if (name == variantName(v)) return v;
    return std::nullopt;
}

bool cpuRuns(Variant v) {
#ifdef MARBLER_X86_VARIANTS
    // Looked up once: the CPU (and the operating system's saving of the wide registers, which
    // the runtime checks too) does not change while the process runs.
    static const bool v3 = [] {
        __builtin_cpu_init();
#if defined(__clang__)
        // clang (14) knows no level names here: the features that the levels add.
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
               __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
#else
        return __builtin_cpu_supports("x86-64-v3") != 0;
#endif
    }();
    static const bool v4 = [] {
#if defined(__clang__)
        return v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
               __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
               __builtin_cpu_supports("avx512vl");
#else
        return __builtin_cpu_supports("x86-64-v4") != 0;
#endif
    }();
    switch (v) {
    case Variant::Avx512:
        return v4;
    case Variant::Avx2:
        return v3;
    case Variant::Baseline:
        return true;
    }
    return false;
#else
    return v == Variant::Baseline;
#endif
}

std::vector<Variant> supportedVariants() {
    std::vector<Variant> out;
    for (Variant v : AllVariants)
        if (cpuRuns(v)) out.push_back(v);
    return out;
}

Choice chooseVariant(const char* requested) {
    return chooseVariant(requested, supportedVariants());
}

Choice chooseVariant(const char* requested, const std::vector<Variant>& supported) {
    const Variant best = supported.front();
    const std::string name = requested ? requested : "";
    if (name.empty() || name == "auto") return {best, "best this CPU runs"};
    const std::string setting = "MARBLER_KERNEL=" + name;
    std::optional<Variant> v = variantNamed(name);
    if (!v) {
        std::string known = "auto";
        for (Variant k : AllVariants)
            known += std::string(", ") + variantName(k);
        return {best, setting + " is not a kernel (" + known + "); using the best this CPU runs"};
    }
    if (std::find(supported.begin(), supported.end(), *v) == supported.end())
        return {best, setting + " asks for instructions this CPU lacks; using the best this CPU runs"};
    return {*v, setting};
}

Choice activeChoice() {
    Active& a = active();
    std::lock_guard lock(a.mutex);
    return a.choice;
}

void setActiveChoice(const Choice& choice) {
    Active& a = active();
    std::lock_guard lock(a.mutex);
    a.choice = choice;
    a.trace = functionOf(choice.variant);
}

std::uint64_t traceTile(const PreparedOp* ops, std::size_t count, int dimension, Tile& tile, int n,
                        int* colors, double* whereX, double* whereY, const Bleed* bleed) {
    return active().trace.load(std::memory_order_relaxed)(ops, count, dimension, tile, n, colors, whereX,
                                                          whereY, bleed);
}

Variant lastVariantRunForTest() {
    return lastVariantRun;
}

std::uint64_t stylusStepsRunForTest() {
    return stylusStepsRun;
}

void sinCosForTest(double x, double& s, double& c) {
    double angle[1] = {x}, sn[1], cs[1];
    sinCosArray(angle, sn, cs, 1);
    s = sn[0];
    c = cs[0];
}

double cbrtForTest(double x) {
    return cbrtUnit(x);
}

} // namespace marbler::kernel
