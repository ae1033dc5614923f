#include "marbler/Families.h"

#include "marbler/Generator.h"
#include "marbler/Operators.h"
#include "marbler/Params.h"
#include "marbler/Random.h"
#include "marbler/Tools.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace marbler {
namespace {

// Streams of their own, apart from randomGenome's.
constexpr std::uint64_t FamilyPaletteStream = 0x66616d70616c3031ULL;
constexpr std::uint64_t FamilyGroundStream = 0x66616d67726e3031ULL;
constexpr std::uint64_t FamilyStrokeStream = 0x66616d7374723031ULL;

// ---------------------------------------------------------------------------------------
// Palettes of the tradition

constexpr std::array<Color, 7> EarthInks{{
    {0x2e, 0x3a, 0x6e}, // indigo
    {0xa0, 0x46, 0x2d}, // red ochre
    {0xc9, 0x9a, 0x3b}, // yellow ochre
    {0x5b, 0x3a, 0x29}, // burnt umber
    {0xb5, 0x73, 0x3a}, // raw sienna
    {0x4f, 0x8a, 0x7b}, // verdigris
    {0x1f, 0x1d, 0x1b}, // lamp black
}};
constexpr std::array<Color, 8> EbruInks{{
    {0x1f, 0x4e, 0x9c}, // lapis
    {0xb3, 0x20, 0x2c}, // crimson
    {0xe6, 0xa9, 0x1a}, // saffron
    {0x1e, 0x9a, 0xa0}, // turquoise
    {0x2f, 0x6b, 0x3a}, // leaf green
    {0x1d, 0x1b, 0x1a}, // black
    {0xd6, 0x6a, 0x86}, // rose
    {0xf0, 0xe6, 0xd2}, // white
}};
constexpr std::array<Color, 7> VictorianInks{{
    {0x1c, 0x3f, 0x5e}, // Prussian blue
    {0x8e, 0x2a, 0x3a}, // madder lake
    {0xd9, 0xa0, 0x2a}, // gamboge
    {0x22, 0x22, 0x22}, // ivory black
    {0x6b, 0x7b, 0x86}, // slate
    {0x8a, 0x9a, 0x6b}, // sage
    {0xa3, 0x4a, 0x32}, // brick
}};
constexpr std::array<Color, 5> IndigoInks{{
    {0x1b, 0x24, 0x4f},
    {0x2e, 0x3f, 0x7f},
    {0x4b, 0x63, 0xa6},
    {0x85, 0x9b, 0xcc},
    {0xc4, 0xcf, 0xe6},
}};

constexpr std::array<TraditionalPalette, 4> Traditions{{
    {"earth pigments and indigo on cream", {0xef, 0xe6, 0xcf}, EarthInks},
    {"Turkish ebru", {0xf4, 0xef, 0xe2}, EbruInks},
    {"Victorian end-paper", {0xe9, 0xdf, 0xc8}, VictorianInks},
    {"indigo shades on white", {0xf7, 0xf5, 0xf0}, IndigoInks},
}};

/// Inks far enough apart to read against each other: a squared redmean distance of 90^2 is a
/// clear step between neighbours (indigo against umber, ochre against sienna).
constexpr double MinContrast2 = 90.0 * 90.0;

/// `count` inks and the paper: from a palette of the tradition (three times in four) or the
/// harmony rules, ordered so that each ink stands apart from the one before it and from the
/// paper (a stone's later colours are dropped on its earlier ones).
std::vector<Color> familyPalette(Pcg32& rng, int count, Color& paper) {
    std::vector<Color> pool;
    if (rng.chance(0.75)) {
        const TraditionalPalette& t = Traditions[rng.below(static_cast<std::uint32_t>(Traditions.size()))];
        paper = t.paper;
        for (Color c : t.inks)
            if (colorDistance2(c, paper) >= MinContrast2) pool.push_back(c);
    } else {
        pool = randomPalette(rng, &paper);
    }
    // A seeded shuffle, then the order that keeps neighbours apart where the pool allows.
    for (std::size_t i = pool.size(); i > 1; --i)
        std::swap(pool[i - 1], pool[rng.below(static_cast<std::uint32_t>(i))]);
    std::vector<Color> inks;
    while (!pool.empty() && static_cast<int>(inks.size()) < count) {
        auto next = pool.begin();
        if (!inks.empty()) {
            next = std::find_if(pool.begin(), pool.end(),
                                [&](Color c) { return colorDistance2(c, inks.back()) >= MinContrast2; });
            if (next == pool.end()) next = pool.begin();
        }
        inks.push_back(*next);
        pool.erase(next);
    }
    return inks;
}

// ---------------------------------------------------------------------------------------
// Turns without the C library (sines are not required to be correctly rounded, and a seed must
// give the same design everywhere): Taylor series in basic operations.

constexpr double FamilyTwoPi = 6.283185307179586;

/// (cos, sin) of `turns` whole turns.
glm::dvec2 cosSinOfTurns(double turns) {
    const double x = FamilyTwoPi * (turns - std::floor(turns + 0.5)); // in [-pi, pi]
    double c = 0.0, s = 0.0, term = 1.0;
    for (int k = 0; k < 40; ++k) {
        (k % 2 ? s : c) += ((k / 2) % 2 ? -term : term);
        term *= x / (k + 1);
    }
    return {c, s};
}

/// A unit vector at `angle` degrees (the genome's convention: (cos a, sin a)).
glm::dvec2 unitAt(double angle) {
    return cosSinOfTurns(angle / 360.0);
}

// ---------------------------------------------------------------------------------------
// The marbler's moves

/// A family's design being made: the ground (initial) and the strokes (operations), every
/// length in design units of a 1000-unit bath.
struct Bath {
    Pcg32& ground;
    Pcg32& rng;
    Genome& g;

