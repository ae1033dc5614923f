// The procedural marbled paper (marbler/Paper.h): its recipe, its spacing rule, determinism.

#include "marbler/Paper.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Operators.h"
#include "marbler/Tools.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace marbler {
namespace {

double luma(Color c) {
    return (0.299 * c.r + 0.587 * c.g + 0.114 * c.b) / 255.0;
}

/// Options of the classic recipe (the tests below the post's are of it).
PaperOptions sheet(double width, double height, int colors = 5, int passes = 3, bool pastel = false) {
    PaperOptions options;
    options.recipe = PaperRecipe::Classic;
    options.width = width;
    options.height = height;
    options.colors = colors;
    options.passes = passes;
    options.pastel = pastel;
    return options;
}

TEST(PaperGenome, SameSeedGivesTheSameGenomeAndOtherSeedsDiffer) {
    const PaperOptions a4 = sheet(210, 297);
    const std::string text = serializeGenome(paperGenome(42, a4));
    EXPECT_EQ(text, serializeGenome(paperGenome(42, a4)));
    EXPECT_NE(text, serializeGenome(paperGenome(43, a4)));
    Genome one = paperGenome(42, a4), other = paperGenome(43, a4);
    EXPECT_NE(one.initial, other.initial);
    EXPECT_NE(one.operations, other.operations);
}

TEST(PaperGenome, IsAValidVersion2GenomeThatRoundTrips) {
    for (bool pastel : {false, true}) {
        Genome g = paperGenome(7, sheet(210, 297, 5, 3, pastel));
        EXPECT_NO_THROW(validateGenome(g, "paper"));
        std::string text = serializeGenome(g);
        EXPECT_EQ(toJson(g)["version"], 2); // stretch and bleed are version 2
        Genome back = parseGenome(text, "paper.marble.json");
        EXPECT_EQ(back, g);
        EXPECT_EQ(g.meta.toJson()["generator"], PaperGeneratorVersion);
        EXPECT_EQ(g.meta.toJson()["seed"], 7);
        EXPECT_EQ(g.size.x, 210.0);
        EXPECT_EQ(g.size.y, 297.0);
    }
}

TEST(PaperGenome, HasTheRecipeDropsByColourShrinkingThenWeakeningStretchPassesAndABleed) {
    for (int colors : {1, 3, 5, 8}) {
        for (int passes : {0, 1, 3, 6}) {
            SCOPED_TRACE("colors " + std::to_string(colors) + ", passes " + std::to_string(passes));
            const double w = 210, h = 297;
            Genome g = paperGenome(1000 + colors * 10 + passes, sheet(w, h, colors, passes));
            const double spacing = paperSpacing(w, h, colors);
            ASSERT_EQ(static_cast<int>(g.palette.size()), colors);

            // Drops only, in layers of one colour each, in palette order; every colour laid.
            std::vector<int> perColour(static_cast<std::size_t>(colors), 0);
            int lastColour = 0;
            for (const Operation& op : g.initial) {
                ASSERT_EQ(op.tool, Tool::Drop);
                ASSERT_GE(op.color, lastColour);
                lastColour = op.color;
                glm::dvec2 radii = paperRadii(spacing, op.color);
                EXPECT_GE(op.radius, radii.x - 0.005);
                EXPECT_LE(op.radius, radii.y + 0.005);
                ++perColour[static_cast<std::size_t>(op.color)];
            }
            for (int count : perColour)
                EXPECT_GT(count, 10);
            // Each later colour's range lies below the one before.
            for (int layer = 1; layer < colors; ++layer) {
                EXPECT_LT(paperRadii(spacing, layer).y, paperRadii(spacing, layer - 1).y);
                EXPECT_LT(paperRadii(spacing, layer).x, paperRadii(spacing, layer - 1).x);
            }

            ASSERT_EQ(static_cast<int>(g.operations.size()), passes);
            double lastShift = 1e300;
            for (const Operation& op : g.operations) {
                ASSERT_EQ(op.tool, Tool::Stretch);
                EXPECT_GE(op.power, 0.25);
                EXPECT_LE(op.power, 0.75);
                EXPECT_GT(std::abs(op.shift), 0.0);
                EXPECT_LT(std::abs(op.shift), lastShift);
                lastShift = std::abs(op.shift);
                // Along x from the top left (N down) or along y from the top right (N left):
                // the teeth measure from the edge N points away from, over the whole sheet.
                ASSERT_TRUE(op.angle == 0.0 || op.angle == 90.0) << op.angle;
                const double extent = op.angle == 0.0 ? h : w;
                EXPECT_EQ(op.center, op.angle == 0.0 ? glm::dvec3(0.0) : glm::dvec3(w, 0.0, 0.0));
                ASSERT_GE(op.teeth.size(), 2u);
                EXPECT_LE(op.teeth.front(), 0.0);
                EXPECT_GE(op.teeth.back(), extent);
                double smallest = 1e300, largest = 0.0;
                for (std::size_t i = 1; i < op.teeth.size(); ++i) {
                    smallest = std::min(smallest, op.teeth[i] - op.teeth[i - 1]);
                    largest = std::max(largest, op.teeth[i] - op.teeth[i - 1]);
                }
                // Poisson-disk spaced: no two teeth closer than the pass's gap, none more than
                // 1.8 gaps apart (the gap is at least 0.35 spacings).
                EXPECT_GE(smallest, 0.35 * spacing - 0.01);
                EXPECT_LE(largest, 1.8 * smallest * (1.0 + 1e-9) + 0.02);
            }
            // Both directions occur over the passes of a few seeds, checked below.
            EXPECT_GT(g.bleed, 0.0);
            EXPECT_LT(g.bleed, 0.02 * spacing);
        }
    }
}

TEST(PaperGenome, PassesGoBothWaysAlongBothAxes) {
    int alongX = 0, alongY = 0, positive = 0, negative = 0;
    for (std::uint64_t seed = 0; seed < 20; ++seed)
        for (const Operation& op : paperGenome(seed, sheet(210, 297)).operations) {
            (op.angle == 0.0 ? alongX : alongY) += 1;
            (op.shift > 0.0 ? positive : negative) += 1;
        }
    EXPECT_GT(alongX, 10);
    EXPECT_GT(alongY, 10);
    EXPECT_GT(positive, 10);
    EXPECT_GT(negative, 10);
}

TEST(PaperGenome, EveryPassCombsTheWholeSheet) {
    // The sign of the stretch's normal decides which side of the origin its teeth lie on: a
    // pass from the wrong edge would move nothing on the sheet. Through the reference map,
    // every point of the sheet off a tooth moves, along the pass's axis only.
    const double w = 148, h = 210;
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
        Genome g = paperGenome(seed, sheet(w, h, 3, 4));
        for (const Operation& op : g.operations) {
            PreparedOp prepared = prepare(op, 2);
            int moved = 0, total = 0;
            for (double x = 0.5; x < w; x += 3.0)
                for (double y = 0.5; y < h; y += 3.0) {
                    glm::dvec3 p(x, y, 0.0);
                    glm::dvec3 q = forwardMap(prepared, p);
                    ++total;
                    if (glm::length(q - p) > 1e-6) ++moved;
                    // Along x the shift is horizontal, along y vertical.
                    EXPECT_NEAR(op.angle == 0.0 ? q.y : q.x, op.angle == 0.0 ? y : x, 1e-9);
                }
            EXPECT_GE(moved, total - total / 50) << "seed " << seed << ", angle " << op.angle;
        }
    }
}

