#include "marbler/Generator.h"

#include "marbler/Error.h"
#include "marbler/Params.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace marbler {
namespace {

// Separate streams for the parts of a design, so that (say) a longer palette does not shift
// every drop of the same seed.
constexpr std::uint64_t PaletteStream = 0x70616c6574746531ULL;
constexpr std::uint64_t InitialStream = 0x696e697469616c31ULL;
constexpr std::uint64_t StrokeStream = 0x7374726f6b657331ULL;
constexpr std::uint64_t NameStream = 0x6e616d6573313131ULL;
constexpr std::uint64_t Version2Stream = 0x76657273696f6e32ULL;
constexpr std::uint64_t Version3Stream = 0x76657273696f6e33ULL;

constexpr double Pi = 3.141592653589793;
constexpr double SqrtHalf = 0.7071067811865476;

/// Cube root by Newton's method on the mantissa: std::cbrt is not required to be correctly
/// rounded, and the generator's output must not depend on the C library.
double cubeRoot(double x) {
    if (!(x > 0.0)) return 0.0;
    int e = 0;
    double m = std::frexp(x, &e); // x = m 2^e, m in [0.5, 1)
    int shift = ((e % 3) + 3) % 3;
    m = std::ldexp(m, shift); // m in [0.5, 8)
    e -= shift;
    double y = 1.0;
    for (int i = 0; i < 40; ++i) {
        double next = y - (y * y * y - m) / (3.0 * y * y);
        if (next == y) break;
        y = next;
    }
    return std::ldexp(y, e / 3);
}

/// A uniformly distributed unit vector, by rejection from the cube (no trigonometry).
glm::dvec3 randomUnit(Pcg32& rng, int dimension) {
    for (;;) {
        glm::dvec3 v(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0),
                     dimension == 3 ? rng.uniform(-1.0, 1.0) : 0.0);
        double len2 = glm::dot(v, v);
        if (len2 > 0.01 && len2 <= 1.0) return v / std::sqrt(len2);
    }
}

// ---------------------------------------------------------------------------------------
// Palette

/// Perceived brightness of gamma-encoded sRGB (Rec. 601 luma): good enough to judge contrast.
// ---------------------------------------------------------------------------------------
// Drops

/// An ink blob while the stone pattern is laid: where an earlier drop now sits (its centre is
/// pushed by later drops; its area or volume is kept, so its radius is a fair estimate).
struct Blob {
    glm::dvec3 center;
    double radius;
    int color;
};

/// The forward map of a drop, applied to earlier blob centres.
glm::dvec3 pushBy(const glm::dvec3& p, const glm::dvec3& c, double r, int dimension) {
    glm::dvec3 rel = p - c;
    double len2 = glm::dot(rel, rel);
    if (!(len2 > 0.0)) return p;
    double factor =
        dimension == 3 ? cubeRoot(1.0 + r * r * r / (len2 * std::sqrt(len2))) : std::sqrt(1.0 + r * r / len2);
    return c + rel * factor;
}

bool insideBox(const glm::dvec3& p, const glm::dvec3& size, int dimension) {
    for (int i = 0; i < dimension; ++i)
        if (p[i] < 0.0 || p[i] > size[i]) return false;
    return true;
}

glm::dvec3 uniformPoint(Pcg32& rng, const glm::dvec3& size, int dimension, double lo = 0.0, double hi = 1.0) {
    glm::dvec3 p(0.0);
    for (int i = 0; i < dimension; ++i)
        p[i] = size[i] * rng.uniform(lo, hi);
    return p;
}

/// How much room a drop of radius r at p has: the smallest gap to the blobs (negative when it
/// overlaps one).
double clearance(const std::vector<Blob>& blobs, const glm::dvec3& p, double r) {
    double best = std::numeric_limits<double>::max();
    for (const Blob& b : blobs)
        best = std::min(best, glm::length(p - b.center) - b.radius - r);
    return best;
}

/// A palette index different from the ones to avoid where the palette allows (first from
/// both, then from the first alone).
int pickColor(Pcg32& rng, int paletteSize, int avoidA, int avoidB) {
    auto draw = [&] { return static_cast<int>(rng.below(static_cast<std::uint32_t>(paletteSize))); };
    if (paletteSize >= 3)
        for (int attempt = 0; attempt < 16; ++attempt)
            if (int c = draw(); c != avoidA && c != avoidB) return c;
    if (paletteSize >= 2)
        for (int attempt = 0; attempt < 16; ++attempt)
            if (int c = draw(); c != avoidA) return c;
    return draw();
}

Operation inkOp(Tool tool, const glm::dvec3& center, double radius, int color, int dimension) {
    Operation op = defaultOperation(tool, dimension, center);
    op.center = center;
    op.radius = radius;
    op.color = color;
    return op;
}

glm::dvec3 tidy(glm::dvec3 p, int dimension) {
    for (int i = 0; i < 3; ++i)
        p[i] = i < dimension ? tenth(p[i]) : 0.0;
    return p;
}

