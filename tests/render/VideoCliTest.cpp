// `marbler video`: every frame of a video marbled with the frame as the genome's source, each
// frame exactly the render of the genome with that decoded frame as its source image file;
// video output at the input's frame rate; bad inputs refused in one line with exit status 2.

#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/ImageFile.h"
#include "marbler/Video.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace marbler {
namespace {

namespace fs = std::filesystem;

constexpr int InFrames = 5, InWidth = 64, InHeight = 48;

/// A short video of colour gradients that move from frame to frame.
fs::path writeInput(const fs::path& file, double fps) {
    auto writer = openVideoWriter(file, InWidth, InHeight, fps);
    std::vector<std::uint8_t> rgb(std::size_t(InWidth) * InHeight * 3);
    for (int k = 0; k < InFrames; ++k) {
        for (int y = 0; y < InHeight; ++y)
            for (int x = 0; x < InWidth; ++x) {
                std::uint8_t* p = rgb.data() + (std::size_t(y) * InWidth + std::size_t(x)) * 3;
                p[0] = std::uint8_t((x * 4 + k * 40) % 256);
                p[1] = std::uint8_t(y * 5);
                p[2] = std::uint8_t(255 - k * 45);
            }
        writer->addFrame(rgb.data(), InWidth * 3);
    }
    writer->finish();
    return file;
}

/// The design with a source image (render/source-2d.marble.json) saved in `dir`, its source the
/// file `source`.
fs::path writeGenome(const fs::path& dir, const std::string& source) {
    Genome genome = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
    genome.source = SourceImage{source};
    const fs::path file = dir / "design.marble.json";
    saveGenome(genome, file);
    return file;
}

std::string firstLine(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

TEST(VideoCli, EveryFrameIsTheRenderWithThatFrameAsTheSource) {
    const fs::path dir = test::outputDir("video-cli-frames");
    const fs::path in = writeInput(dir / "in.mp4", 25.0);
    const fs::path genomeFile = writeGenome(dir, "frame.png");
    test::RunResult r =
        test::runMarbler({"video", genomeFile.string(), in.string(), "-o", (dir / "out").string(), "--width",
                          "96", "--aa", "rgss", "--progress"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // Progress names each frame on one line rewritten in place, blanked at the end.
    EXPECT_NE(r.err.find("\rmarbling frame " + std::to_string(InFrames)), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), std::string::npos) << r.err;
    EXPECT_EQ(r.err.back(), '\r') << r.err;

    // The reference: each decoded frame written as the genome's source image file and rendered
    // as `render` renders it.
    auto reader = openVideoReader(in);
    std::vector<std::uint8_t> rgb;
    int k = 0;
    while (reader->nextFrame(rgb)) {
        Image frame{reader->width(), reader->height(), rgb};
        writeImage(frame, dir / "frame.png");
        const Genome genome = loadGenome(genomeFile);
        RenderSettings settings;
        settings.width = 96;
        settings.height = 48; // the design is 800 x 400
        settings.aa = "rgss";
        const Image expected = CpuRenderer(genome).render(settings);
        char name[32];
        std::snprintf(name, sizeof name, "frame-%04d.png", k);
        ASSERT_TRUE(fs::exists(dir / "out" / name)) << name;
        const Image got = test::readImage8(dir / "out" / name);
        ASSERT_EQ(got.width, 96);
        ASSERT_EQ(got.height, 48);
        EXPECT_EQ(test::compareImages(got, expected, 0).maxDifference, 0) << name;
        ++k;
    }
    EXPECT_EQ(k, InFrames);
    EXPECT_FALSE(fs::exists(dir / "out" / "frame-0005.png"));
    // The frames carry the genome, as every PNG Marbler writes does.
    EXPECT_EQ(loadDesign((dir / "out" / "frame-0000.png").string()).palette, loadGenome(genomeFile).palette);
}

TEST(VideoCli, AnInMemorySourceMustMatchItsSize) {
    const Genome genome = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
    EXPECT_THROW(CpuRenderer(genome, LinearRaster{2, 2, std::vector<float>(11)}), InputError);
    EXPECT_THROW(CpuRenderer(genome, LinearRaster{0, 2, {}}), InputError);
    // A raster of one colour shows that colour wherever no ink lies (the genome's own source
    // file is not read).
    const std::uint8_t grey[3] = {90, 90, 90};
    RenderSettings settings;
    settings.width = 40;
    settings.height = 20;
    const Image image = CpuRenderer(genome, linearRasterOfSrgb8(grey, 1, 1, 3)).render(settings);
    int greys = 0;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
        greys += image.rgb[i] == 90 && image.rgb[i + 1] == 90 && image.rgb[i + 2] == 90;
    EXPECT_GT(greys, 40 * 20 / 4);
}

TEST(VideoCli, AVideoOutKeepsTheInputsRateAndWidth) {
    const fs::path dir = test::outputDir("video-cli-video");
    // 20 frames a second: 5 hundredths a frame, a rate GIF holds exactly.
    const fs::path in = writeInput(dir / "in.webm", 20.0);
    const fs::path genomeFile = writeGenome(dir, "unused.png");
    for (const char* name : {"out.mp4", "out.gif"}) {
        test::RunResult r =
            test::runMarbler({"video", genomeFile.string(), in.string(), "-o", (dir / name).string()});
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
        auto out = openVideoReader(dir / name);
        EXPECT_EQ(out->width(), InWidth) << name;      // default: the input's width
        EXPECT_EQ(out->height(), InWidth / 2) << name; // the design's aspect, 2:1
        EXPECT_NEAR(out->fps(), 20.0, 1e-9) << name;
        std::vector<std::uint8_t> rgb;
        int count = 0;
        while (out->nextFrame(rgb))
            ++count;
        EXPECT_EQ(count, InFrames) << name;
    }
}

TEST(VideoCli, BadInputGivesOneLineAndExit2) {
    const fs::path dir = test::outputDir("video-cli-bad");
    const fs::path in = writeInput(dir / "in.mp4", 25.0);
    const fs::path flat = writeGenome(dir, "unused.png");
    const fs::path solid = test::dataDir() / "render" / "solid-inks.marble.json";
    test::writeFile(dir / "words.mp4", "no video here, only words\n");
    struct Case {
        std::vector<std::string> args;
        std::string says;
    };
    const std::vector<Case> cases = {
        {{"video", solid.string(), in.string(), "-o", (dir / "a").string()}, "solid (3D)"},
        {{"video", flat.string(), (dir / "missing.mp4").string(), "-o", (dir / "b").string()}, "missing.mp4"},
        {{"video", flat.string(), (dir / "words.mp4").string(), "-o", (dir / "c").string()}, "words.mp4"},
        {{"video", flat.string(), in.string(), "-o", (dir / "d.avi").string()}, "d.avi"},
        {{"video", flat.string(), in.string()}, "-o OUT"},
        {{"video", flat.string(), in.string(), "-o", (dir / "e").string(), "--width", "0"}, "--width"},
    };
    for (const Case& c : cases) {
        test::RunResult r = test::runMarbler(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.says << ": " << r.err;
        EXPECT_EQ(r.err, firstLine(r.err) + "\n") << "not one line: " << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    }
    // Nothing is left behind: no output folder or file of any refused run.
    for (const char* name : {"a", "b", "c", "d.avi", "e"})
        EXPECT_FALSE(fs::exists(dir / name)) << name;
}

} // namespace
} // namespace marbler