    double pick(double lo, double hi) { return tenth(rng.uniform(lo, hi)); }
    int inks() const { return static_cast<int>(g.palette.size()); }
    glm::dvec3 anywhere(double margin = 0.05) {
        glm::dvec3 p;
        for (int i = 0; i < g.dimension; ++i)
            p[i] = tenth(ground.uniform(-margin, 1.0 + margin) * g.size[i]);
        if (g.dimension == 2) p.z = 0.0;
        return p;
    }

    void drop(const glm::dvec3& at, double radius, int color, Tool tool = Tool::Drop) {
        Operation op = defaultOperation(tool, g.dimension, at);
        op.radius = tenth(std::max(1.0, radius));
        op.color = color;
        g.initial.push_back(op);
    }

    /// The stone (battal) ground: each colour in turn, the first in big drops covering the
    /// bath, every later colour in fewer-or-more but smaller drops (radii `shrink` times the
    /// colour before), pushing the earlier ones into veined stones.
    void stone(double firstRadius, double shrink, int firstCount, double growCount = 1.3) {
        double radius = firstRadius;
        double count = firstCount;
        for (int k = 0; k < inks(); ++k) {
            for (int i = 0; i < static_cast<int>(count); ++i)
                drop(anywhere(), radius * ground.uniform(0.7, 1.25), k);
            radius *= shrink;
            count *= growCount;
        }
    }

    /// A bull's-eye: `count` drops one in another at one place, the colours alternating, each
    /// ring `width` wide. A drop of radius r moves a ring at rho to sqrt(rho^2 + r^2), so for
    /// rings j w (j = 1..count) the drop that ends up j-th from the centre has radius
    /// w sqrt(2j - 1): the widest first, the last (innermost) of radius w.
    void rings(const glm::dvec3& at, int count, double width, int a, int b) {
        for (int j = count; j >= 1; --j)
            drop(at, width * std::sqrt(2.0 * j - 1.0), (j % 2) ? a : b);
    }

    /// A comb drawn across the bath at `angle` (2D), tines `spacing` apart; `offset` shifts the
    /// tines by that fraction of the spacing.
    void comb(double angle, double spacing, double alpha, double lambda, double offset = 0.0) {
        Operation op = defaultOperation(Tool::Comb, 2, 0.5 * g.size);
        op.angle = angle;
        op.spacing = tenth(spacing);
        op.alpha = tenth(alpha);
        op.lambda = tenth(lambda);
        // N = (-sin a, cos a): for the four directions of the craft, exact.
        const glm::dvec3 n = normalOf(angle);
        op.center = {tenth(op.center.x + n.x * spacing * offset), tenth(op.center.y + n.y * spacing * offset),
                     0.0};
        g.operations.push_back(op);
    }

    /// Gel-git ("come and go"): a comb drawn one way and back the other, the return's tines
    /// between the first's.
    void gelGit(double angle, double spacing, double alpha, double lambda) {
        comb(angle, spacing, alpha, lambda);
        comb(angle + 180.0, spacing, alpha, lambda, 0.5);
    }

    void wave(double angle, double amplitude, double wavelength) {
        Operation op = defaultOperation(Tool::Wave, 2, 0.5 * g.size);
        op.angle = angle;
        op.amplitude = {tenth(amplitude), 0.0};
        op.wavelength = {tenth(wavelength), 1.0};
        op.phase = {std::round(rng.uniform(0.0, 360.0)), 0.0};
        g.operations.push_back(op);
    }

    void vortex(const glm::dvec3& at, double alpha, double lambda, double core) {
        Operation op = defaultOperation(Tool::Vortex, g.dimension, at);
        op.alpha = tenth(alpha);
        op.lambda = tenth(lambda);
        op.core = tenth(core);
        g.operations.push_back(op);
    }

    /// A stretch pass (version 2) across the whole bath at one of the four directions, teeth
    /// every `spacing` (a little uneven, as a hand-made comb is).
    void stretch(double angle, double spacing, double shift, double power) {
        Operation op = defaultOperation(Tool::Stretch, 2, 0.5 * g.size);
        op.angle = angle;
        op.shift = tenth(shift);
        op.power = std::round(power * 100.0) / 100.0;
        // Origin at the centre, teeth from one edge to the other along N whatever the angle.
        op.teeth.clear();
        const double reach = 0.75 * std::max(g.size.x, g.size.y);
        for (double t = -reach; t <= reach; t += spacing * rng.uniform(0.85, 1.15))
            op.teeth.push_back(tenth(t));
        g.operations.push_back(op);
    }

    static glm::dvec3 normalOf(double angle) {
        // The four directions of the craft, without sines (exact and the same everywhere).
        const int quarter = static_cast<int>(std::round(angle / 90.0)) & 3;
        switch (quarter) {
        case 0:
            return {0.0, 1.0, 0.0};
        case 1:
            return {-1.0, 0.0, 0.0};
        case 2:
            return {0.0, -1.0, 0.0};
        default:
            return {1.0, 0.0, 0.0};
        }
    }