// ---------------------------------------------------------------------------------------
// Strokes

/// The eight compass directions with exact unit vectors (angles in degrees, clockwise).
struct Compass {
    double angle;
    double mx, my;
};
constexpr std::array<Compass, 8> Compass8{{
    {0, 1, 0},
    {45, SqrtHalf, SqrtHalf},
    {90, 0, 1},
    {135, -SqrtHalf, SqrtHalf},
    {180, -1, 0},
    {225, -SqrtHalf, -SqrtHalf},
    {270, 0, -1},
    {315, SqrtHalf, -SqrtHalf},
}};

/// Mostly along the bath's sides, as marblers comb; sometimes on a diagonal.
int compassIndex(Pcg32& rng) {
    return rng.chance(0.8) ? 2 * static_cast<int>(rng.below(4)) : 2 * static_cast<int>(rng.below(4)) + 1;
}

struct StrokeMaker {
    Pcg32& rng;
    int dimension;
    glm::dvec3 size;
    double side; // largest side: every length scales with it
    std::vector<Operation> ops;

    double len(double lo, double hi) { return tenth(side * rng.uniform(lo, hi) / 1000.0); }
    double signedLen(double lo, double hi) { return rng.chance(0.5) ? len(lo, hi) : -len(lo, hi); }
    glm::dvec3 centreish(double spread) {
        return tidy(uniformPoint(rng, size, dimension, 0.5 - spread, 0.5 + spread), dimension);
    }

    /// A random orthonormal pair (motion, normal): often along the box's axes.
    std::pair<glm::dvec3, glm::dvec3> frame() {
        if (rng.chance(0.7)) {
            int a = static_cast<int>(rng.below(3));
            int b = (a + 1 + static_cast<int>(rng.below(2))) % 3;
            glm::dvec3 u(0.0), w(0.0);
            u[a] = rng.chance(0.5) ? 1.0 : -1.0;
            w[b] = 1.0;
            return {u, w};
        }
        for (;;) {
            glm::dvec3 u = randomUnit(rng, 3), w = randomUnit(rng, 3);
            w -= glm::dot(w, u) * u;
            double l = glm::length(w);
            if (l > 0.3) return {u, w / l};
        }
    }

    /// A comb pass, and often its return pass offset by half a tine: the chevron / nonpareil
    /// move of a traditional marbler.
    void combPair(double spacingLo, double spacingHi, double alphaLo, double alphaHi, double lambdaLo,
                  double lambdaHi, bool back) {
        double spacing = len(spacingLo, spacingHi);
        double alpha = len(alphaLo, alphaHi);
        double lambda = len(lambdaLo, lambdaHi);
        glm::dvec3 origin = tidy(uniformPoint(rng, size, dimension), dimension);
        Operation there = defaultOperation(Tool::Comb, dimension, origin);
        there.alpha = alpha;
        there.lambda = lambda;
        there.spacing = spacing;
        glm::dvec3 normal;
        if (dimension == 2) {
            const Compass& c = Compass8[static_cast<std::size_t>(compassIndex(rng))];
            there.angle = c.angle;
            normal = {-c.my, c.mx, 0.0};
        } else {
            auto [u, w] = frame();
            there.direction = u;
            there.normal = w;
            normal = w;
        }
        ops.push_back(there);
        if (!back) return;
        Operation ret = there;
        if (dimension == 2)
            ret.angle = there.angle >= 180.0 ? there.angle - 180.0 : there.angle + 180.0;
        else
            ret.direction = -there.direction;
        double offset = rng.chance(0.75) ? 0.5 : rng.uniform(0.25, 0.75);
        ret.center = tidy(there.center + normal * (spacing * offset), dimension);
        ops.push_back(ret);
    }

    void wave() {
        Operation op =
            defaultOperation(Tool::Wave, dimension, tidy(uniformPoint(rng, size, dimension), dimension));
        if (dimension == 2) {
            op.angle = Compass8[static_cast<std::size_t>(compassIndex(rng))].angle +
                       std::round(rng.uniform(-8.0, 8.0));
            op.amplitude = {len(15, 80), 0.0};
            op.wavelength = {len(140, 500), 1.0};
            op.phase = {std::round(rng.uniform(0.0, 360.0)), 0.0};
        } else {
            auto [u, w] = frame();
            op.direction = u;
            op.normal = w;
            if (rng.chance(0.65)) {
                op.shape = WaveShape::Eggcrate;
                op.amplitude = {len(15, 70), len(10, 60)};
                op.wavelength = {len(180, 500), len(180, 500)};
                op.phase = {std::round(rng.uniform(0.0, 360.0)), std::round(rng.uniform(0.0, 360.0))};
            } else {
                op.shape = WaveShape::Ripple;
                op.amplitude = {len(15, 60), 0.0};
                op.wavelength = {len(150, 450), 1.0};
                op.phase = {std::round(rng.uniform(0.0, 360.0)), 0.0};
            }
        }
        ops.push_back(op);
    }

