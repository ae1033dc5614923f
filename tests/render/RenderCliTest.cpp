// `marbler render` through the executable: sizes, exit codes, one-line errors, no partial output.

#include "RenderTestUtil.h"
#include "TestUtil.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <array>

namespace marbler {
namespace {

using test::runMarbler;

TEST(RenderCli, ProgressIsOneLineRewrittenThenClearedAndQuietSaysNothing) {
    const auto dir = test::outputDir("cli-progress");
    const std::vector<std::string> render{"render",  test::examplePath("five-stones.marble.json"),
                                          "-o",      (dir / "a.png").string(),
                                          "--width", "400"};
    std::vector<std::string> args = render;
    args.push_back("--progress");
    auto r = runMarbler(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The line is rewritten in place (no newline), reaches 100 % and is blanked at the end.
    EXPECT_EQ(r.err.find('\n'), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\rrendering 100%"), std::string::npos) << r.err;
    const std::size_t last = r.err.rfind('\r');
    ASSERT_NE(last, std::string::npos);
    EXPECT_EQ(last, r.err.size() - 1) << "the last thing written returns to an empty line";
    EXPECT_EQ(r.err.find_first_not_of(" \r", r.err.rfind("%") + 1), std::string::npos) << "then blanks it";

    // Not a terminal and no --progress, or --quiet even with it: nothing on stderr.
    r = runMarbler(render);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
    args.push_back("--quiet");
    r = runMarbler(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

TEST(RenderCli, DefaultSizeAndAspect) {
    const auto dir = test::outputDir("cli-sizes");
    auto r = runMarbler({"render", test::examplePath("five-stones.marble.json"), "-o",
                         (dir / "a.png").string(), "--threads", "2"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Image a = test::readImage8(dir / "a.png");
    EXPECT_EQ(a.width, 1024);
    EXPECT_EQ(a.height, 1024);

    r = runMarbler({"render", test::examplePath("five-stones.marble.json"), "-o", (dir / "b.png").string(),
                    "--width", "300", "--region", "0,0,1000,500"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Image b = test::readImage8(dir / "b.png");
    EXPECT_EQ(b.width, 300);
    EXPECT_EQ(b.height, 150);

    r = runMarbler({"render", test::examplePath("five-stones.marble.json"), "-o", (dir / "c.tif").string(),
                    "--height", "100", "--region=0,0,1000,500", "--aa", "rgss"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Image c = test::readImage8(dir / "c.tif");
    EXPECT_EQ(c.width, 200);
    EXPECT_EQ(c.height, 100);

    // A y slice of the solid example covers x-z.
    r = runMarbler({"render", test::examplePath("slate-block.marble.json"), "-o", (dir / "d.png").string(),
                    "--width", "64", "--slice", "y=500"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readImage8(dir / "d.png").height, 64);
}

TEST(RenderCli, PrintSizeAndDpiSetThePixels) {
    const auto dir = test::outputDir("cli-print");
    auto r = runMarbler({"render", test::examplePath("five-stones.marble.json"), "-o",
                         (dir / "p.png").string(), "--size", "10x5cm", "--dpi", "254", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto in = OIIO::ImageInput::open((dir / "p.png").string());
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().width, 1000); // 10 cm = 3.937 in at 254 dpi
    EXPECT_EQ(in->spec().height, 500);
    EXPECT_NEAR(in->spec().get_float_attribute("XResolution"), 254.0f, 0.05f);
    in->close();
    r = runMarbler({"render", test::examplePath("five-stones.marble.json"), "-o", (dir / "q.png").string(),
                    "--size", "2x1in", "--dpi", "50"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readImage8(dir / "q.png").width, 100);
    r = runMarbler({"render", test::examplePath("five-stones.marble.json"), "-o", (dir / "r.png").string(),
                    "--size", "20x10mm", "--dpi", "127"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readImage8(dir / "r.png").width, 100);
}

/// A failure: the exit status, one stderr line that mentions `mention`, and no output file.
void expectFailure(const std::vector<std::string>& args, int exitCode, const std::string& mention,
                   const std::filesystem::path& out) {
    auto r = runMarbler(args);
    EXPECT_EQ(r.exitCode, exitCode) << r.err;
    EXPECT_EQ(test::lineCount(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << out;
    for (const auto& entry : std::filesystem::directory_iterator(out.parent_path()))
        ADD_FAILURE() << "left behind: " << entry.path();
}

TEST(RenderCli, BadInputExitsTwoWithOneLineAndNoOutput) {
    const auto dir = test::outputDir("cli-bad");
    const std::string out = (dir / "out.png").string();
    const std::string good = test::examplePath("five-stones.marble.json");
    test::writeFile(dir.parent_path() / "broken.marble.json", "{\"format\": \"marbler-genome\", ");
    expectFailure({"render", (dir.parent_path() / "broken.marble.json").string(), "-o", out}, 2,
                  "broken.marble.json", out);
    expectFailure({"render", (dir.parent_path() / "absent.marble.json").string(), "-o", out}, 2,
                  "absent.marble.json", out);
    expectFailure({"render", good, "-o", out, "--frobnicate"}, 2, "--frobnicate", out);
    expectFailure({"render", good, "-o", out, "--width", "1000000", "--height", "1000000"}, 2, "width", out);
    expectFailure({"render", good, "-o", out, "--width", "60000", "--height", "60000"}, 2, "too large", out);
    expectFailure({"render", good, "-o", out, "--aa", "fxaa"}, 2, "fxaa", out);
    expectFailure({"render", good, "-o", out, "--region", "5,5,5,9"}, 2, "region", out);
    expectFailure({"render", good, "-o", out, "--slice", "z=10"}, 2, "five-stones", out);
    expectFailure({"render", test::examplePath("slate-block.marble.json"), "-o", out}, 2, "slate-block", out);
    expectFailure({"render", good, "-o", out, "--size", "10x10cm"}, 2, "--dpi", out);
    expectFailure({"render", good, "-o", out, "--size", "10x10furlong", "--dpi", "300"}, 2, "--size", out);
    expectFailure({"render", good, "-o", (dir / "out.xyz").string()}, 2, "out.xyz", dir / "out.xyz");
    expectFailure({"render", good}, 2, "-o", out);
    // A flat design on an object with --gpu is drawn now (tests/gl/GlFlatObjectTest.cpp).
}

TEST(RenderCli, EveryVerbRefusesABadSliceInTheSameWords) {
    // render and animate parse --slice in one place, so a person reads one message from both.
    const auto dir = test::outputDir("cli-bad-slice");
    const std::string solid = test::examplePath("slate-block.marble.json");
    const std::string out = (dir / "out.png").string();
    const std::vector<std::pair<std::string, std::string>> cases{
        {"z=abc", "--slice: 'z=abc' is not AXIS=VALUE with a number VALUE (e.g. z=500)"},
        {"z=1,2", "--slice: 'z=1,2' is not AXIS=VALUE with a number VALUE (e.g. z=500)"},
        {"z=", "--slice: 'z=' is not AXIS=VALUE with a number VALUE (e.g. z=500)"},
        {"w=5", "--slice: 'w=5' is not AXIS=VALUE with AXIS x, y or z (e.g. z=500)"},
        {"500", "--slice: '500' is not AXIS=VALUE with AXIS x, y or z (e.g. z=500)"}};
    for (const auto& [text, message] : cases) {
        for (const char* verb : {"render", "animate"}) {
            auto r = runMarbler({verb, solid, "-o", out, "--slice", text});
            EXPECT_EQ(r.exitCode, 2) << verb << ' ' << text << ": " << r.err;
            EXPECT_EQ(r.err, std::string("marbler ") + verb + ": " + message + "\n") << verb << ' ' << text;
        }
        EXPECT_FALSE(std::filesystem::exists(out)) << text;
    }
}

TEST(RenderCli, UnwritableFolderExitsOne) {
    const auto dir = test::outputDir("cli-unwritable");
    const auto out = dir / "no" / "such" / "folder" / "out.png";
    auto r = runMarbler(
        {"render", test::examplePath("five-stones.marble.json"), "-o", out.string(), "--width", "16"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(test::lineCount(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find("out.png"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderCli, GpuEitherRendersOrSaysWhyNot) {
    const auto dir = test::outputDir("cli-gpu");
    const auto out = dir / "gpu.png";
    auto r = runMarbler({"render", test::examplePath("five-stones.marble.json"), "-o", out.string(),
                         "--width", "32", "--gpu"});
    if (r.exitCode == 0) {
        EXPECT_EQ(test::readImage8(out).width, 32);
    } else {
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_EQ(test::lineCount(r.err), 1u) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
}

TEST(RenderCli, MirrorRepeatWrapsWithoutASeam) {
    const auto dir = test::outputDir("cli-repeat");
    const std::string genome = test::examplePath("flame-comb-vortex.marble.json");
    auto r = runMarbler({"render", genome, "-o", (dir / "design.png").string(), "--width", "96", "--height",
                         "64", "--aa", "rgss", "--region", "100,200,700,600"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runMarbler({"render", genome, "-o", (dir / "tile.png").string(), "--width", "96", "--height", "64",
                    "--aa", "rgss", "--region", "100,200,700,600", "--repeat", "mirror"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Image design = test::readImage8(dir / "design.png");
    Image tile = test::readImage8(dir / "tile.png");
    ASSERT_EQ(tile.width, 2 * design.width);
    ASSERT_EQ(tile.height, 2 * design.height);
    const int w = design.width, h = design.height, tw = tile.width, th = tile.height;
    auto px = [](const Image& image, int x, int y) {
        const std::uint8_t* p = image.row(y) + std::size_t(x) * 3;
        return std::array<int, 3>{p[0], p[1], p[2]};
    };
    // The quadrants: the design as rendered (the other options honoured), then its exact mirrors.
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            auto d = px(design, x, y);
            ASSERT_EQ(px(tile, x, y), d) << x << "," << y;
            ASSERT_EQ(px(tile, tw - 1 - x, y), d) << x << "," << y;
            ASSERT_EQ(px(tile, x, th - 1 - y), d) << x << "," << y;
            ASSERT_EQ(px(tile, tw - 1 - x, th - 1 - y), d) << x << "," << y;
        }
    // Wrapping: the last column meets the first, the last row the first, with equal pixels, so
    // laid side by side or one under another the tiles show no seam.
    for (int y = 0; y < th; ++y)
        EXPECT_EQ(px(tile, tw - 1, y), px(tile, 0, y)) << y;
    for (int x = 0; x < tw; ++x)
        EXPECT_EQ(px(tile, x, th - 1), px(tile, x, 0)) << x;
    // The design itself does not wrap: its opposite edges differ, which is why the mirrors are needed.
    int differing = 0;
    for (int y = 0; y < h; ++y)
        differing += px(design, w - 1, y) != px(design, 0, y);
    EXPECT_GT(differing, 0);

    // With --size and --dpi each quarter has the print size.
    r = runMarbler({"render", genome, "-o", (dir / "print.png").string(), "--size", "2x1in", "--dpi", "50",
                    "--repeat", "mirror"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Image print = test::readImage8(dir / "print.png");
    EXPECT_EQ(print.width, 200);
    EXPECT_EQ(print.height, 100);

    const std::string out = (dir / "bad" / "out.png").string();
    std::filesystem::create_directories(dir / "bad");
    expectFailure({"render", genome, "-o", out, "--repeat", "straight"}, 2, "--repeat", out);
    expectFailure(
        {"render", genome, "-o", out, "--repeat", "mirror", "--width", "40000", "--height", "40000"}, 2,
        "--repeat", out);
}

// ---- Half-drop and brick repeats: marbler paper --repeat, render --yardage ----

TEST(RenderCli, YardageOfAHalfDropOrBrickPaperRepeatsOnItsLatticeWithoutASeam) {
    const auto dir = test::outputDir("cli-yardage");
    // A 6 x 4 cm tile at 50.8 dpi is 120 x 80 pixels; 15 x 10 cm of fabric, 300 x 200.
    struct Case {
        const char* repeat;
        int ax, ay, bx, by; // the lattice's vectors in pixels
    };
    for (const Case& c : {Case{"half-drop", 120, 40, 0, 80}, Case{"brick", 120, 0, 60, 80}}) {
        SCOPED_TRACE(c.repeat);
        const std::string name = std::string("tile-") + c.repeat;
        auto r = runMarbler({"paper", "--repeat", c.repeat, "--size", "6x4cm", "--dpi", "50.8", "--seed", "5",
                             "--colors", "4", "-o", (dir / (name + ".png")).string()});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const std::string genome = (dir / (name + ".marble.json")).string();
        EXPECT_NE(test::readFile(genome).find(std::string("\"wrap\": \"") + c.repeat + "\""),
                  std::string::npos);
        r = runMarbler({"render", genome, "--size", "6x4cm", "--dpi", "50.8", "--yardage", "15x10cm", "-o",
                        (dir / (name + "-yardage.png")).string()});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const Image tile = test::readImage8(dir / (name + ".png"));
        const Image yard = test::readImage8(dir / (name + "-yardage.png"));
        ASSERT_EQ(tile.width, 120);
        ASSERT_EQ(tile.height, 80);
        ASSERT_EQ(yard.width, 300);
        ASSERT_EQ(yard.height, 200);
        // Pixels of `a` at (x, y) against `b` at (x + dx, y + dy): how many differ by more than
        // the rounding of a soft edge, of how many compared.
        auto differing = [](const Image& a, const Image& b, int dx, int dy) {
            int count = 0, compared = 0;
            for (int y = 0; y < a.height; ++y)
                for (int x = 0; x < a.width; ++x) {
                    if (x + dx < 0 || y + dy < 0 || x + dx >= b.width || y + dy >= b.height) continue;
                    ++compared;
                    const std::uint8_t* p = a.row(y) + std::size_t(x) * 3;
                    const std::uint8_t* q = b.row(y + dy) + std::size_t(x + dx) * 3;
                    for (int k = 0; k < 3; ++k)
                        if (std::abs(int(p[k]) - int(q[k])) > 2) {
                            ++count;
                            break;
                        }
                }
            return std::pair{count, compared};
        };
        // The fabric starts with the tile, and repeats by each lattice vector.
        auto [first, firstOf] = differing(tile, yard, 0, 0);
        EXPECT_LE(first, firstOf / 1000) << "the tile at the fabric's top left";
        for (auto [dx, dy] :
             {std::pair{c.ax, c.ay}, std::pair{c.bx, c.by}, std::pair{c.ax - c.bx, c.ay - c.by}}) {
            auto [moved, of] = differing(yard, yard, dx, dy);
            EXPECT_GT(of, 10000);
            EXPECT_LE(moved, of / 1000) << "moved by " << dx << ", " << dy;
        }
        // Not a straight repeat: moved by the tile's width (half-drop) or height (brick) it differs.
        auto [straight, of] = differing(yard, yard, c.ay == 0 ? 0 : 120, c.ay == 0 ? 80 : 0);
        EXPECT_GT(straight, of / 10);
    }
    // A design whose bath does not wrap has no yardage; --yardage needs the tile's print size.
    auto r = runMarbler({"render", test::examplePath("flame-comb-vortex.marble.json"), "--size", "6x4cm",
                         "--dpi", "50", "--yardage", "15x10cm", "-o", (dir / "no.png").string()});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--yardage needs a design whose bath wraps"), std::string::npos) << r.err;
    r = runMarbler({"render", (dir / "tile-brick.marble.json").string(), "--dpi", "50", "--yardage",
                    "15x10cm", "-o", (dir / "no.png").string()});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--yardage needs --size"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "no.png"));
}

// ---- end half-drop and brick repeats ----

TEST(RenderCli, HelpDescribesEveryOption) {
    auto r = runMarbler({"render", "--help"});
    EXPECT_EQ(r.exitCode, 0);
    for (const char* option :
         {"-o", "--width", "--height", "--aa", "--region", "--slice", "--dpi", "--size", "--gpu", "--mesh",
          "--view", "--supersample", "--threads", "--quiet", "rooks8", "checker4", "--repeat mirror"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

} // namespace
} // namespace marbler