TEST(PaperGenome, DropCentresOfOneColourKeepThePoissonDiskDistance) {
    for (auto [w, h] : {std::pair{105.0, 148.0}, std::pair{210.0, 297.0}, std::pair{420.0, 594.0}}) {
        Genome g = paperGenome(5, sheet(w, h));
        const double spacing = paperSpacing(w, h, 5);
        double closest = 1e300;
        for (std::size_t i = 0; i < g.initial.size(); ++i)
            for (std::size_t j = i + 1; j < g.initial.size(); ++j) {
                if (g.initial[i].color != g.initial[j].color) continue;
                glm::dvec3 d = g.initial[i].center - g.initial[j].center;
                closest = std::min(closest, std::sqrt(d.x * d.x + d.y * d.y));
            }
        EXPECT_GE(closest, spacing) << w << " x " << h;
        // Centres lie on the sheet or within half a spacing round it.
        for (const Operation& op : g.initial) {
            EXPECT_GE(op.center.x, -0.5 * spacing);
            EXPECT_LE(op.center.x, w + 0.5 * spacing);
            EXPECT_GE(op.center.y, -0.5 * spacing);
            EXPECT_LE(op.center.y, h + 0.5 * spacing);
        }
    }
}

TEST(PaperGenome, PoissonDiskSamplingIsDenseAndKeepsItsDistance) {
    Pcg32 rng(9);
    const double d = 10.0;
    std::vector<glm::dvec2> points = poissonDisk(rng, 0, 0, 200, 100, d, 10000);
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_GE(points[i].x, 0.0);
        EXPECT_LE(points[i].x, 200.0);
        EXPECT_GE(points[i].y, 0.0);
        EXPECT_LE(points[i].y, 100.0);
        for (std::size_t j = i + 1; j < points.size(); ++j)
            EXPECT_GE(glm::length(points[i] - points[j]), d);
    }
    // Bridson's sampling leaves no disc of radius 2d empty: a dense cover (about 0.7 per d^2),
    // far above what a sparse accept-reject would keep.
    EXPECT_GT(points.size(), 200u * 100u / (d * d) * 0.5);
    for (double x = 0; x <= 200; x += 5)
        for (double y = 0; y <= 100; y += 5) {
            double nearest = 1e300;
            for (const glm::dvec2& p : points)
                nearest = std::min(nearest, glm::length(p - glm::dvec2(x, y)));
            EXPECT_LT(nearest, 2.0 * d) << x << ", " << y;
        }
    Pcg32 capped(9);
    EXPECT_EQ(poissonDisk(capped, 0, 0, 200, 100, d, 17).size(), 17u);
}

