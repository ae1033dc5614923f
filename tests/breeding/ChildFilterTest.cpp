// The child filter of breed() and the families' character under alteration (Operators.h):
// dull children and near-duplicates are drawn again within a fixed budget, reproducibly.

#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Operators.h"
#include "marbler/Params.h"
#include "marbler/Random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace marbler;

BreedRequest request(GeneticOperator op, std::vector<Genome> parents, std::uint64_t seed, int count,
                     double strength) {
    BreedRequest r;
    r.op = op;
    r.parents = std::move(parents);
    r.seed = seed;
    r.count = count;
    r.strength = strength;
    return r;
}

/// A design on the edge of dull: one black drop over nearly all of a white sheet (a glimpse's
/// share 0.969, just under DullShare). Its only stroke is the drop, so alteration moves and resizes
/// it, and a drop a little larger covers the whole sheet.
Genome edgeOfDull() {
    Genome g;
    g.dimension = 2;
    g.size = {1000.0, 1000.0, 0.0};
    g.background = {255, 255, 255};
    g.palette = {{0, 0, 0}};
    Operation drop = defaultOperation(Tool::Drop, 2, {500.0, 500.0, 0.0});
    drop.radius = 622.0;
    drop.color = 0;
    g.operations = {drop};
    return g;
}

int redrawsOf(const Genome& child) {
    return child.meta.toJson()["lineage"].value("redraws", 0);
}

bool dull(const Glimpse& look, const Glimpse& parent) {
    return look.dominantShare > DullShare && look.dominantShare > parent.dominantShare;
}

TEST(Glimpse, SeesColoursInLabAndTheDominantShare) {
    Genome white = edgeOfDull();
    white.operations.clear();
    Genome black = white;
    black.background = {0, 0, 0};
    const Glimpse w = glimpseOf(white), b = glimpseOf(black);
    ASSERT_EQ(w.lab.size(), std::size_t(3 * GlimpseSide * GlimpseSide));
    EXPECT_NEAR(w.lab[0], 100.0, 0.01); // white: L* 100, a* b* 0
    EXPECT_NEAR(w.lab[1], 0.0, 0.01);
    EXPECT_NEAR(w.lab[2], 0.0, 0.01);
    EXPECT_NEAR(b.lab[0], 0.0, 1e-9);
    EXPECT_DOUBLE_EQ(w.dominantShare, 1.0);
    EXPECT_NEAR(meanDeltaE(w, b), 100.0, 0.01);
    EXPECT_EQ(meanDeltaE(w, w), 0.0);
    // sRGB red is L* 53.24, a* 80.09, b* 67.20 (D65).
    Genome red = white;
    red.background = {255, 0, 0};
    const Glimpse r = glimpseOf(red);
    EXPECT_NEAR(r.lab[0], 53.24, 0.02);
    EXPECT_NEAR(r.lab[1], 80.09, 0.02);
    EXPECT_NEAR(r.lab[2], 67.20, 0.02);
    // The drop covers about 96 % of the sheet.
    const Glimpse edge = glimpseOf(edgeOfDull());
    EXPECT_GT(edge.dominantShare, 0.96);
    EXPECT_LT(edge.dominantShare, DullShare);
}

TEST(ChildFilter, DullChildrenAreDrawnAgain) {
    const Genome parent = edgeOfDull();
    const Glimpse parentLook = glimpseOf(parent);
    // Unfiltered, alteration of this design often gives a sheet of black (about one in three).
    int plainDull = 0, plain = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        Pcg32 rng(seed, 1);
        for (int k = 0; k < 8; ++k, ++plain)
            plainDull += dull(glimpseOf(alterGenome(parent, 0.2, rng)), parentLook);
    }
    EXPECT_GT(plainDull, plain / 5) << "the parent should give dull children without the filter";
    // Bred, a child is dull only where every redraw was dull too.
    int redrawn = 0, children = 0, dullKept = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        for (const Genome& child : breed(request(GeneticOperator::Alter, {parent}, seed, 8, 0.2))) {
            ++children;
            const int redraws = redrawsOf(child);
            EXPECT_GE(redraws, 0);
            EXPECT_LE(redraws, ChildRedraws); // at most budget + 1 draws
            redrawn += redraws > 0;
            if (dull(glimpseOf(child), parentLook)) {
                ++dullKept;
                EXPECT_EQ(redraws, ChildRedraws) << "a dull child is kept only when every draw failed";
            }
        }
    }
    EXPECT_GT(redrawn, 0);
    EXPECT_LT(dullKept, plainDull);
    EXPECT_LE(dullKept, children / 50);
}

