// `marbler paper` through the built executable (spec/cli.md): same arguments give the same
// files, the image has the asked size and resolution and carries the genome beside it.

#include "TestUtil.h"

#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/Paper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>

namespace marbler {
namespace {

namespace fs = std::filesystem;
using test::runMarbler;

std::uint32_t bigEndian(const std::string& bytes, std::size_t at) {
    auto b = [&](std::size_t i) {
        return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes.at(at + i)));
    };
    return (b(0) << 24) | (b(1) << 16) | (b(2) << 8) | b(3);
}

/// What a PNG's IHDR and pHYs chunks say, read by hand so the test trusts no image library.
struct PngFacts {
    std::uint32_t width = 0, height = 0;
    std::uint32_t pixelsPerMetreX = 0, pixelsPerMetreY = 0;
    int unit = -1; ///< pHYs unit: 1 = metre; -1 = no pHYs chunk
};

PngFacts pngFacts(const fs::path& file) {
    std::string bytes = test::readFile(file);
    PngFacts facts;
    EXPECT_EQ(bytes.substr(1, 3), "PNG");
    for (std::size_t at = 8; at + 8 <= bytes.size();) {
        std::uint32_t length = bigEndian(bytes, at);
        std::string type = bytes.substr(at + 4, 4);
        if (type == "IHDR") {
            facts.width = bigEndian(bytes, at + 8);
            facts.height = bigEndian(bytes, at + 12);
        } else if (type == "pHYs") {
            facts.pixelsPerMetreX = bigEndian(bytes, at + 8);
            facts.pixelsPerMetreY = bigEndian(bytes, at + 12);
            facts.unit = static_cast<unsigned char>(bytes.at(at + 16));
        } else if (type == "IEND") {
            break;
        }
        at += 12 + length;
    }
    return facts;
}

std::vector<std::string> filesIn(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

TEST(PaperCli, SameArgumentsGiveTheSameFilesAndOtherSeedsDiffer) {
    fs::path dir = test::outputDir("paper-same");
    auto make = [&](const std::string& name, const std::string& seed) {
        test::RunResult r = runMarbler({"paper", "--size", "5x7cm", "--dpi", "50", "--colors", "4",
                                        "--passes", "2", "--seed", seed, "-o", (dir / name).string()});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err, "");
    };
    make("one.png", "77");
    make("two.png", "77");
    make("other.png", "78");
    EXPECT_EQ(filesIn(dir), (std::vector<std::string>{"one.marble.json", "one.png", "other.marble.json",
                                                      "other.png", "two.marble.json", "two.png"}));
    EXPECT_EQ(test::readFile(dir / "one.png"), test::readFile(dir / "two.png"));
    EXPECT_EQ(test::readFile(dir / "one.marble.json"), test::readFile(dir / "two.marble.json"));
    EXPECT_NE(test::readFile(dir / "one.png"), test::readFile(dir / "other.png"));
    EXPECT_NE(test::readFile(dir / "one.marble.json"), test::readFile(dir / "other.marble.json"));
}

