// describeChange: what a child changed from its parent, in words, and the lineage that records it.

#include "marbler/ChangeSummary.h"
#include "marbler/Generator.h"
#include "marbler/Operators.h"
#include "marbler/Params.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace marbler {
namespace {

Operation drop(double x, double y, double radius, int color) {
    Operation op = defaultOperation(Tool::Drop, 2, {500.0, 500.0, 0.0});
    op.center = {x, y, 0.0};
    op.radius = radius;
    op.color = color;
    return op;
}

Operation stroke(Tool tool) {
    return defaultOperation(tool, 2, {500.0, 500.0, 0.0});
}

/// Three inks, three drops, then comb, wave, comb, vortex.
Genome base() {
    Genome g;
    g.palette = {{0x1f, 0x4e, 0xa8}, {0xc8, 0x3a, 0x2c}, {0x6a, 0x8f, 0x4e}};
    g.initial = {drop(300, 300, 120, 0), drop(700, 400, 90, 1), drop(500, 700, 60, 2)};
    g.operations = {stroke(Tool::Comb), stroke(Tool::Wave), stroke(Tool::Comb), stroke(Tool::Vortex)};
    g.operations[0].spacing = 18.0;
    g.operations[2].spacing = 40.0;
    return g;
}

TEST(ChangeSummary, EqualDesignsShowNoChange) {
    Genome a = base(), b = base();
    b.meta.name = "another name"; // meta is no part of the design
    EXPECT_EQ(describeChange(a, b), "no visible change");
}

TEST(ChangeSummary, ChangedCombSpacing) {
    Genome a = base(), b = base();
    b.operations[2].spacing = 46.4;
    EXPECT_EQ(describeChange(a, b), "comb 2: spacing 40 → 46");
    b = base();
    b.operations[0].spacing = 23.0;
    EXPECT_EQ(describeChange(a, b), "comb 1: spacing 18 → 23");
    // Values that round alike get the decimals that tell them apart.
    b.operations[0].spacing = 18.3;
    EXPECT_EQ(describeChange(a, b), "comb 1: spacing 18 → 18.3");
    // Angles in degrees; small lengths to one decimal.
    b = base();
    b.operations[1].angle = 42.4;
    b.operations[0].lambda = 4.26;
    a.operations[0].lambda = 3.5;
    EXPECT_EQ(describeChange(a, b), "wave 1: angle 0° → 42°; comb 1: lambda 3.5 → 4.3");
    // An angle turns the short way round: 350° → 10° is 20° (0.8 of its scale), less than the
    // spacing's 20 units (one scale).
    a = b = base();
    a.operations[1].angle = 350.0;
    b.operations[1].angle = 10.0;
    b.operations[0].spacing = 38.0;
    EXPECT_EQ(describeChange(a, b), "comb 1: spacing 18 → 38; wave 1: angle 350° → 10°");
}

TEST(ChangeSummary, MovedDrop) {
    Genome a = base(), b = base();
    b.initial[1].center += glm::dvec3(9.0, 12.0, 0.0);
    EXPECT_EQ(describeChange(a, b), "drop 2: moved 15 units");
    b.initial[1].radius = 100.0;
    EXPECT_EQ(describeChange(a, b), "drop 2: radius 90 → 100, moved 15 units");
}

TEST(ChangeSummary, AddedAndRemovedSteps) {
    Genome a = base(), b = base();
    b.operations.push_back(stroke(Tool::Wave));
    EXPECT_EQ(describeChange(a, b), "added a wave");
    b.operations.push_back(stroke(Tool::Stretch));
    b.operations.push_back(stroke(Tool::Stretch));
    EXPECT_EQ(describeChange(a, b), "added 2 stretches; added a wave");
    // The removed comb is the one that is gone, not the first of its kind.
    b = base();
    b.operations.erase(b.operations.begin());
    EXPECT_EQ(describeChange(a, b), "removed comb 1");
    b = base();
    b.operations.erase(b.operations.begin() + 3);
    b.operations[1].phase.x = 90.0;
    EXPECT_EQ(describeChange(a, b), "removed vortex 1; wave 1: phase 0° → 90°");
}

TEST(ChangeSummary, InitialState) {
    Genome a = base(), b = base();
    b.initial.push_back(drop(100, 100, 30, 1));
    EXPECT_EQ(describeChange(a, b), "initial state: 3 drops → 4 drops");
    b = base();
    for (Operation& op : b.initial)
        op.center.x += 40.0;
    b.initial.push_back(drop(100, 100, 30, 1));
    for (std::size_t i = 0; i < 4; ++i)
        a.initial.push_back(drop(100.0 * i, 50, 20, 0));
    for (std::size_t i = 0; i < 4; ++i)
        b.initial.insert(b.initial.end() - 1, drop(100.0 * i + 3, 50, 20, 0));
    b.initial.pop_back();
    EXPECT_EQ(describeChange(a, b), "new initial state");
}

TEST(ChangeSummary, Palette) {
    Genome a = base(), b = base();
    // Hue shifts keep the colour word and are named by the hue they move towards: ink 3, a
    // green at 94°, goes to 80°; ink 2, an orange at 24°, to 18°.
    b.palette[2] = {0x7a, 0x8f, 0x4e};
    EXPECT_EQ(describeChange(a, b), "palette: ink 3 yellower");
    a.palette[1] = {0xd0, 0x70, 0x30};
    b = a;
    b.palette[1] = {0xd0, 0x60, 0x30};
    EXPECT_EQ(describeChange(a, b), "palette: ink 2 redder");
    b.palette[2] = {0x7a, 0x8f, 0x4e};
    EXPECT_EQ(describeChange(a, b), "palette: ink 3 yellower, ink 2 redder");
    a = b = base();
    b.palette[1] = {0xd6, 0x50, 0x44};
    EXPECT_EQ(describeChange(a, b), "palette: ink 2 lighter");
    b = base();
    b.palette[0] = {0xe8, 0xa8, 0x20};
    EXPECT_EQ(describeChange(a, b),
              "palette: ink 1: " + colorWord(a.palette[0]) + " → " + colorWord(b.palette[0]));
    b = base();
    b.background = {0x40, 0x40, 0x48};
    b.bleed = 2.5;
    EXPECT_EQ(describeChange(a, b),
              "background: " + colorWord(a.background) + " → " + colorWord(b.background) + "; bleed 0 → 2.5");
}

TEST(ChangeSummary, LargestFirstAndTheRestCounted) {
    Genome a = base(), b = base();
    b.operations[0].spacing = 28.0;  // 10 units: half a mutation scale (0.02 of 1000)
    b.operations[0].alpha = 61.0;    // 1 unit of 30
    b.operations[1].angle = 50.0;    // two scales of 25°
    b.operations[3].lambda = 22.0;   // one scale (0.01 of 1000)
    b.operations[3].alpha = 150.0;   // three scales of 30
    b.operations[2].center.y += 4.0; // 4 of 80
    b.palette[1] = {0xd6, 0x50, 0x44};
    EXPECT_EQ(describeChange(a, b), "vortex 1: alpha 60 → 150, lambda 12 → 22; wave 1: angle 0° → 50°; "
                                    "palette: ink 2 lighter; and 3 more");
}

TEST(ChangeSummary, BredChildrenRecordTheirChange) {
    const Genome parent = randomGenome(12, 2);
    BreedRequest r;
    r.op = GeneticOperator::Alter;
    r.parents = {parent};
    r.seed = 5;
    r.count = 4;
    for (const Genome& child : breed(r)) {
        const std::string change = child.meta.toJson()["lineage"]["change"].get<std::string>();
        EXPECT_EQ(change, describeChange(parent, child));
        EXPECT_NE(change, "no visible change");
    }
    // Swap and recombine describe against the home parent and name the other parent a part
    // came from.
    r.op = GeneticOperator::Swap;
    r.parents = {parent, randomGenome(38, 2)};
    const std::vector<Genome> swapped = breed(r);
    for (std::size_t i = 0; i < 2; ++i) {
        const std::string change = swapped[i].meta.toJson()["lineage"]["change"].get<std::string>();
        EXPECT_EQ(change, describeChange(r.parents, i, swapped[i])) << i;
        EXPECT_EQ(change.rfind("the strokes of parent " + std::to_string(2 - i), 0), 0u) << change;
    }
}

TEST(ChangeSummary, PartsFromAnotherParent) {
    Genome a = base(), b = base(), c = base();
    b.operations = {stroke(Tool::Wave), stroke(Tool::Circle)};
    b.operations[0].amplitude.x = 70.0;
    c.operations.push_back(b.operations[0]);
    c.operations.push_back(stroke(Tool::Line));
    c.operations.push_back(stroke(Tool::Line));
    EXPECT_EQ(describeChange({a, b}, 0, c), "added 2 lines; added a wave from parent 2");
    EXPECT_EQ(describeChange(a, c), "added 2 lines; added a wave");
    c = b;
    c.palette = a.palette;
    EXPECT_EQ(describeChange({b, a}, 1, c), "the strokes of parent 1");
}

TEST(ChangeSummary, EveryToolHasAnEnglishPlural) {
    const std::map<Tool, std::string> plurals{
        {Tool::Drop, "drops"},        {Tool::Spray, "sprays"},   {Tool::Cylinder, "cylinders"},
        {Tool::Line, "lines"},        {Tool::Comb, "combs"},     {Tool::Wave, "waves"},
        {Tool::Circle, "circles"},    {Tool::Sphere, "spheres"}, {Tool::Vortex, "vortices"},
        {Tool::Stretch, "stretches"}, {Tool::Flow, "flows"},     {Tool::Stylus, "stylus strokes"}};
    for (const ToolSpec& tool : allTools()) {
        ASSERT_TRUE(plurals.count(tool.tool)) << "a new tool needs its plural here: " << tool.name;
        const int dimension = tool.in2D ? 2 : 3;
        Genome a;
        a.dimension = dimension;
        if (dimension == 3) a.size = {1000.0, 1000.0, 1000.0};
        Genome b = a;
        b.operations = {defaultOperation(tool.tool, dimension, a.size),
                        defaultOperation(tool.tool, dimension, a.size)};
        EXPECT_EQ(describeChange(a, b), "added 2 " + plurals.at(tool.tool));
        // And where steps are counted, in the initial state.
        b = a;
        b.initial = {defaultOperation(tool.tool, dimension, a.size),
                     defaultOperation(tool.tool, dimension, a.size)};
        EXPECT_EQ(describeChange(a, b), "initial state: empty → 2 " + plurals.at(tool.tool));
    }
}

/// `marbler breed swap A B --count 4`: children 3 and 4 repeat the swaps, so they are gentle
/// variations of them; their change is told against the swap each varies (same tools, small
/// moves), not against the home parent.
TEST(ChangeSummary, AVariedChildIsDescribedAgainstTheDesignItVaries) {
    BreedRequest r;
    r.op = GeneticOperator::Swap;
    r.parents = {randomGenome(12, 2), randomGenome(38, 2)};
    r.seed = 5;
    r.count = 4;
    const std::vector<Genome> children = breed(r);
    ASSERT_EQ(children.size(), 4u);
    for (std::size_t i = 2; i < 4; ++i) {
        ASSERT_TRUE(children[i].meta.toJson()["lineage"].contains("variation")) << i;
        const std::string change = children[i].meta.toJson()["lineage"]["change"].get<std::string>();
        EXPECT_EQ(change, "a variation of #" + std::to_string(i - 1) + ": " +
                              describeChange(children[i - 2], children[i]))
            << change;
        EXPECT_EQ(change.find("added"), std::string::npos) << "the same tools as the swap: " << change;
        EXPECT_EQ(change.find("removed"), std::string::npos) << change;
        EXPECT_EQ(change.find("initial state"), std::string::npos) << change;
    }
    // The numbers the window gives its children name the varied one.
    r.childNumbers = {4, 5, 7, 8};
    const std::vector<Genome> numbered = breed(r);
    EXPECT_EQ(
        numbered[2].meta.toJson()["lineage"]["change"].get<std::string>().rfind("a variation of #4: ", 0),
        0u);
    EXPECT_EQ(
        numbered[3].meta.toJson()["lineage"]["change"].get<std::string>().rfind("a variation of #5: ", 0),
        0u);
}

} // namespace
} // namespace marbler