TEST(PaperGenome, TheSpacingRuleGrowsWithTheFourthRootOfTheArea) {
    EXPECT_DOUBLE_EQ(paperSpacing(210, 297, 5), 28.0);
    EXPECT_NEAR(paperSpacing(420, 594, 5), 28.0 * std::sqrt(2.0), 1e-9);            // A2
    EXPECT_NEAR(paperSpacing(148, 210, 5), 28.0 / std::sqrt(std::sqrt(2.0)), 0.05); // A5
    EXPECT_NEAR(paperSpacing(105, 148, 5), 28.0 / std::sqrt(2.0), 0.05);            // A6
    // Drops a colour grow with the side, not the area: about twice as many at A2 as at A4.
    auto countOf = [](double w, double h) { return paperGenome(11, sheet(w, h, 1, 0)).initial.size(); };
    double a6 = countOf(105, 148), a4 = countOf(210, 297), a2 = countOf(420, 594);
    EXPECT_NEAR(a2 / a4, 2.0, 0.35);
    EXPECT_NEAR(a4 / a6, 2.0, 0.35);
}

TEST(PaperGenome, HugeOrThinSheetsStayWithinTheFormatsLimits) {
    for (auto [w, h] : {std::pair{10000.0, 10000.0}, std::pair{100000.0, 10.0}}) {
        Genome g = paperGenome(3, sheet(w, h, MaxPaperColors, MaxPaperPasses));
        EXPECT_LE(g.initial.size() + g.operations.size(), MaxEntries);
        for (const Operation& op : g.operations)
            EXPECT_LE(op.teeth.size(), MaxTeeth);
        EXPECT_NO_THROW(validateGenome(g, "huge"));
    }
}

TEST(PaperGenome, PastelRecoloursTheSameShapesWithPaleInksOnAWhiteBath) {
    Genome random = paperGenome(21, sheet(210, 297, 6, 3, false));
    Genome pastel = paperGenome(21, sheet(210, 297, 6, 3, true));
    EXPECT_EQ(random.initial, pastel.initial);
    EXPECT_EQ(random.operations, pastel.operations);
    EXPECT_NE(random.palette, pastel.palette);
    EXPECT_GT(luma(pastel.background), 0.9);
    for (Color ink : pastel.palette)
        EXPECT_GT(luma(ink), 0.5);
    // Random inks are kept visible on their cream bath.
    for (Color ink : random.palette)
        EXPECT_GE(std::abs(luma(ink) - luma(random.background)), 0.1);
}

TEST(PaperGenome, BadOptionsAreRefused) {
    EXPECT_THROW(paperGenome(1, sheet(0, 297)), InputError);
    EXPECT_THROW(paperGenome(1, sheet(210, -1)), InputError);
    EXPECT_THROW(paperGenome(1, sheet(210, 1e9)), InputError);
    EXPECT_THROW(paperGenome(1, sheet(210, 297, 0)), InputError);
    EXPECT_THROW(paperGenome(1, sheet(210, 297, MaxPaperColors + 1)), InputError);
    EXPECT_THROW(paperGenome(1, sheet(210, 297, 5, -1)), InputError);
    EXPECT_THROW(paperGenome(1, sheet(210, 297, 5, MaxPaperPasses + 1)), InputError);
}