    void swirl(Tool tool) {
        Operation op = defaultOperation(tool, dimension, centreish(0.3));
        op.radius = len(100, 380);
        op.alpha = signedLen(80, 320);
        op.lambda = len(20, 80);
        if (dimension == 3) op.axis = frameAxis();
        ops.push_back(op);
    }

    void vortex(double sign) {
        Operation op = defaultOperation(Tool::Vortex, dimension, centreish(0.3));
        op.alpha = sign * len(150, 900);
        op.lambda = len(30, 100);
        if (dimension == 3) op.axis = frameAxis();
        ops.push_back(op);
    }

    void line() {
        glm::dvec3 origin = centreish(0.35);
        Operation op = defaultOperation(Tool::Line, dimension, origin);
        op.alpha = signedLen(60, 220);
        op.lambda = len(15, 50);
        if (dimension == 2) {
            op.angle = Compass8[static_cast<std::size_t>(compassIndex(rng))].angle;
        } else {
            auto [u, w] = frame();
            op.direction = u;
            op.normal = w;
        }
        ops.push_back(op);
    }

    glm::dvec3 frameAxis() {
        if (rng.chance(0.5)) {
            glm::dvec3 a(0.0);
            a[rng.below(3)] = 1.0;
            return a;
        }
        return randomUnit(rng, 3);
    }
};

/// Colour words for names, each with the sRGB colour it stands for (pigments and stones a
/// marbler would know). A name takes the word nearest its main ink.
struct ColorWord {
    const char* word;
    Color color;
};
constexpr std::array<ColorWord, 40> ColorWords{{
    {"Carmine", {150, 0, 24}},      {"Crimson", {196, 30, 58}},      {"Cinnabar", {227, 66, 52}},
    {"Coral", {240, 128, 110}},     {"Rose", {215, 120, 150}},       {"Madder", {165, 40, 70}},
    {"Russet", {128, 70, 27}},      {"Umber", {99, 81, 71}},         {"Sepia", {112, 66, 20}},
    {"Ochre", {204, 119, 34}},      {"Amber", {230, 150, 20}},       {"Saffron", {244, 196, 48}},
    {"Sand", {214, 190, 150}},      {"Ivory", {240, 234, 214}},      {"Olive", {128, 128, 0}},
    {"Moss", {100, 130, 60}},       {"Sage", {150, 175, 130}},       {"Jade", {0, 168, 107}},
    {"Malachite", {20, 110, 60}},   {"Verdigris", {67, 179, 174}},   {"Teal", {0, 128, 128}},
    {"Azure", {40, 130, 220}},      {"Cobalt", {0, 71, 171}},        {"Lapis", {38, 97, 156}},
    {"Indigo", {55, 45, 125}},      {"Violet", {130, 80, 180}},      {"Plum", {120, 50, 100}},
    {"Lilac", {190, 160, 210}},     {"Slate", {112, 128, 144}},      {"Charcoal", {54, 62, 70}},
    {"Pearl", {212, 212, 205}},     {"Ebony", {30, 28, 26}},         {"Emerald", {50, 190, 70}},
    {"Chartreuse", {150, 215, 40}}, {"Prussian", {0, 49, 83}},       {"Spruce", {35, 88, 82}},
    {"Purple", {110, 35, 135}},     {"Harbour Green", {52, 98, 78}}, {"Rust", {170, 75, 40}},
    {"Mauve", {160, 110, 150}},
}};

/// Nouns for a design of no family: none of them a family's own word ("Peacock" is a peacock's).
constexpr std::array<const char*, 26> Nouns{
    "Tide",    "Quarry",  "Lagoon", "Ember",  "Tapestry", "Current", "Marble", "Ripple",  "Delta",
    "Orchard", "Harbour", "Flame",  "Fern",   "Shell",    "Meadow",  "Dune",   "Veil",    "Spiral",
    "Lattice", "Estuary", "Garden", "Mosaic", "Cloud",    "Wake",    "Drift",  "Reverie",
};