    /// A stylus (one tine) or a rake drawn along `path`, with the fewest steps the format allows
    /// (a render stays as quick as the stroke allows). `pressure`: one value a path point, or
    /// none (the pen pressed fully all along).
    void stylus(const std::vector<glm::dvec2>& path, double alpha, double lambda, double reach, int tines = 1,
                double spacing = 0.0, const std::vector<double>& pressure = {}) {
        Operation op = defaultOperation(Tool::Stylus, 2, glm::dvec3(0.0)); // a file gives a stylus no centre
        op.path.clear();
        op.pressure.clear();
        for (std::size_t i = 0; i < path.size(); ++i) {
            const glm::dvec2 p{tenth(path[i].x), tenth(path[i].y)};
            if (!op.path.empty() && p == op.path.back()) continue;
            op.path.push_back(p);
            if (!pressure.empty()) op.pressure.push_back(std::round(pressure[i] * 100.0) / 100.0);
        }
        if (op.path.size() < 2) return;
        op.alpha = tenth(alpha);
        op.lambda = tenth(std::max(1.0, lambda));
        op.reach = tenth(std::max(1.0, reach));
        op.tines = tines;
        if (tines > 1) op.spacing = tenth(spacing);
        op.steps = minimumStylusSteps(op);
        if (op.steps > MaxStylusSteps) return; // never with the recipes' ranges
        g.operations.push_back(op);
    }

    /// A serpentine path: from `from` along the unit `along`, `length` long, swinging
    /// `amplitude` to each side every `wavelength`, starting `phase` turns into a swing; twelve
    /// points a wavelength, so the polyline reads as a curve.
    static std::vector<glm::dvec2> serpentine(glm::dvec2 from, glm::dvec2 along, double length,
                                              double amplitude, double wavelength, double phase) {
        const glm::dvec2 side(-along.y, along.x);
        const int count = std::max(2, static_cast<int>(std::ceil(12.0 * length / wavelength)) + 1);
        std::vector<glm::dvec2> path;
        for (int i = 0; i < count; ++i) {
            const double t = length * i / (count - 1);
            path.push_back(from + t * along + amplitude * cosSinOfTurns(t / wavelength + phase).y * side);
        }
        return path;
    }

    /// Ringed drops at `at`: `count` drops one in another, the inks `a` and `b` alternating,
    /// the outermost ring `outer` in radius.
    void ringedDrop(const glm::dvec3& at, int count, double outer, int a, int b) {
        rings(at, count, outer / std::sqrt(2.0 * count - 1.0), a, b);
    }

    /// Two different inks for a flower: a ground ink is avoided where the palette allows.
    std::pair<int, int> twoInks(int avoid) {
        const int n = inks();
        int a = static_cast<int>(rng.below(static_cast<std::uint32_t>(n)));
        if (n > 2 && a == avoid) a = (a + 1) % n;
        int c = (a + 1 + static_cast<int>(rng.below(static_cast<std::uint32_t>(std::max(1, n - 1))))) % n;
        if (n > 2 && c == avoid) c = (c + 1) % n == a ? (c + 2) % n : (c + 1) % n;
        return {a, c};
    }

    /// One of the bath's two axes, as a marbler turns the tray: 0 (along x) or 90 (along y).
    double axis() { return rng.chance(0.5) ? 0.0 : 90.0; }