TEST(ChildFilter, NearDuplicatesAreDrawnAgainReproducibly) {
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        const Genome parent = randomGenome(7, dimension);
        // A very gentle alteration: left alone, most children look like the parent.
        const BreedRequest gentle = request(GeneticOperator::Alter, {parent}, 11, 8, 0.02);
        const std::vector<Genome> children = breed(gentle);
        std::vector<Glimpse> looks{glimpseOf(parent)};
        int redrawn = 0;
        for (const Genome& child : children) {
            const int redraws = redrawsOf(child);
            EXPECT_LE(redraws, ChildRedraws);
            redrawn += redraws > 0;
            const Glimpse look = glimpseOf(child);
            double nearest = 1e9;
            for (const Glimpse& other : looks)
                nearest = std::min(nearest, meanDeltaE(look, other));
            // Either the child stands apart from its parent and earlier siblings, or the whole
            // budget was spent looking for one that does.
            if (nearest < NearDuplicateDeltaE) {
                EXPECT_EQ(redraws, ChildRedraws);
            } else if (redraws > 0) {
                EXPECT_GE(nearest, NearDuplicateDeltaE);
            }
            looks.push_back(look);
        }
        EXPECT_GT(redrawn, 0);
        // The same seed gives the same children, redraws and all.
        const std::vector<Genome> again = breed(gentle);
        ASSERT_EQ(again.size(), children.size());
        for (std::size_t i = 0; i < children.size(); ++i)
            EXPECT_EQ(serializeGenome(again[i]), serializeGenome(children[i]));
        // Asking for fewer keeps the first ones (a child sees only the siblings before it).
        BreedRequest fewer = gentle;
        fewer.count = 3;
        const std::vector<Genome> first = breed(fewer);
        for (std::size_t i = 0; i < first.size(); ++i)
            EXPECT_EQ(serializeGenome(first[i]), serializeGenome(children[i]));
    }
}

TEST(ChildFilter, ChildrenThatPassAreNotRedrawnAndSwapIsNotFiltered) {
    const Genome a = randomGenome(21, 2), b = randomGenome(22, 2);
    // Clearly different designs pass at the first draw: reinit draws a whole new ground.
    for (const Genome& child : breed(request(GeneticOperator::Swap, {a, b}, 3, 6, 0.5)))
        EXPECT_FALSE(child.meta.toJson()["lineage"].contains("redraws"));
    int redrawn = 0;
    for (const Genome& child : breed(request(GeneticOperator::Reinit, {a}, 3, 8, 0.5)))
        redrawn += redrawsOf(child) > 0;
    EXPECT_LE(redrawn, 2);
}

/// The fine comb of a nonpareil: its last stroke.
double fineSpacing(const Genome& g) {
    for (auto it = g.operations.rbegin(); it != g.operations.rend(); ++it)
        if (it->tool == Tool::Comb) return it->spacing;
    return 0.0;
}

TEST(FamilyCharacter, GentleAlterationKeepsANonpareilsCombFine) {
    const Family* nonpareil = findFamily("nonpareil");
    ASSERT_NE(nonpareil, nullptr);
    int left = 0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        const Genome parent = familyGenome(*nonpareil, seed);
        const double spacing = fineSpacing(parent);
        ASSERT_GT(spacing, 0.0);
        for (const Genome& child : breed(request(GeneticOperator::Alter, {parent}, seed, 8, 0.5))) {
            const double s = fineSpacing(child);
            EXPECT_LE(s, 2.0 * spacing) << "seed " << seed;
            EXPECT_GE(s, 0.5 * spacing) << "seed " << seed;
            EXPECT_NE(s, spacing);
        }
        for (const Genome& child : breed(request(GeneticOperator::Alter, {parent}, seed, 8, 1.0))) {
            const double s = fineSpacing(child);
            left += s > 2.0 * spacing || s < 0.5 * spacing;
        }
    }
    // A strong alteration may change the family's character.
    EXPECT_GT(left, 0);
}

TEST(FamilyCharacter, DesignsWithoutAFamilyAlterAsBefore) {
    // The same nonpareil without meta.family: a comb's spacing moves by a share of the design,
    // so at 0.5 some fine combs leave the bound.
    int left = 0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        Genome parent = familyGenome(*findFamily("nonpareil"), seed);
        parent.meta.erase(MetaKey::Family);
        const double spacing = fineSpacing(parent);
        Pcg32 rng(seed, 3);
        for (int k = 0; k < 8; ++k) {
            const double s = fineSpacing(alterGenome(parent, 0.5, rng));
            left += s > 2.0 * spacing || s < 0.5 * spacing;
        }
    }
    EXPECT_GT(left, 0);
}

} // namespace