/// Each family's own words, so that a design is named as what it is ("Cobalt Peacock", never
/// "Sage Bouquet" for a peacock). A family missing here takes the nouns above.
struct FamilyWords {
    std::string_view family;
    std::array<const char*, 4> nouns;
};
constexpr std::array<FamilyWords, 20> FamilyNouns{{
    {"stone", {"Stone", "Pebble", "Cobble", "Battal"}},
    {"gel-git", {"Come-and-Go", "Current", "Tide", "Drift"}},
    {"chevron", {"Chevron", "Arrow", "Zigzag", "Herringbone"}},
    {"nonpareil", {"Nonpareil", "Comb", "Stitch", "Row"}},
    {"bouquet", {"Bouquet", "Fan", "Posy", "Spray"}},
    {"peacock", {"Peacock", "Plume", "Eye", "Feather"}},
    {"french-curl", {"Curl", "Snail", "Scroll", "Whorl"}},
    {"spanish-wave", {"Wave", "Swell", "Shimmer", "Crest"}},
    {"birds-nest", {"Nest", "Twig", "Thicket", "Bramble"}},
    {"shawl", {"Shawl", "Paisley", "Drape", "Fringe"}},
    {"tiger-eye", {"Tiger Eye", "Gleam", "Glint", "Cat's Eye"}},
    {"zebra", {"Zebra", "Stripe", "Bar", "Band"}},
    {"first-paper", {"First Paper", "Vein", "Ground", "Leaf"}},
    {"hearts", {"Heart", "Valentine", "Locket", "Keepsake"}},
    {"tulip", {"Tulip", "Petal", "Bloom", "Bud"}},
    {"carnation", {"Carnation", "Frill", "Pink", "Ruffle"}},
    {"curls", {"Curl", "Loop", "Flourish", "Coil"}},
    {"veined", {"Vein", "Seam", "Lode", "Thread"}},
    {"agate", {"Agate", "Geode", "Band", "Onyx"}},
    {"granite", {"Granite", "Grain", "Speckle", "Quartz"}},
}};

/// The stretch passes of a procedural marbled paper: one to three passes across the whole
/// design, each at a right angle to the one before, with teeth a jittered spacing apart from
/// the edge the pass's normal points away from to the far edge, so that every point lies
/// between two teeth.
void stretchPasses(StrokeMaker& make, std::vector<Operation>& out) {
    Pcg32& rng = make.rng;
    const int passes = rng.chance(0.2) ? 1 : rng.chance(0.7) ? 2 : 3;
    int compass = 2 * static_cast<int>(rng.below(4)); // along a side of the bath
    for (int pass = 0; pass < passes; ++pass) {
        const Compass& c = Compass8[static_cast<std::size_t>(compass)];
        // N = (-sin a, cos a): down at 0, left at 90, up at 180, right at 270.
        const double nx = -c.my, ny = c.mx;
        const double w = make.size.x, h = make.size.y;
        Operation op = defaultOperation(Tool::Stretch, 2, {nx < 0.0 ? w : 0.0, ny < 0.0 ? h : 0.0, 0.0});
        op.angle = c.angle;
        const double across = nx != 0.0 ? w : h;
        const double spacing = make.len(40, 160);
        op.teeth = {0.0};
        while (op.teeth.back() < across)
            op.teeth.push_back(tenth(op.teeth.back() + spacing * rng.uniform(0.7, 1.3)));
        op.shift = make.signedLen(20, 90);
        op.power = tenth(rng.uniform(0.3, 2.0));
        out.push_back(op);
        compass = (compass + (rng.chance(0.5) ? 2 : 6)) % 8; // turn a quarter, either way
    }
}

/// A steady flow over the design: a lattice of cells, or one cavity swirl in a box inside it.
/// Its displacement (speed times time) is a fraction of the cell or box, and it takes the
/// fewest steps the format allows, at most about fifty, so it stays quick to render.
Operation randomFlow(StrokeMaker& make) {
    Pcg32& rng = make.rng;
    const bool cells = rng.chance(0.6);
    Operation op = defaultOperation(Tool::Flow, 2, {0.0, 0.0, 0.0});
    op.field = cells ? FlowField::Cells : FlowField::Cavity;
    double lx = cells ? make.len(150, 450) : make.len(350, 650);
    double ly = tenth(lx * rng.uniform(0.7, 1.4));
    op.extent = {lx, ly};
    if (cells) {
        op.center = tidy(uniformPoint(rng, make.size, 2), 2);
        op.angle = Compass8[static_cast<std::size_t>(compassIndex(rng))].angle;
    } else {
        // The box inside the design, upright (its lid on top or bottom).
        glm::dvec3 room(std::max(0.0, make.size.x - lx), std::max(0.0, make.size.y - ly), 0.0);
        op.angle = 0.0;
        op.center = tidy(uniformPoint(rng, room, 2), 2);
    }
    op.time = tenth(rng.uniform(1.0, 3.0));
    const double displacement = std::min(lx, ly) * (cells ? rng.uniform(0.2, 0.7) : rng.uniform(0.3, 0.9));
    op.speed = (rng.chance(0.5) ? 1.0 : -1.0) * std::max(0.1, tenth(displacement / op.time));
    op.steps = minimumFlowSteps(op);
    return op;
}