    // 3D
    void comb3(const glm::dvec3& direction, const glm::dvec3& normal, double spacing, double alpha,
               double lambda) {
        Operation op = defaultOperation(Tool::Comb, 3, 0.5 * g.size);
        op.direction = direction;
        op.normal = normal;
        op.spacing = tenth(spacing);
        op.alpha = tenth(alpha);
        op.lambda = tenth(lambda);
        g.operations.push_back(op);
    }
    void column(const glm::dvec3& at, const glm::dvec3& axisVector, double radius, int color) {
        Operation op = defaultOperation(Tool::Cylinder, 3, at);
        op.axis = axisVector;
        op.radius = tenth(radius);
        op.color = color;
        g.initial.push_back(op);
    }
    void wave3(WaveShape shape, double amplitude, double wavelength) {
        Operation op = defaultOperation(Tool::Wave, 3, 0.5 * g.size);
        op.shape = shape;
        op.direction = {1.0, 0.0, 0.0};
        op.normal = {0.0, rng.chance(0.5) ? 1.0 : 0.0, 0.0};
        if (op.normal.y == 0.0) op.normal = {0.0, 0.0, 1.0};
        op.amplitude = {tenth(amplitude), tenth(amplitude * rng.uniform(0.5, 1.0))};
        op.wavelength = {tenth(wavelength), tenth(wavelength * rng.uniform(0.7, 1.4))};
        op.phase = {std::round(rng.uniform(0.0, 360.0)), std::round(rng.uniform(0.0, 360.0))};
        if (shape == WaveShape::Ripple) {
            // A ripple has one number of each (as a file holds it): the second ones at rest.
            op.amplitude[1] = 0.0;
            op.wavelength[1] = 1.0;
            op.phase[1] = 0.0;
        }
        g.operations.push_back(op);
    }
};

/// A unit vector along one of the box's axes.
glm::dvec3 boxAxis(int index) {
    glm::dvec3 v(0.0);
    v[index % 3] = 1.0;
    return v;
}

// ---------------------------------------------------------------------------------------
// The recipes (docs/families.md says them in the craft's words)

void stone(Bath& b) {
    b.stone(b.pick(90, 130), b.rng.uniform(0.6, 0.8), b.ground.between(22, 32));
}

void gelGit(Bath& b) {
    stone(b);
    b.gelGit(b.axis(), b.pick(60, 120), b.pick(60, 120), b.pick(10, 25));
}

void chevron(Bath& b) {
    stone(b);
    double along = b.axis();
    b.gelGit(along, b.pick(45, 80), b.pick(50, 90), b.pick(8, 18));
    // One wide pass across bends every line of the gel-git into a row of chevrons.
    b.comb(along + 90.0, b.pick(140, 260), b.pick(120, 220), b.pick(20, 45));
}

/// The nonpareil's ground: many small stones of every ink laid evenly, which the gel-git draws
/// into fine stripes.
void fineStone(Bath& b) {
    b.stone(b.pick(40, 50), 0.92, b.ground.between(110, 130), 1.05);
}

/// The nonpareil: a coarse gel-git that draws the stones into fine stripes, then the nonpareil
/// comb drawn once across them, its teeth close but wide enough apart that each stripe is
/// pulled into a row of small, regular points. Returns the fine comb's angle.
double nonpareil(Bath& b) {
    fineStone(b);
    double along = b.axis();
    b.gelGit(along, b.pick(60, 80), b.pick(150, 220), b.pick(12, 16));
    double across = along + 90.0;
    b.comb(across, b.pick(34, 40), b.pick(30, 45), b.pick(4, 5));
    return across;
}

void nonpareilOnly(Bath& b) {
    nonpareil(b);
}

/// A rake with tines `spacing` apart across the whole bath, drawn along `angle` in a
/// serpentine swinging `amplitude` to each side every `wavelength`, from beyond one edge to
/// beyond the other; `offset` shifts the tines by that share of the spacing, `phase` the swing.
void serpentineRake(Bath& b, double angle, double spacing, double amplitude, double wavelength, double alpha,
                    double lambda, double reach, double offset = 0.0, double phase = 0.0) {
    const glm::dvec2 along = unitAt(angle), side(-along.y, along.x);
    const glm::dvec2 centre(0.5 * b.g.size.x, 0.5 * b.g.size.y);
    const double across = std::abs(side.x) * b.g.size.x + std::abs(side.y) * b.g.size.y;
    const double lengthWay = std::abs(along.x) * b.g.size.x + std::abs(along.y) * b.g.size.y;
    const int tines =
        std::min(MaxTines, static_cast<int>(std::ceil((across + 2.0 * amplitude) / spacing)) + 1);
    const glm::dvec2 from = centre - (0.5 * lengthWay + reach) * along + offset * spacing * side;
    b.stylus(Bath::serpentine(from, along, lengthWay + 2.0 * reach, amplitude, wavelength, phase), alpha,
             lambda, reach, tines, spacing);
}

/// The bouquet rake: tines four rows of points apart, swung a third of their spacing to each
/// side, a narrow pull that moves the rows without dragging them off (c = 15 alpha / (16 reach)
/// about 0.4). Its cost is what bounds it: a rake's fewest steps grow with its tines, so its
/// time with their square, and with its pull, reach over lambda and lambda over reach
/// (genome-format.md, stylus): eight tines 160-175 apart, reach 44-48 and a pull of 18-24 render
/// seed 21 at 300 pixels some four times quicker than the twelve tines of 100-120 before them,
/// and the wider swing and shorter reach read as fans where those read as waves. Across many
/// tines the stylus's sideways flow does not fall off (the spec's stream function keeps its
/// strength to the side), so the pull times its sharpness stays small and the reach short
/// beside the swing's wavelength: else the whole bath is swept about and the nonpareil lost.
struct BouquetRake {
    double spacing, amplitude, wavelength, alpha, lambda, reach;
};
BouquetRake bouquetRake(Bath& b) {
    const double spacing = b.pick(160, 175);
    return {spacing,          tenth(spacing * b.rng.uniform(0.3, 0.36)),
            b.pick(190, 230), b.pick(18, 24),
            b.pick(4.5, 5.5), b.pick(44, 48)};
}

void bouquet(Bath& b) {
    const double across = nonpareil(b);
    // The bouquet rake drawn through the nonpareil the fine comb's way in a serpentine: each
    // tine swings the rows of points to one side and the other, and draws them into fans.
    const BouquetRake r = bouquetRake(b);
    serpentineRake(b, across, r.spacing, r.amplitude, r.wavelength, r.alpha, r.lambda, r.reach);
}

void peacock(Bath& b) {
    const double across = nonpareil(b);
    // The bouquet's serpentine rake, then the same rake drawn back more gently (six tenths of
    // the pull: half its cost again, not all of it) with its tines between the first's and its
    // swing the other way: each fan is closed into the round "eye" of a feather.
    const BouquetRake r = bouquetRake(b);
    serpentineRake(b, across, r.spacing, r.amplitude, r.wavelength, r.alpha, r.lambda, r.reach);
    serpentineRake(b, across + 180.0, r.spacing, r.amplitude, r.wavelength, 0.6 * r.alpha, r.lambda, r.reach,
                   0.5, 0.5);
}

void frenchCurl(Bath& b) {
    if (b.rng.chance(0.5))
        nonpareil(b);
    else
        gelGit(b);
    // Curls on a grid, each turned the other way from its neighbours, with a clean eye.
    const int n = b.rng.between(3, 5);
    const double step = 1000.0 / n;
    const double alpha = b.pick(250, 500), lambda = b.pick(20, 40), core = b.pick(5, 12);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double sign = ((i + j) % 2) ? 1.0 : -1.0;
            b.vortex({tenth((i + 0.5) * step), tenth((j + 0.5) * step), 0.0}, sign * alpha, lambda, core);
        }
}

