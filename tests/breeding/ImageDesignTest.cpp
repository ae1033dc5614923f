// Designs that marble a picture (marbler/ImageDesign.h): valid, reproducible, the picture as
// the bath with no ink on it, a flow that carries it, and the picture's shape kept.

#include "marbler/ImageDesign.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "marbler/Tools.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace marbler;

namespace {

const Operation* flowOf(const Genome& g) {
    auto it = std::find_if(g.operations.begin(), g.operations.end(),
                           [](const Operation& op) { return op.tool == Tool::Flow; });
    return it == g.operations.end() ? nullptr : &*it;
}

} // namespace

TEST(ImageDesign, AValidVersion2DesignWithThePictureAsItsBathAndAFlow) {
    std::set<std::string> fields;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const Genome g = imageDesign(seed, "photo.jpg", 1.5, "photo marbled");
        ASSERT_NO_THROW(validateGenome(g, "design")) << "seed " << seed;
        ASSERT_TRUE(g.source.has_value());
        EXPECT_EQ(g.source->image, "photo.jpg");
        EXPECT_TRUE(g.initial.empty()) << "no ink hides the picture";
        const Operation* flow = flowOf(g);
        ASSERT_NE(flow, nullptr) << "seed " << seed;
        fields.insert(flow->field == FlowField::Cells ? "cells" : "cavity");
        EXPECT_GE(g.operations.size(), 2u) << "a flow and strokes of the craft";
        EXPECT_EQ(requiredVersion(g), 2);
        EXPECT_EQ(g.meta.toJson().value("name", ""), "photo marbled");
        // Saved and read back: the same design.
        EXPECT_EQ(parseGenome(serializeGenome(g), "design"), g);
    }
    EXPECT_EQ(fields.size(), 2u) << "both fields are drawn";
}

TEST(ImageDesign, TheSameSeedGivesTheSameDesignAndOthersDiffer) {
    EXPECT_EQ(imageDesign(7, "a.png", 1.0, "a"), imageDesign(7, "a.png", 1.0, "a"));
    EXPECT_NE(imageDesign(7, "a.png", 1.0, "a").operations, imageDesign(8, "a.png", 1.0, "a").operations);
}

TEST(ImageDesign, KeepsThePicturesShape) {
    const Genome wide = imageDesign(3, "a.png", 2.0, "a");
    EXPECT_DOUBLE_EQ(wide.size.x, 1000.0);
    EXPECT_DOUBLE_EQ(wide.size.y, 500.0);
    const Genome tall = imageDesign(3, "a.png", 0.5, "a");
    EXPECT_DOUBLE_EQ(tall.size.y, 2000.0);
}

TEST(ImageDesign, TheCavityLiesInsideTheBath) {
    // The cavity's box (its local [0, Lx] x [0, Ly]) is placed inside the design at every angle
    // drawn, so the flow carries the picture rather than the bath beyond it.
    int cavities = 0;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        const Genome g = imageDesign(seed, "a.png", 0.8, "a");
        const Operation* flow = flowOf(g);
        ASSERT_NE(flow, nullptr);
        if (flow->field != FlowField::Cavity) continue;
        ++cavities;
        const PreparedOp op = prepare(*flow, 2);
        for (double s : {0.0, 1.0})
            for (double t : {0.0, 1.0}) {
                const glm::dvec3 corner = op.c + s * flow->extent.x * op.m + t * flow->extent.y * op.n;
                EXPECT_GE(corner.x, -1e-6) << "seed " << seed;
                EXPECT_LE(corner.x, g.size.x + 1e-6) << "seed " << seed;
                EXPECT_GE(corner.y, -1e-6) << "seed " << seed;
                EXPECT_LE(corner.y, g.size.y + 1e-6) << "seed " << seed;
            }
    }
    EXPECT_GT(cavities, 5);
}

TEST(ImageDesign, RefusesNoPictureOrNoShape) {
    EXPECT_THROW(imageDesign(1, "", 1.0, "a"), InputError);
    EXPECT_THROW(imageDesign(1, "a.png", 0.0, "a"), InputError);
    EXPECT_THROW(imageDesign(1, "a.png", std::numeric_limits<double>::infinity(), "a"), InputError);
}