TEST(PaperCli, WritesTheLibrarysGenomeBesideAndInsideTheImage) {
    fs::path dir = test::outputDir("paper-genome");
    test::RunResult r = runMarbler({"paper", "--size", "50x70mm", "--dpi", "40", "--pastel", "--seed", "5",
                                    "--output", (dir / "sheet.png").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    PaperOptions options;
    options.width = 50.0;
    options.height = 70.0;
    options.pastel = true;
    const Genome expected = paperGenome(5, options);
    EXPECT_EQ(test::readFile(dir / "sheet.marble.json"), serializeGenome(expected));
    EXPECT_EQ(loadDesign(dir / "sheet.png"), expected);
    // The defaults: 5 colours, 3 passes.
    EXPECT_EQ(expected.palette.size(), 5u);
    EXPECT_EQ(expected.operations.size(), 3u);
}

TEST(PaperCli, ThePostsRecipeIsTheDefaultAndWrapsAndClassicIsKept) {
    fs::path dir = test::outputDir("paper-recipes");
    for (const char* recipe : {"", "post", "classic"}) {
        const std::string name = std::string("sheet-") + (*recipe ? recipe : "default");
        std::vector<std::string> args = {"paper", "--size", "40x30mm",
                                         "--dpi", "30",     "--seed",
                                         "8",     "-o",     (dir / (name + ".png")).string()};
        if (*recipe) args.insert(args.end(), {"--recipe", recipe});
        test::RunResult r = runMarbler(args);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        PaperOptions options;
        options.width = 40.0;
        options.height = 30.0;
        options.recipe = std::string(recipe) == "classic" ? PaperRecipe::Classic : PaperRecipe::Post;
        const std::string file = test::readFile(dir / (name + ".marble.json"));
        EXPECT_EQ(file, serializeGenome(paperGenome(8, options))) << name;
        // The post's paper is a straight-repeat tile: its genome says the bath wraps.
        EXPECT_EQ(file.find("\"wrap\": true") != std::string::npos, options.recipe == PaperRecipe::Post)
            << name;
    }
}

TEST(PaperCli, TheImageHasThePixelSizeAndResolutionAsked) {
    fs::path dir = test::outputDir("paper-size");
    struct Case {
        std::string size, dpi;
        std::uint32_t width, height;
    };
    // 5 cm at 50 dpi is 98.4 pixels, 7 cm 137.8; 2 x 3 in at 30 dpi is 60 x 90.
    for (const Case& c :
         {Case{"5x7cm", "50", 98, 138}, Case{"2x3in", "30", 60, 90}, Case{"30x20mm", "100", 118, 79}}) {
        fs::path file = dir / ("sheet-" + c.size + ".png");
        test::RunResult r =
            runMarbler({"paper", "--size", c.size, "--dpi", c.dpi, "--seed", "1", "-o", file.string()});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        PngFacts facts = pngFacts(file);
        EXPECT_EQ(facts.width, c.width) << c.size;
        EXPECT_EQ(facts.height, c.height) << c.size;
        EXPECT_EQ(facts.unit, 1) << c.size;
        double perMetre = std::stod(c.dpi) / 0.0254;
        EXPECT_NEAR(facts.pixelsPerMetreX, perMetre, 1.0) << c.size;
        EXPECT_NEAR(facts.pixelsPerMetreY, perMetre, 1.0) << c.size;
        Genome genome = loadGenome(dir / ("sheet-" + c.size + ".marble.json"));
        // The design is measured in millimetres of the sheet.
        EXPECT_NEAR(genome.size.x / genome.size.y, static_cast<double>(c.width) / c.height, 0.02) << c.size;
    }
}

TEST(PaperCli, BadOptionsExit2WithOneLineAndLeaveNoFile) {
    fs::path dir = test::outputDir("paper-bad");
    const std::string out = (dir / "sheet.png").string();
    const std::vector<std::vector<std::string>> cases = {{"--size", "0x5cm"},
                                                         {"--size", "5x7"},
                                                         {"--size", "5x7furlongs"},
                                                         {"--size", "axbcm"},
                                                         {"--dpi", "0"},
                                                         {"--dpi", "-300"},
                                                         {"--dpi", "many"},
                                                         {"--colors", "0"},
                                                         {"--colors", "17"},
                                                         {"--colors", "2.5"},
                                                         {"--passes", "-1"},
                                                         {"--passes", "11"},
                                                         {"--passes", "three"},
                                                         {"--seed", "-4"},
                                                         {"--bogus"},
                                                         {"stray"},
                                                         {"--recipe", "turkish"},
                                                         {"--recipe"},
                                                         {"--repeat", "diagonal"},
                                                         {"--recipe", "classic", "--repeat", "brick"},
                                                         {"--size", "5x25cm", "--repeat", "half-drop"},
                                                         {"--size", "2000x2000cm", "--dpi", "1000"}};
    for (const std::vector<std::string>& bad : cases) {
        std::vector<std::string> args = {"paper", "--size", "5x7cm", "--dpi", "20", "--seed", "3", "-o", out};
        args.insert(args.end(), bad.begin(), bad.end());
        test::RunResult r = runMarbler(args);
        std::string what = bad[0] + (bad.size() > 1 ? " " + bad[1] : "");
        EXPECT_EQ(r.exitCode, 2) << what;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << ": " << r.err;
        EXPECT_TRUE(r.err.starts_with("marbler paper: ")) << r.err;
        EXPECT_TRUE(filesIn(dir).empty()) << what;
    }
    // No seed, no output, an image format Marbler does not write.
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"paper", "--dpi", "20", "-o", out},
          std::vector<std::string>{"paper", "--dpi", "20", "--seed", "1"},
          std::vector<std::string>{"paper", "--size", "5x7cm", "--dpi", "20", "--seed", "1", "-o",
                                   (dir / "sheet.unknownformat").string()}}) {
        test::RunResult r = runMarbler(args);
        EXPECT_EQ(r.exitCode, 2) << args.back();
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_TRUE(filesIn(dir).empty()) << args.back();
    }
}