void spanishWave(Bath& b) {
    stone(b);
    // The paper rocked as it is laid: bands of ink pushed along, most between the "teeth".
    double along = b.axis();
    b.stretch(along, b.pick(35, 70), b.pick(15, 35) * (b.rng.chance(0.5) ? 1 : -1), b.rng.uniform(0.3, 0.6));
    if (b.rng.chance(0.5)) b.wave(along, b.pick(8, 20), b.pick(200, 400));
}

void birdsNest(Bath& b) {
    // A stone ground, then nests: a few drops one in another (two inks alternating), and in
    // each nest a small curl with a clean eye.
    b.stone(b.pick(100, 130), b.rng.uniform(0.7, 0.85), b.ground.between(26, 34), 1.0);
    const int inks = b.inks();
    const int nests = b.ground.between(8, 14);
    std::vector<std::pair<glm::dvec3, std::size_t>> centres; // where, and the drops laid after
    for (int n = 0; n < nests; ++n) {
        const glm::dvec3 at = b.anywhere(-0.05);
        const int a = static_cast<int>(b.ground.below(static_cast<std::uint32_t>(inks)));
        const int c =
            (a + 1 + static_cast<int>(b.ground.below(static_cast<std::uint32_t>(std::max(1, inks - 1))))) %
            inks;
        b.rings(at, b.ground.between(3, 5), b.pick(10, 16), a, c);
        centres.emplace_back(at, b.g.initial.size());
    }
    // Later nests push earlier ones aside: each curl goes where its nest's centre was carried.
    const std::vector<PreparedOp> ground = prepare(b.g);
    for (auto [at, after] : centres) {
        glm::dvec3 p = at;
        for (std::size_t k = after; k < ground.size(); ++k)
            p = forwardMap(ground[k], p);
        b.vortex({tenth(p.x), tenth(p.y), 0.0}, (b.rng.chance(0.5) ? 1.0 : -1.0) * b.pick(150, 350),
                 b.pick(15, 25), b.pick(2, 5));
    }
}

void shawl(Bath& b) {
    stone(b);
    double along = b.axis();
    b.gelGit(along, b.pick(50, 90), b.pick(50, 90), b.pick(8, 16));
    // The şal's wide comb drawn in long waves across.
    b.comb(along + 90.0, b.pick(60, 110), b.pick(60, 110), b.pick(10, 20));
    b.wave(along + 90.0, b.pick(40, 90), b.pick(180, 320));
}

void tigerEye(Bath& b) {
    stone(b);
    // Sprinkled drops that push nothing: the tiger-eye's small bright spots.
    const int spots = b.ground.between(60, 140);
    const int ink = b.inks() - 1;
    for (int i = 0; i < spots; ++i)
        b.drop(b.anywhere(0.0), b.ground.uniform(3.0, 11.0), ink, Tool::Spray);
}

void zebra(Bath& b) {
    // The tray covered with bull's-eyes of a dark and a light ink, ring in ring, then drawn
    // into stripes by a wide gel-git and a wave.
    // The eyes sit on a loose grid and are about as wide as its cells, so together they cover
    // the whole tray (no bare paper between them once they push each other about).
    const int dark = 0, light = b.inks() > 1 ? 1 : 0;
    const int across = b.ground.between(3, 4);
    const double cell = b.g.size.x / across;
    for (int i = 0; i < across; ++i)
        for (int j = 0; j < across; ++j) {
            const glm::dvec3 at{tenth((i + b.ground.uniform(0.3, 0.7)) * cell),
                                tenth((j + b.ground.uniform(0.3, 0.7)) * cell), 0.0};
            const int count = b.ground.between(8, 12);
            const double outer = cell * b.ground.uniform(0.7, 0.8);
            b.rings(at, count, tenth(outer / std::sqrt(2.0 * count - 1.0)), dark, light);
        }
    double along = b.axis();
    b.gelGit(along, b.pick(120, 220), b.pick(80, 160), b.pick(20, 40));
    b.wave(along, b.pick(30, 70), b.pick(200, 400));
}

void firstPaper(Bath& b) {
    // The making shown in the first mathematical marbling paper (Lu et al. 2012, fig. 1).
    stone(b);
    double s = b.pick(70, 110), alpha = b.pick(50, 90), lambda = b.pick(8, 16);
    b.comb(180.0, s, alpha, lambda);    // right to left
    b.comb(0.0, s, alpha, lambda, 0.5); // and back, the teeth in between
    b.comb(270.0, s, alpha, lambda);    // the same vertically
    b.comb(90.0, s, alpha, lambda, 0.5);
    double fine = b.pick(25, 45);
    b.comb(180.0, fine, 0.6 * alpha, 0.6 * lambda); // two horizontal passes
    b.comb(0.0, fine, 0.6 * alpha, 0.6 * lambda, 0.5);
    b.wave(90.0, b.pick(20, 50), b.pick(150, 350)); // then a wave
}

