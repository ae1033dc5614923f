// The making of a design (genome-format.md): the design after K steps, each tool's growth within
// a step, and the frames' growth; every grown design is a valid genome.

#include "marbler/Growth.h"
#include "TestUtil.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "marbler/Tools.h"

#include <gtest/gtest.h>

#include <cmath>

namespace marbler {
namespace {

Genome growthGenome() {
    nlohmann::json file =
        nlohmann::json::parse(test::readFile(test::dataDir() / "conformance" / "growth-v2.json"));
    return parseGenome(file.at("genome").dump(), "growth-v2.json");
}

TEST(Growth, StepsKeepTheFirstEntriesOfInitialThenOperations) {
    const Genome genome = growthGenome();
    ASSERT_EQ(stepCount(genome), genome.initial.size() + genome.operations.size());
    ASSERT_GT(genome.operations.size(), 2u);
    const std::size_t ink = genome.initial.size();

    Genome bare = designAfterSteps(genome, 0);
    EXPECT_TRUE(bare.initial.empty());
    EXPECT_TRUE(bare.operations.empty());
    EXPECT_EQ(bare.palette, genome.palette);
    EXPECT_EQ(bare.background, genome.background);

    Genome some = designAfterSteps(genome, 3);
    ASSERT_EQ(some.initial.size(), 3u);
    EXPECT_TRUE(some.operations.empty());
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(some.initial[i], genome.initial[i]);

    EXPECT_EQ(designAfterSteps(genome, ink).initial, genome.initial);
    Genome later = designAfterSteps(genome, ink + 2);
    EXPECT_EQ(later.initial, genome.initial);
    ASSERT_EQ(later.operations.size(), 2u);
    EXPECT_EQ(later.operations[1], genome.operations[1]);

    EXPECT_EQ(designAfterSteps(genome, stepCount(genome)), genome);
    EXPECT_THROW(designAfterSteps(genome, stepCount(genome) + 1), InputError);
}

/// The parameter a tool grows, read through the registry: its components.
std::vector<double> grownComponents(const Operation& op, int dimension, ParamField field) {
    std::vector<double> values;
    for (const ParamSpec& spec : toolSpec(op.tool).params(dimension))
        if (spec.field == field)
            for (int i = 0; i < componentCount(spec, op, dimension); ++i)
                values.push_back(getComponent(spec, op, i));
    return values;
}

TEST(Growth, EveryToolOfTheRegistryGrowsAsTheSpecSays) {
    const double s = 0.3;
    int checked = 0;
    for (const ToolSpec& tool : allTools())
        for (int dimension : {2, 3}) {
            if (!tool.available(dimension)) continue;
            std::vector<Operation> ops{defaultOperation(tool.tool, dimension, {500.0, 500.0, 500.0})};
            if (tool.tool == Tool::Wave && dimension == 3) {
                ops[0].shape = WaveShape::Eggcrate;
                ops[0].amplitude = {25.0, -40.0};
                ops.push_back(ops[0]);
                ops[1].shape = WaveShape::Ripple;
            }
            for (Operation& op : ops) {
                // A non-zero value of every parameter that could grow.
                op.alpha = 70.0;
                op.shift = -35.0;
                op.time = 1.5;
                op.radius = 80.0;
                SCOPED_TRACE(std::string(tool.name) + " in " + std::to_string(dimension) + "D");
                if (tool.tool == Tool::Stylus) {
                    // The stylus travels: at progress s it runs its first floor(s n) steps,
                    // each at the time and place it has in the whole stroke.
                    op.path = {{300.0, 500.0}, {520.0, 430.0}, {700.0, 560.0}};
                    op.pressure = {1.0, 0.4, 0.8};
                    op.lambda = 6.0;
                    op.reach = 40.0;
                    op.steps = minimumStylusSteps(op) + 7;
                    std::optional<Operation> grown = grownOperation(op, dimension, s);
                    ASSERT_TRUE(grown);
                    const int runs = static_cast<int>(std::floor(s * op.steps));
                    EXPECT_EQ(grown->steps, runs);
                    const PreparedOp whole = prepare(op, 2), part = prepare(*grown, 2);
                    EXPECT_NEAR(part.step, whole.step, 1e-12 * whole.step);
                    for (glm::dvec2 p : {glm::dvec2(520.0, 436.0), glm::dvec2(410.0, 462.0)}) {
                        glm::dvec2 expected = p;
                        for (int i = 0; i < runs; ++i)
                            expected = stylusStep(whole, expected, i, +1.0);
                        glm::dvec3 got = forwardMap(part, {p.x, p.y, 0.0});
                        EXPECT_NEAR(got.x, expected.x, 1e-7);
                        EXPECT_NEAR(got.y, expected.y, 1e-7);
                    }
                    Genome holder;
                    holder.palette = {Color{}};
                    holder.operations = {*grown};
                    EXPECT_NO_THROW(validateGenome(holder, "grown"));
                    EXPECT_FALSE(grownOperation(op, dimension, 0.0)) << "progress 0 leaves the step out";
                    EXPECT_EQ(grownOperation(op, dimension, 1.0), op);
                    ++checked;
                    continue;
                }
                ParamField field{};
                double factor = s;
                switch (tool.tool) {
                case Tool::Drop:
                case Tool::Spray:
                case Tool::Cylinder:
                    field = ParamField::Radius;
                    factor = dimension == 3 ? std::cbrt(s) : std::sqrt(s);
                    break;
                case Tool::Line:
                case Tool::Comb:
                case Tool::Circle:
                case Tool::Sphere:
                case Tool::Vortex:
                    field = ParamField::Alpha;
                    break;
                case Tool::Wave:
                    field = ParamField::Amplitude;
                    break;
                case Tool::Stretch:
                    field = ParamField::Shift;
                    break;
                case Tool::Flow:
                    field = ParamField::Time;
                    break;
                case Tool::Stylus:
                    break; // above
                }
                std::optional<Operation> grown = grownOperation(op, dimension, s);
                ASSERT_TRUE(grown);
                std::vector<double> before = grownComponents(op, dimension, field);
                std::vector<double> after = grownComponents(*grown, dimension, field);
                ASSERT_FALSE(before.empty());
                ASSERT_EQ(before.size(), after.size());
                for (std::size_t i = 0; i < before.size(); ++i) {
                    EXPECT_NE(before[i], 0.0);
                    EXPECT_NEAR(after[i], before[i] * factor, 1e-12 * std::abs(before[i]));
                }
                // Nothing else changes (the circle's radius is its size, not its growth).
                Operation restored = *grown;
                for (const ParamSpec& spec : tool.params(dimension))
                    if (spec.field == field)
                        for (int i = 0; i < componentCount(spec, op, dimension); ++i)
                            setComponent(spec, restored, i, getComponent(spec, op, i));
                EXPECT_EQ(restored, op);

                EXPECT_FALSE(grownOperation(op, dimension, 0.0)) << "progress 0 leaves the step out";
                EXPECT_EQ(grownOperation(op, dimension, 1.0), op);
                ++checked;
            }
        }
    EXPECT_GE(checked, 17);
}

TEST(Growth, FramesRunFromTheBareBathToTheDesign) {
    EXPECT_EQ(frameGrowth(69, 0, 9), 0.0);
    EXPECT_EQ(frameGrowth(69, 8, 9), 69.0);
    EXPECT_EQ(frameGrowth(69, 3, 9), 69.0 * 3 / 8);
    EXPECT_EQ(frameGrowth(7, 99, 100), 7.0);
    for (int f = 1; f < 100; ++f)
        EXPECT_GT(frameGrowth(7, f, 100), frameGrowth(7, f - 1, 100));
}

TEST(Growth, PartialStepsGrowInPlaceAndStayValidGenomes) {
    const Genome genome = growthGenome();
    const std::size_t ink = genome.initial.size();
    const double count = static_cast<double>(stepCount(genome));

    // Within initial: the grown ink is the last entry, with a quarter of its area.
    Genome early = designAtGrowth(genome, 2.25);
    ASSERT_EQ(early.initial.size(), 3u);
    EXPECT_TRUE(early.operations.empty());
    EXPECT_DOUBLE_EQ(early.initial[2].radius, genome.initial[2].radius * 0.5);
    EXPECT_EQ(early.initial[2].center, genome.initial[2].center);

    // Within operations: the grown stroke is the last operation.
    Genome late = designAtGrowth(genome, ink + 1.5);
    EXPECT_EQ(late.initial, genome.initial);
    ASSERT_EQ(late.operations.size(), 2u);
    EXPECT_EQ(late.operations[0], genome.operations[0]);
    EXPECT_EQ(late.operations[1], *grownOperation(genome.operations[1], 2, 0.5));

    // A whole number of steps: that design, with no step at progress 0.
    EXPECT_EQ(designAtGrowth(genome, 5.0), designAfterSteps(genome, 5));
    EXPECT_EQ(designAtGrowth(genome, count), genome);
    EXPECT_THROW(designAtGrowth(genome, -0.5), InputError);
    EXPECT_THROW(designAtGrowth(genome, count + 0.5), InputError);
    EXPECT_THROW(designAtGrowth(genome, std::nan("")), InputError);

    // Every frame of a long animation saves and reads back as the same valid genome.
    for (int f = 0; f < 200; ++f) {
        Genome design = designAtGrowth(genome, frameGrowth(stepCount(genome), f, 200));
        EXPECT_NO_THROW(validateGenome(design, "frame"));
        EXPECT_EQ(parseGenome(serializeGenome(design), "frame"), design) << "frame " << f;
    }
}

TEST(Growth, FlowsAndSolidsStayValidAsTheyGrow) {
    // A flow's steps stay enough for a shorter time; a 3D egg-crate keeps both amplitudes.
    Genome flat;
    flat.palette = {Color{10, 20, 30}};
    flat.initial.push_back(defaultOperation(Tool::Drop, 2, {500.0, 500.0, 0.0}));
    Operation flow = defaultOperation(Tool::Flow, 2, {500.0, 500.0, 0.0});
    flow.speed = 90.0;
    flow.steps = minimumFlowSteps(flow);
    flat.operations.push_back(flow);
    flat.operations.push_back(defaultOperation(Tool::Stretch, 2, {500.0, 500.0, 0.0}));
    for (double g = 0.0; g <= 3.0; g += 0.125)
        EXPECT_NO_THROW(validateGenome(designAtGrowth(flat, g), "flat")) << g;
    EXPECT_DOUBLE_EQ(designAtGrowth(flat, 1.25).operations[0].time, flow.time * 0.25);

    Genome solid;
    solid.dimension = 3;
    solid.palette = {Color{10, 20, 30}};
    solid.initial.push_back(defaultOperation(Tool::Cylinder, 3, {500.0, 500.0, 500.0}));
    solid.initial.push_back(defaultOperation(Tool::Drop, 3, {300.0, 500.0, 500.0}));
    solid.operations.push_back(defaultOperation(Tool::Wave, 3, {500.0, 500.0, 500.0}));
    for (double g = 0.0; g <= 3.0; g += 0.125)
        EXPECT_NO_THROW(validateGenome(designAtGrowth(solid, g), "solid")) << g;
    Genome half = designAtGrowth(solid, 1.125);
    EXPECT_NEAR(half.initial[1].radius, solid.initial[1].radius * 0.5, 1e-12);
}

} // namespace
} // namespace marbler
