// The genetic operators: what each keeps and exchanges, locks, reproducibility and lineage.

#include "marbler/Operators.h"
#include "marbler/Error.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "marbler/Random.h"

#include "TestUtil.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <set>

namespace marbler {
namespace {

std::vector<Tool> toolsOf(const std::vector<Operation>& ops) {
    std::vector<Tool> tools;
    for (const Operation& op : ops)
        tools.push_back(op.tool);
    return tools;
}

BreedRequest request(GeneticOperator op, std::vector<Genome> parents, std::uint64_t seed, int count = 8,
                     double strength = 0.5) {
    BreedRequest r;
    r.op = op;
    r.parents = std::move(parents);
    r.seed = seed;
    r.count = count;
    r.strength = strength;
    return r;
}

/// How far the strokes of b lie from those of a, every component measured in its own
/// mutation scale (so lengths, angles and directions count alike).
double scaledDistance(const Genome& a, const Genome& b) {
    double sum = 0.0;
    int n = 0;
    const double side = 1000.0;
    for (std::size_t k = 0; k < a.operations.size(); ++k) {
        const Operation& x = a.operations[k];
        const Operation& y = b.operations[k];
        for (const ParamSpec& spec : toolSpec(x.tool).params(a.dimension)) {
            if (spec.mutationScale == 0.0) continue;
            double unit = spec.kind == ParamKind::Angle || spec.kind == ParamKind::Phase ? spec.mutationScale
                          : spec.kind == ParamKind::Direction                            ? spec.mutationScale
                                                              : spec.mutationScale * side;
            for (int i = 0; i < componentCount(spec, x, a.dimension); ++i) {
                sum += std::abs(getComponent(spec, y, i) - getComponent(spec, x, i)) / unit;
                ++n;
            }
        }
    }
    return n ? sum / n : 0.0;
}

class Operators : public ::testing::TestWithParam<int> {
protected:
    int dimension() const { return GetParam(); }
    Genome parent(std::uint64_t seed) const { return randomGenome(seed, dimension()); }
};

TEST_P(Operators, SwapExchangesExactlyInitialStateAndOperations) {
    Genome a = parent(1), b = parent(2);
    std::vector<Genome> children = breed(request(GeneticOperator::Swap, {a, b}, 7, 5));
    ASSERT_EQ(children.size(), 5u);
    for (std::size_t i = 0; i < children.size(); ++i) {
        const Genome& home = i % 2 == 0 ? a : b;
        const Genome& other = i % 2 == 0 ? b : a;
        const Genome& child = children[i];
        EXPECT_EQ(child.initial, home.initial) << i;
        EXPECT_EQ(child.palette, home.palette) << i;
        EXPECT_EQ(child.background, home.background) << i;
        EXPECT_EQ(child.size, home.size) << i;
        if (i < 2) {
            // The two swaps themselves.
            EXPECT_EQ(child.operations, other.operations) << i;
            EXPECT_FALSE(child.meta.toJson()["lineage"].contains("variation")) << i;
        } else {
            // Then gentle variations of them, in turn: the other's tools, moved a little.
            EXPECT_EQ(toolsOf(child.operations), toolsOf(other.operations)) << i;
            EXPECT_NE(child.operations, other.operations) << i;
            const auto variation = child.meta.toJson()["lineage"]["variation"];
            ASSERT_TRUE(variation.is_object()) << i;
            EXPECT_EQ(variation["of"], genomeId(children[i % 2])) << i;
            EXPECT_GT(variation["strength"].get<double>(), 0.0) << i;
            EXPECT_LE(variation["strength"].get<double>(), 0.5) << i;
        }
    }
}

/// Every child is worth a cell: for every operator and count, the children differ from each
/// other and from the parents (meta aside), whatever the parents are like.
TEST_P(Operators, AlteringABathWithoutStrokesStillChangesIt) {
    // A swap can leave a child with no strokes; varying a repeat of it must still give a new
    // design, or two cells of the grid show the same one.
    Genome bath = parent(17);
    bath.operations.clear();
    ASSERT_FALSE(bath.initial.empty());
    Pcg32 rng(5);
    const Genome altered = alterGenome(bath, 0.2, rng);
    EXPECT_NE(genomeId(altered), genomeId(bath));
    EXPECT_TRUE(altered.operations.empty());
    validateGenome(altered, "altered");
}

TEST_P(Operators, NoTwoChildrenAreEqual) {
    Genome a = parent(80), b = parent(81), c = parent(82);
    Genome few = parent(83); // few strokes: crossovers repeat easily
    few.operations.resize(std::min<std::size_t>(few.operations.size(), 1));
    Genome sameStrokes = parent(84); // swapping with `a` gives `a` back
    sameStrokes.operations = a.operations;
    struct Case {
        GeneticOperator op;
        std::vector<Genome> parents;
        double strength;
        const char* what;
    };
    const std::vector<Case> cases{
        {GeneticOperator::Alter, {a}, 0.5, "alter"},
        {GeneticOperator::Alter, {a}, 0.0, "alter at strength 0"},
        {GeneticOperator::Alter, {a}, 0.01, "alter at strength 0.01"},
        {GeneticOperator::Recombine, {a, b}, 0.5, "recombine of two"},
        {GeneticOperator::Recombine, {a, b, c}, 0.5, "recombine of three"},
        {GeneticOperator::Recombine, {few, few}, 0.5, "recombine of equal parents"},
        {GeneticOperator::Recombine, {few, sameStrokes}, 0.5, "recombine of few strokes"},
        {GeneticOperator::Swap, {a, b}, 0.5, "swap"},
        {GeneticOperator::Swap, {a, sameStrokes}, 0.5, "swap of the same strokes"},
        {GeneticOperator::Reinit, {a}, 0.5, "reinit"},
    };
    for (const Case& k : cases)
        for (std::uint64_t seed : {1ull, 2ull, 3ull})
            for (int count = 1; count <= 9; count += test::fullOrSanitized(1, 4)) {
                SCOPED_TRACE(std::string(k.what) + ", seed " + std::to_string(seed) + ", count " +
                             std::to_string(count));
                std::vector<Genome> children = breed(request(k.op, k.parents, seed, count, k.strength));
                ASSERT_EQ(children.size(), std::size_t(count));
                std::set<std::string> ids;
                for (const Genome& p : k.parents)
                    ids.insert(genomeId(p));
                const std::size_t parentIds = ids.size();
                for (const Genome& child : children) {
                    EXPECT_TRUE(ids.insert(genomeId(child)).second)
                        << "a child repeats a design of its generation";
                    EXPECT_NO_THROW(validateGenome(child, "child"));
                }
                EXPECT_EQ(ids.size(), parentIds + children.size());
            }
}

TEST_P(Operators, ChildrenCarryTheGenerationAndNumbersTheyAreGiven) {
    Genome a = parent(90);
    BreedRequest r = request(GeneticOperator::Alter, {a}, 3, 3);
    r.generation = 7;
    r.childNumbers = {2, 5, 9};
    std::vector<Genome> children = breed(r);
    for (std::size_t i = 0; i < children.size(); ++i) {
        EXPECT_EQ(children[i].meta.toJson()["lineage"]["generation"], 7);
        EXPECT_EQ(children[i].meta.toJson()["lineage"]["child"], int(i) + 1);
        const std::string name = children[i].meta.toJson()["name"];
        EXPECT_NE(name.find(" (g7 #" + std::to_string(r.childNumbers[i]) + ")"), std::string::npos) << name;
    }
    r.childNumbers = {1};
    EXPECT_THROW(breed(r), InputError);
    r.childNumbers.clear();
    r.generation = 0;
    EXPECT_THROW(breed(r), InputError);
}

TEST_P(Operators, SwapClampsColourIndicesToTheHomePalette) {
    Genome a = parent(1), b = parent(2);
    a.palette.resize(2);
    for (Operation& op : a.initial)
        op.color %= 2;
    Operation drop = defaultOperation(Tool::Drop, dimension(), {500, 500, 500});
    drop.color = static_cast<int>(b.palette.size()) - 1;
    b.operations.push_back(drop);
    std::vector<Genome> children = breed(request(GeneticOperator::Swap, {a, b}, 1, 2));
    EXPECT_EQ(children[0].operations.back().color, 1);
    EXPECT_NO_THROW(validateGenome(children[0], "child"));
}

TEST_P(Operators, ReinitKeepsOperationsAndDrawsANewInitialState) {
    Genome p = parent(3);
    std::vector<Genome> children = breed(request(GeneticOperator::Reinit, {p}, 11, 4));
    std::set<std::string> initials;
    for (const Genome& child : children) {
        EXPECT_EQ(child.operations, p.operations);
        EXPECT_EQ(child.palette, p.palette);
        EXPECT_NE(child.initial, p.initial);
        for (const Operation& op : child.initial)
            EXPECT_LT(op.color, static_cast<int>(p.palette.size()));
        initials.insert(serializeGenome(child));
    }
    EXPECT_EQ(initials.size(), children.size()); // each child its own pattern
}

TEST_P(Operators, AlterKeepsTheToolSequenceAndStaysValid) {
    for (std::uint64_t seed = 0; seed < 25; ++seed) {
        Genome p = parent(seed);
        for (double strength : {0.1, 0.5, 1.0}) {
            for (const Genome& child : breed(request(GeneticOperator::Alter, {p}, seed, 4, strength))) {
                EXPECT_EQ(toolsOf(child.operations), toolsOf(p.operations));
                EXPECT_EQ(child.initial, p.initial);
                EXPECT_EQ(child.palette, p.palette);
                EXPECT_NE(child.operations, p.operations);
                ASSERT_NO_THROW(validateGenome(child, "child"));
                if (dimension() == 3)
                    for (const Operation& op : child.operations) {
                        if (op.tool != Tool::Comb && op.tool != Tool::Line && op.tool != Tool::Wave) continue;
                        EXPECT_NEAR(glm::length(op.direction), 1.0, 1e-9);
                        EXPECT_NEAR(glm::length(op.normal), 1.0, 1e-9);
                        EXPECT_NEAR(glm::dot(op.direction, op.normal), 0.0, 1e-9);
                    }
            }
        }
    }
}

TEST_P(Operators, AlterKeepsEveryParameterOfEveryToolInItsTablesRange) {
    // Every tool of the registry as a stroke, twice (at its defaults, and with every bounded
    // number at its bound's edge), altered generation after generation at full strength:
    // every component of every parameter stays finite and within its table's range.
    Genome g;
    g.dimension = dimension();
    g.palette = {Color{}, Color{10, 20, 30}};
    for (const ToolSpec& spec : allTools()) {
        if (!spec.available(dimension())) continue;
        Operation op = defaultOperation(spec.tool, dimension(), {500, 500, 500});
        g.operations.push_back(op);
        for (const ParamSpec& param : spec.params(dimension())) {
            if (param.kind == ParamKind::Choice || param.kind == ParamKind::Color) continue;
            for (int i = 0; i < componentCount(param, op, dimension()); ++i) {
                if (std::isfinite(param.range.min))
                    setComponent(param, op, i, param.range.min + 1e-3);
                else if (std::isfinite(param.range.max))
                    setComponent(param, op, i, param.range.max);
            }
        }
        // A flow's steps have a bound of their own, which depends on the other numbers: at its
        // edge too, the fewest steps they allow.
        if (spec.tool == Tool::Flow) op.steps = minimumFlowSteps(op);
        // A stylus at its smallest sharpness and reach would need more steps than the format
        // allows: those two keep their starting values, the steps the fewest allowed.
        if (spec.tool == Tool::Stylus) {
            const Operation start = defaultOperation(spec.tool, dimension(), {500, 500, 500});
            op.lambda = start.lambda;
            op.reach = start.reach;
            op.steps = minimumStylusSteps(op);
        }
        g.operations.push_back(op);
    }
    ASSERT_NO_THROW(validateGenome(g, "start"));
    Pcg32 rng(99);
    for (int generation = 0; generation < 200; ++generation) {
        g = alterGenome(g, 1.0, rng);
        for (const Operation& op : g.operations) {
            for (const ParamSpec& param : toolSpec(op.tool).params(dimension())) {
                const std::string what = std::string(toolSpec(op.tool).name) + "." + std::string(param.key);
                if (param.kind == ParamKind::Choice) {
                    EXPECT_LT(getComponent(param, op, 0), double(param.choices.size())) << what;
                    continue;
                }
                for (int i = 0; i < componentCount(param, op, dimension()); ++i) {
                    double v = getComponent(param, op, i);
                    ASSERT_TRUE(std::isfinite(v)) << what << " generation " << generation;
                    ASSERT_TRUE(param.range.contains(v))
                        << what << "[" << i << "] = " << v << " " << param.range.describe() << ", generation "
                        << generation;
                }
            }
        }
        ASSERT_NO_THROW(validateGenome(g, "child")) << "generation " << generation;
    }
    // The version-2 numbers moved (none is stuck at its start), and a core at its edge stays a
    // core: alteration never switches a feature on or off.
    for (const Operation& op : g.operations) {
        if (op.tool == Tool::Stretch) {
            EXPECT_EQ(op.teeth.size(), 11u);
        }
        if (op.tool == Tool::Flow) {
            EXPECT_GE(op.steps, minimumFlowSteps(op));
            EXPECT_NE(op.time, 2.0);
            EXPECT_NE(op.time, 1e-3);
        }
    }
}

/// A 2D design that uses every version-2 feature: a stretch, a flow of each field, a cored
/// vortex and a bleed.
Genome versionTwoDesign(std::uint64_t seed) {
    Genome g = randomGenome(seed, 2);
    std::erase_if(g.operations, [](const Operation& op) { return op.tool == Tool::Stylus; }); // version 3
    Operation stretch = defaultOperation(Tool::Stretch, 2, {500, 500, 0});
    stretch.shift = -35.0;
    stretch.power = 1.5;
    Operation cells = defaultOperation(Tool::Flow, 2, {500, 500, 0});
    Operation cavity = defaultOperation(Tool::Flow, 2, {500, 500, 0});
    cavity.field = FlowField::Cavity;
    cavity.center = {150, 200, 0};
    cavity.extent = {600, 450};
    cavity.speed = -50.0;
    cavity.steps = minimumFlowSteps(cavity);
    Operation vortex = defaultOperation(Tool::Vortex, 2, {400, 600, 0});
    vortex.core = 25.0;
    g.operations.insert(g.operations.begin(), {stretch, cells, cavity, vortex});
    g.bleed = 1.5;
    return g;
}

/// The same design with no version-2 feature.
Genome versionOneDesign(std::uint64_t seed) {
    Genome g = randomGenome(seed, 2);
    std::erase_if(g.operations, [](const Operation& op) { return toolSpec(op.tool).version > 1; });
    for (Operation& op : g.operations)
        op.core = 0.0;
    g.operations.push_back(defaultOperation(Tool::Vortex, 2, {400, 600, 0}));
    g.bleed = 0.0;
    return g;
}

TEST(OperatorsVersionTwo, AlteredDesignsStayValidVersionTwoAndReproducible) {
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
        const Genome p = versionTwoDesign(seed);
        ASSERT_NO_THROW(validateGenome(p, "parent"));
        for (double strength : {0.1, 0.5, 1.0}) {
            const std::vector<Genome> children =
                breed(request(GeneticOperator::Alter, {p}, seed, 6, strength));
            const std::vector<Genome> again = breed(request(GeneticOperator::Alter, {p}, seed, 6, strength));
            const std::vector<Genome> other =
                breed(request(GeneticOperator::Alter, {p}, seed + 100, 6, strength));
            for (std::size_t i = 0; i < children.size(); ++i) {
                const Genome& child = children[i];
                SCOPED_TRACE("seed " + std::to_string(seed) + " strength " + std::to_string(strength) +
                             " child " + std::to_string(i));
                ASSERT_NO_THROW(validateGenome(child, "child"));
                EXPECT_EQ(requiredVersion(child), 2);
                EXPECT_EQ(child.bleed, p.bleed);
                EXPECT_EQ(toolsOf(child.operations), toolsOf(p.operations));
                const Operation& stretch = child.operations[0];
                EXPECT_EQ(stretch.teeth.size(), p.operations[0].teeth.size());
                EXPECT_NE(stretch.teeth, p.operations[0].teeth);
                EXPECT_NE(stretch.shift, p.operations[0].shift);
                for (std::size_t k : {1u, 2u}) {
                    const Operation& flow = child.operations[k];
                    EXPECT_EQ(flow.field, p.operations[k].field);
                    EXPECT_GE(flow.steps, minimumFlowSteps(flow));
                    EXPECT_GE(flow.steps, p.operations[k].steps);
                }
                EXPECT_GT(child.operations[3].core, 0.0);
                // Saved and loaded, the child is the same design.
                EXPECT_EQ(parseGenome(serializeGenome(child), "child"), child);
                // The same seed gives the same child; another seed another one.
                EXPECT_EQ(serializeGenome(again[i]), serializeGenome(child));
                EXPECT_NE(genomeId(other[i]), genomeId(child));
            }
        }
    }
}

TEST(OperatorsVersionTwo, AlteredVersionOneDesignsStayVersionOne) {
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
        const Genome p = versionOneDesign(seed);
        ASSERT_EQ(requiredVersion(p), 1);
        for (const Genome& child : breed(request(GeneticOperator::Alter, {p}, seed, 6, 1.0))) {
            EXPECT_EQ(requiredVersion(child), 1) << "seed " << seed;
            EXPECT_EQ(child.bleed, 0.0);
            for (const Operation& op : child.operations)
                EXPECT_EQ(op.core, 0.0);
        }
    }
    // A solid design too: its cores stay 0.
    const Genome solid = randomGenome(3, 3);
    ASSERT_EQ(requiredVersion(solid), 1);
    for (const Genome& child : breed(request(GeneticOperator::Alter, {solid}, 3, 4, 1.0)))
        EXPECT_EQ(requiredVersion(child), 1);
}

