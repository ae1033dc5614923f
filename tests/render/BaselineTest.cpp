// Renders of small sample genomes (every tool, 2D and 3D, slices on every axis, every
// antialiasing pattern) against committed baseline images. MARBLER_UPDATE_BASELINES=1 rewrites
// the baselines instead of comparing.

#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/ImageFile.h"
#include "marbler/Params.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <set>

namespace marbler {
namespace {

struct BaselineCase {
    std::string name;   ///< baseline file stem
    std::string genome; ///< tests/data/render/NAME.marble.json
    std::string aa;
    std::optional<Slice> slice;
    int width = 128, height = 128;
    std::optional<Region> region;
};

std::ostream& operator<<(std::ostream& out, const BaselineCase& c) {
    return out << c.name;
}

std::vector<BaselineCase> cases() {
    return {
        {"drops-combs-none", "drops-combs-2d", "none", {}, 128, 128, {}},
        {"drops-combs-grid4", "drops-combs-2d", "grid4", {}, 96, 96, {}},
        {"drops-combs-grid7-region", "drops-combs-2d", "grid7", {}, 64, 48, Region{300, 350, 700, 650}},
        {"waves-swirls-rgss", "waves-swirls-2d", "rgss", {}, 144, 96, {}},
        {"waves-swirls-grid5", "waves-swirls-2d", "grid5", {}, 96, 64, {}},
        {"waves-swirls-grid8", "waves-swirls-2d", "grid8", {}, 72, 48, {}},
        {"source-quincunx", "source-2d", "quincunx", {}, 128, 64, {}},
        {"source-grid6-outside", "source-2d", "grid6", {}, 96, 64, Region{-200, -100, 1000, 500}},
        {"solid-inks-z-grid2", "solid-inks", "grid2", Slice{2, 300.0}, 128, 102, {}},
        {"solid-inks-y-grid3", "solid-inks", "grid3", Slice{1, 400.0}, 128, 77, {}},
        {"solid-inks-x-none", "solid-inks", "none", Slice{0, 500.0}, 107, 80, {}},
        {"solid-swirls-z-none", "solid-swirls", "none", Slice{2, 400.0}, 128, 128, {}},
        {"solid-swirls-y-checker4", "solid-swirls", "checker4", Slice{1, 420.0}, 128, 128, {}},
        {"solid-swirls-x-rooks8", "solid-swirls", "rooks8", Slice{0, 380.0}, 128, 128, {}},
        {"stretch-flow-grid3", "stretch-flow-2d", "grid3", {}, 125, 100, {}},
        {"stretch-flow-none-region", "stretch-flow-2d", "none", {}, 96, 96, Region{250, 150, 650, 550}},
        {"bleed-rgss", "bleed-2d", "rgss", {}, 125, 100, {}},
        {"bleed-none-region", "bleed-2d", "none", {}, 80, 80, Region{300, 200, 500, 400}},
        {"stylus-grid3", "stylus-2d", "grid3", {}, 100, 60, {}},
    };
}

class Baseline : public ::testing::TestWithParam<BaselineCase> {};

TEST_P(Baseline, RenderMatchesTheCommittedImage) {
    const BaselineCase& c = GetParam();
    const std::filesystem::path dir = test::dataDir() / "render";
    Genome genome = loadGenome(dir / (c.genome + ".marble.json"));
    RenderSettings settings;
    settings.width = c.width;
    settings.height = c.height;
    settings.aa = c.aa;
    settings.slice = c.slice;
    settings.region = c.region;
    Image actual = CpuRenderer(genome).render(settings);

    const std::filesystem::path baseline = dir / "baseline" / (c.name + ".png");
    const char* update = std::getenv("MARBLER_UPDATE_BASELINES");
    if (update && std::string(update) == "1") {
        writeImage(actual, baseline);
        GTEST_SKIP() << "baseline rewritten: " << baseline;
    }
    ASSERT_TRUE(std::filesystem::exists(baseline))
        << "no baseline " << baseline << " (run with MARBLER_UPDATE_BASELINES=1 to make it)";
    Image expected = test::readImage8(baseline);
    test::ImageDiff diff = test::compareImages(actual, expected, 2);
    if (!(diff.shareWithin >= 0.995)) {
        std::filesystem::path out = test::outputDir("baseline-" + c.name) / (c.name + ".actual.png");
        writeImage(actual, out);
        ADD_FAILURE() << c.name << ": " << (1.0 - diff.shareWithin) * 100.0
                      << "% of pixels differ by more than 2 levels (largest difference " << diff.maxDifference
                      << "); actual image saved to " << out;
    }
}

INSTANTIATE_TEST_SUITE_P(Render, Baseline, ::testing::ValuesIn(cases()), [](const auto& info) {
    std::string name = info.param.name;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
});

TEST(Baseline, EveryToolAndPatternIsCovered) {
    std::set<std::string> patterns;
    for (const BaselineCase& c : cases())
        patterns.insert(c.aa);
    for (const std::string& name : aaPatternNames())
        EXPECT_TRUE(patterns.count(name)) << name;
    // Every tool of the registry, in every dimension it exists in, with every choice of its
    // choice parameters (a wave's shapes): a new tool without a baseline fails here.
    std::set<std::string> seen;
    for (const BaselineCase& c : cases())
        test::addToolsUsed(loadGenome(test::dataDir() / "render" / (c.genome + ".marble.json")), seen);
    test::expectEveryRegistryTool(seen, "no baseline renders");
}

} // namespace
} // namespace marbler
