// The tool maps against the conformance data (maps.json, maps-v2.json, probes-*.json,
// probes-v2-*.json), and their two laws on random tools and points: F^-1(F(P)) = P, and
// det(dF/dP) = 1 (area and volume kept).

#include "TestUtil.h"

#include "marbler/Atan.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "marbler/Random.h"
#include "marbler/Tools.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

using namespace marbler;
using Json = nlohmann::ordered_json;

namespace {

Json readJson(const std::string& name) {
    return Json::parse(test::readFile(test::dataDir() / "conformance" / name));
}

glm::dvec3 point(const Json& values) {
    glm::dvec3 p(0.0);
    for (std::size_t i = 0; i < values.size() && i < 3; ++i)
        p[static_cast<int>(i)] = values[i].get<double>();
    return p;
}

/// The map conformance files: version 1's, then version 2's (core, stretch, flow).
struct MapsFile {
    const char* name;
    int version; ///< the format version its cases are read as
};
constexpr MapsFile MapsFiles[] = {{"maps.json", 1}, {"maps-v2.json", 2}, {"maps-v3.json", 3}};

/// The colour probe files of both versions.
constexpr const char* ProbeFiles[] = {"probes-0.json",       "probes-1.json",       "probes-2.json",
                                      "probes-3.json",       "probes-4.json",       "probes-v2-stretch.json",
                                      "probes-v2-core.json", "probes-v2-flow.json", "probes-v3-stylus.json"};

/// A genome of the given dimension that holds one operation, as the loader would see it. The
/// palette is as large as the format allows so that any colour index of the data is valid.
Json wrap(const Json& op, int dimension, int version) {
    Json genome = {{"format", "marbler-genome"}, {"version", version}, {"dimension", dimension}};
    genome["size"] = dimension == 3 ? Json::array({1000, 1000, 1000}) : Json::array({1000, 1000});
    genome["background"] = "#000000";
    genome["palette"] = Json::array();
    for (int i = 0; i < 16; ++i)
        genome["palette"].push_back("#102030");
    const ToolSpec* tool = findTool(op["tool"].get<std::string>());
    bool initial = tool && allowedInInitial(tool->tool, dimension);
    genome["initial"] = initial ? Json::array({op}) : Json::array();
    genome["operations"] = initial ? Json::array() : Json::array({op});
    return genome;
}

/// Whether a case's value of an optional parameter differs from its default: a number, or any
/// number of a list (a stylus's pressure).
bool awayFromDefault(const Json& value, const ParamSpec& param) {
    if (value.is_number()) return value.get<double>() != param.defaultValue;
    if (!value.is_array()) return false;
    for (const Json& v : value)
        if (v.is_number() && v.get<double>() != param.defaultValue) return true;
    return false;
}

PreparedOp loadOp(const Json& op, int dimension, int version) {
    Genome g = parseGenome(wrap(op, dimension, version).dump(), "maps.json");
    std::vector<PreparedOp> ops = prepare(g);
    EXPECT_EQ(ops.size(), 1u);
    return ops.at(0);
}

} // namespace

TEST(Maps, ConformanceCases) {
    for (const MapsFile& file : MapsFiles) {
        Json maps = readJson(file.name);
        const Json& cases = maps["cases"];
        ASSERT_GE(cases.size(), file.version == 1 ? 60u : file.version == 2 ? 14u : 6u) << file.name;
        std::size_t checked = 0;
        for (std::size_t c = 0; c < cases.size(); ++c) {
            const Json& entry = cases[c];
            int dimension = entry["dimension"].get<int>();
            PreparedOp op = loadOp(entry["op"], dimension, file.version);
            const Json& points = entry["points"];
            ASSERT_EQ(points.size(), entry["forward"].size());
            ASSERT_EQ(points.size(), entry["inverse"].size());
            for (std::size_t i = 0; i < points.size(); ++i) {
                glm::dvec3 p = point(points[i]);
                glm::dvec3 f = forwardMap(op, p), expectedF = point(entry["forward"][i]);
                glm::dvec3 b = inverseMap(op, p), expectedB = point(entry["inverse"][i]);
                for (int k = 0; k < dimension; ++k) {
                    EXPECT_NEAR(f[k], expectedF[k], 1e-6)
                        << file.name << " case " << c << " (" << entry["op"].dump() << ") point " << i;
                    EXPECT_NEAR(b[k], expectedB[k], 1e-6)
                        << file.name << " case " << c << " (" << entry["op"].dump() << ") point " << i;
                }
                ++checked;
            }
        }
        EXPECT_GT(checked, file.version == 1 ? 1000u : file.version == 2 ? 300u : 90u) << file.name;
    }
}