TEST(OperatorsVersionTwo, RecombineAndSwapCarryWholeStrokes) {
    const Genome a = versionTwoDesign(20), b = versionOneDesign(21);
    for (const Genome& child : breed(request(GeneticOperator::Swap, {a, b}, 5, 2))) {
        ASSERT_NO_THROW(validateGenome(child, "child"));
        const bool homeIsA = child.initial == a.initial;
        EXPECT_EQ(child.operations, homeIsA ? b.operations : a.operations);
        EXPECT_EQ(child.bleed, homeIsA ? a.bleed : b.bleed);
        EXPECT_EQ(requiredVersion(child), 2) << "a's bleed or a's strokes";
    }
    int withFlow = 0;
    for (const Genome& child : breed(request(GeneticOperator::Recombine, {a, b}, 7, 16))) {
        ASSERT_NO_THROW(validateGenome(child, "child"));
        for (const Operation& op : child.operations) {
            // Every stroke is one of a parent's, whole: a flow keeps its steps, a stretch its teeth.
            bool found = false;
            for (const Genome* parent : {&a, &b})
                for (const Operation& q : parent->operations)
                    found = found || q == op;
            EXPECT_TRUE(found);
            withFlow += op.tool == Tool::Flow ? 1 : 0;
        }
        EXPECT_EQ(parseGenome(serializeGenome(child), "child"), child);
    }
    EXPECT_GT(withFlow, 0);
}

