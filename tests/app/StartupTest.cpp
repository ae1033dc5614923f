// What the marbler executable loads: the headless verbs start without OpenImageIO, Qt or
// assimp (their libraries take longer to load than a small render takes to run), and load the
// module that holds them only for the work that needs it.

#include "TestUtil.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace marbler {
namespace {

const std::string Example = (test::dataDir() / "examples" / "flame-comb-vortex.marble.json").string();

/// The shared libraries the executable names (readelf's NEEDED entries).
std::string neededLibraries() {
    std::string command = std::string("readelf -d '") + MARBLER_EXECUTABLE + "' 2>&1";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), ::pclose);
    if (!pipe) return {};
    std::string out;
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe.get()))
        out.append(buffer, n);
    return out;
}

/// Runs marbler with the dynamic loader reporting every library it loads (on stderr).
test::RunResult runTracingLoads(const std::vector<std::string>& args) {
    return test::runMarbler(args, {{"LD_DEBUG", "files"}});
}

TEST(Startup, ExecutableLinksNeitherOpenImageIONorQtNorAssimpNorFFmpeg) {
    const std::string needed = neededLibraries();
    ASSERT_NE(needed.find("(NEEDED)"), std::string::npos) << needed;
    EXPECT_NE(needed.find("libpng16"), std::string::npos) << needed;
    for (const char* heavy :
         {"OpenImageIO", "Qt6", "assimp", "libGL", "libavcodec", "libavformat", "libswscale"})
        EXPECT_EQ(needed.find(heavy), std::string::npos) << heavy << " is linked into marbler:\n" << needed;
}

TEST(Startup, PngAndTiffRendersLoadNoModule) {
    const auto dir = test::outputDir("startup-builtin");
    for (const char* name : {"a.png", "a.tif", "a.ppm"}) {
        test::RunResult r =
            runTracingLoads({"render", Example, "-o", (dir / name).string(), "--width", "32"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("marbler-imageio.so"), std::string::npos) << name;
        EXPECT_EQ(r.err.find("libOpenImageIO"), std::string::npos) << name;
        EXPECT_EQ(r.err.find("marbler-window.so"), std::string::npos) << name;
        EXPECT_EQ(r.err.find("marbler-video.so"), std::string::npos) << name;
        EXPECT_TRUE(std::filesystem::exists(dir / name));
    }
    test::RunResult info = runTracingLoads({"info", Example});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_EQ(info.err.find("marbler-imageio.so"), std::string::npos);
    EXPECT_EQ(info.err.find("marbler-window.so"), std::string::npos);
}

TEST(Startup, GenomesInsideImagesAreReadWithoutAModule) {
    const auto dir = test::outputDir("startup-genome-image");
    for (const char* name : {"a.png", "a.tif"}) {
        ASSERT_EQ(
            test::runMarbler({"render", Example, "-o", (dir / name).string(), "--width", "32"}).exitCode, 0);
        // libpng and libtiff alone read the genome back: no OpenImageIO, no Qt.
        for (const std::vector<std::string>& args :
             {std::vector<std::string>{"info", (dir / name).string()},
              std::vector<std::string>{"render", (dir / name).string(), "-o", (dir / "again.png").string(),
                                       "--width", "16"}}) {
            test::RunResult r = runTracingLoads(args);
            ASSERT_EQ(r.exitCode, 0) << r.err;
            EXPECT_EQ(r.err.find("marbler-imageio.so"), std::string::npos) << args[0] << " " << name;
            EXPECT_EQ(r.err.find("libOpenImageIO"), std::string::npos) << args[0] << " " << name;
            EXPECT_EQ(r.err.find("marbler-window.so"), std::string::npos) << args[0] << " " << name;
        }
    }
}

TEST(Startup, OtherFormatsLoadTheImageModule) {
    const auto dir = test::outputDir("startup-module");
    test::RunResult r = runTracingLoads({"render", Example, "-o", (dir / "a.exr").string(), "--width", "32"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("marbler-imageio.so"), std::string::npos);
    EXPECT_NE(r.err.find("libOpenImageIO"), std::string::npos);
    EXPECT_EQ(r.err.find("marbler-window.so"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(dir / "a.exr"));
}

TEST(Startup, ABrokenModuleIsAClearFailureThatWritesNothing) {
    // MARBLER_MODULE_DIR is searched first: a file there that is not a shared object must be
    // reported by name, with exit status 1, and leave no output behind.
    const auto dir = test::outputDir("startup-broken-module");
    test::writeFile(dir / "marbler-imageio.so", "not a shared object");
    test::RunResult r = test::runMarbler({"render", Example, "-o", (dir / "a.exr").string(), "--width", "16"},
                                         {{"MARBLER_MODULE_DIR", dir.string()}});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("cannot load " + (dir / "marbler-imageio.so").string()), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "a.exr"));
    // The built-in formats do not need it.
    test::RunResult png =
        test::runMarbler({"render", Example, "-o", (dir / "a.png").string(), "--width", "16"},
                         {{"MARBLER_MODULE_DIR", dir.string()}});
    EXPECT_EQ(png.exitCode, 0) << png.err;
}

} // namespace
} // namespace marbler