/// Version 2's touches on a 2D design, drawn from their own stream so that the stone pattern
/// and the strokes of a seed stay those version 1 drew: now and then stretch passes first
/// (the marbled-paper look; alone, or followed by the seed's strokes), a finite core in its
/// swirls, a flow, and a slight bleed. A design without any is still version 1.
void addVersion2Touches(Pcg32& rng, Genome& g) {
    StrokeMaker make{rng, 2, g.size, std::max(g.size.x, g.size.y), {}};
    if (rng.chance(0.25)) {
        std::vector<Operation> passes;
        stretchPasses(make, passes);
        if (rng.chance(0.4)) g.operations.clear(); // a plain marbled paper
        g.operations.insert(g.operations.begin(), passes.begin(), passes.end());
    }
    if (rng.chance(0.35))
        for (Operation& op : g.operations)
            if (op.tool == Tool::Circle || op.tool == Tool::Vortex) op.core = make.len(8, 60);
    if (rng.chance(0.12)) {
        Operation flow = randomFlow(make);
        // Most often last, as a finishing stir; sometimes before the last stroke, unless that
        // is a stretch pass (they come first, together).
        auto at = g.operations.end();
        const bool beforeLast = rng.chance(0.3);
        if (beforeLast && !g.operations.empty() && g.operations.back().tool != Tool::Stretch) --at;
        g.operations.insert(at, flow);
    }
    if (rng.chance(0.3)) g.bleed = tenth(rng.uniform(0.5, 3.0));
}

/// Version 3's touch on a 2D design, from its own stream so that everything else a seed drew
/// stays: now and then a free-hand stroke, a stylus (or a small rake) drawn along a wandering
/// path of a few points across part of the design, with the fewest steps the format allows so
/// it stays quick to render. A design without one is still what version 2 made of it.
void addVersion3Touches(Pcg32& rng, Genome& g) {
    if (!rng.chance(0.15)) return;
    StrokeMaker make{rng, 2, g.size, std::max(g.size.x, g.size.y), {}};
    Operation op = defaultOperation(Tool::Stylus, 2, glm::dvec3(0.0)); // a file gives a stylus no centre
    // A hand's path: from somewhere in the design, heading one way and turning a little at
    // each of its points.
    const glm::dvec3 start = uniformPoint(rng, g.size, 2, 0.1, 0.9);
    glm::dvec2 at(start.x, start.y), heading(randomUnit(rng, 2));
    const int points = rng.between(3, 9);
    const double segment = make.len(60, 160);
    op.path = {{tenth(at.x), tenth(at.y)}};
    for (int i = 1; i < points; ++i) {
        const glm::dvec2 turn(randomUnit(rng, 2));
        heading = glm::normalize(heading + 0.6 * turn);
        at += segment * rng.uniform(0.6, 1.0) * heading;
        const glm::dvec2 p{tenth(at.x), tenth(at.y)};
        if (p != op.path.back()) op.path.push_back(p);
    }
    if (op.path.size() < 2) return;
    op.alpha = make.signedLen(20, 90);
    op.lambda = make.len(6, 20);
    op.reach = make.len(30, 80);
    if (rng.chance(0.3)) {
        op.tines = rng.between(2, 6);
        op.spacing = make.len(15, 50);
    }
    // A gentler pull where the stroke would take many steps (a strong rake on a long path).
    while (minimumStylusSteps(op) > 3000 && std::abs(op.alpha) > 1.0)
        op.alpha = tenth(0.7 * op.alpha);
    op.steps = minimumStylusSteps(op);
    if (op.steps > MaxStylusSteps) return;
    // Most often last, a final flourish; sometimes before the last stroke.
    auto where = g.operations.end();
    if (rng.chance(0.3) && !g.operations.empty() && g.operations.back().tool != Tool::Stretch) --where;
    g.operations.insert(where, op);
}

} // namespace

std::string colorWord(Color color) {
    const ColorWord* best = &ColorWords[0];
    for (const ColorWord& w : ColorWords)
        if (colorDistance2(color, w.color) < colorDistance2(color, best->color)) best = &w;
    return best->word;
}

int mainInk(const Genome& genome) {
    if (genome.palette.empty()) return -1;
    // Area (volume) is what a drop keeps through every later stroke, so the initial state's
    // share of each ink is what the eye sees most of.
    std::vector<double> share(genome.palette.size(), 0.0);
    for (const Operation& op : genome.initial) {
        if (!toolSpec(op.tool).laysInk || op.color < 0 || op.color >= static_cast<int>(share.size()))
            continue;
        double r = std::max(op.radius, 1.0);
        share[static_cast<std::size_t>(op.color)] += genome.dimension == 3 ? r * r * r : r * r;
    }
    return static_cast<int>(std::max_element(share.begin(), share.end()) - share.begin());
}

std::vector<std::string> familyNouns(std::string_view family) {
    for (const FamilyWords& f : FamilyNouns)
        if (f.family == family) return {f.nouns.begin(), f.nouns.end()};
    return {Nouns.begin(), Nouns.end()};
}

std::string paletteWords(const Genome& genome, int most) {
    if (genome.palette.empty()) return {};
    // The inks by what they cover of the initial state, most first (as mainInk); equal shares in
    // palette order.
    std::vector<double> share(genome.palette.size(), 0.0);
    for (const Operation& op : genome.initial) {
        if (!toolSpec(op.tool).laysInk || op.color < 0 || op.color >= static_cast<int>(share.size()))
            continue;
        const double r = std::max(op.radius, 1.0);
        share[static_cast<std::size_t>(op.color)] += genome.dimension == 3 ? r * r * r : r * r;
    }
    std::vector<std::size_t> order(share.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return share[a] > share[b]; });
    std::vector<std::string> words;
    for (std::size_t i : order) {
        if (static_cast<int>(words.size()) >= most) break;
        std::string word = colorWord(genome.palette[i]);
        if (std::find(words.begin(), words.end(), word) == words.end()) words.push_back(std::move(word));
    }
    std::string out;
    for (std::size_t i = 0; i < words.size(); ++i)
        out += (i == 0 ? "" : i + 1 == words.size() ? " and " : ", ") + words[i];
    return out;
}