TEST_P(Operators, AlterKeepsPositiveParametersPositiveEvenWhenTheyAreTiny) {
    Genome p = parent(4);
    // A stylus this sharp would need more steps than the format allows (its steps follow its
    // numbers): it has tests of its own (OperatorsStylus).
    std::erase_if(p.operations, [](const Operation& op) { return op.tool == Tool::Stylus; });
    for (Operation& op : p.operations) {
        op.lambda = 0.01;
        op.spacing = 0.01;
        op.wavelength = {0.01, 0.01};
        op.radius = 0.01;
    }
    for (const Genome& child : breed(request(GeneticOperator::Alter, {p}, 3, 20, 1.0)))
        EXPECT_NO_THROW(validateGenome(child, "child"));
}

TEST_P(Operators, AlterWithStrengthZeroKeepsEveryParameter) {
    Genome p = parent(5);
    Pcg32 rng(9, 1);
    const Genome same = alterGenome(p, 0.0, rng);
    EXPECT_EQ(same.operations, p.operations);
    EXPECT_EQ(same.initial, p.initial);
    EXPECT_EQ(genomeId(same), genomeId(p));
    // Bred, copies of the parent would waste cells: the children are gentle variations.
    for (const Genome& child : breed(request(GeneticOperator::Alter, {p}, 9, 3, 0.0))) {
        EXPECT_EQ(toolsOf(child.operations), toolsOf(p.operations));
        EXPECT_NE(genomeId(child), genomeId(p));
        EXPECT_EQ(child.meta.toJson()["lineage"]["variation"]["of"], genomeId(p));
        EXPECT_LT(scaledDistance(p, child), 0.5);
    }
}

