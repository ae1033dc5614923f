// A CMYK TIFF for a printer's ICC profile (issue 29, marbler/PrintProfile.h, `render --icc`):
// read back with OpenImageIO, the file has 4 separated channels, the given profile byte for
// byte, and LittleCMS's own transform of the sRGB render; what makes no sense is refused.

#include "marbler/PrintProfile.h"
#include "CmykTestProfile.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeImage.h"
#include "marbler/Image.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace marbler {
namespace {

namespace fs = std::filesystem;

/// A CMYK TIFF as OpenImageIO reads it, the channels as stored (no conversion to RGB).
struct CmykFile {
    int width = 0, height = 0, channels = 0, bits = 0;
    std::string photometric;
    std::vector<unsigned char> icc;
    std::vector<std::uint16_t> values; ///< every sample, 8-bit ones widened
};

CmykFile readCmyk(const fs::path& file) {
    OIIO::ImageSpec config;
    config.attribute("oiio:RawColor", 1);
    auto in = OIIO::ImageInput::open(file.string(), &config);
    EXPECT_TRUE(in) << OIIO::geterror();
    CmykFile out;
    if (!in) return out;
    const OIIO::ImageSpec& spec = in->spec();
    out.width = spec.width;
    out.height = spec.height;
    out.channels = spec.nchannels;
    out.bits = spec.format == OIIO::TypeDesc::UINT16 ? 16 : spec.format == OIIO::TypeDesc::UINT8 ? 8 : 0;
    out.photometric = spec.get_string_attribute("tiff:ColorSpace");
    if (const OIIO::ParamValue* p = spec.find_attribute("ICCProfile")) {
        const auto* data = static_cast<const unsigned char*>(p->data());
        out.icc.assign(data, data + p->type().size());
    }
    out.values.resize(std::size_t(spec.width) * spec.height * spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT16, out.values.data()));
    if (out.bits == 8)
        for (auto& v : out.values)
            v = std::uint16_t(std::lround(v / 257.0));
    return out;
}

Genome example(const std::string& name) {
    return test::loadExample(name);
}

RenderSettings small(int width = 96, int height = 64) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.aa = "rgss";
    return settings;
}

/// Every sample within one code value of the reference; the first that is not is reported.
template <typename T>
void expectWithinOne(const std::vector<std::uint16_t>& actual, const std::vector<T>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    int worst = 0;
    std::size_t at = 0;
    for (std::size_t k = 0; k < actual.size(); ++k) {
        const int d = std::abs(int(actual[k]) - int(expected[k]));
        if (d > worst) worst = d, at = k;
    }
    EXPECT_LE(worst, 1) << "sample " << at << " (pixel " << at / 4 << ", channel " << at % 4
                        << "): " << actual[at] << " where LittleCMS gives " << expected[at];
}

TEST(PrintProfile, EightBitTiffIsLittleCmsOwnTransformWithTheProfileEmbedded) {
    const auto dir = test::outputDir("print-profile-8");
    const std::vector<unsigned char> icc = test::makeCmykProfile();
    test::writeBytes(dir / "press.icc", icc);
    const Genome genome = example("five-stones.marble.json");
    const RenderSettings settings = small();
    const fs::path file = dir / "out.tif";
    CmykTiffOptions options;
    options.dpi = 300.0;
    renderToCmykTiff(genome, settings, file, loadPrintProfile(dir / "press.icc"), options);

    const CmykFile read = readCmyk(file);
    EXPECT_EQ(read.width, settings.width);
    EXPECT_EQ(read.height, settings.height);
    EXPECT_EQ(read.channels, 4);
    EXPECT_EQ(read.bits, 8);
    EXPECT_EQ(read.photometric, "CMYK") << "PHOTOMETRIC_SEPARATED";
    EXPECT_EQ(read.icc, icc) << "the printer's profile, byte for byte";
    const Image rgb = CpuRenderer(genome).render(settings);
    expectWithinOne(read.values, test::lcmsCmykOf(rgb.rgb, icc));
    // Like every TIFF Marbler writes, it carries its design.
    EXPECT_EQ(loadDesign(file).initial.size(), genome.initial.size());
}

TEST(PrintProfile, SixteenBitTiffFromTheLinearAverageAndEveryIntent) {
    const auto dir = test::outputDir("print-profile-16");
    const std::vector<unsigned char> icc = test::makeCmykProfile();
    test::writeBytes(dir / "press.icc", icc);
    const Genome genome = example("five-stones.marble.json");
    const RenderSettings settings = small(64, 48);
    std::vector<float> linear(std::size_t(settings.width) * settings.height * 3);
    CpuRenderer(genome).renderRowsLinear(settings, 0, settings.height, linear.data());
    std::vector<std::uint16_t> rgb16(linear.size());
    for (std::size_t k = 0; k < linear.size(); ++k)
        rgb16[k] =
            std::uint16_t(std::lround(linearToSrgb(std::clamp(double(linear[k]), 0.0, 1.0)) * 65535.0));
    const cmsUInt32Number intents[] = {INTENT_PERCEPTUAL, INTENT_RELATIVE_COLORIMETRIC, INTENT_SATURATION,
                                       INTENT_ABSOLUTE_COLORIMETRIC};
    for (int i = 0; i < 4; ++i) {
        SCOPED_TRACE(renderingIntentNames()[std::size_t(i)]);
        CmykTiffOptions options;
        options.bitsPerSample = 16;
        options.intent = *parseRenderingIntent(renderingIntentNames()[std::size_t(i)]);
        const fs::path file = dir / ("out-" + std::to_string(i) + ".tiff");
        renderToCmykTiff(genome, settings, file, loadPrintProfile(dir / "press.icc"), options);
        const CmykFile read = readCmyk(file);
        EXPECT_EQ(read.channels, 4);
        EXPECT_EQ(read.bits, 16);
        EXPECT_EQ(read.icc, icc);
        expectWithinOne(read.values, test::lcmsCmykOf(rgb16, icc, intents[i]));
    }
}