std::string randomName(std::uint64_t seed, const Genome& genome, std::string_view family) {
    Pcg32 rng(seed, NameStream);
    const int ink = mainInk(genome);
    std::string adjective = ink >= 0 ? colorWord(genome.palette[static_cast<std::size_t>(ink)]) : "Quiet";
    const std::vector<std::string> nouns = familyNouns(family);
    return adjective + " " + nouns[rng.below(static_cast<std::uint32_t>(nouns.size()))];
}

std::string recolouredName(const std::string& name, const Genome& parent, const Genome& colourway) {
    // The parent's own colour word, when its name starts with it, gives way to the colourway's.
    std::string noun = name;
    if (const int ink = mainInk(parent); ink >= 0) {
        const std::string word = colorWord(parent.palette[static_cast<std::size_t>(ink)]);
        if (noun.rfind(word + " ", 0) == 0)
            noun.erase(0, word.size() + 1);
        else if (noun == word)
            noun.clear();
    }
    if (noun.empty()) return paletteWords(colourway, 2);
    return paletteWords(colourway, 1) + " " + noun;
}

std::string uniqueName(const std::string& name, const std::set<std::string>& taken) {
    if (!taken.count(name)) return name;
    // A bred name's number goes before its " (gN #K)", so that its children, named from the
    // root, carry it too.
    std::string root = name, suffix;
    if (auto pos = name.rfind(" (g"); pos != std::string::npos && name.back() == ')') {
        root = name.substr(0, pos);
        suffix = name.substr(pos);
    }
    for (int n = 2;; ++n) {
        std::string candidate = root + " " + std::to_string(n) + suffix;
        if (!taken.count(candidate)) return candidate;
    }
}

std::vector<Color> randomPalette(Pcg32& rng, Color* background) {
    double base = rng.uniform(0.0, 360.0);
    int count = rng.between(3, 6);
    // Hue offsets of the classic harmony schemes; inks cycle through them.
    std::vector<double> offsets;
    switch (rng.below(5)) {
    case 0: { // analogous
        double step = rng.uniform(18.0, 40.0);
        offsets = {0.0, step, -step, 2.0 * step, -2.0 * step, 0.5 * step};
        break;
    }
    case 1:
        offsets = {0.0, 180.0, 20.0, 200.0, -20.0, 160.0};
        break; // complementary
    case 2:
        offsets = {0.0, 150.0, 210.0, 15.0, 165.0, 195.0};
        break; // split-complementary
    case 3:
        offsets = {0.0, 120.0, 240.0, 15.0, 135.0, 255.0};
        break; // triadic
    default:
        offsets = {0.0, 0.0, 180.0, 10.0, -10.0, 0.0};
        break; // monochrome with an accent
    }
    bool dark = rng.chance(0.3);
    double mood = rng.uniform(0.3, 0.72); // muted or vivid, for the whole palette
    double lo = dark ? 0.38 : 0.2, hi = dark ? 0.8 : 0.68;

    Hsl bg;
    if (dark) {
        bg = {wrapHue(base + rng.uniform(150.0, 210.0)), rng.uniform(0.15, 0.45), rng.uniform(0.07, 0.15)};
    } else if (rng.chance(0.6)) {
        bg = {rng.uniform(30.0, 50.0), rng.uniform(0.25, 0.55), rng.uniform(0.86, 0.93)}; // paper and cream
    } else {
        bg = {wrapHue(base + 180.0 + rng.uniform(-20.0, 20.0)), rng.uniform(0.15, 0.4),
              rng.uniform(0.84, 0.92)};
    }
    Color bgColor = colorFromHsl(bg);

    // Lightness spread evenly over the inks, then shuffled, so the stones differ in value too.
    std::vector<double> lightness(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i)
        lightness[static_cast<std::size_t>(i)] = lo + (hi - lo) * (i + rng.uniform(0.2, 0.8)) / count;
    for (int i = count - 1; i > 0; --i)
        std::swap(lightness[static_cast<std::size_t>(i)],
                  lightness[rng.below(static_cast<std::uint32_t>(i + 1))]);

    std::vector<Color> palette;
    for (int i = 0; i < count; ++i) {
        Hsl ink{wrapHue(base + offsets[static_cast<std::size_t>(i)] + rng.uniform(-8.0, 8.0)),
                std::clamp(mood + rng.uniform(-0.15, 0.15), 0.2, 0.95),
                lightness[static_cast<std::size_t>(i)]};
        Color c = colorFromHsl(ink);
        // Keep every ink visible on the bath and apart from the inks before it.
        for (int attempt = 0; attempt < 8; ++attempt) {
            bool tooCloseToBath = std::abs(lumaOf(c) - lumaOf(bgColor)) < 0.2;
            bool tooCloseToInk = false;
            for (Color other : palette)
                tooCloseToInk = tooCloseToInk || rgbDistance2(c, other) < 45.0 * 45.0;
            if (!tooCloseToBath && !tooCloseToInk) break;
            ink.l = dark ? std::min(0.85, ink.l + 0.07) : std::max(0.15, ink.l - 0.07);
            if (tooCloseToInk) ink.h = wrapHue(ink.h + 25.0);
            c = colorFromHsl(ink);
        }
        palette.push_back(c);
    }
    if (background) *background = bgColor;
    return palette;
}