TEST_P(Operators, StrongerAlterationMovesFurtherOnAverage) {
    double weak = 0.0, strong = 0.0;
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
        Genome p = parent(seed + 50);
        for (const Genome& c : breed(request(GeneticOperator::Alter, {p}, seed, 8, 0.1)))
            weak += scaledDistance(p, c);
        for (const Genome& c : breed(request(GeneticOperator::Alter, {p}, seed, 8, 0.8)))
            strong += scaledDistance(p, c);
    }
    // Gaussian steps scale with strength: about eight times further, allowing for the clamps.
    EXPECT_GT(strong, 4.0 * weak);
    EXPECT_GT(weak, 0.0);
}

TEST_P(Operators, RecombineOnlyUsesTheParentsOperations) {
    std::vector<Genome> parents{parent(10), parent(11), parent(12)};
    for (std::size_t n : {2u, 3u}) {
        std::vector<Genome> some(parents.begin(), parents.begin() + static_cast<std::ptrdiff_t>(n));
        std::vector<Genome> children = breed(request(GeneticOperator::Recombine, some, 21, 12));
        for (std::size_t i = 0; i < children.size(); ++i) {
            const Genome& child = children[i];
            const Genome& home = some[i % n];
            EXPECT_EQ(child.initial, home.initial);
            EXPECT_EQ(child.palette, home.palette);
            EXPECT_FALSE(child.operations.empty());
            for (const Operation& op : child.operations) {
                bool found = false;
                for (const Genome& p : some)
                    for (const Operation& q : p.operations)
                        found = found || q == op;
                EXPECT_TRUE(found) << "child " << i << " has a stroke no parent has";
            }
            EXPECT_NO_THROW(validateGenome(child, "child"));
        }
    }
}