// Drawn with the stylus (format version 3): çiçekli ebru.

/// A light battal ground under the flowers: a stone of middling drops over the whole tray.
void flowerGround(Bath& b) {
    b.stone(b.pick(75, 100), b.rng.uniform(0.75, 0.85), b.ground.between(34, 44), 1.25);
}

/// Ringed drops in `rows` rows of `perRow` along one of the tray's axes, each `outer` in
/// radius with `count` rings of two inks; returns the centres, row by row, where the drops laid
/// after each have carried it (a stroke through a drop goes through its middle as it now lies).
std::vector<std::vector<glm::dvec2>> flowerRows(Bath& b, double along, int rows, int perRow, double outer,
                                                int count, bool stagger) {
    const glm::dvec2 m = unitAt(along), n(-m.y, m.x);
    const double lengthWay = std::abs(m.x) * b.g.size.x + std::abs(m.y) * b.g.size.y;
    const double across = std::abs(n.x) * b.g.size.x + std::abs(n.y) * b.g.size.y;
    const glm::dvec2 centre(0.5 * b.g.size.x, 0.5 * b.g.size.y);
    std::vector<std::vector<glm::dvec2>> centres;
    std::vector<std::size_t> laidAfter; // the drops laid before each centre's last ring, and it
    for (int r = 0; r < rows; ++r) {
        centres.emplace_back();
        const double shiftAlong = stagger && (r % 2) ? 0.5 : 0.0;
        for (int i = 0; i < perRow; ++i) {
            const double u = ((i + 0.5 + shiftAlong) / perRow - 0.5) * lengthWay;
            const double v = ((r + 0.5) / rows - 0.5) * across;
            const glm::dvec2 at = centre + u * m + v * n;
            const glm::dvec3 at3{tenth(at.x), tenth(at.y), 0.0};
            const auto [a, c] = b.twoInks(0);
            b.ringedDrop(at3, count, outer, a, c);
            centres.back().push_back({at3.x, at3.y});
            laidAfter.push_back(b.g.initial.size());
        }
    }
    const std::vector<PreparedOp> laid = prepare(b.g);
    std::size_t k = 0;
    for (auto& row : centres)
        for (glm::dvec2& at : row) {
            glm::dvec3 p{at.x, at.y, 0.0};
            for (std::size_t j = laidAfter[k++]; j < laid.size(); ++j)
                p = forwardMap(laid[j], p);
            at = {tenth(p.x), tenth(p.y)};
        }
    return centres;
}

void hearts(Bath& b) {
    // Ebru hearts: rows of ringed drops, then one stroke of the stylus drawn through the
    // centres of each row, which pulls every drop into a heart pointing the way it went.
    flowerGround(b);
    const double along = b.axis();
    const int rows = b.rng.between(2, 4), perRow = b.rng.between(4, 6);
    const double cell = std::min(1000.0 / perRow, 1000.0 / rows);
    const double outer = b.pick(0.3, 0.38) * cell;
    const auto centres = flowerRows(b, along, rows, perRow, outer, b.rng.between(2, 3), false);
    const glm::dvec2 m = unitAt(along);
    const double alpha = outer * b.rng.uniform(0.9, 1.2), reach = outer * b.rng.uniform(0.6, 0.8);
    const double lambda = outer * b.rng.uniform(0.12, 0.18);
    for (const auto& row : centres) {
        // From beyond the first drop, through every middle, to beyond the last.
        std::vector<glm::dvec2> path{row.front() - (outer + reach) * m};
        path.insert(path.end(), row.begin(), row.end());
        path.push_back(row.back() + (outer + reach) * m);
        b.stylus(path, alpha, lambda, reach);
    }
}

void tulip(Bath& b) {
    // Lale: ringed drops, each pulled into a cup by a short stroke drawn up through it from
    // below; the pen is lifted as it leaves the drop, so the cup closes in a point.
    flowerGround(b);
    const int rows = b.rng.between(2, 3), perRow = b.rng.between(3, 4);
    const double cell = std::min(1000.0 / perRow, 1000.0 / rows);
    const double outer = b.pick(0.28, 0.34) * cell;
    const auto centres = flowerRows(b, 0.0, rows, perRow, outer, b.rng.between(3, 4), true);
    const double alpha = outer * b.rng.uniform(0.9, 1.2), reach = outer * b.rng.uniform(0.5, 0.7);
    const double lambda = outer * b.rng.uniform(0.12, 0.2);
    for (const auto& row : centres)
        for (glm::dvec2 at : row)
            b.stylus({at + glm::dvec2(0.0, 1.4 * outer), at, at - glm::dvec2(0.0, 0.9 * outer)}, alpha,
                     lambda, reach, 1, 0.0, {1.0, 1.0, 0.3});
}

