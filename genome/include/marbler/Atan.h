#pragma once
/// The project's own arctangent, for the stylus (genome-format.md, stylus): the scalar
/// reference (Tools.cpp stylusVelocity) and the CPU kernel (render/src/Kernel.cpp stylus2) both
/// call it, so they stay bit for bit the same, and it is made of basic operations and selects
/// only, so the kernel's loops vectorise through it (the C library's atan is a call a point at a
/// time, and took some 60 % of a stylus render).

#include <cmath>

namespace marbler {

/// atan(x) within 4 ulp of the true value (Atan.AgreesWithTheLibraryWithinFourUlps), odd,
/// atan(+-inf) = +-pi/2, NaN for NaN. The argument is reduced to s = min(|x|, 1 / |x|) in
/// [0, 1] (atan |x| = pi/2 - atan(1 / |x|) beyond 1), where s + s^3 P(s^2) with the minimax
/// polynomial P of degree 18 of SLEEF's xatan (Shibata, Boost licence) takes it. Written to be
/// compiled without fused multiply-adds (the kernel's -ffp-contract=off, the reference's
/// baseline x86-64), so that every caller rounds every operation alike.
[[gnu::always_inline]] inline double vectorAtan(double x) {
    const double a = std::abs(x);
    const bool beyond = a > 1.0;
    const double s = beyond ? 1.0 / a : a;
    const double t = s * s;
    double u = -1.88796008463073496563746e-05;
    u = u * t + 0.000209850076645816976906797;
    u = u * t + -0.00110611831486672482563471;
    u = u * t + 0.00370026744188713119232403;
    u = u * t + -0.00889896195887655491740809;
    u = u * t + 0.016599329773529201970117;
    u = u * t + -0.0254517624932312641616861;
    u = u * t + 0.0337852580001353069993897;
    u = u * t + -0.0407629191276836500001934;
    u = u * t + 0.0466667150077840625632675;
    u = u * t + -0.0523674852303482457616113;
    u = u * t + 0.0587666392926673580854313;
    u = u * t + -0.0666573579361080525984562;
    u = u * t + 0.0769219538311769618355029;
    u = u * t + -0.090908995008245008229153;
    u = u * t + 0.111111105648261418443745;
    u = u * t + -0.14285714266771329383765;
    u = u * t + 0.199999999996591265594148;
    u = u * t + -0.333333333333311110369124;
    double r = s + s * (t * u);
    r = beyond ? 1.570796326794896557998982 - r : r;
    return std::copysign(r, x);
}

} // namespace marbler
