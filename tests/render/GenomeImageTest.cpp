// Genomes inside images (marbler/GenomeImage.h): every PNG and TIFF written carries its genome
// and gives it back equal; images without one, of another kind, broken or hostile are refused
// with one clear line; the verbs take such images wherever they take a genome.

#include "marbler/GenomeImage.h"
#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/RenderToFile.h"

#include <gtest/gtest.h>
#include <tiffio.h>
#include <zlib.h>

#include <cstdint>
#include <fstream>

namespace marbler {
namespace {

namespace fs = std::filesystem;

std::vector<unsigned char> bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

void writeBytes(const fs::path& file, const std::vector<unsigned char>& bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

RenderSettings small() {
    RenderSettings s;
    s.width = 40;
    s.height = 30;
    return s;
}

/// A small genome, whose text is short enough to stay uncompressed in a PNG.
Genome tiny() {
    return parseGenome(R"({"format": "marbler-genome", "version": 1, "dimension": 2, "size": [100, 100],
        "background": "#ffffff", "palette": ["#102030"],
        "initial": [{"tool": "drop", "center": [50, 50], "radius": 20, "color": 0}], "operations": [],
        "meta": {"name": "Tiny <&> “stone”"}})",
                       "tiny");
}

/// A PNG chunk: length, type, data, CRC.
void appendChunk(std::vector<unsigned char>& png, const std::string& type, const std::string& data) {
    const auto n = std::uint32_t(data.size());
    for (int shift : {24, 16, 8, 0})
        png.push_back(static_cast<unsigned char>(n >> shift));
    const std::string body = type + data;
    png.insert(png.end(), body.begin(), body.end());
    const std::uint32_t crc =
        std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size())));
    for (int shift : {24, 16, 8, 0})
        png.push_back(static_cast<unsigned char>(crc >> shift));
}

std::string deflate(const std::string& data) {
    uLongf size = compressBound(uLong(data.size()));
    std::string out(size, '\0');
    compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(data.data()),
              uLong(data.size()), Z_BEST_SPEED);
    out.resize(size);
    return out;
}

/// A 2 x 2 RGB PNG built chunk by chunk, with `before` chunks ahead of the image data and
/// `after` chunks behind it (type, data).
std::vector<unsigned char> handMadePng(const std::vector<std::pair<std::string, std::string>>& before,
                                       const std::vector<std::pair<std::string, std::string>>& after) {
    std::vector<unsigned char> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    appendChunk(png, "IHDR", std::string("\0\0\0\2\0\0\0\2\x08\x02\0\0\0", 13));
    for (const auto& [type, data] : before)
        appendChunk(png, type, data);
    appendChunk(png, "IDAT", deflate(std::string(2 * (1 + 2 * 3), '\0')));
    for (const auto& [type, data] : after)
        appendChunk(png, type, data);
    appendChunk(png, "IEND", "");
    return png;
}

/// An iTXt chunk's data: keyword, compression flag and method, empty language and translated
/// keyword, then the text.
std::string itxt(const std::string& keyword, const std::string& text, bool compressed) {
    return keyword + std::string("\0", 1) + (compressed ? std::string("\1\0", 2) : std::string("\0\0", 2)) +
           std::string("\0\0", 2) + (compressed ? deflate(text) : text);
}

TEST(GenomeImage, EveryPngAndTiffGivesItsGenomeBack) {
    const fs::path dir = test::outputDir("genome-image-roundtrip");
    for (const Genome& g : {tiny(), test::loadExample("five-stones.marble.json"),
                            test::loadExample("flame-comb-vortex.marble.json")}) {
        const std::string canonical = serializeGenome(g);
        for (const char* ext : {".png", ".tif", ".tiff"}) {
            const fs::path file = dir / (g.meta.toJson().value("name", std::string("x")).substr(0, 4) + ext);
            renderToFile(g, small(), file);
            const ImageKind kind = std::string(ext) == ".png" ? ImageKind::Png : ImageKind::Tiff;
            std::optional<std::string> text = readGenomeText(file, kind, file.string());
            ASSERT_TRUE(text) << file;
            EXPECT_EQ(*text, canonical) << file; // the very text a genome file holds
            Genome back = loadDesign(file);
            EXPECT_EQ(serializeGenome(back), canonical) << file;
            EXPECT_EQ(back, g) << file;
            EXPECT_EQ(back.baseDirectory, dir.string());
        }
    }
}

