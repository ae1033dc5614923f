// `marbler doctor`: every line it promises (spec/cli.md), and that what it says follows the
// machine and the environment.

#include "TestUtil.h"
#include "marbler/CpuRenderer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace marbler {
namespace {

/// The value of the line "what: value" in doctor's output; empty when there is none.
std::string lineValue(const std::string& out, const std::string& what) {
    const std::string key = what + ": ";
    std::size_t at = out.find("\n" + key);
    if (at == std::string::npos)
        return out.rfind(key, 0) == 0 ? out.substr(key.size(), out.find('\n') - key.size()) : "";
    at += 1 + key.size();
    return out.substr(at, out.find('\n', at) - at);
}

bool glRequired() {
    const char* value = std::getenv("MARBLER_REQUIRE_GL");
    return value && std::string(value) == "1";
}

TEST(Doctor, ReportsVersionsFormatsAndTheCpuKernel) {
    test::RunResult r = test::runMarbler({"doctor"}, {{"MARBLER_KERNEL", std::nullopt}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lineValue(r.out, "marbler"), "0.1.0") << r.out;
    EXPECT_NE(lineValue(r.out, "CPU kernel").find(cpuKernel().name + " ("), std::string::npos) << r.out;
    EXPECT_NE(lineValue(r.out, "image files built in").find("PNG (libpng 1.6"), std::string::npos) << r.out;
    EXPECT_NE(lineValue(r.out, "other image formats").find("OpenImageIO 2."), std::string::npos) << r.out;
    EXPECT_NE(lineValue(r.out, "window and GL back end").find("Qt 6."), std::string::npos) << r.out;
    EXPECT_FALSE(lineValue(r.out, "OpenGL").empty()) << r.out;
    EXPECT_FALSE(lineValue(r.out, "window renders with").empty()) << r.out;
}

TEST(Doctor, FollowsMarblerKernel) {
    test::RunResult r = test::runMarbler({"doctor"}, {{"MARBLER_KERNEL", "baseline"}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lineValue(r.out, "CPU kernel").rfind("baseline (", 0), 0u) << r.out;
    EXPECT_NE(lineValue(r.out, "CPU kernel").find("MARBLER_KERNEL"), std::string::npos) << r.out;
}

TEST(Doctor, SaysWhyThereIsNoOpenGLWithoutADisplay) {
    test::RunResult r = test::runMarbler(
        {"doctor"},
        {{"DISPLAY", std::nullopt}, {"WAYLAND_DISPLAY", std::nullopt}, {"QT_QPA_PLATFORM", std::nullopt}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lineValue(r.out, "OpenGL").rfind("none: ", 0), 0u) << r.out;
    EXPECT_EQ(lineValue(r.out, "window renders with").rfind("CPU: ", 0), 0u) << r.out;
}

TEST(Doctor, NamesTheRendererAndTheWindowsChoice) {
    // A settings folder of its own, so no remembered choice of the window's interferes.
    const std::string config = test::outputDir("doctor-config").string();
    test::RunResult r =
        test::runMarbler({"doctor"}, {{"MARBLER_RENDERER", std::nullopt}, {"XDG_CONFIG_HOME", config}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string gl = lineValue(r.out, "OpenGL");
    if (gl.rfind("none: ", 0) == 0) {
        if (glRequired()) FAIL() << "MARBLER_REQUIRE_GL=1 but doctor found no OpenGL: " << gl;
        GTEST_SKIP() << "no OpenGL here: " << gl;
    }
    const bool software = gl.find("a software rasteriser") != std::string::npos;
    EXPECT_TRUE(software || gl.find(", hardware") != std::string::npos) << gl;
    // Automatic: a software rasteriser renders on the CPU, hardware on the GPU.
    EXPECT_EQ(lineValue(r.out, "window renders with").rfind(software ? "CPU: " : "GPU: ", 0), 0u) << r.out;
    // The environment's override wins either way.
    test::RunResult cpu = test::runMarbler({"doctor"}, {{"MARBLER_RENDERER", "cpu"}});
    EXPECT_EQ(lineValue(cpu.out, "window renders with").rfind("CPU: ", 0), 0u) << cpu.out;
    test::RunResult gpu = test::runMarbler({"doctor"}, {{"MARBLER_RENDERER", "gpu"}});
    EXPECT_EQ(lineValue(gpu.out, "window renders with").rfind("GPU: ", 0), 0u) << gpu.out;
    // The window's remembered setting is followed when the environment says nothing.
    test::writeFile(std::filesystem::path(config) / "Marbler" / "Marbler.conf",
                    std::string("[view]\nrenderer=") + (software ? "gpu" : "cpu") + "\n");
    test::RunResult remembered =
        test::runMarbler({"doctor"}, {{"MARBLER_RENDERER", std::nullopt}, {"XDG_CONFIG_HOME", config}});
    EXPECT_EQ(lineValue(remembered.out, "window renders with").rfind(software ? "GPU: " : "CPU: ", 0), 0u)
        << remembered.out;
}

} // namespace
} // namespace marbler