TEST_P(Operators, RecombineMixesStrokesOfBothParents) {
    Genome a = parent(20), b = parent(21);
    int mixed = 0;
    for (const Genome& child : breed(request(GeneticOperator::Recombine, {a, b}, 5, 20))) {
        bool fromA = false, fromB = false;
        for (const Operation& op : child.operations) {
            for (const Operation& q : a.operations)
                fromA = fromA || q == op;
            for (const Operation& q : b.operations)
                fromB = fromB || q == op;
        }
        mixed += fromA && fromB ? 1 : 0;
    }
    EXPECT_GE(mixed, 8);
}

TEST_P(Operators, RecombineNeverCopiesTheHomeParent) {
    // Parents with few strokes make a copy of one parent a likely draw; no cell may be wasted
    // on one when the other parent's strokes differ.
    for (std::uint64_t seed = 30; seed < 40; ++seed) {
        Genome a = parent(seed), b = parent(seed + 100);
        a.operations.resize(std::min<std::size_t>(a.operations.size(), 2));
        b.operations.resize(std::min<std::size_t>(b.operations.size(), 2));
        ASSERT_NE(a.operations, b.operations);
        for (const Genome& child : breed(request(GeneticOperator::Recombine, {a, b}, seed, 8))) {
            EXPECT_NE(child.operations, child.initial == a.initial ? a.operations : b.operations)
                << "seed " << seed;
        }
    }
}

