// `marbler render --gpu` with the GL back end: clean stderr on success, the cutting plane, and
// the one-line usage errors of the mesh-only options.

#include "GlTestUtil.h"
#include "TestUtil.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/Params.h"
#include "marbler/gl/Backend.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace marbler {
namespace {

std::string solidGenome() {
    return (test::dataDir() / "examples" / "slate-block.marble.json").string();
}

TEST(GlCli, GpuRenderWritesNothingOnStderr) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    std::filesystem::path dir = test::outputDir("gl-cli-gpu");
    std::string out = (dir / "flat.png").string();
    test::RunResult run =
        test::runMarbler({"render", (test::dataDir() / "examples" / "five-stones.marble.json").string(),
                          "--gpu", "--width", "96", "-o", out});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_TRUE(std::filesystem::exists(out));
}

TEST(GlCli, GpuRendersAStylusDesignAsTheCpuDoes) {
    // The stylus once had no shader and --gpu refused it (exit 1); now the GPU draws it, and
    // the image on disk is the CPU's but for a hair's width of edges.
    MARBLER_REQUIRE_GL_OR_SKIP();
    std::filesystem::path dir = test::outputDir("gl-cli-stylus");
    const std::string design = (test::dataDir() / "examples" / "ebru-hearts.marble.json").string();
    const std::string gpu = (dir / "gpu.png").string(), cpu = (dir / "cpu.png").string();
    test::RunResult run = test::runMarbler({"render", design, "--gpu", "--width", "250", "-o", gpu});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    run = test::runMarbler({"render", design, "--width", "250", "-o", cpu});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Image a = test::loadPng(gpu), b = test::loadPng(cpu);
    ASSERT_EQ(a.width, 250);
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    std::size_t near = 0;
    for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
        int worst = 0;
        for (std::size_t c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])));
        near += worst <= 2;
    }
    EXPECT_GE(double(near), 0.995 * double(a.rgb.size() / 3)) << "of " << a.rgb.size() / 3 << " pixels";
    EXPECT_EQ(serializeGenome(loadDesign(gpu)), serializeGenome(loadGenome(design)));
}

TEST(GlCli, GpuRefusesWhatASoftwareRasteriserCannotDrawWithItsReason) {
    // A rake dragging ink along a long spiral at four samples a pixel needs more loop
    // iterations than llvmpipe runs (tools.glsl, loopsWereCut): --gpu, asked explicitly, exits 1
    // with the reason on one line and writes nothing, as for any other GL refusal.
    MARBLER_REQUIRE_GL_OR_SKIP();
    if (!gl::isSoftwareRenderer(test::glRenderer()->rendererName()))
        GTEST_SKIP() << "a hardware GPU draws it: " << test::glRenderer()->rendererName();
    std::filesystem::path dir = test::outputDir("gl-cli-stylus-limit");
    Genome genome = loadGenome(test::dataDir() / "examples" / "ebru-hearts.marble.json");
    Operation& rake = genome.operations.back();
    rake.path.clear();
    for (int k = 0; k < 240; ++k)
        rake.path.push_back(
            {500 + (30 + 1.1 * k) * std::cos(0.045 * k), 300 + (30 + 1.1 * k) * std::sin(0.045 * k)});
    rake.alpha = 45;
    rake.lambda = 9;
    rake.reach = 40;
    rake.tines = 4;
    rake.spacing = 25;
    rake.steps = minimumStylusSteps(rake);
    const std::filesystem::path design = dir / "long-rake.marble.json";
    std::ofstream(design) << serializeGenome(genome);
    const std::string out = (dir / "rake.png").string();
    test::RunResult run =
        test::runMarbler({"render", design.string(), "--gpu", "--aa", "rgss", "--width", "250", "-o", out});
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_NE(run.err.find("loop iterations"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    // Without --gpu the CPU renderer draws it.
    run = test::runMarbler({"render", design.string(), "--aa", "none", "--width", "100", "-o", out});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(std::filesystem::exists(out));
}

TEST(GlCli, GpuAndMeshImagesCarryTheirGenome) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    std::filesystem::path dir = test::outputDir("gl-cli-genome");
    const std::string flat = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    test::RunResult run =
        test::runMarbler({"render", flat, "--gpu", "--width", "48", "-o", (dir / "flat.png").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(serializeGenome(loadDesign(dir / "flat.png")), serializeGenome(loadGenome(flat)));
    run = test::runMarbler({"render", solidGenome(), "--gpu", "--mesh", "sphere", "--view", "30,20",
                            "--width", "48", "--supersample", "1", "-o", (dir / "solid.tif").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(serializeGenome(loadDesign(dir / "solid.tif")), serializeGenome(loadGenome(solidGenome())));
    // And the image renders again as its genome does.
    run = test::runMarbler({"render", (dir / "solid.tif").string(), "--mesh", "sphere", "--view", "30,20",
                            "--width", "48", "--supersample", "1", "-o", (dir / "again.png").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
}

TEST(GlCli, CutRenderDiffersFromTheWholeObject) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    std::filesystem::path dir = test::outputDir("gl-cli-cut");
    std::string whole = (dir / "whole.png").string(), cut = (dir / "cut.png").string();
    const std::vector<std::string> common = {"render", solidGenome(),   "--gpu", "--mesh",
                                             "sphere", "--view",        "30,20", "--width",
                                             "96",     "--supersample", "1"};
    std::vector<std::string> args = common;
    args.insert(args.end(), {"-o", whole});
    test::RunResult run = test::runMarbler(args);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    args = common;
    args.insert(args.end(), {"--cut", "1,0,1,1000", "-o", cut});
    run = test::runMarbler(args);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    Image a = test::loadPng(whole), b = test::loadPng(cut);
    ASSERT_EQ(a.width, 96);
    ASSERT_EQ(b.width, 96);
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.rgb.size(); i += 3)
        if (!std::equal(a.rgb.begin() + long(i), a.rgb.begin() + long(i + 3), b.rgb.begin() + long(i)))
            ++differing;
    EXPECT_GT(differing, a.rgb.size() / 3 / 20) << "the cut should change a good part of the picture";
}

TEST(GlCli, CutNeedsMeshAndAPlane) {
    // Usage errors, checked before any GL context is made: no display needed.
    std::filesystem::path dir = test::outputDir("gl-cli-cut-usage");
    std::string out = (dir / "x.png").string();
    auto expectUsage = [&](const std::vector<std::string>& args) {
        test::RunResult run = test::runMarbler(args);
        EXPECT_EQ(run.exitCode, 2);
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_NE(run.err.find("--cut"), std::string::npos) << run.err;
        EXPECT_FALSE(std::filesystem::exists(out));
    };
    expectUsage({"render", solidGenome(), "--slice", "z=500", "--cut", "0,0,1,500", "-o", out});
    expectUsage({"render", solidGenome(), "--mesh", "sphere", "--view", "0,0", "--cut", "0,0,1", "-o", out});
    expectUsage(
        {"render", solidGenome(), "--mesh", "sphere", "--view", "0,0", "--cut", "0,0,0,5", "-o", out});
}

} // namespace
} // namespace marbler