std::vector<Operation> randomInitial(Pcg32& rng, int dimension, const glm::dvec3& size, int paletteSize) {
    if (dimension != 2 && dimension != 3) throw InputError("dimension must be 2 or 3");
    if (paletteSize < 1) throw InputError("a palette needs at least one colour");
    const bool solid = dimension == 3;
    const int count = solid ? rng.between(60, 180) : rng.between(30, 120);
    const double space = solid ? size.x * size.y * size.z : size.x * size.y;
    const double side = std::max({size.x, size.y, solid ? size.z : 0.0});

    // Radii shrink from first to last, the way a marbler lays big stones first and fills in;
    // scaled so that the inks' area (volume) comes to more than the bath's, covering it.
    std::vector<double> weight(static_cast<std::size_t>(count));
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        double w = (1.0 - 0.65 * i / count) * rng.uniform(0.75, 1.25);
        weight[static_cast<std::size_t>(i)] = w;
        sum += solid ? w * w * w : w * w;
    }
    const double coverage = solid ? rng.uniform(1.9, 2.5) : rng.uniform(2.0, 2.6);
    const double scale = solid ? cubeRoot(coverage * space / (4.0 / 3.0 * Pi * sum))
                               : std::sqrt(coverage * space / (Pi * sum));

    std::vector<Blob> blobs;
    std::vector<Operation> ops;
    int lastColor = -1;
    for (int i = 0; i < count; ++i) {
        double r = std::max(side * 0.004, weight[static_cast<std::size_t>(i)] * scale);
        glm::dvec3 center(0.0);
        int avoid = -1;
        double kind = rng.uniform();
        if (blobs.empty()) {
            center = uniformPoint(rng, size, dimension, 0.3, 0.7);
        } else if (kind < 0.14) {
            // Bull's-eye: into a recent drop, which becomes a ring round the new one.
            std::size_t j = blobs.size() - 1 -
                            rng.below(static_cast<std::uint32_t>(std::min<std::size_t>(blobs.size(), 6)));
            const Blob& host = blobs[j];
            r = std::min(r, host.radius * rng.uniform(0.4, 0.8));
            center = host.center + randomUnit(rng, dimension) * (host.radius * rng.uniform(0.0, 0.12));
            avoid = host.color;
        } else {
            // Touching an earlier stone (most drops), else into the largest gap found; the
            // small late drops go more often into the gaps, as a marbler fills the bath.
            bool touching = kind < 0.75 - 0.35 * i / count;
            double bestRoom = -std::numeric_limits<double>::max();
            for (int attempt = 0; attempt < (touching ? 10 : 14); ++attempt) {
                glm::dvec3 candidate;
                int candidateAvoid = -1;
                if (touching) {
                    std::size_t j = rng.chance(0.5) ? blobs.size() - 1 -
                                                          rng.below(static_cast<std::uint32_t>(
                                                              std::min<std::size_t>(blobs.size(), 8)))
                                                    : rng.below(static_cast<std::uint32_t>(blobs.size()));
                    candidate = blobs[j].center +
                                randomUnit(rng, dimension) * ((blobs[j].radius + r) * rng.uniform(0.9, 1.0));
                    candidateAvoid = blobs[j].color;
                    if (!insideBox(candidate, size, dimension)) continue;
                } else {
                    candidate = uniformPoint(rng, size, dimension);
                }
                double room = clearance(blobs, candidate, r);
                if (room > bestRoom) {
                    bestRoom = room;
                    center = candidate;
                    avoid = candidateAvoid;
                }
            }
            if (bestRoom == -std::numeric_limits<double>::max()) center = uniformPoint(rng, size, dimension);
        }
        center = tidy(center, dimension);
        r = std::max(0.1, tenth(r));
        int color = pickColor(rng, paletteSize, avoid, lastColor);
        lastColor = color;
        for (Blob& b : blobs)
            b.center = pushBy(b.center, center, r, dimension);
        blobs.push_back({center, r, color});
        ops.push_back(inkOp(Tool::Drop, center, r, color, dimension));
    }

    if (solid) {
        // Ink columns run through the stones like veins through a block.
        int columns = rng.between(1, 5);
        for (int i = 0; i < columns; ++i) {
            Operation op =
                inkOp(Tool::Cylinder, tidy(uniformPoint(rng, size, dimension, 0.1, 0.9), dimension),
                      tenth(side * rng.uniform(0.02, 0.06)),
                      static_cast<int>(rng.below(static_cast<std::uint32_t>(paletteSize))), dimension);
            if (rng.chance(0.7)) {
                op.axis = glm::dvec3(0.0);
                op.axis[rng.below(3)] = 1.0;
            } else {
                op.axis = randomUnit(rng, 3);
            }
            ops.push_back(op);
        }
    }
    if (rng.chance(solid ? 0.15 : 0.3)) {
        // A spatter of sprayed ink on top of the stones.
        int drops = rng.between(5, 25);
        int color = static_cast<int>(rng.below(static_cast<std::uint32_t>(paletteSize)));
        for (int i = 0; i < drops; ++i) {
            if (rng.chance(0.3)) color = static_cast<int>(rng.below(static_cast<std::uint32_t>(paletteSize)));
            ops.push_back(inkOp(Tool::Spray, tidy(uniformPoint(rng, size, dimension), dimension),
                                tenth(side * rng.uniform(0.003, 0.012)) + 0.1, color, dimension));
        }
    }
    return ops;
}

