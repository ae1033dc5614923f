// Image files: every format round trip with its resolution, atomic writes, no partial files.

#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Image.h"
#include "marbler/RenderToFile.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

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

/// The numbers of an ICC profile that say what it does, read from its bytes as the ICC
/// specification lays them out.
struct IccProfile {
    std::string deviceClass, colourSpace, pcs, signature;
    std::map<std::string, std::vector<unsigned char>> tags;
    std::uint32_t declaredSize = 0;
};

std::uint32_t be32(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

IccProfile parseIcc(const std::vector<unsigned char>& bytes) {
    IccProfile icc;
    if (bytes.size() < 132) return icc;
    icc.declaredSize = be32(bytes.data());
    icc.deviceClass.assign(bytes.begin() + 12, bytes.begin() + 16);
    icc.colourSpace.assign(bytes.begin() + 16, bytes.begin() + 20);
    icc.pcs.assign(bytes.begin() + 20, bytes.begin() + 24);
    icc.signature.assign(bytes.begin() + 36, bytes.begin() + 40);
    const std::uint32_t count = be32(bytes.data() + 128);
    for (std::uint32_t i = 0; i < count && 132 + 12 * (i + 1) <= bytes.size(); ++i) {
        const unsigned char* e = bytes.data() + 132 + 12 * i;
        const std::uint32_t offset = be32(e + 4), size = be32(e + 8);
        if (offset + size <= bytes.size())
            icc.tags[std::string(e, e + 4)] =
                std::vector<unsigned char>(bytes.begin() + offset, bytes.begin() + offset + size);
    }
    return icc;
}

double s15f16(const std::vector<unsigned char>& tag, std::size_t at) {
    return double(std::int32_t(be32(tag.data() + at))) / 65536.0;
}

TEST(ImageFiles, PngTiffAndJpegCarryAnSrgbProfile) {
    // Print and layout software keeps a file's colours by its ICC profile; PNG's sRGB chunk or
    // an untagged TIFF leave them to guesswork.
    const std::filesystem::path dir = test::outputDir("image-icc");
    RenderSettings s;
    s.width = 40;
    s.height = 24;
    const Image image = CpuRenderer(example()).render(s);
    for (const char* ext : {".png", ".tif", ".jpg"}) {
        const std::filesystem::path file = dir / (std::string("tagged") + ext);
        writeImage(image, file);
        auto in = OIIO::ImageInput::open(file.string());
        ASSERT_TRUE(in) << file << ": " << OIIO::geterror();
        const OIIO::ParamValue* p = in->spec().find_attribute("ICCProfile");
        ASSERT_TRUE(p) << ext << " has no ICC profile";
        const auto* data = static_cast<const unsigned char*>(p->data());
        const IccProfile icc = parseIcc(std::vector<unsigned char>(data, data + p->type().size()));
        EXPECT_EQ(icc.declaredSize, p->type().size()) << ext;
        EXPECT_EQ(icc.signature, "acsp") << ext;
        EXPECT_EQ(icc.deviceClass, "mntr") << ext;
        EXPECT_EQ(icc.colourSpace, "RGB ") << ext;
        EXPECT_EQ(icc.pcs, "XYZ ") << ext;
        // The colorants add up to the D50 white, and are sRGB's adapted to it (as in every sRGB
        // profile: red X 0.4361, green Y 0.7169, blue Z 0.7141).
        for (const char* tag : {"rXYZ", "gXYZ", "bXYZ", "rTRC", "gTRC", "bTRC", "wtpt", "desc"})
            ASSERT_TRUE(icc.tags.count(tag)) << ext << " lacks " << tag;
        double sum[3] = {};
        for (const char* tag : {"rXYZ", "gXYZ", "bXYZ"})
            for (int i = 0; i < 3; ++i)
                sum[i] += s15f16(icc.tags.at(tag), 8 + 4 * std::size_t(i));
        EXPECT_NEAR(sum[0], 0.9642, 2e-4) << ext;
        EXPECT_NEAR(sum[1], 1.0, 2e-4) << ext;
        EXPECT_NEAR(sum[2], 0.8249, 2e-4) << ext;
        EXPECT_NEAR(s15f16(icc.tags.at("rXYZ"), 8), 0.4361, 5e-4) << ext;
        EXPECT_NEAR(s15f16(icc.tags.at("gXYZ"), 12), 0.7169, 5e-4) << ext;
        EXPECT_NEAR(s15f16(icc.tags.at("bXYZ"), 16), 0.7141, 5e-4) << ext;
        // The transfer curve: code 0.5 is 21.4 % of the light, as sRGB decodes it.
        const std::vector<unsigned char>& trc = icc.tags.at("rTRC");
        ASSERT_EQ(std::string(trc.begin(), trc.begin() + 4), "curv");
        const std::uint32_t n = be32(trc.data() + 8);
        ASSERT_GT(n, 255u);
        auto at = [&](std::uint32_t i) { return double(trc[12 + 2 * i] << 8 | trc[13 + 2 * i]) / 65535.0; };
        EXPECT_NEAR(at((n - 1) / 2), srgbToLinear(double((n - 1) / 2) / double(n - 1)), 1e-4);
        EXPECT_EQ(at(0), 0.0);
        EXPECT_EQ(at(n - 1), 1.0);
    }
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
