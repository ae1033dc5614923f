// Colourways (marbler/Colourways.h): a design's structure kept exactly and only its palette
// and background changed, reproducibly from the seed, varied, and every palette readable.

#include "marbler/Colourways.h"
#include "marbler/ChangeSummary.h"
#include "marbler/Error.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Operators.h"

#include <gtest/gtest.h>

#include <set>

namespace marbler {
namespace {

std::vector<Genome> designs() {
    std::vector<Genome> out;
    for (std::uint64_t seed : {1u, 2u, 3u})
        out.push_back(randomGenome(seed, 2));
    out.push_back(randomGenome(4, 3));
    for (const Family& f : allFamilies())
        out.push_back(familyGenome(f, 7));
    return out;
}

std::string palettes(const Genome& g) {
    std::string s = toHex(g.background);
    for (Color c : g.palette)
        s += " " + toHex(c);
    return s;
}

TEST(Colourways, KeepTheStructureExactlyAndChangeThePalette) {
    for (const Genome& design : designs()) {
        ColourwayRequest request;
        request.parents = {design};
        request.seed = 11;
        for (double strength : {1.0, 0.3}) {
            request.strength = strength;
            for (const Genome& c : colourways(request)) {
                EXPECT_TRUE(sameStructure(c, design));
                EXPECT_EQ(c.dimension, design.dimension);
                EXPECT_EQ(c.size, design.size);
                EXPECT_EQ(c.initial, design.initial);
                EXPECT_EQ(c.operations, design.operations);
                EXPECT_EQ(c.source, design.source);
                EXPECT_EQ(c.bleed, design.bleed);
                ASSERT_EQ(c.palette.size(), design.palette.size());
                EXPECT_NE(palettes(c), palettes(design));
                EXPECT_NO_THROW(validateGenome(c, "colourway"));
                EXPECT_EQ(c.meta.toJson()["lineage"]["operator"], ColourwayOperator);
                // It says what changed, and that is only colour.
                const std::string change = c.meta.toJson()["lineage"].value("change", "");
                EXPECT_EQ(change, describeChange(design, c));
                EXPECT_NE(change, "no visible change");
                for (const char* stroke :
                     {"drop", "comb", "wave", "vortex", "initial state", "added", "removed"})
                    EXPECT_EQ(change.find(stroke), std::string::npos) << change;
            }
        }
    }
}

TEST(Colourways, AreReproducibleFromTheSeed) {
    ColourwayRequest request;
    request.parents = {randomGenome(5, 2)};
    request.seed = 99;
    const auto a = colourways(request), b = colourways(request);
    ASSERT_EQ(a.size(), 8u);
    for (std::size_t i = 0; i < a.size(); ++i)
        EXPECT_EQ(a[i], b[i]);
    request.count = 3; // asking for fewer keeps the first ones
    const auto c = colourways(request);
    for (std::size_t i = 0; i < c.size(); ++i)
        EXPECT_EQ(palettes(c[i]), palettes(a[i]));
    request.count = 8;
    request.seed = 100;
    const auto d = colourways(request);
    int same = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        same += palettes(a[i]) == palettes(d[i]);
    EXPECT_LT(same, 2);
}

TEST(Colourways, AreVariedAndNeverRepeatADesign) {
    for (const Genome& design : designs()) {
        for (bool mix : {false, true}) {
            ColourwayRequest request;
            request.parents = {design};
            if (mix) {
                Pcg32 rng(3);
                request.parents.push_back(colourwayOf(design, 1.0, rng));
            }
            request.mix = mix;
            request.seed = 5;
            std::set<std::string> seen;
            for (const Genome& p : request.parents)
                seen.insert(genomeId(p));
            std::set<std::string> backgrounds;
            for (const Genome& c : colourways(request)) {
                EXPECT_TRUE(seen.insert(genomeId(c)).second) << "a repeated design";
                EXPECT_TRUE(sameStructure(
                    c, request.parents[std::size_t(c.meta.toJson()["lineage"]["child"].get<int>() - 1) %
                                       request.parents.size()]));
                backgrounds.insert(palettes(c));
            }
            EXPECT_EQ(backgrounds.size(), 8u);
        }
    }
}

TEST(Colourways, HoldContrastBetweenNeighbouringInksAndTheGround) {
    int fresh = 0, plain = 0, total = 0;
    for (const Genome& design : designs()) {
        for (std::uint64_t seed = 0; seed < 40; ++seed) {
            Pcg32 rng(seed);
            for (double strength : {1.0, 0.5, 0.1}) {
                Genome c = colourwayOf(design, strength, rng);
                ASSERT_TRUE(paletteHasContrast(c.palette, c.background)) << palettes(c);
                fresh += c.palette != design.palette;
                // The greys of last resort are rare: the palettes drawn nearly always hold.
                plain += c.background == Color{0xeb, 0xeb, 0xeb};
                ++total;
            }
        }
    }
    EXPECT_GT(fresh, 0);
    EXPECT_LT(plain, total / 20);
    // The rule itself: too close to the ground, or to the ink before, fails.
    EXPECT_FALSE(paletteHasContrast({{0xf0, 0xf0, 0xf0}}, {0xf3, 0xec, 0xdc}));
    EXPECT_FALSE(paletteHasContrast({{0x20, 0x20, 0x60}, {0x22, 0x22, 0x66}}, {0xf3, 0xec, 0xdc}));
    EXPECT_TRUE(paletteHasContrast({{0x20, 0x20, 0x60}, {0xc0, 0x60, 0x20}}, {0xf3, 0xec, 0xdc}));
}

TEST(Colourways, MixedPalettesComeFromTheParents) {
    const Genome design = randomGenome(8, 2);
    Pcg32 rng(1);
    std::vector<Genome> parents{colourwayOf(design, 1.0, rng), colourwayOf(design, 1.0, rng)};
    std::set<std::string> inks;
    for (const Genome& p : parents)
        for (Color c : p.palette)
            inks.insert(toHex(c));
    int fromParents = 0, total = 0;
    for (int i = 0; i < 20; ++i) {
        Genome c = mixedColourway(parents, std::size_t(i % 2), rng);
        EXPECT_TRUE(sameStructure(c, design));
        EXPECT_TRUE(c.background == parents[0].background || c.background == parents[1].background);
        for (Color ink : c.palette)
            fromParents += inks.count(toHex(ink)), ++total;
    }
    EXPECT_GT(fromParents, total / 2);
}

TEST(Colourways, RefuseALockedPalette) {
    Genome design = randomGenome(2, 2);
    setLocks(design, Locks{.palette = true});
    ColourwayRequest request;
    request.parents = {design};
    EXPECT_THROW(colourways(request), InputError);
    request.parents.clear();
    EXPECT_THROW(colourways(request), InputError);
}

} // namespace
} // namespace marbler