TEST(Maps, VersionTwoCasesNeedVersionTwo) {
    // Each case of maps-v2.json uses a version-2 tool or parameter, so a version-1 file that
    // holds it is refused: the cases test what they say they test.
    Json maps = readJson("maps-v2.json");
    for (const Json& entry : maps["cases"]) {
        int dimension = entry["dimension"].get<int>();
        EXPECT_THROW(parseGenome(wrap(entry["op"], dimension, 1).dump(), "maps-v2.json"), GenomeError)
            << entry["op"].dump();
    }
}

TEST(Maps, VersionThreeCasesNeedVersionThree) {
    // A stylus in a version-1 or version-2 file is refused, naming the tool's place.
    Json maps = readJson("maps-v3.json");
    for (const Json& entry : maps["cases"])
        for (int version : {1, 2}) {
            try {
                parseGenome(wrap(entry["op"], 2, version).dump(), "maps-v3.json");
                ADD_FAILURE() << "version " << version << " accepted " << entry["op"].dump();
            } catch (const GenomeError& e) {
                EXPECT_NE(std::string(e.what()).find("operations[0].tool"), std::string::npos) << e.what();
                EXPECT_NE(std::string(e.what()).find("needs format version 3"), std::string::npos)
                    << e.what();
            }
        }
}

TEST(Maps, ConformanceCasesCoverEveryToolOfTheRegistry) {
    // A tool without conformance cases fails here rather than going unchecked: every tool in
    // every dimension it exists in, every choice of its choice parameters (a wave's shapes, a
    // flow's fields), and every optional version-2 parameter (a swirl's core) away from its
    // default, in maps.json and maps-v2.json together.
    Json cases = Json::array();
    for (const MapsFile& file : MapsFiles) {
        const Json maps = readJson(file.name);
        for (const Json& entry : maps["cases"])
            cases.push_back(entry);
    }
    for (int dimension : {2, 3}) {
        for (const ToolSpec& spec : allTools()) {
            if (!spec.available(dimension)) continue;
            const std::string name(spec.name);
            int count = 0;
            for (const Json& entry : cases)
                if (entry["dimension"] == dimension && entry["op"]["tool"] == name) ++count;
            EXPECT_GE(count, 2) << "the maps files have no conformance cases for " << spec.name << " in "
                                << dimension << "D";
            for (const ParamSpec& param : spec.params(dimension)) {
                const std::string key(param.key);
                for (std::string_view choice : param.choices) {
                    bool seen = false;
                    for (const Json& entry : cases)
                        seen = seen || (entry["dimension"] == dimension && entry["op"]["tool"] == name &&
                                        entry["op"].value(key, std::string()) == choice);
                    EXPECT_TRUE(seen) << "the maps files have no " << spec.name << " with " << param.key
                                      << " \"" << choice << "\" in " << dimension << "D";
                }
                if (!param.optional) continue;
                bool seen = false;
                for (const Json& entry : cases)
                    seen = seen || (entry["dimension"] == dimension && entry["op"]["tool"] == name &&
                                    entry["op"].contains(key) && awayFromDefault(entry["op"][key], param));
                EXPECT_TRUE(seen) << "the maps files have no " << spec.name << " with a " << param.key
                                  << " in " << dimension << "D";
            }
        }
    }
}

TEST(Maps, ConformanceProbes) {
    for (const std::string name : ProbeFiles) {
        Json data = readJson(name);
        Genome genome = parseGenome(data["genome"].dump(), name);
        std::vector<PreparedOp> ops = prepare(genome);
        const Json& probes = data["probes"];
        ASSERT_GT(probes.size(), 100u) << name;
        int mismatches = 0;
        for (const Json& probe : probes) {
            glm::dvec3 p(probe[0].get<double>(), probe[1].get<double>(),
                         genome.dimension == 3 ? probe[2].get<double>() : 0.0);
            int expected = probe[static_cast<std::size_t>(genome.dimension)].get<int>();
            int got = traceColor(ops, p);
            if (got != expected && ++mismatches <= 5)
                ADD_FAILURE() << name << ": " << probe.dump() << " gives " << got;
        }
        EXPECT_EQ(mismatches, 0) << name;
    }
}