TEST(GenomeImage, ShortGenomesStayReadableLongOnesAreDeflated) {
    const fs::path dir = test::outputDir("genome-image-compression");
    auto fileHolds = [](const fs::path& file, const std::string& text) {
        return test::readFile(file).find(text) != std::string::npos;
    };
    const std::string shortText = serializeGenome(tiny());
    ASSERT_LE(shortText.size(), PngCompressAbove);
    renderToFile(tiny(), small(), dir / "short.png");
    EXPECT_TRUE(fileHolds(dir / "short.png", shortText));

    const Genome big = test::loadExample("flame-comb-vortex.marble.json");
    ASSERT_GT(serializeGenome(big).size(), PngCompressAbove);
    renderToFile(big, small(), dir / "long.png");
    EXPECT_FALSE(fileHolds(dir / "long.png", serializeGenome(big)));
    EXPECT_EQ(loadDesign(dir / "long.png"), big);
    // Deflated, the long genome takes less room than its text.
    EXPECT_LT(fs::file_size(dir / "long.png"),
              fs::file_size(dir / "short.png") + serializeGenome(big).size());
}

TEST(GenomeImage, WriteImageCarriesTheGenomeItIsGiven) {
    const fs::path dir = test::outputDir("genome-image-write");
    const Genome g = test::loadExample("five-stones.marble.json");
    const Image image = CpuRenderer(g).render(small());
    for (const char* ext : {".png", ".tif"}) {
        ExportOptions options;
        options.genome = serializeGenome(g);
        writeImage(image, dir / (std::string("with") + ext), options);
        EXPECT_EQ(loadDesign(dir / (std::string("with") + ext)), g);
        // Without a genome the image is plain, and refused as a design.
        const fs::path plain = dir / (std::string("plain") + ext);
        writeImage(image, plain);
        try {
            loadDesign(plain);
            ADD_FAILURE() << plain << " loaded";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), plain.string() + " is an image without a Marbler genome in it");
        }
    }
}

TEST(GenomeImage, ErrorsInAnEmbeddedGenomeNameTheImageAndTheLocation) {
    const fs::path dir = test::outputDir("genome-image-bad-genome");
    std::string text = serializeGenome(tiny());
    text.replace(text.find("\"radius\": 20"), 12, "\"radius\": -2");
    ExportOptions options;
    options.genome = text;
    for (const auto& [ext, kind] : {std::pair{".png", "PNG"}, std::pair{".tif", "TIFF"}}) {
        const fs::path file = dir / (std::string("bad") + ext);
        writeImage(CpuRenderer(tiny()).render(small()), file, options);
        try {
            loadDesign(file);
            ADD_FAILURE() << file << " loaded";
        } catch (const GenomeError& e) {
            EXPECT_EQ(std::string(e.what()), file.string() + ": genome in " + kind +
                                                 " metadata: initial[0].radius: must be > 0 (got -2)");
        }
    }
}

