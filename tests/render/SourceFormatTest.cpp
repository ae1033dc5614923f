// A genome's `source` reaches one decoder or none (SourceFormat.h): its first bytes must be
// those of PNG, JPEG, TIFF, OpenEXR or WebP, and only that format's reader decodes it, whatever
// the file's name or a data URL's MIME type says. Before this rule a Photoshop or DPX file named
// x.png, and a DPX file in a data:image/png URL, were decoded and rendered. (The size in the
// header, checked before any pixel is decoded, is SamplingTest's Render.HugeSource....)

#include "SourceFormat.h"
#include "TestUtil.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/SourceDecoder.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace marbler {
namespace {

namespace fs = std::filesystem;
using test::runMarbler;

constexpr int Width = 37, Height = 19;

/// A smooth RGB gradient, 0.1 to 0.9, as sRGB-encoded values (linear light for EXR).
std::vector<float> gradient() {
    std::vector<float> pixels(std::size_t(Width) * Height * 3);
    for (int y = 0; y < Height; ++y)
        for (int x = 0; x < Width; ++x)
            for (int c = 0; c < 3; ++c)
                pixels[(std::size_t(y) * Width + std::size_t(x)) * 3 + std::size_t(c)] =
                    0.1f + 0.8f * float(x + y * (c + 1)) / float(Width + Height * 3);
    return pixels;
}

/// Writes the gradient with OpenImageIO's writer for `format` (its extension) into `file`.
void writeWith(const std::string& format, const fs::path& file) {
    auto out = OIIO::ImageOutput::create(format);
    ASSERT_TRUE(out) << format << ": " << OIIO::geterror();
    OIIO::ImageSpec spec(Width, Height, 3, format == "exr" ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
    if (format == "jpg" || format == "webp")
        spec.attribute("Compression", format == "jpg" ? "jpeg:100" : "webp:100");
    ASSERT_TRUE(out->open(file.string(), spec)) << format << ": " << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, gradient().data())) << out->geterror();
    out->close();
}

/// A real Photoshop file (one layer, RGB, 8 bits, raw), as OpenImageIO's PSD reader accepts.
std::string photoshopFile() {
    std::string b = "8BPS";
    auto u16 = [&](unsigned v) { b += char(v >> 8), b += char(v & 0xff); };
    auto u32 = [&](std::uint32_t v) { u16(v >> 16), u16(v & 0xffff); };
    u16(1);                                          // version
    b.append(6, '\0');                               // reserved
    u16(3), u32(Height), u32(Width), u16(8), u16(3); // RGB, 8 bits
    u32(0), u32(0), u32(0);                          // colour mode data, resources, layers: none
    u16(0);                                          // raw image data, channel by channel
    for (int c = 0; c < 3; ++c)
        for (int p = 0; p < Width * Height; ++p)
            b += char(40 + 70 * c);
    return b;
}

std::string base64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::uint32_t buffer = 0;
    int bits = 0;
    for (unsigned char c : bytes) {
        buffer = (buffer << 8) | c;
        bits += 8;
        while (bits >= 6) {
            bits -= 6;
            out += alphabet[(buffer >> bits) & 63u];
        }
    }
    if (bits > 0) out += alphabet[(buffer << (6 - bits)) & 63u];
    while (out.size() % 4)
        out += '=';
    return out;
}

