// Bleed (genome-format.md, version 2): soft ink edges composited in linear light.

#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/ImageFile.h"
#include "marbler/Params.h"
#include "marbler/Tools.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <set>

namespace marbler {
namespace {

/// The reference's render: traceCovers per sample, composited newest ink first.
Image referenceRender(const Genome& genome, const RenderSettings& settings) {
    std::vector<PreparedOp> ops = prepare(genome);
    const SampleFrame frame = sampleFrame(genome, settings);
    const AaPattern aa = aaPattern(settings.aa);
    Image image;
    image.width = settings.width;
    image.height = settings.height;
    image.rgb.resize(std::size_t(image.width) * image.height * 3);
    std::vector<InkCover> covers;
    for (int j = 0; j < settings.height; ++j)
        for (int i = 0; i < settings.width; ++i) {
            glm::dvec3 sum(0.0);
            for (std::size_t s = 0; s < aa.offsets.size(); ++s) {
                glm::dvec3 p = frame.at(i, j, aa.offsets[s].x, aa.offsets[s].y);
                if (genome.dimension == 2) p.z = 0.0;
                bool stopped = traceCovers(ops, genome.bleed, p, covers);
                glm::dvec3 colour = stopped ? glm::dvec3(0.0) : linearOf(genome.background);
                for (auto it = covers.rbegin(); it != covers.rend(); ++it)
                    colour = it->coverage * linearOf(genome.palette[std::size_t(it->color)]) +
                             (1.0 - it->coverage) * colour;
                sum += aa.weights[s] * colour;
            }
            std::uint8_t* out = image.row(j) + i * 3;
            out[0] = encodeSrgb8(sum.x);
            out[1] = encodeSrgb8(sum.y);
            out[2] = encodeSrgb8(sum.z);
        }
    return image;
}

int mismatches(const Image& image, const nlohmann::json& rows, const std::string& what) {
    int bad = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const nlohmann::json& want = rows[y][x];
            const std::uint8_t* got = image.row(y) + x * 3;
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(got[c]) - want[c].get<int>()) > 2) {
                    ++bad;
                    std::printf("  %s pixel (%d, %d): got %d %d %d, expected %s\n", what.c_str(), x, y,
                                got[0], got[1], got[2], want.dump().c_str());
                    break;
                }
        }
    return bad;
}

/// The conformance file's 2D genome, its settings, and its 3D genome.
struct BleedCase {
    nlohmann::json file = test::loadConformance("bleed-v2.json");
    Genome genome = test::genomeOf(file, "bleed-v2.json");
    Genome solid = test::genomeOf(nlohmann::json{{"genome", file.at("genome3d")}}, "bleed-v2.json genome3d");
    RenderSettings settings() const {
        const nlohmann::json& region = file.at("region");
        RenderSettings s;
        s.width = s.height = 32;
        s.region = Region{region[0].get<double>(), region[1].get<double>(), region[2].get<double>(),
                          region[3].get<double>()};
        return s;
    }
    RenderSettings slice() const {
        RenderSettings s;
        s.width = s.height = 32;
        s.aa = "grid3";
        s.slice = Slice{2, 500.0};
        return s;
    }
};

TEST(Bleed, TheRendererMatchesTheConformanceRenders) {
    BleedCase bleed;
    ASSERT_GT(bleed.genome.bleed, 0.0);
    ASSERT_GT(bleed.solid.bleed, 0.0);
    CpuRenderer renderer(bleed.genome);
    RenderSettings settings = bleed.settings();
    int patterns = 0;
    for (const auto& [name, rows] : bleed.file.at("images").items()) {
        settings.aa = name;
        EXPECT_LE(mismatches(renderer.render(settings), rows, name), 3) << name;
        ++patterns;
    }
    EXPECT_EQ(patterns, 2);
    EXPECT_LE(mismatches(CpuRenderer(bleed.solid).render(bleed.slice()), bleed.file.at("image3d"), "3D"), 3);
}

TEST(Bleed, TheRendererMatchesTheReferenceInEveryVariant) {
    BleedCase bleed;
    for (const std::string& variant : cpuKernelsSupported()) {
        setCpuKernelForTesting(variant);
        for (int dim : {2, 3}) {
            const Genome& genome = dim == 2 ? bleed.genome : bleed.solid;
            RenderSettings settings = dim == 2 ? bleed.settings() : bleed.slice();
            settings.aa = "grid3";
            const Image want = referenceRender(genome, settings);
            const Image got = CpuRenderer(genome).render(settings);
            test::ImageDiff diff = test::compareImages(got, want, 1);
            EXPECT_LE(diff.maxDifference, 1) << variant << " " << dim << "D";
        }
    }
    setCpuKernelForTesting("");
}