TEST(PaperCli, HelpDescribesEveryOption) {
    test::RunResult r = runMarbler({"paper", "--help"});
    EXPECT_EQ(r.exitCode, 0);
    for (const char* option :
         {"--size", "--dpi", "--colors", "--passes", "--pastel", "--seed", "-o", "--recipe", "--repeat"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

// Issue 29: `paper --quiet` was refused while `render --quiet` was taken. The common flags
// (Cli.h CommonFlags) work on every verb, and paper shows its progress like render.
TEST(PaperCli, EveryVerbTakesTheCommonOptions) {
    const fs::path dir = test::outputDir("paper-common-options");
    const std::string example = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    const std::vector<std::vector<std::string>> runs = {
        {"paper", "--size", "2x3cm", "--dpi", "30", "--seed", "4", "-o", (dir / "quiet.png").string()},
        {"info", example},
        {"random", "--dimension", "2", "--seed", "3", "-o", (dir / "random.marble.json").string()},
        {"svg", example, "-o", (dir / "design.svg").string()},
    };
    for (const std::vector<std::string>& run : runs) {
        for (const char* flag : {"--quiet", "--progress"}) {
            std::vector<std::string> args = run;
            args.emplace_back(flag);
            test::RunResult r = runMarbler(args);
            EXPECT_EQ(r.exitCode, 0) << run[0] << ' ' << flag << ": " << r.err;
            EXPECT_EQ(r.err.find("unknown option"), std::string::npos) << r.err;
        }
    }
    EXPECT_TRUE(fs::exists(dir / "quiet.png"));
    EXPECT_TRUE(fs::exists(dir / "quiet.marble.json"));

    // paper says how far it is with --progress, and nothing with --quiet.
    test::RunResult shown = runMarbler({"paper", "--size", "2x3cm", "--dpi", "30", "--seed", "4",
                                        "--progress", "-o", (dir / "shown.png").string()});
    EXPECT_EQ(shown.exitCode, 0) << shown.err;
    EXPECT_NE(shown.err.find("rendering"), std::string::npos) << shown.err;
    test::RunResult quiet = runMarbler({"paper", "--size", "2x3cm", "--dpi", "30", "--seed", "4", "--quiet",
                                        "--progress", "-o", (dir / "still.png").string()});
    EXPECT_EQ(quiet.exitCode, 0) << quiet.err;
    EXPECT_EQ(quiet.err, "");

    test::RunResult help = runMarbler({"paper", "--help"});
    EXPECT_NE(help.out.find("--quiet"), std::string::npos);
}

} // namespace
} // namespace marbler