// ---- The post's recipe (docs/paper.md) ----

PaperOptions postSheet(double width, double height, int colors = 5, int passes = 3) {
    PaperOptions options;
    options.width = width;
    options.height = height;
    options.colors = colors;
    options.passes = passes;
    return options;
}

TEST(PaperPostRecipe, IsTheDefaultAndReproducibleFromTheSeed) {
    EXPECT_EQ(PaperOptions{}.recipe, PaperRecipe::Post);
    const std::string text = serializeGenome(paperGenome(42, PaperOptions{}));
    EXPECT_EQ(text, serializeGenome(paperGenome(42, postSheet(210, 297))));
    EXPECT_NE(text, serializeGenome(paperGenome(43, PaperOptions{})));
    // The classic recipe is another design from the same seed, and stays what it was.
    EXPECT_NE(text, serializeGenome(paperGenome(42, sheet(210, 297))));
    EXPECT_EQ(paperGenome(42, sheet(210, 297)).meta.toJson()["generator"], PaperGeneratorVersion);
    EXPECT_EQ(paperGenome(42, PaperOptions{}).meta.toJson()["generator"], PaperPostGeneratorVersion);
}

TEST(PaperPostRecipe, IsAValidWrappedVersion3GenomeThatRoundTrips) {
    Genome g = paperGenome(7, postSheet(210, 297));
    EXPECT_TRUE(g.wrap);
    EXPECT_NO_THROW(validateGenome(g, "paper"));
    EXPECT_EQ(toJson(g)["version"], 3);
    EXPECT_EQ(parseGenome(serializeGenome(g), "paper.marble.json"), g);
    EXPECT_EQ(g.meta.toJson()["paper"]["recipe"], "post");
}

TEST(PaperPostRecipe, TheSpacingIsTwoCentimetresAtA4) {
    EXPECT_DOUBLE_EQ(paperPostSpacing(210, 297, 5), 20.0);
    EXPECT_NEAR(paperPostSpacing(420, 594, 5), 20.0 * std::sqrt(2.0), 1e-9);
}

TEST(PaperPostRecipe, TheBathIsTheFirstColourAndTheDropsArePaintedCirclesNewestOnTop) {
    for (int colors : {1, 2, 5, 9}) {
        Genome g = paperGenome(300 + colors, postSheet(210, 297, colors));
        ASSERT_EQ(static_cast<int>(g.palette.size()), colors);
        EXPECT_EQ(g.background, g.palette.front());
        // Sprays (they push nothing: a later circle covers what it lies on), one layer for each
        // colour after the first, in palette order, every one laid.
        std::vector<int> perColour(static_cast<std::size_t>(colors), 0);
        int lastColour = 1;
        for (const Operation& op : g.initial) {
            ASSERT_EQ(op.tool, Tool::Spray);
            ASSERT_GE(op.color, lastColour);
            lastColour = op.color;
            ++perColour[static_cast<std::size_t>(op.color)];
        }
        EXPECT_EQ(perColour[0], 0);
        for (int color = 1; color < colors; ++color)
            EXPECT_GT(perColour[static_cast<std::size_t>(color)], 50) << color;
    }
}

TEST(PaperPostRecipe, DropRadiiAreThreeQuartersToOneSpacingShrinkingByTheGoldenRatio) {
    const double spacing = paperPostSpacing(210, 297, 6);
    EXPECT_DOUBLE_EQ(paperPostRadii(spacing, 1).x, 0.75 * spacing);
    EXPECT_DOUBLE_EQ(paperPostRadii(spacing, 1).y, 1.0 * spacing);
    for (int color = 2; color < 6; ++color) {
        EXPECT_NEAR(paperPostRadii(spacing, color - 1).x / paperPostRadii(spacing, color).x, GoldenRatio,
                    1e-12);
        EXPECT_NEAR(paperPostRadii(spacing, color - 1).y / paperPostRadii(spacing, color).y, GoldenRatio,
                    1e-12);
    }
    std::vector<double> least(6, 1e300), most(6, 0.0);
    for (std::uint64_t seed = 0; seed < 4; ++seed)
        for (const Operation& op : paperGenome(seed, postSheet(210, 297, 6)).initial) {
            glm::dvec2 radii = paperPostRadii(spacing, op.color);
            EXPECT_GE(op.radius, radii.x - 0.005);
            EXPECT_LE(op.radius, radii.y + 0.005);
            least[std::size_t(op.color)] = std::min(least[std::size_t(op.color)], op.radius);
            most[std::size_t(op.color)] = std::max(most[std::size_t(op.color)], op.radius);
        }
    // The draws cover the range, not a part of it.
    for (int color = 1; color < 6; ++color) {
        glm::dvec2 radii = paperPostRadii(spacing, color);
        EXPECT_LT(least[std::size_t(color)], radii.x + 0.05 * (radii.y - radii.x)) << color;
        EXPECT_GT(most[std::size_t(color)], radii.y - 0.05 * (radii.y - radii.x)) << color;
    }
}

