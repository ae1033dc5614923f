// `marbler render --gpu` with the GL back end: clean stderr on success, the cutting plane, and
// the one-line usage errors of the mesh-only options.

#include "GlTestUtil.h"
#include "TestUtil.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

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