// traceStep sees what traceColor sees, and names the step that laid it: two drops at one centre
// make a ring, and a point in the ring is the older drop's ink, pushed outward.
TEST(Maps, TraceStepNamesTheInksStep) {
    for (const std::string name : ProbeFiles) {
        Json data = readJson(name);
        Genome genome = parseGenome(data["genome"].dump(), name);
        std::vector<PreparedOp> ops = prepare(genome);
        for (const Json& probe : data["probes"]) {
            glm::dvec3 p(probe[0].get<double>(), probe[1].get<double>(),
                         genome.dimension == 3 ? probe[2].get<double>() : 0.0);
            TracedInk ink = traceStep(ops, p);
            ASSERT_EQ(ink.color, traceColor(ops, p)) << name;
            if (ink.color < 0) {
                EXPECT_EQ(ink.step, -1);
            } else {
                ASSERT_GE(ink.step, 0);
                ASSERT_LT(std::size_t(ink.step), ops.size());
                EXPECT_EQ(ops[std::size_t(ink.step)].color, ink.color);
            }
        }
    }
    Genome rings;
    rings.palette = {{255, 0, 0}, {0, 0, 255}};
    Operation older = defaultOperation(Tool::Drop, 2, {500, 500, 0});
    older.radius = 100;
    older.color = 0;
    Operation newer = older;
    newer.color = 1;
    rings.initial = {older, newer};
    std::vector<PreparedOp> ops = prepare(rings);
    EXPECT_EQ(traceStep(ops, {500, 500, 0}).step, 1);
    EXPECT_EQ(traceStep(ops, {500, 500, 0}).color, 1);
    TracedInk ring = traceStep(ops, {500 + 120, 500, 0}); // between 100 and 100 sqrt 2
    EXPECT_EQ(ring.step, 0);
    EXPECT_EQ(ring.color, 0);
    EXPECT_EQ(traceStep(ops, {900, 900, 0}).step, -1);
}

