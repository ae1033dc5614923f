#pragma once
/// The forward and inverse maps of every tool (genome-format.md, Tools).
///
/// A genome is prepared once into PreparedOp records that hold everything a map needs in
/// ready form (unit vectors, radians, squared radii). The scalar maps here are the reference:
/// the vectorised CPU renderer and the GLSL shaders compute the same formulas from the same
/// prepared records, and the tests hold them to these.

#include "marbler/Genome.h"
#include "marbler/Params.h"

#include <glm/vec3.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace marbler {

/// Where a stylus is at one time tau (genome-format.md, stylus): its segment i, the point S(tau)
/// and the pull c = 15 alpha p(tau) / (16 l) there.
struct StylusStation {
    std::size_t segment = 0;
    glm::dvec2 s{0.0};
    double c = 0.0;
};

/// One tool, ready to apply. 2D tools use x and y and leave z at 0.
struct PreparedOp {
    Tool tool = Tool::Drop;
    int dimension = 2;
    WaveShape shape = WaveShape::Eggcrate;
    ShaderForm form = ShaderForm::PushArea; ///< the tool's form in this dimension (Params.h)
    int color = -1;                         ///< palette index for ink-laying tools, else -1
    glm::dvec3 c{0.0};                      ///< center or origin
    glm::dvec3 m{1, 0, 0};                  ///< motion direction M (line, comb, wave 2D), wave 3D u
    glm::dvec3 n{0, 1, 0};                  ///< normal N (line, comb, wave 2D), wave 3D shift direction w
    glm::dvec3 v{0, 0, 1};                  ///< wave 3D second axis v = w x u
    glm::dvec3 a{0, 0, 1};                  ///< rotation or column axis (unit)
    double r = 0.0;                         ///< radius
    double rPow = 0.0;                      ///< r^d of the push: r^2 (2D drop, cylinder), r^3 (3D drop)
    double alphaLambda = 0;                 ///< alpha * lambda
    double lambda = 1.0;
    double spacing = 1.0;
    double amp[2] = {0, 0};
    double freq[2] = {0, 0};  ///< 2 pi / wavelength
    double phase[2] = {0, 0}; ///< radians
    // Version 2.
    double core2 = 0.0;        ///< core^2 of a circle, sphere or vortex (0: the version-1 turn)
    double shift = 0.0;        ///< stretch: largest shift
    double power = 1.0;        ///< stretch: tooth profile exponent
    std::vector<double> teeth; ///< stretch: tooth positions along n
    FlowField field = FlowField::Cells;
    double size[2] = {1, 1}; ///< flow: Lx, Ly
    double speed = 0.0;      ///< flow: U
    double step = 0.0;       ///< flow: h = T / n
    int steps = 0;           ///< flow: n
    double tolerance = 0.0;  ///< flow: 1e-12 (Lx + Ly); stylus: 1e-12 (L + reach); the iteration's stop
    // Version 3: the stylus.
    std::vector<glm::dvec2> path;  ///< its points
    std::vector<glm::dvec2> along; ///< the unit direction T of each segment
    std::vector<double> cum;       ///< the arc length at each point (cum[0] = 0, back() = L)
    std::vector<double> pressure;  ///< one value a point (all 1 when the file gives none)
    double length = 0.0;           ///< L
    double reach = 1.0;            ///< l
    double pull = 0.0;             ///< 15 alpha / (16 l): c at pressure 1
    int tines = 1;                 ///< k
    /// Where the stylus is at each integration step's time tau_i = i h + h / 2 (stylusStation),
    /// for renderers that visit the steps of many points.
    std::vector<StylusStation> stations;
    /// The first integration step of each segment (the steps whose time lies on it), one more
    /// entry holding n: segment i runs the steps firstStep[i] to firstStep[i + 1] - 1.
    std::vector<int> firstStep;
    /// A wrapping bath (docs/genome-format.md, "Wrapping bath"): the design's width and height,
    /// the periods every step is taken modulo; (0, 0) where the bath does not wrap. A spray's
    /// centre `c` is then stored wrapped into [0, w) x [0, h).
    glm::dvec2 wrap{0.0};
    /// The wrap's lattice (Genome.h Lattice) as the shift one period brings across it: (0, h / 2)
    /// for half-drop (a step of w in x drops h / 2 in y), (w / 2, 0) for brick (a step of h in y
    /// moves w / 2 in x), (0, 0) for straight. A stretch's period across its pass is then
    /// wrap - wrapShift along that axis.
    glm::dvec2 wrapShift{0.0};
};

/// x taken into [0, period): x - period floor(x / period) (the kernel and the shaders round alike).
inline double wrapInto(double x, double period) {
    return x - period * std::floor(x / period);
}

/// The nearest image of a difference d of two points in [0, period): d +- period where |d| is
/// more than half the period.
inline double nearestImage(double d, double period) {
    return d > 0.5 * period ? d - period : (d < -0.5 * period ? d + period : d);
}

/// A point taken into the tile [0, w) x [0, h) of the lattice (PreparedOp::wrap, wrapShift):
/// half-drop first takes whole columns off (k = floor(x / w): x -= k w, y -= k h / 2), brick
/// whole rows, then both coordinates go through wrapInto (all a straight lattice does).
inline glm::dvec2 wrapPoint(double x, double y, const glm::dvec2& size, const glm::dvec2& shift) {
    if (shift.y > 0.0) {
        const double k = std::floor(x / size.x);
        x = x - k * size.x;
        y = y - k * shift.y;
    } else if (shift.x > 0.0) {
        const double k = std::floor(y / size.y);
        y = y - k * size.y;
        x = x - k * shift.x;
    }
    return {wrapInto(x, size.x), wrapInto(y, size.y)};
}