void carnation(Bath& b) {
    // Karanfil: ringed drops, each fringed by short strokes from its middle out across its
    // edge, evenly round it: every stroke pulls the rings out into a petal's jagged tip.
    flowerGround(b);
    const int rows = b.rng.between(2, 3), perRow = b.rng.between(2, 3);
    const double cell = std::min(1000.0 / perRow, 1000.0 / rows);
    const double outer = b.pick(0.3, 0.36) * cell;
    const auto centres = flowerRows(b, 0.0, rows, perRow, outer, b.rng.between(3, 4), true);
    const int petals = b.rng.between(7, 11);
    const double alpha = outer * b.rng.uniform(0.35, 0.5), reach = outer * b.rng.uniform(0.25, 0.35);
    const double lambda = outer * b.rng.uniform(0.06, 0.1), turn = b.rng.uniform(0.0, 1.0);
    for (const auto& row : centres)
        for (glm::dvec2 at : row)
            for (int k = 0; k < petals; ++k) {
                const glm::dvec2 out = cosSinOfTurns(turn + double(k) / petals);
                b.stylus({at + 0.35 * outer * out, at + 1.25 * outer * out}, alpha, lambda, reach);
            }
}

void curls(Bath& b) {
    // Free-hand French curls: a combed ground (a gel-git), then the stylus drawn in a spiral
    // from outside in at every point of a grid, each turning the other way from its neighbours,
    // winding the combed lines it crosses round into a curl. Found by looking (seed 21 at 240
    // pixels): a pull just short of dragging ink along (c = 15 alpha / (16 reach) 0.85-1), a
    // reach some two fifths of the curl's radius and a path of 48 points a turn read as curls;
    // a stronger, sharper pull or a shorter reach threw radial spikes round each curl instead
    // (the stylus's sideways flow does not fall off, and it turns at every corner of the path).
    gelGit(b);
    const int n = b.rng.between(3, 4);
    const double cell = 1000.0 / n;
    const double outer = cell * b.rng.uniform(0.28, 0.32), turns = b.rng.uniform(1.4, 1.75);
    const double reach = outer * b.rng.uniform(0.38, 0.45);
    const double alpha = reach * b.rng.uniform(0.91, 1.07), lambda = reach * b.rng.uniform(0.22, 0.28);
    const int points = static_cast<int>(std::ceil(48.0 * turns)) + 1;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double sign = ((i + j) % 2) ? 1.0 : -1.0, start = b.rng.uniform(0.0, 1.0);
            const glm::dvec2 centre{(i + 0.5) * cell, (j + 0.5) * cell};
            std::vector<glm::dvec2> path;
            for (int k = 0; k < points; ++k) {
                const double t = double(k) / (points - 1);
                path.push_back(centre + outer * (1.0 - 0.7 * t) * cosSinOfTurns(start + sign * turns * t));
            }
            b.stylus(path, alpha, lambda, reach);
        }
}

// Solid families.

void veined(Bath& b) {
    // A ground of the first ink through the whole block (marble has no holes: a sphere to its
    // corners), spheres of ink in it, big first, then thin 3D combs drawing them into veins.
    b.drop(0.5 * b.g.size, 0.5 * glm::length(b.g.size) + 10.0, 0);
    b.stone(b.pick(170, 230), 0.7, b.ground.between(12, 18), 1.2);
    int a = static_cast<int>(b.rng.below(3));
    b.comb3(boxAxis(a), boxAxis(a + 1), b.pick(150, 260), b.pick(100, 200), b.pick(5, 15));
    b.comb3(boxAxis(a + 1), boxAxis(a + 2), b.pick(200, 320), b.pick(60, 140), b.pick(5, 15));
    b.wave3(WaveShape::Eggcrate, b.pick(30, 70), b.pick(300, 600));
}

void agate(Bath& b) {
    // Columns one in another, the colours alternating: the bands of agate, then waved.
    b.column(0.5 * b.g.size, boxAxis(2), 720.0, 0); // the ground, to the box's corners
    // Wide enough together to band most of the stone, not to leave a plain block round them.
    const int centres = b.ground.between(2, 3);
    for (int c = 0; c < centres; ++c) {
        glm::dvec3 at = b.anywhere(-0.15);
        glm::dvec3 axisVector = boxAxis(static_cast<int>(b.ground.below(3)));
        const int bands = b.ground.between(9, 14);
        const double width = b.pick(22, 38);
        // As Bath::rings: the widest column first, so the bands come out equally wide.
        for (int k = bands; k >= 1; --k)
            b.column(at, axisVector, width * std::sqrt(2.0 * k - 1.0), 1 + (k % std::max(1, b.inks() - 1)));
    }
    b.wave3(b.rng.chance(0.5) ? WaveShape::Ripple : WaveShape::Eggcrate, b.pick(20, 60), b.pick(200, 450));
}

void granite(Bath& b) {
    // Close-packed grains of every ink, then speckles that push nothing.
    b.stone(b.pick(80, 110), 0.9, b.ground.between(220, 280), 1.0);
    const int specks = b.ground.between(1200, 1800);
    for (int i = 0; i < specks; ++i)
        b.drop(b.anywhere(0.0), b.ground.uniform(10.0, 25.0),
               static_cast<int>(b.ground.below(static_cast<std::uint32_t>(b.inks()))), Tool::Spray);
    if (b.rng.chance(0.5)) b.wave3(WaveShape::Eggcrate, b.pick(10, 30), b.pick(300, 600));
}

struct Recipe {
    Family family;
    int inksLo, inksHi;
    void (*make)(Bath&);
};