namespace {

glm::dvec3 randomUnit(Pcg32& rng) {
    for (;;) {
        glm::dvec3 v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        double len = glm::length(v);
        if (len > 0.2 && len <= 1.0) return v / len;
    }
}

/// A random operation of `tool`, every parameter from its table, then normalised by a trip
/// through the loader.
Operation randomOperation(Pcg32& rng, Tool tool, int dimension) {
    Operation op = defaultOperation(tool, dimension, {500.0, 500.0, 500.0});
    op.shape = rng.chance(0.5) ? WaveShape::Ripple : WaveShape::Eggcrate;
    for (const ParamSpec& spec : toolSpec(tool).params(dimension)) {
        for (int i = 0; i < componentCount(spec, op, dimension); ++i) {
            double value = 0.0;
            switch (spec.field) {
            case ParamField::Center:
                value = rng.uniform(0, 1000);
                break;
            case ParamField::Angle:
                value = rng.uniform(0, 360);
                break;
            case ParamField::Radius:
                value = rng.uniform(20, 200);
                break;
            case ParamField::Alpha:
                value = rng.uniform(-100, 100);
                break;
            case ParamField::Lambda:
                value = rng.uniform(5, 60);
                break;
            case ParamField::Spacing:
                value = rng.uniform(30, 150);
                break;
            case ParamField::Amplitude:
                value = rng.uniform(-40, 40);
                break;
            case ParamField::Wavelength:
                value = rng.uniform(100, 500);
                break;
            case ParamField::Phase:
                value = rng.uniform(0, 360);
                break;
            case ParamField::Core:
                value = rng.chance(0.5) ? 0.0 : rng.uniform(1, 80);
                break;
            case ParamField::Teeth:
                value = -600.0 + 1800.0 * (i + rng.uniform(0.1, 0.9)) / componentCount(spec, op, dimension);
                break;
            case ParamField::Shift:
                value = rng.uniform(-100, 100);
                break;
            case ParamField::Power:
                value = rng.uniform(0.25, 2.5);
                break;
            case ParamField::Size:
                value = rng.uniform(150, 600);
                break;
            case ParamField::Speed:
                value = rng.uniform(-60, 60);
                break;
            case ParamField::Time:
                value = rng.uniform(0.5, 5);
                break;
            default:
                continue; // directions, shape, colour, steps: below or as defaulted
            }
            setComponent(spec, op, i, value);
        }
    }
    op.field = rng.chance(0.5) ? FlowField::Cells : FlowField::Cavity;
    op.steps = minimumFlowSteps(op) + static_cast<int>(rng.uniform(0, 20));
    op.axis = randomUnit(rng) * rng.uniform(0.5, 3.0);
    op.direction = randomUnit(rng) * rng.uniform(0.5, 3.0);
    do {
        op.normal = randomUnit(rng);
    } while (glm::length(glm::cross(op.normal, glm::normalize(op.direction))) < 0.1);

    if (tool == Tool::Stylus) {
        // A path of 2 to 6 points, across the middle of the design, and a rake half the time.
        int points = 2 + static_cast<int>(rng.uniform(0, 5));
        op.path.clear();
        for (int i = 0; i < points; ++i)
            op.path.push_back({rng.uniform(200, 800), rng.uniform(200, 800)});
        op.alpha = rng.uniform(-60, 60);
        op.lambda = rng.uniform(2, 20);
        op.reach = rng.uniform(20, 80);
        op.tines = rng.chance(0.5) ? 1 : 2 + static_cast<int>(rng.uniform(0, 4));
        op.spacing = rng.uniform(10, 40);
        op.pressure.clear();
        if (rng.chance(0.5))
            for (int i = 0; i < points; ++i)
                op.pressure.push_back(rng.uniform(0, 1));
        op.steps = minimumStylusSteps(op) + static_cast<int>(rng.uniform(0, 20));
    }

    Genome g;
    g.dimension = dimension;
    g.palette = {Color{}};
    (allowedInInitial(tool, dimension) ? g.initial : g.operations).push_back(op);
    Genome loaded = parseGenome(serializeGenome(g), "random");
    return allowedInInitial(tool, dimension) ? loaded.initial[0] : loaded.operations[0];
}

/// Whether the map is smooth enough around P for central differences: away from the kinks of
/// d (tines, comb midpoints, circle radii) and from the singular centres.
bool smoothAt(const PreparedOp& op, const glm::dvec3& p) {
    constexpr double Margin = 1e-2;
    glm::dvec3 rel = p - op.c;
    switch (op.tool) {
    case Tool::Drop:
        return glm::length(rel) > 0.5 * op.r;
    case Tool::Cylinder:
        return glm::length(rel - glm::dot(rel, op.a) * op.a) > 0.5 * op.r;
    case Tool::Line:
        return std::abs(glm::dot(rel, op.n)) > Margin;
    case Tool::Comb: {
        double t = glm::dot(rel, op.n), half = 0.5 * op.spacing;
        double m = t - half * std::floor(t / half);
        return m > Margin && half - m > Margin;
    }
    case Tool::Circle: {
        double rho = op.dimension == 3 ? glm::length(rel - glm::dot(rel, op.a) * op.a) : glm::length(rel);
        return rho > 20.0 && std::abs(rho - op.r) > Margin;
    }
    case Tool::Sphere:
        return glm::length(rel) > 20.0 && std::abs(glm::length(rel) - op.r) > Margin;
    case Tool::Vortex:
        return glm::length(rel) > 20.0;
    case Tool::Stretch: {
        // Away from the teeth, where |sin|^p with p < 1 has no derivative.
        double u = glm::dot(rel, op.n);
        for (double t : op.teeth)
            if (std::abs(u - t) < 1.0) return false;
        return true;
    }
    case Tool::Flow: {
        // The cells' field is smooth everywhere; the cavity's velocity is continuous but its
        // gradient jumps on the box's edges (the field stops there), so stay a unit off them.
        if (op.field == FlowField::Cells) return true;
        double x = glm::dot(rel, op.m), y = glm::dot(rel, op.n);
        return std::min({std::abs(x), std::abs(x - op.size[0]), std::abs(y), std::abs(y - op.size[1])}) > 1.0;
    }
    case Tool::Stylus: {
        // Its window's second derivative jumps at |u| = 1 in every step, so the map has kinks
        // along the lines where a window's edge passed: where the one-sided differences
        // disagree, central ones would average two Jacobians.
        constexpr double H = 1e-4;
        for (const glm::dvec3 step : {glm::dvec3(H, 0, 0), glm::dvec3(0, H, 0)}) {
            glm::dvec3 f = forwardMap(op, p);
            glm::dvec3 ahead = (forwardMap(op, p + step) - f) / H,
                       behind = (f - forwardMap(op, p - step)) / H;
            if (glm::length(ahead - behind) > 1e-3) return false;
        }
        return true;
    }
    case Tool::Spray:
    case Tool::Wave:
        return true; // smooth everywhere
    }
    return true;
}

/// How far F^-1(F(P)) may lie from P. The closed-form maps undo themselves to rounding:
/// 1e-9 of |P|. A flow undoes itself only to its solver's tolerance: each of its n forward and
/// n backward implicit midpoint steps stops its fixed-point iteration when an iterate moves
/// less than tol = 1e-12 (Lx + Ly), and the iteration contracts by at least half (the steps
/// rule), so each step lands within tol of its exact solution; later steps carry that error
/// on, stretched by at most the flow's shear, for which a factor 10 is allowed: 2 n tol 10.
double roundTripTolerance(const PreparedOp& op, const glm::dvec3& p) {
    double rounding = 1e-9 * std::max(1.0, glm::length(p));
    // A stylus: within 1e-9 of the design's size (1000), as the spec's tolerance allows.
    if (op.tool == Tool::Stylus) return 1e-9 * 1000.0;
    return op.tool == Tool::Flow ? rounding + 20.0 * op.steps * op.tolerance : rounding;
}

double jacobianDeterminant(const PreparedOp& op, const glm::dvec3& p, int dimension) {
    // A flow's map is its solver's iterate, a smooth function of P as long as the number of
    // fixed-point iterations stays the same; where it changes, the iterate jumps by less than
    // half the tolerance (about 1e-9 units), which this step turns into less than 1e-6 of
    // the determinant. A larger step would not help: a strong flow's truncation error is
    // already 1e-6 at a step of 1e-2.
    constexpr double H = 1e-4;
    glm::dmat3 j(1.0);
    for (int k = 0; k < dimension; ++k) {
        glm::dvec3 step(0.0);
        step[k] = H;
        j[k] = (forwardMap(op, p + step) - forwardMap(op, p - step)) / (2.0 * H);
    }
    if (dimension == 2) return j[0][0] * j[1][1] - j[1][0] * j[0][1];
    return glm::determinant(j);
}

} // namespace

