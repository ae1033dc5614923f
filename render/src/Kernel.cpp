// The tile kernel. Every loop here computes exactly the formulas of genome/src/Tools.cpp (the
// scalar reference), in the same order of operations, so that the renderer and the reference
// agree to the last bit wherever no sine, cosine or cube root is involved, and within an ulp or
// two where one is. This file is built with -O3 -fno-math-errno -fno-trapping-math
// -ffp-contract=off: the first two let GCC vectorise sqrt and floor, the last keeps it from
// fusing multiply-adds, which would round differently from the reference.
//
// traceTile is compiled three times (AVX-512, AVX2+FMA, baseline x86-64) and the loader picks
// the best for the running CPU, so the binary runs anywhere and uses the widest vectors it can.

#include "Kernel.h"

#include <bit>
#include <cmath>

namespace marbler::kernel {
namespace {

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
#pragma GCC ivdep
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

/// Removes the points whose flag is set (they found ink), recording their colour.
[[gnu::always_inline]] inline int compact(Tile& t, int n, int dimension, int color, int* colors) {
    int j = 0;
    for (int i = 0; i < n; ++i) {
        if (t.flag[i]) {
            colors[t.id[i]] = color;
            continue;
        }
        t.x[j] = t.x[i];
        t.y[j] = t.y[i];
        if (dimension == 3) t.z[j] = t.z[i];
        t.id[j] = t.id[i];
        ++j;
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
    const double cx = op.c.x, cy = op.c.y, rr = op.r * op.r, r2 = op.r2;
    std::int64_t inside = 0;
#pragma GCC ivdep
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

[[gnu::always_inline]] inline void line2(const PreparedOp& op, Tile& t, int n, bool comb) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    const double cx = op.c.x, cy = op.c.y, nx = op.n.x, ny = op.n.y, mx = op.m.x, my = op.m.y;
    const double al = op.alphaLambda, lambda = op.lambda, s = op.spacing;
#pragma GCC ivdep
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
#pragma GCC ivdep
    for (int i = 0; i < n; ++i) arg[i] = freq * ((x[i] - cx) * nx + (y[i] - cy) * ny) + phase;
    sinArray(arg, sn, t.t2, n);
#pragma GCC ivdep
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
    const double cx = op.c.x, cy = op.c.y, r = op.r, al = op.alphaLambda, lambda = op.lambda;
#pragma GCC ivdep
    for (int i = 0; i < n; ++i) {
        double dx = x[i] - cx, dy = y[i] - cy;
        double rho = std::sqrt(dx * dx + dy * dy);
        double d = vortex ? rho : std::abs(rho - r);
        theta[i] = -(al / (d + lambda)) / rho;
    }
    sinCosArray(theta, sn, cs, n);
#pragma GCC ivdep
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

/// Drop (volume law), spray and cylinder (area law across the axis): ink test, then the push.
[[gnu::always_inline]] inline std::int64_t ink3(const PreparedOp& op, Tile& t, int n) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict z = t.z;
    std::int64_t* __restrict flag = t.flag;
    const double cx = op.c.x, cy = op.c.y, cz = op.c.z, rr = op.r * op.r, r2 = op.r2;
    const double ax = op.a.x, ay = op.a.y, az = op.a.z;
    std::int64_t inside = 0;
    if (op.tool == Tool::Cylinder) {
#pragma GCC ivdep
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
    } else if (op.tool == Tool::Drop) {
#pragma GCC ivdep
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
#pragma GCC ivdep
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
#pragma GCC ivdep
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
#pragma GCC ivdep
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
#pragma GCC ivdep
        for (int i = 0; i < n; ++i) arg0[i] = op.amp[0] * sn[i];
    } else {
#pragma GCC ivdep
        for (int i = 0; i < n; ++i) arg0[i] = op.amp[0] * sn[i];
        sinArray(arg1, sn, scratch, n);
#pragma GCC ivdep
        for (int i = 0; i < n; ++i) arg0[i] = arg0[i] + op.amp[1] * sn[i];
    }
#pragma GCC ivdep
    for (int i = 0; i < n; ++i) {
        double shift = arg0[i];
        x[i] = x[i] - shift * wx;
        y[i] = y[i] - shift * wy;
        z[i] = z[i] - shift * wz;
    }
}

/// Circle (about the axis line), sphere and vortex (distance to the centre) in 3D: turn by
/// -theta about the line through the centre along the axis (Tools.cpp rotateAbout).
[[gnu::always_inline]] inline void swirl3(const PreparedOp& op, Tile& t, int n) {
    double* __restrict x = t.x;
    double* __restrict y = t.y;
    double* __restrict z = t.z;
    double* __restrict theta = t.t0;
    double* __restrict sn = t.t1;
    double* __restrict cs = t.t2;
    const double cx = op.c.x, cy = op.c.y, cz = op.c.z, ax = op.a.x, ay = op.a.y, az = op.a.z;
    const double r = op.r, al = op.alphaLambda, lambda = op.lambda;
    std::int64_t* __restrict moves = t.flag;
    const bool cylindrical = op.tool == Tool::Circle, vortex = op.tool == Tool::Vortex;
#pragma GCC ivdep
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
        double th = -(al / (d + lambda)) / rho;
        // The centre (or axis) stays where it is; 0 keeps the sine pass off a NaN.
        theta[i] = rho > 0.0 ? th : 0.0;
        moves[i] = rho > 0.0;
    }
    sinCosArray(theta, sn, cs, n);
#pragma GCC ivdep
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

} // namespace

__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
std::uint64_t traceTile(const PreparedOp* ops, std::size_t count, int dimension, Tile& tile, int n, int* colors,
                        double* whereX, double* whereY) {
    std::uint64_t traversed = 0;
    for (std::size_t k = 0; k < count && n > 0; ++k) {
        const PreparedOp& op = ops[k];
        traversed += static_cast<std::uint64_t>(n);
        if (dimension == 2) {
            switch (op.tool) {
            case Tool::Drop:
            case Tool::Spray:
                if (ink2(op, tile, n, op.tool == Tool::Drop) != 0) n = compact(tile, n, 2, op.color, colors);
                break;
            case Tool::Line: line2(op, tile, n, false); break;
            case Tool::Comb: line2(op, tile, n, true); break;
            case Tool::Wave: wave2(op, tile, n); break;
            case Tool::Circle: swirl2(op, tile, n, false); break;
            case Tool::Vortex: swirl2(op, tile, n, true); break;
            case Tool::Cylinder:
            case Tool::Sphere: break; // not in 2D genomes (the loader refuses them)
            }
        } else {
            switch (op.tool) {
            case Tool::Drop:
            case Tool::Spray:
            case Tool::Cylinder:
                if (ink3(op, tile, n) != 0) n = compact(tile, n, 3, op.color, colors);
                break;
            case Tool::Line: line3(op, tile, n, false); break;
            case Tool::Comb: line3(op, tile, n, true); break;
            case Tool::Wave: wave3(op, tile, n); break;
            case Tool::Circle:
            case Tool::Sphere:
            case Tool::Vortex: swirl3(op, tile, n); break;
            }
        }
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

void sinCosForTest(double x, double& s, double& c) {
    double angle[1] = {x}, sn[1], cs[1];
    sinCosArray(angle, sn, cs, 1);
    s = sn[0];
    c = cs[0];
}

double cbrtForTest(double x) { return cbrtUnit(x); }

} // namespace marbler::kernel
