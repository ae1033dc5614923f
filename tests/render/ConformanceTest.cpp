// The CPU renderer against data made by an independent implementation: colour probes at design
// points, and small antialiased renders.

#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/Growth.h"
#include "marbler/ImageFile.h"
#include "marbler/Tools.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace marbler {
namespace {

class ProbeFile : public ::testing::TestWithParam<std::string> {};

TEST_P(ProbeFile, EveryProbeMatchesInTheKernelTheReferenceAndARender) {
    const std::string name = GetParam() + ".json";
    nlohmann::json file = test::loadConformance(name);
    Genome genome = test::genomeOf(file, name);
    CpuRenderer renderer(genome);
    std::vector<PreparedOp> ops = prepare(genome);
    const int dim = genome.dimension;
    int checked = 0;
    for (const nlohmann::json& probe : file.at("probes")) {
        glm::dvec3 p(probe[0].get<double>(), probe[1].get<double>(), dim == 3 ? probe[2].get<double>() : 0.0);
        int expected = probe[dim].get<int>();
        EXPECT_EQ(renderer.colorIndexAt(p), expected) << name << " at " << probe.dump();
        EXPECT_EQ(traceColor(ops, p), expected) << name << " (reference) at " << probe.dump();

        // A one-pixel render centred on the probe sees the same colour.
        RenderSettings settings;
        settings.width = settings.height = 1;
        settings.threads = 1;
        settings.region = Region{p.x - 0.5, p.y - 0.5, p.x + 0.5, p.y + 0.5};
        if (dim == 3) settings.slice = Slice{2, p.z};
        Image image = renderer.render(settings);
        Color want = expected >= 0 ? genome.palette[expected] : genome.background;
        EXPECT_EQ((Color{image.rgb[0], image.rgb[1], image.rgb[2]}), want)
            << name << " pixel at " << probe.dump();
        ++checked;
    }
    EXPECT_GT(checked, 100);
}

INSTANTIATE_TEST_SUITE_P(Conformance, ProbeFile,
                         ::testing::Values("probes-0", "probes-1", "probes-2", "probes-3", "probes-4",
                                           "probes-v2-stretch", "probes-v2-core", "probes-v2-flow",
                                           "probes-v3-stylus"),
                         [](const auto& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

TEST(Conformance, AStylusGrowsAsTheReferenceDraws) {
    // probes-v3-stylus.json's design with its last step, the rake, at progress 0.25, 0.5 and 1
    // (the stylus has travelled that far), at 24x24 without antialiasing.
    nlohmann::json file = test::loadConformance("probes-v3-stylus.json");
    Genome genome = test::genomeOf(file, "probes-v3-stylus.json");
    const double last = double(stepCount(genome) - 1);
    int frames = 0;
    for (const auto& [progress, rows] : file.at("progress").items()) {
        Genome design = designAtGrowth(genome, last + std::stod(progress));
        RenderSettings settings;
        settings.width = settings.height = 24;
        settings.aa = "none";
        Image image = CpuRenderer(design).render(settings);
        int equal = 0;
        for (int y = 0; y < 24; ++y)
            for (int x = 0; x < 24; ++x) {
                const nlohmann::json& want = rows[y][x];
                const std::size_t at = 3 * std::size_t(y * 24 + x);
                equal += image.rgb[at] == want[0].get<int>() && image.rgb[at + 1] == want[1].get<int>() &&
                         image.rgb[at + 2] == want[2].get<int>();
            }
        EXPECT_EQ(equal, 24 * 24) << "progress " << progress;
        ++frames;
    }
    EXPECT_EQ(frames, 3);
}

TEST(Conformance, EbruHeartsRenderAsTheirReference) {
    // The example of version 3 (a row of ringed drops, one stylus stroke through them) against
    // the independent reference's render without antialiasing: pixel for pixel but for a hair's
    // width of edges.
    Genome genome = loadGenome(test::dataDir() / "examples" / "ebru-hearts.marble.json");
    Image expected = test::readImage8(test::dataDir() / "reference" / "ebru-hearts-noaa.png");
    RenderSettings settings;
    settings.width = expected.width;
    settings.height = expected.height;
    settings.aa = "none";
    Image actual = CpuRenderer(genome).render(settings);
    test::ImageDiff diff = test::compareImages(actual, expected, 0);
    if (!(diff.shareWithin >= 0.995)) {
        std::filesystem::path out = test::outputDir("ebru-hearts") / "ebru-hearts.actual.png";
        writeImage(actual, out);
        ADD_FAILURE() << (1.0 - diff.shareWithin) * 100.0 << "% of pixels differ; actual image saved to "
                      << out;
    }
}

TEST(Conformance, AntialiasedRendersMatchWithinTwoLevels) {
    nlohmann::json file = test::loadConformance("antialias.json");
    Genome genome = test::genomeOf(file, "antialias.json");
    CpuRenderer renderer(genome);
    const nlohmann::json& region = file.at("region");
    RenderSettings settings;
    settings.width = file.at("width").get<int>();
    settings.height = file.at("height").get<int>();
    settings.region = Region{region[0].get<double>(), region[1].get<double>(), region[2].get<double>(),
                             region[3].get<double>()};
    int patterns = 0;
    for (const auto& [name, rows] : file.at("images").items()) {
        settings.aa = name;
        Image image = renderer.render(settings);
        // A sample a hair from an ink boundary may fall either way in two implementations; such
        // pixels are rare and differ by a sample's weight, so allow a handful and print them.
        int mismatches = 0;
        for (int y = 0; y < settings.height; ++y)
            for (int x = 0; x < settings.width; ++x) {
                const nlohmann::json& want = rows[y][x];
                const std::uint8_t* got = image.row(y) + x * 3;
                for (int c = 0; c < 3; ++c)
                    if (std::abs(int(got[c]) - want[c].get<int>()) > 2) {
                        ++mismatches;
                        std::printf("  %s pixel (%d, %d): got %d %d %d, expected %s\n", name.c_str(), x, y,
                                    got[0], got[1], got[2], want.dump().c_str());
                        break;
                    }
            }
        EXPECT_LE(mismatches, 3) << name;
        ++patterns;
    }
    EXPECT_GE(patterns, 8);
}

} // namespace
} // namespace marbler