TEST(PrintProfile, RefusesWhatIsNoCmykPrinterProfileNamingTheFile) {
    const auto dir = test::outputDir("print-profile-refused");
    auto refusal = [&](const std::string& name, const std::vector<unsigned char>& bytes) {
        test::writeBytes(dir / name, bytes);
        try {
            loadPrintProfile(dir / name);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    const std::string text = "not a profile at all, just some words in a file that is long enough to "
                             "pass for a header of one hundred and twenty-eight bytes, or more than that";
    std::string message = refusal("notes.icc", std::vector<unsigned char>(text.begin(), text.end()));
    EXPECT_NE(message.find("notes.icc': not an ICC profile"), std::string::npos) << message;
    message = refusal("srgb.icc", test::makeDisplayProfile());
    EXPECT_NE(message.find("srgb.icc': a display profile, not a printer's"), std::string::npos) << message;
    message = refusal("rgb-printer.icc", test::makeRgbOutputProfile());
    EXPECT_NE(message.find("rgb-printer.icc': a printer profile for RGB, not CMYK"), std::string::npos)
        << message;
    try {
        loadPrintProfile(dir / "missing.icc");
        ADD_FAILURE() << "a missing file accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.icc': cannot read the printer profile (no such file)"),
                  std::string::npos)
            << e.what();
    }
    // The profile's own name is read for the window to show.
    test::writeBytes(dir / "press.icc", test::makeCmykProfile("Coated press 42"));
    EXPECT_EQ(loadPrintProfile(dir / "press.icc").description, "Coated press 42");
}

TEST(PrintProfile, OnlyATiffAndNothingLeftOnCancel) {
    const auto dir = test::outputDir("print-profile-tiff-only");
    test::writeBytes(dir / "press.icc", test::makeCmykProfile());
    const PrintProfile profile = loadPrintProfile(dir / "press.icc");
    const Genome genome = example("five-stones.marble.json");
    try {
        renderToCmykTiff(genome, small(), dir / "out.png", profile);
        ADD_FAILURE() << "a PNG accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("is a TIFF (.tif or .tiff), not .png"), std::string::npos)
            << e.what();
    }
    std::atomic<bool> cancel{true};
    RenderControl control;
    control.cancel = &cancel;
    EXPECT_THROW(renderToCmykTiff(genome, small(), dir / "cancelled.tif", profile, {}, &control), Cancelled);
    EXPECT_FALSE(fs::exists(dir / "cancelled.tif"));
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename(), "press.icc") << "nothing else is left";
}

TEST(PrintProfileCli, RenderIccWritesTheCmykTiff) {
    const auto dir = test::outputDir("print-profile-cli");
    const std::vector<unsigned char> icc = test::makeCmykProfile();
    test::writeBytes(dir / "press.icc", icc);
    const fs::path out = dir / "poster.tif";
    auto r = test::runMarbler({"render", test::examplePath("five-stones.marble.json"), "-o", out.string(),
                               "--width", "80", "--aa", "rgss", "--icc", (dir / "press.icc").string(),
                               "--intent", "relative", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const CmykFile read = readCmyk(out);
    EXPECT_EQ(read.channels, 4);
    EXPECT_EQ(read.icc, icc);
    const Genome genome = example("five-stones.marble.json");
    RenderSettings settings = small(read.width, read.height);
    const Image rgb = CpuRenderer(genome).render(settings);
    expectWithinOne(read.values, test::lcmsCmykOf(rgb.rgb, icc, INTENT_RELATIVE_COLORIMETRIC));
    // The help says the option.
    r = test::runMarbler({"render", "--help"});
    EXPECT_NE(r.out.find("--icc PRINTER.icc"), std::string::npos);
    EXPECT_NE(r.out.find("--intent NAME"), std::string::npos);
}

TEST(PrintProfileCli, BadInputExitsTwoWithOneLineAndNoFile) {
    const auto dir = test::outputDir("print-profile-cli-bad");
    test::writeBytes(dir / "press.icc", test::makeCmykProfile());
    test::writeBytes(dir / "screen.icc", test::makeDisplayProfile());
    const std::string good = test::examplePath("five-stones.marble.json");
    const std::string press = (dir / "press.icc").string();
    const fs::path tif = dir / "out.tif";
    auto expectBad = [&](const std::vector<std::string>& args, const std::string& mention) {
        auto r = test::runMarbler(args);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    };
    expectBad({"render", good, "-o", (dir / "out.png").string(), "--icc", press},
              "OUT must end in .tif or .tiff");
    expectBad({"render", good, "-o", tif.string(), "--icc", (dir / "screen.icc").string()},
              "a display profile, not a printer's");
    expectBad({"render", good, "-o", tif.string(), "--icc", good}, "not an ICC profile");
    expectBad({"render", good, "-o", tif.string(), "--icc", press, "--intent", "vivid"}, "--intent: 'vivid'");
    expectBad({"render", good, "-o", tif.string(), "--icc", press, "--bits", "12"},
              "--bits: must be 8 or 16");
    expectBad({"render", good, "-o", tif.string(), "--intent", "relative"},
              "--intent only applies with --icc");
    expectBad({"render", good, "-o", tif.string(), "--icc", press, "--repeat", "mirror"},
              "--icc and --repeat exclude each other");
    expectBad({"render", good, "-o", tif.string(), "--icc", press, "--mesh", "vase", "--view", "0,0"},
              "--icc and --mesh exclude each other");
    EXPECT_FALSE(fs::exists(tif));
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

} // namespace
} // namespace marbler
