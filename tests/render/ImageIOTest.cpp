// Image files: every format round trip with its resolution, atomic writes, no partial files.

#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/RenderToFile.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <mutex>

namespace marbler {
namespace {

Genome example() {
    return loadGenome(test::dataDir() / "examples" / "five-stones.marble.json");
}

std::size_t filesIn(const std::filesystem::path& dir) {
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir))
        ++count;
    return count;
}

TEST(ImageFiles, EveryFormatRoundTripsWithItsResolution) {
    const std::filesystem::path dir = test::outputDir("image-formats");
    Genome g = example();
    RenderSettings s;
    s.width = 150;
    s.height = 90;
    s.region = Region{100, 100, 600, 400};
    Image image = CpuRenderer(g).render(s);
    for (const char* ext : {".png", ".tif", ".tiff", ".exr", ".jpg", ".jpeg"}) {
        for (bool streamed : {false, true}) {
            std::filesystem::path file = dir / (std::string(streamed ? "streamed" : "whole") + ext);
            ExportOptions options;
            options.dpi = 300.0;
            if (streamed)
                renderToFile(g, s, file, options);
            else
                writeImage(image, file, options);
            auto in = OIIO::ImageInput::open(file.string());
            ASSERT_TRUE(in) << file << ": " << OIIO::geterror();
            const OIIO::ImageSpec& spec = in->spec();
            EXPECT_EQ(spec.width, 150) << file;
            EXPECT_EQ(spec.height, 90) << file;
            EXPECT_GE(spec.nchannels, 3) << file;
            EXPECT_NEAR(spec.get_float_attribute("XResolution"), 300.0f, 0.05f) << file;
            EXPECT_NEAR(spec.get_float_attribute("YResolution"), 300.0f, 0.05f) << file;
            std::string unit = spec.get_string_attribute("ResolutionUnit");
            EXPECT_TRUE(unit == "inch" || unit == "in") << file << ": " << unit;
            in->close();
            Image back = test::readImage8(file);
            bool lossy = std::string(ext) == ".jpg" || std::string(ext) == ".jpeg";
            bool halfFloat = std::string(ext) == ".exr";
            if (halfFloat) {
                // Read as floats: linear light, the decoded sRGB values within half precision.
                auto exr = OIIO::ImageInput::open(file.string());
                std::vector<float> linear(std::size_t(150) * 90 * 3);
                ASSERT_TRUE(exr->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, linear.data()));
                for (std::size_t k = 0; k < linear.size(); k += 97)
                    EXPECT_NEAR(linear[k], srgbToLinear(image.rgb[k] / 255.0), 2e-3)
                        << file << " value " << k;
            } else {
                test::ImageDiff diff = test::compareImages(back, image, lossy ? 40 : 0);
                EXPECT_GE(diff.shareWithin, lossy ? 0.95 : 1.0) << file;
            }
        }
    }
    // Only the finished files remain: no temporaries beside them.
    EXPECT_EQ(filesIn(dir), 12u);
}

TEST(ImageFiles, NoResolutionWithoutDpi) {
    const std::filesystem::path file = test::outputDir("image-nodpi") / "plain.png";
    Image image;
    image.width = image.height = 4;
    image.rgb.assign(48, 128);
    writeImage(image, file);
    auto in = OIIO::ImageInput::open(file.string());
    ASSERT_TRUE(in);
    EXPECT_EQ(test::readImage8(file).rgb, image.rgb);
}

TEST(ImageFiles, UnknownFormatIsAnInputErrorAndWritesNothing) {
    const std::filesystem::path dir = test::outputDir("image-unknown");
    Image image;
    image.width = image.height = 2;
    image.rgb.assign(12, 0);
    EXPECT_THROW(writeImage(image, dir / "out.xyz"), InputError);
    RenderSettings s;
    s.width = s.height = 8;
    EXPECT_THROW(renderToFile(example(), s, dir / "out.nope", {}), InputError);
    EXPECT_EQ(filesIn(dir), 0u);
}

TEST(ImageFiles, UnwritableFolderFailsWithoutLeavingAnything) {
    const std::filesystem::path dir = test::outputDir("image-unwritable");
    RenderSettings s;
    s.width = s.height = 8;
    EXPECT_THROW(renderToFile(example(), s, dir / "missing" / "out.png", {}), RuntimeFailure);
    EXPECT_EQ(filesIn(dir), 0u);
}

TEST(ImageFiles, CancelledRenderLeavesNoFile) {
    const std::filesystem::path dir = test::outputDir("image-cancel");
    RenderSettings s;
    s.width = 64;
    s.height = 300; // several strips
    std::atomic<bool> cancel{false};
    RenderControl control;
    control.cancel = &cancel;
    double last = 0;
    control.progress = [&](double f) {
        last = f;
        if (f > 0.5) cancel = true;
    };
    EXPECT_THROW(renderToFile(example(), s, dir / "cancelled.png", {}, &control), Cancelled);
    EXPECT_GT(last, 0.5);
    EXPECT_EQ(filesIn(dir), 0u);
    // An existing file is not touched by a failed render.
    test::writeFile(dir / "keep.png", "old");
    cancel = false;
    control.progress = [&](double f) {
        if (f > 0.1) cancel = true;
    };
    EXPECT_THROW(renderToFile(example(), s, dir / "keep.png", {}, &control), Cancelled);
    EXPECT_EQ(test::readFile(dir / "keep.png"), "old");
    EXPECT_EQ(filesIn(dir), 1u);
}

TEST(ImageFiles, PosterSizedRenderStreamsInStrips) {
    // Progress arrives strip by strip, monotone, ending at 1.
    const std::filesystem::path dir = test::outputDir("image-strips");
    RenderSettings s;
    s.width = 40;
    s.height = 1000;
    std::vector<double> seen;
    std::mutex mutex;
    RenderControl control;
    control.progress = [&](double f) {
        std::lock_guard lock(mutex);
        seen.push_back(f);
    };
    renderToFile(example(), s, dir / "tall.png", {}, &control);
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.back(), 1.0);
    EXPECT_EQ(test::readImage8(dir / "tall.png").height, 1000);
}

} // namespace
} // namespace marbler