constexpr std::array<Recipe, 20> Recipes{{
    {{"stone", 2, "battal: drops only, big first, later colours smaller"}, 3, 5, stone},
    {{"gel-git", 2, "stone combed one way and back (come and go)"}, 3, 4, gelGit},
    {{"chevron", 2, "gel-git, then one wide comb across: rows of chevrons"}, 3, 4, chevron},
    {{"nonpareil", 2, "gel-git, then a fine comb across: rows of small points"}, 3, 5, nonpareilOnly},
    {{"bouquet", 2, "nonpareil, then a rake in a serpentine: rows of fans"}, 3, 5, bouquet},
    {{"peacock", 2, "bouquet, then the rake back between: rows of eyes"}, 3, 5, peacock},
    {{"french-curl", 2, "curls on a grid over a nonpareil or gel-git"}, 3, 4, frenchCurl},
    {{"spanish-wave", 2, "stone rocked into bands (a stretch pass)"}, 3, 4, spanishWave},
    {{"birds-nest", 2, "bülbül yuvası: a small curl in each drop"}, 2, 4, birdsNest},
    {{"shawl", 2, "şal: gel-git, then a wide comb in long waves"}, 3, 4, shawl},
    {{"tiger-eye", 2, "stone sprinkled with small bright spots"}, 3, 4, tigerEye},
    {{"zebra", 2, "bull's-eyes of two inks combed into stripes"}, 2, 3, zebra},
    {{"first-paper", 2, "stone, combs both ways across and down, a wave (Lu et al. 2012)"}, 3, 5, firstPaper},
    {{"hearts", 2, "ebru hearts: rows of ringed drops, a stylus drawn through each row"}, 3, 5, hearts},
    {{"tulip", 2, "lale: ringed drops pulled into cups by a short stroke each"}, 3, 5, tulip},
    {{"carnation", 2, "karanfil: ringed drops fringed by short strokes round the edge"}, 3, 5, carnation},
    {{"curls", 2, "free-hand French curl: a stylus drawn in spirals through a gel-git"}, 3, 4, curls},
    {{"veined", 3, "solid: spheres of ink drawn into veins by combs"}, 2, 4, veined},
    {{"agate", 3, "solid: columns of banded ink, waved"}, 3, 5, agate},
    {{"granite", 3, "solid: speckles over close-packed grains"}, 3, 5, granite},
}};

constexpr std::array<Family, Recipes.size()> familiesOf() {
    std::array<Family, Recipes.size()> out{};
    for (std::size_t i = 0; i < Recipes.size(); ++i)
        out[i] = Recipes[i].family;
    return out;
}
constexpr std::array<Family, Recipes.size()> Families = familiesOf();

} // namespace

std::span<const Family> allFamilies() {
    return Families;
}

const Family* findFamily(std::string_view name) {
    for (const Family& f : Families)
        if (f.name == name) return &f;
    return nullptr;
}

const Family* parentsFamily(std::span<const Genome> parents) {
    const Family* family = nullptr;
    for (const Genome& parent : parents)
        if (!family && parent.meta.family) family = findFamily(*parent.meta.family);
    if (family && !parents.empty() && family->dimension != parents.front().dimension) return nullptr;
    return family;
}

std::vector<Genome> newPopulation(std::uint64_t seed, int dimension, const Family* only, int count,
                                  std::set<std::string> taken) {
    std::vector<const Family*> sources;
    if (only) {
        sources.push_back(only);
    } else {
        for (const Family& f : allFamilies())
            if (f.dimension == dimension) sources.push_back(&f);
        sources.push_back(nullptr);
        Pcg32 order(seed, 0x6d6978666d6c7931ULL);
        for (std::size_t i = sources.size(); i > 1; --i)
            std::swap(sources[i - 1], sources[order.below(std::uint32_t(i))]);
    }
    std::vector<Genome> designs;
    std::uint64_t draw = 0;
    for (int i = 0; i < count; ++i) {
        for (;;) {
            const std::uint64_t s = mixSeed(seed, draw++) & 0xffffffffULL;
            const Family* source = sources[std::size_t(i) % sources.size()];
            Genome g = source ? familyGenome(*source, s) : randomGenome(s, dimension);
            if (!taken.insert(genomeId(g)).second && draw < 1000) continue;
            if (!g.meta.seed) g.meta.seed = s;
            designs.push_back(std::move(g));
            break;
        }
    }
    return designs;
}

std::span<const TraditionalPalette> traditionalPalettes() {
    return Traditions;
}

Genome familyGenome(const Family& family, std::uint64_t seed) {
    const Recipe* recipe = nullptr;
    for (const Recipe& r : Recipes)
        if (r.family.name == family.name) recipe = &r;
    if (!recipe) recipe = &Recipes.front();
    Genome g;
    g.dimension = recipe->family.dimension;
    g.size = {1000.0, 1000.0, 1000.0};
    Pcg32 paletteRng(seed, FamilyPaletteStream);
    g.palette = familyPalette(paletteRng, paletteRng.between(recipe->inksLo, recipe->inksHi), g.background);
    Pcg32 ground(seed, FamilyGroundStream), strokes(seed, FamilyStrokeStream);
    Bath bath{ground, strokes, g};
    recipe->make(bath);
    // Stay within the format's limits whatever the draw.
    if (g.initial.size() + g.operations.size() > MaxEntries)
        g.initial.resize(MaxEntries - g.operations.size());
    g.meta = Meta{};
    g.meta.name = randomName(seed, g, recipe->family.name);
    g.meta.seed = seed;
    g.meta.generator = FamiliesVersion;
    g.meta.family = std::string(recipe->family.name);
    return g;
}

} // namespace marbler