/// The nearest image over the lattice of a difference d of two points of the tile: for a
/// straight lattice each axis alone (nearestImage); for half-drop the nearest in each of the
/// three columns of images nearest in x (i0 - 1, i0, i0 + 1), for brick in each of three rows,
/// the first of the closest kept. Three are enough while the tile is at most 4 times as long
/// across them as along (the validator's rule): a fourth column lies 3w/2 away, the best of
/// these within sqrt(w^2 + h^2 / 16).
inline glm::dvec2 nearestImage(glm::dvec2 d, const glm::dvec2& size, const glm::dvec2& shift) {
    if (!(shift.x > 0.0) && !(shift.y > 0.0)) return {nearestImage(d.x, size.x), nearestImage(d.y, size.y)};
    // Brick is half-drop with the axes swapped.
    const bool brick = shift.x > 0.0;
    const double a = brick ? d.y : d.x, b = brick ? d.x : d.y;
    const double along = brick ? size.y : size.x, across = brick ? size.x : size.y;
    const double drop = brick ? shift.x : shift.y;
    const double i0 = std::floor(a / along + 0.5);
    double bestA = 0.0, bestB = 0.0, best = std::numeric_limits<double>::infinity();
    for (double i = i0 - 1.0; i <= i0 + 1.0; i += 1.0) {
        const double ea = a - i * along;
        double eb = b - i * drop;
        eb = eb - across * std::floor(eb / across + 0.5);
        const double len2 = ea * ea + eb * eb;
        if (len2 < best) {
            best = len2;
            bestA = ea;
            bestB = eb;
        }
    }
    return brick ? glm::dvec2(bestB, bestA) : glm::dvec2(bestA, bestB);
}

/// Prepares one entry of a genome of the given dimension.
PreparedOp prepare(const Operation& op, int dimension);

/// The whole genome in time order: `initial` then `operations`.
std::vector<PreparedOp> prepare(const Genome& genome);

/// F: where the tool moves P.
glm::dvec3 forwardMap(const PreparedOp& op, const glm::dvec3& p);
/// F^-1: where Q came from. For ink-laying tools defined outside the ink only.
glm::dvec3 inverseMap(const PreparedOp& op, const glm::dvec3& q);
/// Whether P (at the time right after the tool) lies in the tool's ink (open boundary).
bool insideInk(const PreparedOp& op, const glm::dvec3& p);

/// The colour rule: the palette index seen at P after all of `ops` (time order), or -1 where
/// no ink lies. `where`, if given, receives the point P maps back to (for a source image).
int traceColor(const std::vector<PreparedOp>& ops, glm::dvec3 p, glm::dvec3* where = nullptr);

/// What the colour rule sees at P: the palette index (-1 where no ink lies) and the index in
/// `ops` of the step that laid it (-1 for the bath), as the editor's ink picker shows them.
struct TracedInk {
    int color = -1;
    std::ptrdiff_t step = -1;
};
/// traceColor, also naming the step whose ink is seen.
TracedInk traceStep(const std::vector<PreparedOp>& ops, glm::dvec3 p);

/// One ink met by the bleed colour rule (genome-format.md, version 2, `bleed`).
struct InkCover {
    int color = -1;        ///< palette index
    double coverage = 1.0; ///< in (0, 1]
};

/// How far P lies outside an ink-laying tool's ink: |P - C| - r, across the axis for a
/// cylinder (negative inside).
double inkEdgeDistance(const PreparedOp& op, const glm::dvec3& p);

/// The coverage of an ink at edge distance e under bleed b: clamp(0.5 - e / b, 0, 1), or for
/// b = 0 the hard rule (1 inside, 0 outside).
double bleedCoverage(double e, double bleed);

/// The colour rule with bleed: the inks met going back from P, newest first, each with its
/// coverage; the search stops at the first ink of coverage 1, or reaches the bath (or source),
/// whose point is stored in `where`. Returns whether it stopped on an ink. The colour is
/// c0 ink0 + (1 - c0)(c1 ink1 + (1 - c1)(... bath)) in linear light. With bleed 0 it meets at
/// most one ink, the one traceColor returns.
bool traceCovers(const std::vector<PreparedOp>& ops, double bleed, glm::dvec3 p,
                 std::vector<InkCover>& covers, glm::dvec3* where = nullptr);

/// The velocity of a flow at local coordinates (x, y) (along its M and N), in those coordinates.
glm::dvec2 flowVelocity(const PreparedOp& op, double x, double y);

/// The velocity of a stylus at P at time tau in [0, L] (genome-format.md, stylus): the sum over
/// its tines of c w(u) / (1 + q^2) T - c lambda atan(q) w'(u) / l N.
glm::dvec2 stylusVelocity(const PreparedOp& op, const glm::dvec2& p, double tau);

/// Where a stylus is at time tau in [0, L]: the segment i with cum_i <= tau < cum_i+1 (the last
/// one at tau = L), S(tau) and c there, exactly as stylusVelocity computes them.
StylusStation stylusStation(const PreparedOp& op, double tau);

/// One implicit midpoint step of a stylus, integration step `i` (time i h + h / 2), forward
/// (`sign` +1: P_i to P_i+1) or backward (-1: P_i+1 to P_i), by fixed-point iteration as the
/// spec says.
glm::dvec2 stylusStep(const PreparedOp& op, const glm::dvec2& p, int i, double sign);

/// The distance-dependent shift l = alpha * lambda / (d + lambda).
inline double shiftFor(const PreparedOp& op, double d) {
    return op.alphaLambda / (d + op.lambda);
}

} // namespace marbler