TEST(PaperPostRecipe, TheFirstPassShiftsTwoToSevenSpacingsAndEachLaterOneByTheGoldenRatioLess) {
    const double spacing = paperPostSpacing(210, 297, 5);
    EXPECT_EQ(paperPostFirstShift(spacing), glm::dvec2(2.0 * spacing, 7.0 * spacing));
    double least = 1e300, most = 0.0;
    int positive = 0, negative = 0, alongX = 0, alongY = 0;
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
        Genome g = paperGenome(seed, postSheet(210, 297, 5, 4));
        ASSERT_EQ(g.operations.size(), 4u);
        const double first = std::abs(g.operations[0].shift);
        EXPECT_GE(first, 2.0 * spacing - 0.005);
        EXPECT_LE(first, 7.0 * spacing + 0.005);
        least = std::min(least, first);
        most = std::max(most, first);
        for (std::size_t pass = 1; pass < g.operations.size(); ++pass)
            EXPECT_NEAR(std::abs(g.operations[pass].shift), first / std::pow(GoldenRatio, double(pass)),
                        0.011);
        for (const Operation& op : g.operations) {
            (op.shift > 0.0 ? positive : negative) += 1;
            (op.angle == 0.0 ? alongX : alongY) += 1;
        }
    }
    EXPECT_LT(least, 2.5 * spacing);
    EXPECT_GT(most, 6.5 * spacing);
    EXPECT_GT(positive, 40);
    EXPECT_GT(negative, 40);
    EXPECT_GT(alongX, 40);
    EXPECT_GT(alongY, 40);
}

TEST(PaperPostRecipe, ToothGapsGrowByTheGoldenRatioPerPassAndTheTeethEndAtTheBorders) {
    const double w = 210, h = 297;
    const double spacing = paperPostSpacing(w, h, 5);
    for (int pass = 1; pass < 5; ++pass)
        EXPECT_NEAR(paperPostToothGap(spacing, pass).x / paperPostToothGap(spacing, pass - 1).x, GoldenRatio,
                    1e-12);
    EXPECT_EQ(paperPostToothGap(spacing, 0), glm::dvec2(0.5 * spacing, 1.0 * spacing));
    std::vector<double> meanGap(4, 0.0);
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        Genome g = paperGenome(seed, postSheet(w, h, 5, 4));
        for (std::size_t pass = 0; pass < g.operations.size(); ++pass) {
            const Operation& op = g.operations[pass];
            ASSERT_TRUE(op.angle == 0.0 || op.angle == 90.0) << op.angle;
            EXPECT_EQ(op.center, op.angle == 0.0 ? glm::dvec3(0.0) : glm::dvec3(w, 0.0, 0.0));
            const double extent = op.angle == 0.0 ? h : w;
            ASSERT_GE(op.teeth.size(), 2u);
            EXPECT_EQ(op.teeth.front(), 0.0);
            EXPECT_EQ(op.teeth.back(), extent);
            const glm::dvec2 gaps = paperPostToothGap(spacing, int(pass));
            for (std::size_t i = 1; i < op.teeth.size(); ++i) {
                double gap = op.teeth[i] - op.teeth[i - 1];
                // The last gap ends at the border: at least half a gap (a shorter one merges).
                const double least = i + 1 == op.teeth.size() ? 0.5 : 1.0;
                EXPECT_GE(gap, least * std::min(gaps.x, 0.5 * extent) - 0.011);
                // 1.8 gaps at most, the last one (merged with a short remainder) 2.3.
                EXPECT_LE(gap, 2.3 * gaps.y + 0.02);
            }
            meanGap[pass] += extent / double(op.teeth.size() - 1);
            // The shift follows the |sin|^p profile with one of the kernel's exact powers.
            EXPECT_TRUE(op.power == 0.5 || op.power == 1.0 || op.power == 2.0) << op.power;
        }
    }
    for (std::size_t pass = 1; pass < meanGap.size(); ++pass)
        EXPECT_GT(meanGap[pass], meanGap[pass - 1] * 1.2) << pass;
}