/// A folder of the test's own, and the design with its source set to `image`.
struct SourceCase {
    fs::path dir;
    Genome genome;
    SourceCase() {
        dir = test::outputDir(std::string("source-format-") +
                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        genome = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
        genome.baseDirectory = dir.string();
    }
    /// The source's decoding error ("" when it decodes).
    std::string errorOf(const std::string& image) {
        genome.source = SourceImage{image};
        try {
            decodeSourceImage(genome);
        } catch (const GenomeError& e) {
            return e.what();
        }
        return "";
    }
};

TEST(SourceFormat, TellsFormatsByTheirFirstBytes) {
    auto sniff = [](const std::string& bytes) {
        return detail::sniffSourceFormat(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
    };
    EXPECT_EQ(sniff("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR").reader, "png");
    EXPECT_EQ(sniff("\xff\xd8\xff\xe0 JFIF").reader, "jpeg");
    EXPECT_EQ(sniff(std::string("II*\0\x08\0\0\0", 8)).reader, "tiff");
    EXPECT_EQ(sniff(std::string("MM\0*\0\0\0\x08", 8)).reader, "tiff");
    EXPECT_EQ(sniff("v/1\x01\x02").reader, "openexr");
    EXPECT_EQ(sniff(std::string("RIFF\x10\0\0\0WEBPVP8 ", 16)).reader, "webp");
    struct Refused {
        std::string bytes, description;
    };
    for (const Refused& r :
         {Refused{photoshopFile(), "a Photoshop file"}, Refused{"SDPX\0\0", "a DPX file"},
          Refused{"GIF89a", "a GIF image"}, Refused{std::string("RIFF\0\0\0\0AVI LIST", 16), "an AVI video"},
          Refused{std::string(128, '\0') + "DICM", "a DICOM file"},
          Refused{std::string("\0\0\0\x18"
                              "ftypheic",
                              12),
                  "a HEIF image"},
          Refused{"<svg>", "an SVG or other XML or HTML file"}, Refused{"", "an empty file"}}) {
        const detail::SourceFormat f = sniff(r.bytes);
        EXPECT_EQ(f.reader, "") << r.description;
        EXPECT_EQ(f.description, r.description);
    }
    // Fewer bytes than a signature are no match, not a read past the end.
    EXPECT_EQ(sniff("\x89PN").reader, "");
    EXPECT_EQ(sniff("\x01\x02\x03").description, "a file of an unknown kind (it begins 01 02 03)");
}

TEST(SourceFormat, DisguisedFilesAreRefusedByWhatTheyAre) {
    SourceCase c;
    test::writeFile(c.dir / "photo.png", photoshopFile());
    // OpenImageIO itself would decode it, as Marbler did before the rule.
    {
        auto in = OIIO::ImageInput::open((c.dir / "photo.png").string());
        ASSERT_TRUE(in) << "the Photoshop file is not one OpenImageIO reads: " << OIIO::geterror();
        EXPECT_EQ(std::string(in->format_name()), "psd");
    }
    std::string error = c.errorOf("photo.png");
    EXPECT_NE(error.find("source.image"), std::string::npos) << error;
    EXPECT_NE(error.find("a Photoshop file: sources must be PNG, JPEG, TIFF, EXR or WebP"), std::string::npos)
        << error;

    writeWith("dpx", c.dir / "film.dpx");
    fs::rename(c.dir / "film.dpx", c.dir / "film.png");
    error = c.errorOf("film.png");
    EXPECT_NE(error.find("a DPX file: sources must be"), std::string::npos) << error;

    error = c.errorOf("data:image/png;base64," + base64(test::readFile(c.dir / "film.png")));
    EXPECT_NE(error.find("source.image"), std::string::npos) << error;
    EXPECT_NE(error.find("a DPX file: sources must be"), std::string::npos) << error;
}

TEST(SourceFormat, EveryAllowedFormatDecodesByItsContentWhateverItsName) {
    SourceCase c;
    writeWith("png", c.dir / "reference.png");
    c.genome.source = SourceImage{"reference.png"};
    const LinearRaster reference = decodeSourceImage(c.genome);
    ASSERT_EQ(reference.width, Width);
    ASSERT_EQ(reference.height, Height);
    struct Allowed {
        std::string format;
        double tolerance; // in linear light
    };
    for (const Allowed& a : {Allowed{"png", 0.0}, Allowed{"tif", 0.0}, Allowed{"jpg", 0.02},
                             Allowed{"webp", 0.03}, Allowed{"exr", 0.002}}) {
        writeWith(a.format, c.dir / ("own." + a.format));
        // Under its own name, under a misleading one, and in a data URL with a wrong MIME type.
        fs::copy_file(c.dir / ("own." + a.format), c.dir / ("named-wrongly-" + a.format + ".bmp"));
        for (const std::string& image :
             {"own." + a.format, "named-wrongly-" + a.format + ".bmp",
              "data:image/gif;base64," + base64(test::readFile(c.dir / ("own." + a.format)))}) {
            c.genome.source = SourceImage{image};
            LinearRaster raster;
            try {
                raster = decodeSourceImage(c.genome);
            } catch (const GenomeError& e) {
                ADD_FAILURE() << a.format << " " << image.substr(0, 40) << ": " << e.what();
                continue;
            }
            ASSERT_EQ(raster.width, Width) << a.format;
            ASSERT_EQ(raster.height, Height) << a.format;
            double worst = 0;
            for (std::size_t i = 0; i < raster.rgb.size(); ++i) {
                // EXR holds the values as linear light; the others as sRGB codes.
                double expected = a.format == "exr" ? double(gradient()[i]) : double(reference.rgb[i]);
                worst = std::max(worst, std::abs(double(raster.rgb[i]) - expected));
            }
            EXPECT_LE(worst, a.tolerance) << a.format << " " << image.substr(0, 40);
        }
    }
}

TEST(SourceFormat, ADamagedImageIsRefusedOnOneLine) {
    // Found by fuzz_source: OpenImageIO reports each of libpng's errors on a line of its own.
    SourceCase c;
    const std::string damaged =
        "data:image/"
        "png;base64,iVBORw0KGgoAAAANSUhEUgAAAAQAAAACCAIAAADwyuo0AAAAI0lEQVR4tyGcYycnOMBGw+bEhzs2DCIiIr9+/"
        "arQWGBz4hIAhF4Lc/CVkv0AAAAASUVORK5CYII=";
    const std::string error = c.errorOf(damaged);
    EXPECT_NE(error.find("source.image"), std::string::npos) << error;
    EXPECT_NE(error.find("IDAT"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(SourceFormat, AnExrAttributeLongerThanTheFileIsRefusedBeforeOpenExrReadsIt) {
    // Found by fuzz_source: OpenEXR 3.1 allocates what an attribute's size says before it finds
    // the file shorter (11 s under the sanitisers for one such file).
    SourceCase c;
    writeWith("exr", c.dir / "own.exr");
    std::string exr = test::readFile(c.dir / "own.exr");
    // The first attribute's size, after its name and type, made 300,000,000.
    const std::size_t sizeAt = 8 + exr.find('\0', 8) - 8 + 1;
    const std::size_t afterType = exr.find('\0', sizeAt) + 1;
    exr.replace(afterType, 4, std::string("\x00\xa3\xe1\x11", 4));
    test::writeFile(c.dir / "long.exr", exr);
    for (const std::string& image : {std::string("long.exr"), "data:image/x-exr;base64," + base64(exr)}) {
        const std::string error = c.errorOf(image);
        EXPECT_NE(error.find("a damaged OpenEXR image: its attribute"), std::string::npos) << error;
        EXPECT_NE(error.find("says 300000000 bytes, more than the file holds"), std::string::npos) << error;
    }
    // The sound file still decodes.
    EXPECT_EQ(c.errorOf("own.exr"), "");
    // Found by fuzz_source: an attribute's name is the file's bytes, a line break among them.
    std::string named = exr;
    named[8] = '\n';
    const std::string error = c.errorOf("data:image/x-exr;base64," + base64(named));
    EXPECT_NE(error.find("its attribute '\?"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(SourceFormat, AnExrInADataUrlIsReadOnlyWithinItsBytes) {
    // Found by fuzz_source: this file's line offsets make OpenImageIO 2.4's memory reader copy
    // from before its buffer (AddressSanitizer: heap-buffer-overflow). Refused or decoded, but
    // never read outside the bytes (the sanitised test run would report it).
    SourceCase c;
    const std::string exr = test::readFile(test::dataDir() / "render" / "exr-negative-offset.exr");
    ASSERT_GT(exr.size(), 100u);
    const std::string error = c.errorOf("data:image/x-exr;base64," + base64(exr));
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(SourceFormatCli, ADisguisedSourceEndsTheRenderWithOneLine) {
    SourceCase c;
    writeWith("dpx", c.dir / "x.dpx");
    fs::rename(c.dir / "x.dpx", c.dir / "x.png");
    c.genome.source = SourceImage{"x.png"};
    const fs::path file = c.dir / "disguised.marble.json";
    saveGenome(c.genome, file);
    const fs::path out = c.dir / "out.png";
    auto r = runMarbler({"render", file.string(), "-o", out.string(), "--width", "40"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(test::lineCount(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.find("marbler render: " + file.string() + ": source.image: "), 0u) << r.err;
    EXPECT_NE(r.err.find("a DPX file: sources must be PNG, JPEG, TIFF, EXR or WebP"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out));
}

} // namespace
} // namespace marbler