TEST(Maps, InverseUndoesForwardAndKeepsMeasure) {
    Pcg32 rng(20240601);
    // Points the version-2 maps really moved, by kind: a swirl with a core, a stretch, a flow
    // of cells and a flow in a cavity (most points outside a cavity's box stay where they are).
    int moved[4] = {0, 0, 0, 0};
    const char* movedWhat[4] = {"swirls with a core", "stretches", "flows of cells", "flows in a cavity"};
    int movedStylus = 0;
    double worstFlow = 0.0; // the largest flow round trip error, in units of its tolerance
    for (int dimension : {2, 3}) {
        for (const ToolSpec& spec : allTools()) {
            if (!spec.available(dimension)) continue;
            int checked = 0;
            for (int trial = 0; trial < 40; ++trial) {
                PreparedOp op = prepare(randomOperation(rng, spec.tool, dimension), dimension);
                int kind = op.core2 > 0.0             ? 0
                           : op.tool == Tool::Stretch ? 1
                           : op.tool == Tool::Flow    ? (op.field == FlowField::Cells ? 2 : 3)
                                                      : -1;
                for (int i = 0; i < 50; ++i) {
                    glm::dvec3 p(rng.uniform(-200, 1200), rng.uniform(-200, 1200),
                                 dimension == 3 ? rng.uniform(-200, 1200) : 0.0);
                    // Half the points of a cavity in its box, where the flow moves anything.
                    if (kind == 3 && rng.chance(0.5))
                        p = op.c + rng.uniform(0, op.size[0]) * op.m + rng.uniform(0, op.size[1]) * op.n;
                    // Most points of a stylus near its path, where it moves them.
                    if (op.tool == Tool::Stylus && rng.chance(0.8)) {
                        std::size_t at = static_cast<std::size_t>(rng.uniform(0, double(op.path.size() - 1)));
                        glm::dvec2 on = op.path[at] + rng.uniform(0, 1) * (op.path[at + 1] - op.path[at]);
                        p = {on.x + rng.uniform(-30, 30), on.y + rng.uniform(-30, 30), 0.0};
                    }
                    if (!smoothAt(op, p)) continue;
                    glm::dvec3 q = forwardMap(op, p);
                    glm::dvec3 back = inverseMap(op, q);
                    double tolerance = roundTripTolerance(op, p);
                    ASSERT_LE(glm::length(back - p), tolerance) << spec.name << " " << dimension << "D at ("
                                                                << p.x << ", " << p.y << ", " << p.z << ")";
                    if (op.tool == Tool::Flow)
                        worstFlow = std::max(worstFlow, glm::length(back - p) / tolerance);
                    double det = jacobianDeterminant(op, p, dimension);
                    ASSERT_NEAR(det, 1.0, 1e-6) << spec.name << " " << dimension << "D at (" << p.x << ", "
                                                << p.y << ", " << p.z << ")";
                    ++checked;
                    if (kind >= 0 && glm::length(q - p) > 1e-3) ++moved[kind];
                    if (op.tool == Tool::Stylus && glm::length(q - p) > 1e-3) ++movedStylus;
                }
            }
            EXPECT_GT(checked, 1000) << spec.name << " " << dimension << "D";
            if (spec.tool == Tool::Stylus) {
                EXPECT_GT(movedStylus, 500);
            }
        }
    }
    for (int kind = 0; kind < 4; ++kind)
        EXPECT_GT(moved[kind], 300) << movedWhat[kind];
    std::printf("flow round trips: worst error %.3g of the tolerance\n", worstFlow);
}