TEST_P(Operators, LocksHoldForEveryOperator) {
    Genome a = parent(30), b = parent(31);
    for (int mask = 0; mask < 8; ++mask) {
        Locks locks{(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0};
        Genome la = a, lb = b;
        setLocks(la, locks);
        setLocks(lb, locks);
        EXPECT_EQ(locksOf(la), locks);
        struct Case {
            GeneticOperator op;
            std::vector<Genome> parents;
        };
        std::vector<Case> cases{{GeneticOperator::Alter, {la}},
                                {GeneticOperator::Reinit, {la}},
                                {GeneticOperator::Swap, {la, lb}},
                                {GeneticOperator::Recombine, {la, lb}}};
        for (const Case& c : cases) {
            std::vector<Genome> children = breed(request(c.op, c.parents, 99, 6, 1.0));
            for (std::size_t i = 0; i < children.size(); ++i) {
                const Genome& child = children[i];
                const Genome& home = c.parents[i % c.parents.size()];
                SCOPED_TRACE(std::string(operatorName(c.op)) + " locks " + std::to_string(mask) + " child " +
                             std::to_string(i));
                if (locks.palette) {
                    EXPECT_EQ(child.palette, home.palette);
                    EXPECT_EQ(child.background, home.background);
                }
                if (locks.initial) {
                    EXPECT_EQ(child.initial, home.initial);
                }
                if (locks.operations) {
                    EXPECT_EQ(child.operations, home.operations);
                }
                EXPECT_EQ(locksOf(child), locks); // locks travel on to the children
                EXPECT_NO_THROW(validateGenome(child, "child"));
            }
        }
    }
}

TEST_P(Operators, FirstDrawsThatRepeatTheParentAreVariedInTheirTurn) {
    // With its palette and initial state locked, reinit can only give the parent back: every
    // child's first draw, made ahead on some core, repeats it, so in its turn each child is
    // varied gently at once (the filter never sees the repeat, so no redraw is spent on it),
    // unlike its siblings.
    Genome p = parent(33);
    setLocks(p, Locks{.palette = true, .initial = true});
    const std::vector<Genome> children = breed(request(GeneticOperator::Reinit, {p}, 6, 8));
    ASSERT_EQ(children.size(), 8u);
    std::set<std::string> ids{genomeId(p)};
    for (const Genome& child : children) {
        EXPECT_TRUE(ids.insert(genomeId(child)).second) << "a repeat";
        EXPECT_EQ(child.meta.toJson()["lineage"]["variation"]["of"], genomeId(p));
        EXPECT_FALSE(child.meta.toJson()["lineage"].contains("redraws"));
        EXPECT_EQ(child.initial, p.initial);
        EXPECT_EQ(child.palette, p.palette);
    }
    // Made on every core, the same request still gives the same children.
    const std::vector<Genome> again = breed(request(GeneticOperator::Reinit, {p}, 6, 8));
    for (std::size_t i = 0; i < children.size(); ++i)
        EXPECT_EQ(genomeId(again[i]), genomeId(children[i])) << i;
}

TEST_P(Operators, AlterWithLockedOperationsVariesWhatIsFree) {
    Genome p = parent(32);
    setLocks(p, {false, false, true});
    for (const Genome& child : breed(request(GeneticOperator::Alter, {p}, 4, 4, 0.8))) {
        EXPECT_EQ(child.operations, p.operations);
        EXPECT_NE(child.palette, p.palette);
        EXPECT_NE(child.initial, p.initial);
        EXPECT_EQ(toolsOf(child.initial), toolsOf(p.initial));
    }
    setLocks(p, {true, true, true});
    for (const Genome& child : breed(request(GeneticOperator::Alter, {p}, 4, 2, 0.8)))
        EXPECT_EQ(genomeId(child), genomeId(p));
}

TEST_P(Operators, ReinitWithLockedInitialStateRecolours) {
    Genome p = parent(33);
    setLocks(p, {false, true, false});
    for (const Genome& child : breed(request(GeneticOperator::Reinit, {p}, 4, 3))) {
        EXPECT_EQ(child.initial, p.initial);
        EXPECT_EQ(child.operations, p.operations);
        EXPECT_EQ(child.palette.size(), p.palette.size());
        EXPECT_NE(child.palette, p.palette);
    }
}

TEST_P(Operators, SeedsReproduceAndChildrenAreIndependentOfCount) {
    Genome a = parent(40), b = parent(41);
    for (GeneticOperator op : {GeneticOperator::Alter, GeneticOperator::Recombine, GeneticOperator::Reinit}) {
        std::vector<Genome> parents =
            op == GeneticOperator::Recombine ? std::vector<Genome>{a, b} : std::vector<Genome>{a};
        std::vector<Genome> first = breed(request(op, parents, 1234, 6));
        std::vector<Genome> again = breed(request(op, parents, 1234, 6));
        std::vector<Genome> fewer = breed(request(op, parents, 1234, 3));
        std::vector<Genome> other = breed(request(op, parents, 1235, 6));
        ASSERT_EQ(first.size(), 6u);
        for (std::size_t i = 0; i < first.size(); ++i) {
            EXPECT_EQ(serializeGenome(first[i]), serializeGenome(again[i]));
            if (i < fewer.size()) {
                EXPECT_EQ(serializeGenome(first[i]), serializeGenome(fewer[i]));
            }
        }
        int same = 0;
        for (std::size_t i = 0; i < first.size(); ++i)
            same += genomeId(first[i]) == genomeId(other[i]) ? 1 : 0;
        EXPECT_LT(same, 3) << operatorName(op);
    }
}

TEST_P(Operators, LineageIsRecorded) {
    Genome a = parent(50), b = parent(51);
    a.meta.lineage = MetaLineage{};
    a.meta.lineage->generation = 4;
    std::vector<Genome> children = breed(request(GeneticOperator::Recombine, {a, b}, 77, 3));
    for (std::size_t i = 0; i < children.size(); ++i) {
        const auto meta = children[i].meta.toJson();
        ASSERT_TRUE(meta.contains("lineage"));
        const auto& lineage = meta["lineage"];
        EXPECT_EQ(lineage["parents"], (nlohmann::ordered_json{genomeId(a), genomeId(b)}));
        EXPECT_EQ(lineage["operator"], "recombine");
        EXPECT_EQ(lineage["seed"], 77);
        EXPECT_EQ(lineage["generation"], 5);
        EXPECT_EQ(lineage["child"], static_cast<int>(i) + 1);
        EXPECT_EQ(meta["id"], genomeId(children[i]));
        EXPECT_FALSE(meta.contains("seed")); // the generator's seed belongs to the parent
        EXPECT_NE(meta["name"].get<std::string>().find(" (g5 #"), std::string::npos);
    }
    // A child of a child: generation counts on, the name keeps one suffix.
    std::vector<Genome> grand = breed(request(GeneticOperator::Alter, {children[0]}, 1, 1));
    EXPECT_EQ(grand[0].meta.toJson()["lineage"]["generation"], 6);
    std::string name = grand[0].meta.toJson()["name"];
    EXPECT_EQ(name.find(" (g"), name.rfind(" (g"));
}

TEST_P(Operators, GenomeIdDependsOnContentOnly) {
    Genome a = parent(60);
    std::string id = genomeId(a);
    EXPECT_EQ(id.size(), 16u);
    EXPECT_EQ(id.find_first_not_of("0123456789abcdef"), std::string::npos);
    Genome renamed = a;
    renamed.meta.name = "something else";
    EXPECT_EQ(genomeId(renamed), id);
    Genome moved = a;
    moved.initial[0].radius += 1.0;
    EXPECT_NE(genomeId(moved), id);
}

TEST_P(Operators, BadRequestsAreInputErrors) {
    Genome a = parent(70), b = parent(71);
    EXPECT_THROW(breed(request(GeneticOperator::Alter, {}, 1)), InputError);
    EXPECT_THROW(breed(request(GeneticOperator::Alter, {a, b}, 1)), InputError);
    EXPECT_THROW(breed(request(GeneticOperator::Swap, {a}, 1)), InputError);
    EXPECT_THROW(breed(request(GeneticOperator::Swap, {a, b, a}, 1)), InputError);
    EXPECT_THROW(breed(request(GeneticOperator::Recombine, {a}, 1)), InputError);
    EXPECT_THROW(breed(request(GeneticOperator::Alter, {a}, 1, 8, 1.5)), InputError);
    EXPECT_THROW(breed(request(GeneticOperator::Alter, {a}, 1, 8, -0.1)), InputError);
    EXPECT_THROW(breed(request(GeneticOperator::Alter, {a}, 1, 0)), InputError);
    Genome other = randomGenome(72, dimension() == 2 ? 3 : 2);
    EXPECT_THROW(breed(request(GeneticOperator::Swap, {a, other}, 1)), InputError);
    Genome broken = a;
    broken.operations[0].lambda = -1.0;
    EXPECT_THROW(breed(request(GeneticOperator::Alter, {broken}, 1)), InputError);
}

INSTANTIATE_TEST_SUITE_P(Dimensions, Operators, ::testing::Values(2, 3),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return std::to_string(info.param) + "D";
                         });

