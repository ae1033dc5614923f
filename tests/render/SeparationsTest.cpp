// Raster separations (`marbler render --separations DIR`, marbler/Separations.h): the masks
// recombined with the inks' colours give the raster render back, byte for byte without
// antialiasing and within the masks' rounding with it; the indexed PNG decodes to the render and
// its palette is the design's inks; 1-bit masks for screens; what separations refuse.

#include "RenderTestUtil.h"
#include "TestUtil.h"

#include "marbler/GenomeIO.h"
#include "marbler/Image.h"
#include "marbler/Separations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace marbler {
namespace {

using test::runMarbler;

/// Designs without bleed (separations draw its hard edges, the render its soft ones): flat
/// examples and render designs of every flat tool, and a solid's slice.
struct SeparatedCase {
    std::string name;
    std::filesystem::path file;
    std::vector<std::string> extra; ///< options the render needs (a slice)
};

std::vector<SeparatedCase> separatedCases() {
    std::vector<SeparatedCase> cases;
    for (const char* name : {"five-stones", "flame-comb-vortex", "ebru-hearts"})
        cases.push_back({name, test::dataDir() / "examples" / (std::string(name) + ".marble.json"), {}});
    for (const char* name : {"drops-combs-2d", "waves-swirls-2d", "stretch-flow-2d"})
        cases.push_back({name, test::dataDir() / "render" / (std::string(name) + ".marble.json"), {}});
    cases.push_back(
        {"slate-block", test::dataDir() / "examples" / "slate-block.marble.json", {"--slice", "z=500"}});
    return cases;
}

/// Renders `c` to a PNG and its separations into a folder with the same options.
struct Rendered {
    Image raster;
    std::filesystem::path folder;
    Genome genome;
};

Rendered renderBoth(const SeparatedCase& c, const std::filesystem::path& dir,
                    const std::vector<std::string>& options) {
    Rendered out;
    out.genome = loadGenome(c.file);
    out.folder = dir / (c.name + "-separations");
    const auto png = dir / (c.name + ".png");
    std::vector<std::string> common = {"--width", "160"};
    common.insert(common.end(), options.begin(), options.end());
    common.insert(common.end(), c.extra.begin(), c.extra.end());
    std::vector<std::string> plain = {"render", c.file.string(), "-o", png.string()};
    plain.insert(plain.end(), common.begin(), common.end());
    auto r = runMarbler(plain);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::vector<std::string> separated = {"render", c.file.string(), "--separations", out.folder.string()};
    separated.insert(separated.end(), common.begin(), common.end());
    r = runMarbler(separated);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    out.raster = test::readImage8(png);
    return out;
}

/// The masks of a folder, background first, as bytes (the red channel of the grey image).
std::vector<std::vector<std::uint8_t>> readMasks(const std::filesystem::path& folder, std::size_t inks) {
    std::vector<std::vector<std::uint8_t>> masks;
    const std::vector<std::string> names = separationFileNames(inks);
    for (std::size_t k = 0; k + 1 < names.size(); ++k) {
        const Image image = test::readImage8(folder / names[k]);
        std::vector<std::uint8_t>& mask = masks.emplace_back(std::size_t(image.width) * image.height);
        for (std::size_t p = 0; p < mask.size(); ++p)
            mask[p] = image.rgb[p * 3];
    }
    return masks;
}

/// Bytes of a PNG file's chunk `type` (its data), or empty.
std::string pngChunk(const std::string& file, const std::string& type) {
    for (std::size_t at = 8; at + 12 <= file.size();) {
        const auto byte = [&](std::size_t i) { return std::uint32_t(std::uint8_t(file[i])); };
        const std::uint32_t length = byte(at) << 24 | byte(at + 1) << 16 | byte(at + 2) << 8 | byte(at + 3);
        if (file.compare(at + 4, 4, type) == 0) return file.substr(at + 8, length);
        at += 12 + length;
    }
    return "";
}

TEST(Separations, MasksRecombineToTheRenderByteForByteWithoutAntialiasing) {
    const auto dir = test::outputDir("separations-exact");
    for (const SeparatedCase& c : separatedCases()) {
        SCOPED_TRACE(c.name);
        const Rendered r = renderBoth(c, dir, {});
        const auto masks = readMasks(r.folder, r.genome.palette.size());
        ASSERT_EQ(masks.size(), r.genome.palette.size() + 1);
        std::vector<Color> colors = {r.genome.background};
        colors.insert(colors.end(), r.genome.palette.begin(), r.genome.palette.end());
        std::size_t differ = 0, notOne = 0;
        for (std::size_t p = 0; p < masks[0].size(); ++p) {
            // Without antialiasing every pixel is one ink: its mask is 255, the others 0.
            int on = 0;
            std::size_t ink = 0;
            for (std::size_t k = 0; k < masks.size(); ++k) {
                ASSERT_TRUE(masks[k][p] == 0 || masks[k][p] == 255) << "pixel " << p;
                if (masks[k][p] == 255) {
                    ++on;
                    ink = k;
                }
            }
            notOne += on != 1;
            const std::uint8_t* px = r.raster.rgb.data() + p * 3;
            differ += px[0] != colors[ink].r || px[1] != colors[ink].g || px[2] != colors[ink].b;
        }
        EXPECT_EQ(notOne, 0u);
        EXPECT_EQ(differ, 0u);
    }
}

TEST(Separations, MasksRecombineToTheAntialiasedRenderWithinTheirRounding) {
    const auto dir = test::outputDir("separations-aa");
    for (const SeparatedCase& c : separatedCases()) {
        SCOPED_TRACE(c.name);
        const Rendered r = renderBoth(c, dir, {"--aa", "grid4"});
        const auto masks = readMasks(r.folder, r.genome.palette.size());
        ASSERT_EQ(masks.size(), r.genome.palette.size() + 1);
        std::vector<glm::dvec3> linear = {linearOf(r.genome.background)};
        for (Color ink : r.genome.palette)
            linear.push_back(linearOf(ink));
        std::size_t outside = 0, mixed = 0;
        for (std::size_t p = 0; p < masks[0].size(); ++p) {
            // Each mask is the samples' weight rounded to 1/255: the recombined colour is the
            // render's up to half a step of each mask, in linear light.
            glm::dvec3 sum(0.0), slack(0.0);
            int total = 0;
            for (std::size_t k = 0; k < masks.size(); ++k) {
                sum += (masks[k][p] / 255.0) * linear[k];
                slack += (0.5 / 255.0) * linear[k];
                total += masks[k][p];
                mixed += masks[k][p] != 0 && masks[k][p] != 255;
            }
            EXPECT_NEAR(total, 255, double(masks.size()) / 2.0);
            for (int ch = 0; ch < 3; ++ch) {
                const int lo = encodeSrgb8(sum[ch] - slack[ch]), hi = encodeSrgb8(sum[ch] + slack[ch]);
                const int got = r.raster.rgb[p * 3 + ch];
                outside += got < lo || got > hi;
            }
        }
        EXPECT_EQ(outside, 0u);
        EXPECT_GT(mixed, 0u) << "the antialiased edges have partial coverage";
    }
}

TEST(Separations, IndexedPngIsTheRenderWithTheInksAsItsPalette) {
    const auto dir = test::outputDir("separations-indexed");
    for (const SeparatedCase& c : separatedCases()) {
        SCOPED_TRACE(c.name);
        const Rendered r = renderBoth(c, dir, {});
        const auto indexed = r.folder / "indexed.png";
        const Image decoded = test::readImage8(indexed);
        ASSERT_EQ(decoded.width, r.raster.width);
        ASSERT_EQ(decoded.height, r.raster.height);
        EXPECT_TRUE(decoded.rgb == r.raster.rgb) << "the indexed PNG decodes to the render";
        // An indexed PNG (colour type 3) whose palette is the inks, then the background.
        const std::string bytes = test::readFile(indexed);
        const std::string header = pngChunk(bytes, "IHDR");
        ASSERT_EQ(header.size(), 13u);
        EXPECT_EQ(int(header[8]), 8) << "bit depth";
        EXPECT_EQ(int(header[9]), 3) << "colour type: indexed";
        std::string expected;
        for (Color ink : r.genome.palette)
            expected += {char(ink.r), char(ink.g), char(ink.b)};
        expected += {char(r.genome.background.r), char(r.genome.background.g), char(r.genome.background.b)};
        EXPECT_EQ(pngChunk(bytes, "PLTE"), expected);
    }
}

TEST(Separations, OneBitMasksForScreens) {
    const auto dir = test::outputDir("separations-1bit");
    const SeparatedCase c = separatedCases().front();
    const Genome genome = loadGenome(c.file);
    const auto eight = dir / "eight", one = dir / "one";
    for (const auto& [folder, bits] : {std::pair{eight, "8"}, std::pair{one, "1"}}) {
        auto r = runMarbler({"render", c.file.string(), "--separations", folder.string(), "--width", "120",
                             "--aa", "rgss", "--mask-bits", bits, "--dpi", "300"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    const auto coverage = readMasks(eight, genome.palette.size());
    const auto screens = readMasks(one, genome.palette.size());
    ASSERT_EQ(coverage.size(), screens.size());
    for (std::size_t k = 0; k < coverage.size(); ++k) {
        const std::string bytes = test::readFile(one / separationFileNames(genome.palette.size())[k]);
        const std::string header = pngChunk(bytes, "IHDR");
        ASSERT_EQ(header.size(), 13u);
        EXPECT_EQ(int(header[8]), 1) << "bit depth";
        EXPECT_EQ(int(header[9]), 0) << "colour type: grey";
        EXPECT_FALSE(pngChunk(bytes, "pHYs").empty()) << "the resolution is written";
        for (std::size_t p = 0; p < coverage[k].size(); ++p)
            ASSERT_EQ(screens[k][p], coverage[k][p] >= 128 ? 255 : 0) << "layer " << k << " pixel " << p;
    }
}

TEST(SeparationsCli, BadInputExitsTwoWithOneLineAndNoFiles) {
    const auto dir = test::outputDir("separations-bad");
    const std::string good = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    const auto folder = dir / "out";
    auto expectBad = [&](const std::vector<std::string>& args, const std::string& mention) {
        auto r = runMarbler(args);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(folder) && !std::filesystem::is_empty(folder)) << "files left";
    };
    expectBad({"render", good, "--separations", folder.string(), "--mask-bits", "4"}, "--mask-bits");
    expectBad({"render", good, "-o", (dir / "x.png").string(), "--mask-bits", "1"}, "--separations");
    expectBad({"render", good, "--separations", folder.string(), "--repeat", "mirror"}, "--repeat");
    expectBad({"render", (test::dataDir() / "render" / "source-2d.marble.json").string(), "--separations",
               folder.string()},
              "source image");
    expectBad({"render", (test::dataDir() / "examples" / "slate-block.marble.json").string(), "--separations",
               folder.string()},
              "--slice");
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
    // A file where the folder should be is named, and stays as it was.
    const auto file = dir / "a-file";
    { std::ofstream(file) << "kept"; }
    auto r = runMarbler({"render", good, "--separations", file.string()});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("a-file' is a file"), std::string::npos) << r.err;
    EXPECT_EQ(test::readFile(file), "kept");
}

} // namespace
} // namespace marbler