TEST(Maps, ForwardPushesOutOfTheInk) {
    // What a drop or column moves ends up outside its ink, so the inverse is defined there.
    Pcg32 rng(7);
    for (int dimension : {2, 3}) {
        for (const ToolSpec& spec : allTools()) {
            // Every ink-laying tool that moves ink: drop and cylinder.
            if (!spec.laysInk || !spec.movesInk || !spec.available(dimension)) continue;
            const Tool tool = spec.tool;
            for (int trial = 0; trial < 20; ++trial) {
                PreparedOp op = prepare(randomOperation(rng, tool, dimension), dimension);
                for (int i = 0; i < 100; ++i) {
                    glm::dvec3 p = op.c + randomUnit(rng) * rng.uniform(1e-3, 400.0);
                    if (dimension == 2) p.z = 0.0;
                    if (p == op.c) continue;
                    EXPECT_FALSE(insideInk(op, forwardMap(op, p)));
                }
            }
        }
    }
}

namespace {

/// How many doubles lie between a and b (both finite, of one sign).
std::uint64_t ulpsApart(double a, double b) {
    const auto ia = std::bit_cast<std::int64_t>(a), ib = std::bit_cast<std::int64_t>(b);
    return static_cast<std::uint64_t>(ia > ib ? ia - ib : ib - ia);
}

} // namespace

TEST(Atan, AgreesWithTheLibraryWithinFourUlps) {
    // The stylus's arctangent (Atan.h) replaced the C library's in the reference and the kernel:
    // a few ulps from the correctly rounded value everywhere, its argument reduction (beyond 1)
    // included, so the maps move by far less than the conformance's 1e-6.
    Pcg32 rng(24);
    std::uint64_t worst = 0;
    double worstAt = 0.0;
    const auto check = [&](double x) {
        const double mine = vectorAtan(x), library = std::atan(x);
        ASSERT_EQ(std::signbit(mine), std::signbit(library)) << x;
        const std::uint64_t apart = ulpsApart(mine, library);
        if (apart > worst) {
            worst = apart;
            worstAt = x;
        }
    };
    for (int i = 0; i < 400000; ++i) {
        // Log-uniform over 1e-12 .. 1e12 (the whole polynomial's range and the reduced one's),
        // and uniform near 1 where the reduction changes over.
        const double x = std::pow(10.0, rng.uniform(-12.0, 12.0));
        check(rng.chance(0.5) ? x : -x);
        check(rng.uniform(-2.0, 2.0));
    }
    for (double x : {1.0, -1.0, std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0), 1e-300, 1e300, 5e-324})
        check(x);
    EXPECT_LE(worst, 4u) << "at " << worstAt;
    std::printf("vectorAtan: worst %llu ulps (at %.17g)\n", static_cast<unsigned long long>(worst), worstAt);
}