TEST(GenomeImage, TextAfterTheImageDataAndOlderTextChunksAreFound) {
    const Genome g = tiny();
    const std::string text = serializeGenome(g);
    // Moved behind the pixels, as other programs may do when they save the file again.
    for (bool compressed : {false, true}) {
        std::vector<unsigned char> png =
            handMadePng({}, {{"iTXt", itxt(PngGenomeKeyword, text, compressed)}});
        std::optional<std::string> found = readGenomeText(png, ImageKind::Png, "after.png");
        ASSERT_TRUE(found);
        EXPECT_EQ(*found, text);
    }
    // tEXt is Latin-1: the name's non-ASCII letters arrive as UTF-8.
    Genome latin = g;
    latin.meta.name = "Caf\xc3\xa9";
    std::string latinText = serializeGenome(latin);
    latinText.replace(latinText.find("Caf\xc3\xa9"), 5, "Caf\xe9");
    std::vector<unsigned char> png =
        handMadePng({{"tEXt", std::string(PngGenomeKeyword) + '\0' + latinText}}, {});
    EXPECT_EQ(
        parseEmbeddedGenome(*readGenomeText(png, ImageKind::Png, "latin.png"), ImageKind::Png, "latin.png"),
        latin);
    // Other text is not a genome.
    png = handMadePng({{"iTXt", itxt("Comment", text, false)}}, {});
    EXPECT_FALSE(readGenomeText(png, ImageKind::Png, "comment.png"));
}

TEST(GenomeImage, XmpInTheFormsOtherToolsWrite) {
    const std::string text = serializeGenome(tiny());
    EXPECT_EQ(genomeFromXmp(genomeXmpPacket(text)), text);
    // Another prefix, the attribute form, entities for every special character.
    const std::string attribute =
        std::string("<x:xmpmeta xmlns:x='adobe:ns:meta/'><rdf:RDF><rdf:Description xmlns:ns1 = '") +
        XmpNamespace + "' ns1:genome=\"{&quot;a&quot;: &#x3C;1&#62;, &amp;&apos;\"/></rdf:RDF></x:xmpmeta>";
    EXPECT_EQ(genomeFromXmp(attribute), std::string("{\"a\": <1>, &'"));
    const std::string cdata =
        std::string("<r xmlns:m=\"") + XmpNamespace + "\"><m:genome><![CDATA[{<&>}]]></m:genome></r>";
    EXPECT_EQ(genomeFromXmp(cdata), std::string("{<&>}"));
    // The property of another namespace, or no property, is no genome.
    EXPECT_FALSE(
        genomeFromXmp("<r xmlns:marbler=\"http://example.com/\"><marbler:genome>{}</marbler:genome></r>"));
    EXPECT_FALSE(
        genomeFromXmp(std::string("<r xmlns:m=\"") + XmpNamespace + "\"><m:genomes>{}</m:genomes></r>"));
    EXPECT_FALSE(genomeFromXmp(""));
}