std::vector<Operation> randomStrokes(Pcg32& rng, int dimension, const glm::dvec3& size) {
    if (dimension != 2 && dimension != 3) throw InputError("dimension must be 2 or 3");
    StrokeMaker make{rng, dimension, size, std::max({size.x, size.y, dimension == 3 ? size.z : 0.0}), {}};
    // One family of the craft, then now and then a finishing stroke.
    switch (rng.below(dimension == 3 ? 7 : 6)) {
    case 0: // chevron: comb there and back, offset by half a tine
        make.combPair(50, 140, 40, 180, 8, 30, true);
        if (rng.chance(0.4)) make.wave();
        break;
    case 1: // nonpareil: a coarse get-gel pass both ways, then a fine comb
        make.combPair(150, 260, 60, 160, 15, 40, true);
        make.combPair(18, 45, 15, 45, 4, 10, rng.chance(0.3));
        if (rng.chance(0.35)) make.wave(); // a bouquet-like ripple of the fine comb
        break;
    case 2: // waved
        make.combPair(60, 160, 40, 150, 8, 30, rng.chance(0.5));
        make.wave();
        if (rng.chance(0.3)) make.wave();
        break;
    case 3: { // swirled
        int circles = rng.between(1, 3);
        for (int i = 0; i < circles; ++i)
            make.swirl(Tool::Circle);
        if (rng.chance(0.5)) make.vortex(rng.chance(0.5) ? 1.0 : -1.0);
        break;
    }
    case 4: { // vortices, turning alternately
        int count = rng.between(2, 4);
        double sign = rng.chance(0.5) ? 1.0 : -1.0;
        for (int i = 0; i < count; ++i, sign = -sign)
            make.vortex(sign);
        break;
    }
    case 5: // a stone pattern touched by a few single strokes
        for (int i = rng.between(1, 3); i > 0; --i)
            make.line();
        if (rng.chance(0.5)) make.wave();
        break;
    default: // solid only: the sphere stroke of solid marbling
        make.combPair(60, 160, 40, 150, 8, 30, rng.chance(0.6));
        make.swirl(Tool::Sphere);
        if (rng.chance(0.5)) make.swirl(Tool::Sphere);
        break;
    }
    if (rng.chance(0.3)) {
        if (dimension == 3 && rng.chance(0.4))
            make.swirl(Tool::Sphere);
        else if (rng.chance(0.5))
            make.vortex(rng.chance(0.5) ? 1.0 : -1.0);
        else
            make.wave();
    }
    return make.ops;
}

Genome randomGenome(std::uint64_t seed, int dimension) {
    if (dimension != 2 && dimension != 3)
        throw InputError("dimension must be 2 or 3 (got " + std::to_string(dimension) + ")");
    Genome g;
    g.dimension = dimension;
    g.size = {1000.0, 1000.0, 1000.0};
    Pcg32 paletteRng(seed, PaletteStream);
    g.palette = randomPalette(paletteRng, &g.background);
    Pcg32 initialRng(seed, InitialStream);
    g.initial = randomInitial(initialRng, dimension, g.size, static_cast<int>(g.palette.size()));
    Pcg32 strokeRng(seed, StrokeStream);
    g.operations = randomStrokes(strokeRng, dimension, g.size);
    if (dimension == 2) {
        Pcg32 version2Rng(seed, Version2Stream);
        addVersion2Touches(version2Rng, g);
        Pcg32 version3Rng(seed, Version3Stream);
        addVersion3Touches(version3Rng, g);
    }
    g.meta = Meta{};
    g.meta.name = randomName(seed, g);
    g.meta.seed = seed;
    g.meta.generator = GeneratorVersion;
    return g;
}

} // namespace marbler