TEST(Atan, KeepsTheLibrarysSpecialValues) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(std::bit_cast<std::uint64_t>(vectorAtan(0.0)), std::bit_cast<std::uint64_t>(0.0));
    EXPECT_TRUE(std::signbit(vectorAtan(-0.0)));
    EXPECT_EQ(vectorAtan(-0.0), 0.0);
    EXPECT_DOUBLE_EQ(vectorAtan(inf), std::atan(inf));
    EXPECT_DOUBLE_EQ(vectorAtan(-inf), std::atan(-inf));
    EXPECT_TRUE(std::isnan(vectorAtan(std::numeric_limits<double>::quiet_NaN())));
    // Odd, bit for bit.
    Pcg32 rng(3);
    for (int i = 0; i < 1000; ++i) {
        const double x = rng.uniform(-50.0, 50.0);
        EXPECT_EQ(vectorAtan(-x), -vectorAtan(x)) << x;
    }
}

TEST(Maps, TheStylusSkipsOnlyTheStepsThatLeaveAPointWhereItIs) {
    // forwardMap and inverseMap skip the steps whose stylus is out of reach of the point along
    // the track (genome-format.md allows it: the result is the same). Against every step run,
    // bit for bit, on random strokes and rakes, at points on, near and far from the path.
    Pcg32 rng(20261204);
    int skippedSome = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const PreparedOp op = prepare(randomOperation(rng, Tool::Stylus, 2), 2);
        for (int k = 0; k < 20; ++k) {
            glm::dvec2 p(rng.uniform(-200, 1200), rng.uniform(-200, 1200));
            if (k % 2 == 0) {
                std::size_t at = static_cast<std::size_t>(rng.uniform(0, double(op.path.size() - 1)));
                p = op.path[at] + rng.uniform(0, 1) * (op.path[at + 1] - op.path[at]) +
                    glm::dvec2(rng.uniform(-40, 40), rng.uniform(-40, 40));
            }
            if (k % 5 == 0) {
                // Exactly the reach ahead of a station along its track: the edge of the window.
                const std::size_t i = static_cast<std::size_t>(rng.uniform(0, double(op.steps)));
                const glm::dvec2 t = op.along[op.stations[i].segment];
                p = op.stations[i].s + (k % 10 == 0 ? op.reach : -op.reach) * t +
                    glm::dvec2(-t.y, t.x) * rng.uniform(-30, 30);
            }
            glm::dvec2 forward = p, backward = p;
            int moved = 0;
            for (int i = 0; i < op.steps; ++i) {
                const glm::dvec2 next = stylusStep(op, forward, i, +1.0);
                moved += next != forward;
                forward = next;
            }
            for (int i = op.steps; i-- > 0;)
                backward = stylusStep(op, backward, i, -1.0);
            const glm::dvec3 f = forwardMap(op, {p.x, p.y, 0.0}), b = inverseMap(op, {p.x, p.y, 0.0});
            ASSERT_EQ(std::bit_cast<std::uint64_t>(f.x), std::bit_cast<std::uint64_t>(forward.x))
                << trial << " " << k;
            ASSERT_EQ(std::bit_cast<std::uint64_t>(f.y), std::bit_cast<std::uint64_t>(forward.y))
                << trial << " " << k;
            ASSERT_EQ(std::bit_cast<std::uint64_t>(b.x), std::bit_cast<std::uint64_t>(backward.x))
                << trial << " " << k;
            ASSERT_EQ(std::bit_cast<std::uint64_t>(b.y), std::bit_cast<std::uint64_t>(backward.y))
                << trial << " " << k;
            skippedSome += moved < op.steps;
        }
    }
    EXPECT_GT(skippedSome, 1000) << "most points lie out of reach of most steps";
}