TEST(Bleed, TheSoftEdgeNarrowsToTheHardRender) {
    BleedCase bleed;
    RenderSettings settings = bleed.settings();
    settings.aa = "grid3";
    Genome hard = bleed.genome;
    hard.bleed = 0.0;
    const Image sharp = CpuRenderer(hard).render(settings);
    double lastShare = 0.0;
    for (double width : {8.0, 1.0, 0.01, 1e-6}) {
        Genome soft = bleed.genome;
        soft.bleed = width;
        test::ImageDiff diff = test::compareImages(CpuRenderer(soft).render(settings), sharp, 1);
        EXPECT_GE(diff.shareWithin, lastShare) << "bleed " << width;
        lastShare = diff.shareWithin;
    }
    // A bleed far below a sample's spacing changes no pixel but those whose samples sit on an
    // edge.
    EXPECT_GT(lastShare, 0.995);
    Genome tiny = bleed.genome;
    tiny.bleed = 1e-9;
    EXPECT_LE(test::compareImages(CpuRenderer(tiny).render(settings), sharp, 1).maxDifference, 1);
}

TEST(Bleed, ColoursAtPointsCompositeLikeTheRender) {
    // linearColorsAt (a mesh's surface points) against a one-sample render, in 3D.
    BleedCase bleed;
    CpuRenderer renderer(bleed.solid);
    RenderSettings settings = bleed.slice();
    settings.aa = "none";
    const Image image = renderer.render(settings);
    const SampleFrame frame = sampleFrame(bleed.solid, settings);
    std::vector<double> xs, ys, zs;
    for (int j = 0; j < 32; ++j)
        for (int i = 0; i < 32; ++i) {
            glm::dvec3 p = frame.at(i, j, 0.0, 0.0);
            xs.push_back(p.x);
            ys.push_back(p.y);
            zs.push_back(p.z);
        }
    std::vector<double> rgb(xs.size() * 3);
    renderer.linearColorsAt(xs.data(), ys.data(), zs.data(), xs.size(), rgb.data());
    std::set<int> reds;
    for (std::size_t k = 0; k < xs.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(encodeSrgb8(rgb[3 * k + std::size_t(c)]), image.rgb[3 * k + std::size_t(c)]) << k;
            reds.insert(encodeSrgb8(rgb[3 * k]));
        }
    // More shades than the three inks and the background: soft edges were composited.
    EXPECT_GT(reds.size(), 4u);
}

TEST(Bleed, ASoftEdgeBlendsOverTheSourceImage) {
    // One drop over a source image of one colour: a pixel at edge distance e shows
    // c ink + (1 - c) source, c = clamp(0.5 - e / b, 0, 1), in linear light.
    const auto dir = test::outputDir("bleed-source");
    Image plain;
    plain.width = plain.height = 2;
    plain.rgb = {200, 120, 40, 200, 120, 40, 200, 120, 40, 200, 120, 40};
    writeImage(plain, dir / "plain.png");
    Genome genome;
    genome.size = {1000.0, 1000.0, 1000.0};
    genome.palette = {{20, 60, 180}};
    genome.background = {0, 0, 0};
    genome.source = SourceImage{"plain.png"};
    genome.baseDirectory = dir.string();
    genome.bleed = 40.0;
    Operation drop = defaultOperation(Tool::Drop, 2, {500.0, 500.0, 0.0});
    drop.radius = 200.0;
    drop.color = 0;
    genome.initial.push_back(drop);
    CpuRenderer renderer(genome);
    const glm::dvec3 ink = linearOf(genome.palette[0]), source = linearOf({200, 120, 40});
    int blended = 0;
    for (double e = -30.0; e <= 30.0; e += 2.5) {
        const glm::dvec3 p(500.0 + 200.0 + e, 500.0, 0.0);
        const double c = bleedCoverage(e, genome.bleed);
        blended += c > 0.0 && c < 1.0;
        const glm::dvec3 want = c * ink + (1.0 - c) * source;
        RenderSettings settings;
        settings.width = settings.height = 1;
        settings.region = Region{p.x - 0.01, p.y - 0.01, p.x + 0.01, p.y + 0.01};
        const Image image = renderer.render(settings);
        EXPECT_EQ(int(image.rgb[0]), int(encodeSrgb8(want.x))) << "e " << e;
        EXPECT_EQ(int(image.rgb[1]), int(encodeSrgb8(want.y))) << "e " << e;
        EXPECT_EQ(int(image.rgb[2]), int(encodeSrgb8(want.z))) << "e " << e;
    }
    EXPECT_GT(blended, 10);
}

TEST(Bleed, ReferenceMatchesTheConformanceRenders) {
    nlohmann::json file = test::loadConformance("bleed-v2.json");
    Genome genome = test::genomeOf(file, "bleed-v2.json");
    const nlohmann::json& region = file.at("region");
    RenderSettings settings;
    settings.width = settings.height = 32;
    settings.region = Region{region[0].get<double>(), region[1].get<double>(), region[2].get<double>(),
                             region[3].get<double>()};
    for (const auto& [name, rows] : file.at("images").items()) {
        settings.aa = name;
        EXPECT_LE(mismatches(referenceRender(genome, settings), rows, "reference " + name), 3) << name;
    }
    nlohmann::json solid = {{"genome", file.at("genome3d")}};
    Genome genome3 = test::genomeOf(solid, "bleed-v2.json genome3d");
    RenderSettings at;
    at.width = at.height = 32;
    at.aa = "grid3";
    at.slice = Slice{2, 500.0};
    EXPECT_LE(mismatches(referenceRender(genome3, at), file.at("image3d"), "reference 3D"), 3);
}

} // namespace
} // namespace marbler
