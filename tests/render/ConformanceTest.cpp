// The CPU renderer against data made by an independent implementation: colour probes at design
// points, and small antialiased renders.

#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
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
                                           "probes-v2-stretch", "probes-v2-core", "probes-v2-flow"),
                         [](const auto& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

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