/// A flat design with a stylus stroke along a curve with a pen's pressure, and a rake.
Genome stylusDesign(std::uint64_t seed) {
    Genome g = versionOneDesign(seed);
    Operation stroke = defaultOperation(Tool::Stylus, 2, {0, 0, 0}); // no centre, as read from a file
    stroke.path = {{100, 200}, {250, 260}, {400, 240}, {520, 380}, {700, 420}};
    stroke.pressure = {0.4, 0.8, 1.0, 0.9, 0.5};
    stroke.alpha = 60.0;
    stroke.lambda = 12.0;
    stroke.reach = 50.0;
    stroke.steps = minimumStylusSteps(stroke);
    Operation rake = defaultOperation(Tool::Stylus, 2, {0, 0, 0});
    rake.path = {{0, 700}, {300, 650}, {600, 750}, {1000, 700}};
    rake.tines = 4;
    rake.spacing = 60.0;
    rake.alpha = 30.0;
    rake.reach = 60.0;
    rake.lambda = 10.0;
    rake.steps = minimumStylusSteps(rake);
    g.operations.push_back(stroke);
    g.operations.push_back(rake);
    return g;
}

TEST(OperatorsStylus, AlterationMovesSmoothsAndReTimesAStrokeAndKeepsItValid) {
    const Genome parent = stylusDesign(3);
    ASSERT_NO_THROW(validateGenome(parent, "parent"));
    const Operation& stroke = parent.operations[parent.operations.size() - 2];
    const Operation& rake = parent.operations.back();
    int moved = 0, smoothed = 0, retimed = 0, pressed = 0, draws = 0;
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
        Pcg32 rng(seed);
        for (double strength : {0.2, 0.6, 1.0}) {
            const Genome child = alterGenome(parent, strength, rng);
            SCOPED_TRACE("seed " + std::to_string(seed) + " strength " + std::to_string(strength));
            ASSERT_NO_THROW(validateGenome(child, "child"));
            ASSERT_EQ(toolsOf(child.operations), toolsOf(parent.operations));
            const Operation& s = child.operations[child.operations.size() - 2];
            const Operation& r = child.operations.back();
            ++draws;
            // Still the same kind of stroke: a stylus and a rake of as many tines, as many points.
            EXPECT_EQ(s.tines, 1);
            EXPECT_EQ(r.tines, rake.tines);
            ASSERT_EQ(s.path.size(), stroke.path.size());
            ASSERT_EQ(s.pressure.size(), s.path.size());
            EXPECT_GE(s.steps, minimumStylusSteps(s));
            EXPECT_GE(r.steps, minimumStylusSteps(r));
            EXPECT_TRUE(r.pressure.empty()) << "a stroke without a pen's pressure gets none";
            moved += s.path != stroke.path && r.path != rake.path;
            // Smoothed: an inner point lies nearer the middle of its neighbours than any jitter
            // alone would put it (the stroke's corners are sharp, 30 units or more off).
            const glm::dvec2 corner = s.path[3] - 0.5 * (s.path[2] + s.path[4]);
            const glm::dvec2 before = stroke.path[3] - 0.5 * (stroke.path[2] + stroke.path[4]);
            smoothed += glm::length(corner) < 0.75 * glm::length(before) - 10.0;
            retimed += s.steps > minimumStylusSteps(s);
            pressed += s.pressure != stroke.pressure;
            for (double p : s.pressure) {
                EXPECT_GE(p, 0.0);
                EXPECT_LE(p, 1.0);
            }
        }
    }
    EXPECT_EQ(moved, draws) << "every alteration moves the paths";
    EXPECT_GT(smoothed, draws / 10);
    EXPECT_LT(smoothed, draws);
    EXPECT_GT(retimed, draws / 10);
    EXPECT_EQ(pressed, draws);
    // Saved and read back, the children are what they were.
    Pcg32 rng(1);
    const Genome child = alterGenome(parent, 0.5, rng);
    EXPECT_EQ(parseGenome(serializeGenome(child), "child"), child);
}

TEST(OperatorsStylus, AStrokeThatWouldNeedTooManyStepsKeepsItsPath) {
    // A long rake at its strongest pull: any longer path would ask for more steps than the
    // format allows, so what the alteration drew is refused and the old stroke kept valid.
    Genome g = versionOneDesign(5);
    Operation rake = defaultOperation(Tool::Stylus, 2, {500, 500, 0});
    rake.path = {{0, 500}, {1000, 500}};
    rake.tines = 64;
    rake.spacing = 10.0;
    rake.lambda = 2.0;
    rake.reach = 20.0;
    rake.alpha = 1.0;
    while (minimumStylusSteps(rake) <= MaxStylusSteps)
        rake.alpha *= 1.05;
    rake.alpha /= 1.05;
    rake.steps = minimumStylusSteps(rake);
    ASSERT_LE(rake.steps, MaxStylusSteps);
    g.operations = {rake};
    ASSERT_NO_THROW(validateGenome(g, "parent"));
    Pcg32 rng(4);
    for (int i = 0; i < 50; ++i) {
        const Genome child = alterGenome(g, 1.0, rng);
        ASSERT_NO_THROW(validateGenome(child, "child")) << i;
        EXPECT_LE(child.operations[0].steps, MaxStylusSteps);
    }
}