TEST(GenomeImage, ATiffDescriptionHoldingAGenomeIsReadToo) {
    // As a tool leaves it that keeps the description but not the XMP packet.
    const fs::path dir = test::outputDir("genome-image-description");
    auto writeTiff = [&](const fs::path& file, const char* description) {
        TIFF* tiff = TIFFOpen(file.c_str(), "w");
        ASSERT_NE(tiff, nullptr);
        TIFFSetField(tiff, TIFFTAG_IMAGEWIDTH, 1u);
        TIFFSetField(tiff, TIFFTAG_IMAGELENGTH, 1u);
        TIFFSetField(tiff, TIFFTAG_SAMPLESPERPIXEL, 3);
        TIFFSetField(tiff, TIFFTAG_BITSPERSAMPLE, 8);
        TIFFSetField(tiff, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
        TIFFSetField(tiff, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
        TIFFSetField(tiff, TIFFTAG_IMAGEDESCRIPTION, description);
        unsigned char pixel[3] = {1, 2, 3};
        EXPECT_GE(TIFFWriteScanline(tiff, pixel, 0, 0), 0);
        TIFFClose(tiff);
    };
    const std::string text = serializeGenome(test::loadExample("five-stones.marble.json"));
    writeTiff(dir / "described.tif", text.c_str());
    EXPECT_EQ(loadDesign(dir / "described.tif"), test::loadExample("five-stones.marble.json"));
    // A description that is no genome is just a description.
    writeTiff(dir / "scan.tif", "Scanned at 600 dpi");
    EXPECT_THROW(loadDesign(dir / "scan.tif"), InputError);
}

TEST(GenomeImage, RelativeSourcesResolveAgainstTheImagesFolder) {
    const fs::path dir = test::outputDir("genome-image-source");
    fs::create_directories(dir / "shared");
    fs::copy_file(test::dataDir() / "render" / "source-4x2.png", dir / "shared" / "source-4x2.png");
    const Genome g = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
    ASSERT_TRUE(g.source);
    ASSERT_FALSE(fs::path(g.source->image).is_absolute());
    RenderSettings s = small();
    renderToFile(g, s, dir / "shared" / "design.png");
    const Genome back = loadDesign(dir / "shared" / "design.png");
    EXPECT_EQ(back.baseDirectory, (dir / "shared").string());
    // It renders from the image's folder, whatever the working folder: as the genome file did.
    EXPECT_EQ(CpuRenderer(back).render(s).rgb, CpuRenderer(g).render(s).rgb);
}

TEST(GenomeImage, OtherImageKindsAreRefusedByName) {
    const fs::path dir = test::outputDir("genome-image-kinds");
    writeBytes(dir / "photo.jpg", {0xff, 0xd8, 0xff, 0xe0, 0, 0x10, 'J', 'F', 'I', 'F', 0, 1, 1, 0, 0, 1});
    try {
        loadDesign(dir / "photo.jpg");
        ADD_FAILURE() << "a JPEG loaded";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  (dir / "photo.jpg").string() +
                      " is a JPEG image; only PNG and TIFF images carry a Marbler genome");
    }
    // A file named as an image that is not one says both what it is not.
    test::writeFile(dir / "fake.png", "not an image");
    try {
        loadDesign(dir / "fake.png");
        ADD_FAILURE() << "fake.png loaded";
    } catch (const InputError& e) {
        EXPECT_TRUE(std::string(e.what()).starts_with((dir / "fake.png").string() + " is not a PNG image"))
            << e.what();
    }
    // A genome file is still a genome file, whatever it is called.
    test::writeFile(dir / "genome.png", serializeGenome(tiny()));
    EXPECT_EQ(loadDesign(dir / "genome.png"), tiny());
}

/// Every prefix of a Marbler image is refused (an InputError, or no genome found) or gives the
/// genome itself, never a part of it, a crash or another exception; a prefix that ends before
/// the genome's data does is refused. Only the metadata is read, so an image whose pixels are
/// cut off still gives its whole genome.
void expectEveryTruncationSafe(const std::vector<unsigned char>& bytes, ImageKind kind, const Genome& genome,
                               std::size_t genomeEnd) {
    for (std::size_t size = 0; size < bytes.size(); size += (size < 600 ? 1 : 41)) {
        std::span<const unsigned char> prefix(bytes.data(), size);
        try {
            std::optional<std::string> text = readGenomeText(prefix, kind, "cut");
            if (!text) continue;
            EXPECT_GE(size, genomeEnd) << "a genome was read from a file cut before its end";
            EXPECT_EQ(parseEmbeddedGenome(*text, kind, "cut"), genome) << size;
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
    }
}

TEST(GenomeImage, TruncatedAndDamagedImagesAreRefused) {
    const fs::path dir = test::outputDir("genome-image-truncated");
    const Genome g = test::loadExample("flame-comb-vortex.marble.json");
    renderToFile(g, small(), dir / "a.png");
    renderToFile(g, small(), dir / "a.tif");
    const std::vector<unsigned char> png = bytesOf(dir / "a.png");
    const std::vector<unsigned char> tif = bytesOf(dir / "a.tif");
    // The PNG's genome chunk ends where the image data begins.
    const std::string idat = "IDAT";
    const std::size_t idatAt =
        std::size_t(std::search(png.begin(), png.end(), idat.begin(), idat.end()) - png.begin());
    expectEveryTruncationSafe(png, ImageKind::Png, g, idatAt - 4);
    const std::string packetEnd = "</x:xmpmeta>";
    const auto packetAt = std::search(tif.begin(), tif.end(), packetEnd.begin(), packetEnd.end());
    ASSERT_NE(packetAt, tif.end());
    expectEveryTruncationSafe(tif, ImageKind::Tiff, g,
                              std::size_t(packetAt - tif.begin()) + packetEnd.size());

    // A damaged byte inside the genome's chunk fails its CRC.
    std::vector<unsigned char> damaged = png;
    const std::string key = PngGenomeKeyword;
    const auto keyAt = std::search(damaged.begin(), damaged.end(), key.begin(), key.end());
    ASSERT_NE(keyAt, damaged.end());
    keyAt[key.size() + 10] ^= 0x55;
    writeBytes(dir / "damaged.png", damaged);
    try {
        loadDesign(dir / "damaged.png");
        ADD_FAILURE() << "a damaged genome chunk was read";
    } catch (const InputError& e) {
        EXPECT_TRUE(
            std::string(e.what()).starts_with((dir / "damaged.png").string() + ": cannot read the PNG: "))
            << e.what();
    }
}

TEST(GenomeImage, HugeChunksAreRefusedBeforeTheyAreRead) {
    // A chunk that claims 2 GiB, in a file of a few bytes.
    std::vector<unsigned char> png = handMadePng({}, {});
    std::vector<unsigned char> huge(png.begin(), png.begin() + 33); // signature and IHDR
    for (unsigned char b : {0x7f, 0xff, 0xff, 0xf0})
        huge.push_back(b);
    for (char c : std::string("iTXt"))
        huge.push_back(static_cast<unsigned char>(c));
    huge.resize(huge.size() + 64, 'x');
    EXPECT_THROW(readGenomeText(huge, ImageKind::Png, "huge.png"), InputError);

    // A deflated genome that inflates past the 16 MiB limit: said, not allocated without end.
    const std::string bomb = std::string("{\"format\": \"marbler-genome\", \"x\": \"") +
                             std::string(2 * MaxFileBytes, 'a') + "\"}";
    png = handMadePng({{"iTXt", itxt(PngGenomeKeyword, bomb, true)}}, {});
    ASSERT_LT(png.size(), std::size_t(1) << 20);
    try {
        readGenomeText(png, ImageKind::Png, "bomb.png");
        ADD_FAILURE() << "the bomb was read";
    } catch (const InputError& e) {
        EXPECT_TRUE(
            std::string(e.what()).starts_with("bomb.png is an image without a readable Marbler genome"))
            << e.what();
    }

    // A TIFF whose XMP tag claims 4 GiB.
    const fs::path dir = test::outputDir("genome-image-huge");
    renderToFile(tiny(), small(), dir / "a.tif");
    std::vector<unsigned char> tif = bytesOf(dir / "a.tif");
    ASSERT_EQ(tif[0], 'I'); // little-endian, as libtiff writes on this machine
    const std::uint32_t ifd = tif[4] | tif[5] << 8 | tif[6] << 16 | std::uint32_t(tif[7]) << 24;
    const unsigned entries = tif[ifd] | tif[ifd + 1] << 8;
    bool patched = false;
    for (unsigned e = 0; e < entries; ++e) {
        unsigned char* entry = &tif[ifd + 2 + 12 * e];
        if ((entry[0] | entry[1] << 8) == 700) {
            entry[4] = entry[5] = entry[6] = 0xff;
            entry[7] = 0xff;
            patched = true;
        }
    }
    ASSERT_TRUE(patched);
    try {
        EXPECT_FALSE(readGenomeText(tif, ImageKind::Tiff, "huge.tif"));
    } catch (const InputError& e) {
        EXPECT_TRUE(std::string(e.what()).starts_with("huge.tif: cannot read the TIFF: ")) << e.what();
    }
}

// --- the verbs ---------------------------------------------------------------------------------

TEST(GenomeImageCli, VerbsTakeImagesThatCarryGenomes) {
    const fs::path dir = test::outputDir("genome-image-cli");
    const std::string genome = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    auto r =
        test::runMarbler({"render", genome, "-o", (dir / "design.png").string(), "--width", "64", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = test::runMarbler({"render", genome, "-o", (dir / "design.tif").string(), "--width", "64", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;

    for (const char* image : {"design.png", "design.tif"}) {
        r = test::runMarbler({"info", (dir / image).string()});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.out.find("name:       Five stones, combed and swirled"), std::string::npos) << r.out;
        EXPECT_TRUE(r.err.empty()) << r.err;
    }
    // An image renders like its genome, and the new image carries the same genome on.
    r = test::runMarbler(
        {"render", (dir / "design.png").string(), "-o", (dir / "again.png").string(), "--width", "64"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readImage8(dir / "again.png").rgb, test::readImage8(dir / "design.png").rgb);
    EXPECT_EQ(serializeGenome(loadDesign(dir / "again.png")), serializeGenome(loadGenome(genome)));
    r = test::runMarbler(
        {"render", (dir / "design.tif").string(), "-o", (dir / "again.tif").string(), "--width", "64"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(loadDesign(dir / "again.tif"), loadGenome(genome));

    // Parents of breed may be images too: the same children as from the genome file.
    r = test::runMarbler({"breed", "alter", (dir / "design.png").string(), "--seed", "3", "--count", "2",
                          "-o", (dir / "from-image").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = test::runMarbler(
        {"breed", "alter", genome, "--seed", "3", "--count", "2", "-o", (dir / "from-file").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readFile(dir / "from-image" / "child-01.marble.json"),
              test::readFile(dir / "from-file" / "child-01.marble.json"));
}

TEST(GenomeImageCli, PlainBrokenAndForeignImagesAreBadInputOnOneLine) {
    const fs::path dir = test::outputDir("genome-image-cli-bad");
    const Genome g = test::loadExample("five-stones.marble.json");
    const Image image = CpuRenderer(g).render(small());
    writeImage(image, dir / "plain.png");
    writeImage(image, dir / "plain.tif");
    renderToFile(g, small(), dir / "whole.png");
    std::vector<unsigned char> bytes = bytesOf(dir / "whole.png");
    bytes.resize(60);
    writeBytes(dir / "cut.png", bytes);
    writeBytes(dir / "garbage.png", {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 1, 2, 3, 4, 5, 6, 7, 8, 9});

    const std::vector<std::pair<std::string, std::string>> cases = {
        {"plain.png", "plain.png is an image without a Marbler genome in it"},
        {"plain.tif", "plain.tif is an image without a Marbler genome in it"},
        {"cut.png", "cut.png: cannot read the PNG: "},
        {"garbage.png", "garbage.png: cannot read the PNG: "},
    };
    for (const auto& [file, message] : cases) {
        for (const char* verb : {"info", "render"}) {
            std::vector<std::string> args = {verb, (dir / file).string()};
            if (std::string(verb) == "render") args.insert(args.end(), {"-o", (dir / "out.png").string()});
            auto r = test::runMarbler(args);
            EXPECT_EQ(r.exitCode, 2) << verb << " " << file;
            EXPECT_EQ(test::lineCount(r.err), 1u) << r.err;
            EXPECT_EQ(r.err.find(std::string("marbler ") + verb + ": " + (dir / message).string()), 0u)
                << r.err;
        }
        EXPECT_FALSE(fs::exists(dir / "out.png"));
    }
}

} // namespace
} // namespace marbler