TEST(PaperPostRecipe, BleedsForThePostsBlur) {
    Genome g = paperGenome(5, postSheet(210, 297));
    EXPECT_DOUBLE_EQ(g.bleed, 20.0 / 25.0);
}

TEST(PaperPostRecipe, HugeOrThinSheetsStayWithinTheFormatsLimits) {
    for (auto [w, h] : {std::pair{10000.0, 10000.0}, std::pair{100000.0, 10.0}, std::pair{3.0, 2.0}}) {
        Genome g = paperGenome(3, postSheet(w, h, MaxPaperColors, MaxPaperPasses));
        EXPECT_LE(g.initial.size() + g.operations.size(), MaxEntries);
        for (const Operation& op : g.operations)
            EXPECT_LE(op.teeth.size(), MaxTeeth);
        EXPECT_NO_THROW(validateGenome(g, "huge")) << w << " x " << h;
    }
}

TEST(PaperPostRecipe, BreedingAWrappedPaperGivesValidChildrenThatWrapWhileTheyCan) {
    // The window breeds from a new paper: every operator's children are valid, and a child
    // keeps the wrap exactly when all its steps can wrap (a drop or comb it was given cannot).
    PaperOptions options = postSheet(60, 40, 4, 3);
    const Genome a = paperGenome(1, options), b = paperGenome(2, options);
    const Genome plain = paperGenome(3, sheet(60, 40, 4, 3)); // classic: drops, no wrap
    int wrapped = 0;
    for (GeneticOperator op : {GeneticOperator::Alter, GeneticOperator::Recombine, GeneticOperator::Swap,
                               GeneticOperator::Reinit}) {
        BreedRequest request;
        request.op = op;
        request.parents = op == GeneticOperator::Alter || op == GeneticOperator::Reinit
                              ? std::vector<Genome>{a}
                              : std::vector<Genome>{a, op == GeneticOperator::Swap ? plain : b};
        request.seed = 11;
        request.count = 6;
        request.strength = 0.8;
        std::vector<Genome> children;
        ASSERT_NO_THROW(children = breed(request)) << int(op);
        for (const Genome& child : children) {
            EXPECT_NO_THROW(validateGenome(child, "child"));
            if (child.wrap) {
                EXPECT_TRUE(canWrap(child));
            }
            wrapped += child.wrap;
        }
    }
    EXPECT_GT(wrapped, 0);
}

TEST(PaperPostRecipe, BreedingAHalfDropPaperKeepsItsLatticeOrDropsTheWrapWhole) {
    // Issue 29: a child that keeps the wrap keeps the parents' lattice (and its steps fit it); a
    // child that loses it is a plain design, written and read back as the same genome.
    PaperOptions options = postSheet(60, 40, 4, 3);
    options.lattice = Lattice::HalfDrop;
    const Genome a = paperGenome(1, options), b = paperGenome(2, options);
    const Genome plain = paperGenome(3, sheet(60, 40, 4, 3));
    int wrapped = 0, plainChildren = 0;
    for (GeneticOperator op : {GeneticOperator::Alter, GeneticOperator::Recombine, GeneticOperator::Swap}) {
        BreedRequest request;
        request.op = op;
        request.parents = op == GeneticOperator::Alter
                              ? std::vector<Genome>{a}
                              : std::vector<Genome>{a, op == GeneticOperator::Swap ? plain : b};
        request.seed = 12;
        request.count = 6;
        request.strength = 0.8;
        for (const Genome& child : breed(request)) {
            EXPECT_NO_THROW(validateGenome(child, "child"));
            EXPECT_EQ(child.lattice, child.wrap ? Lattice::HalfDrop : Lattice::Straight);
            EXPECT_EQ(parseGenome(serializeGenome(child), "child").lattice, child.lattice);
            wrapped += child.wrap;
            plainChildren += !child.wrap;
        }
    }
    EXPECT_GT(wrapped, 0);
    EXPECT_GT(plainChildren, 0); // the swap with a classic paper's drops
}

// ---- end of the post's recipe ----

} // namespace
} // namespace marbler