TEST(OperatorsStylus, RecombinationAndSwapCarryAStrokeWhole) {
    const Genome a = stylusDesign(6), b = stylusDesign(8);
    Genome other = b;
    for (Operation& op : other.operations)
        if (op.tool == Tool::Stylus)
            for (glm::dvec2& p : op.path)
                p += glm::dvec2(13.0, -7.0);
    int strokes = 0;
    for (const Genome& child : breed(request(GeneticOperator::Recombine, {a, other}, 11, 12))) {
        ASSERT_NO_THROW(validateGenome(child, "child"));
        for (const Operation& op : child.operations) {
            if (op.tool != Tool::Stylus) continue;
            ++strokes;
            // Path, pressure, tines and steps all from one parent's stroke.
            bool whole = false;
            for (const Genome* parent : {&a, static_cast<const Genome*>(&other)})
                for (const Operation& q : parent->operations)
                    whole = whole || q == op;
            EXPECT_TRUE(whole);
        }
    }
    EXPECT_GT(strokes, 0);
    for (const Genome& child : breed(request(GeneticOperator::Swap, {a, other}, 2, 2)))
        EXPECT_TRUE(child.operations == a.operations || child.operations == other.operations);
}

TEST(Wildcard, AFreshDesignOfTheParentsFamilyInTheReplacedChildsPlace) {
    BreedRequest request;
    request.parents = {familyGenome(*findFamily("zebra"), 4)};
    request.seed = 77;
    request.childNumbers = {2, 3, 4, 5, 6, 7, 8, 9};
    const std::vector<Genome> children = breed(request);
    const Genome wild = wildcardChild(request, children.back());
    EXPECT_EQ(wild.meta.family, std::optional<std::string>("zebra"));
    EXPECT_NE(genomeId(wild), genomeId(request.parents.front()));
    ASSERT_TRUE(wild.meta.lineage);
    EXPECT_EQ(wild.meta.lineage->op, std::optional<std::string>("wildcard"));
    EXPECT_EQ(wild.meta.lineage->child, children.back().meta.lineage->child);
    EXPECT_EQ(wild.meta.lineage->generation, children.back().meta.lineage->generation);
    EXPECT_NE(wild.meta.name.value_or("").find("#9)"), std::string::npos) << wild.meta.name.value_or("");
    EXPECT_EQ(wild.meta.id, std::optional<std::string>(genomeId(wild)));
    EXPECT_NO_THROW(validateGenome(wild, "wildcard"));
    // The seed alone decides it.
    EXPECT_EQ(serializeGenome(wildcardChild(request, children.back())), serializeGenome(wild));
    request.seed = 78;
    EXPECT_NE(genomeId(wildcardChild(request, children.back())), genomeId(wild));
    // A solid parent of a flat family's name: a free solid design, not the flat family's.
    Genome solid = randomGenome(5, 3);
    solid.meta.family = "zebra";
    request.parents = {solid};
    const Genome free = wildcardChild(request, children.back());
    EXPECT_EQ(free.dimension, 3);
    EXPECT_FALSE(free.meta.family);
    EXPECT_THROW(wildcardChild(BreedRequest{}, children.back()), InputError);
}

TEST(OperatorNames, RoundTrip) {
    for (GeneticOperator op :
         {GeneticOperator::Alter, GeneticOperator::Recombine, GeneticOperator::Swap, GeneticOperator::Reinit})
        EXPECT_EQ(parseOperator(operatorName(op)), op);
    EXPECT_FALSE(parseOperator("mutate"));
    EXPECT_EQ(minParents(GeneticOperator::Recombine), 2);
    EXPECT_EQ(maxParents(GeneticOperator::Recombine), 0);
    EXPECT_EQ(maxParents(GeneticOperator::Swap), 2);
}

TEST(AlterPart, EachPartChangesItselfAloneAndALockedPartStays) {
    int changed[3] = {0, 0, 0};
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        const Genome parent = randomGenome(seed, 2);
        ASSERT_FALSE(parent.operations.empty());
        for (DesignPart part : {DesignPart::Palette, DesignPart::Initial, DesignPart::Strokes}) {
            Pcg32 rng(seed * 31 + std::uint64_t(part));
            const Genome child = alterPart(parent, part, 0.4, rng);
            const bool palette = child.palette != parent.palette || child.background != parent.background;
            const bool initial = child.initial != parent.initial;
            const bool strokes = child.operations != parent.operations;
            EXPECT_TRUE(part == DesignPart::Palette || !palette) << seed;
            EXPECT_TRUE(part == DesignPart::Initial || !initial) << seed;
            EXPECT_TRUE(part == DesignPart::Strokes || !strokes) << seed;
            changed[int(part)] += palette || initial || strokes;
            EXPECT_NO_THROW(validateGenome(child, "child"));
        }
        // Locked, the part stays as it is.
        Genome locked = parent;
        setLocks(locked, Locks{true, true, true});
        for (DesignPart part : {DesignPart::Palette, DesignPart::Initial, DesignPart::Strokes}) {
            Pcg32 rng(seed);
            EXPECT_EQ(alterPart(locked, part, 0.8, rng), locked) << seed;
        }
    }
    // Rounding to whole sRGB levels can leave a small nudge without effect now and then.
    EXPECT_GE(changed[0], 10);
    EXPECT_EQ(changed[1], 12);
    EXPECT_EQ(changed[2], 12);
}

} // namespace
} // namespace marbler
