// The back-end choice (pure: no context needed), the GL probe, and the hybrid mesh render
// (GL rasterises, the CPU kernel colours) against the all-GL mesh render.

#include "GlTestUtil.h"
#include "TestUtil.h"
#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/gl/Backend.h"
#include "marbler/gl/HybridMesh.h"
#include "marbler/gl/RenderView.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>

namespace marbler {
namespace {

using gl::BackendPreference;

gl::GlProbe probeOf(const std::string& renderer) {
    gl::GlProbe probe;
    probe.available = true;
    probe.vendor = "test";
    probe.renderer = renderer;
    probe.version = "4.5 (Core Profile)";
    probe.software = gl::isSoftwareRenderer(renderer);
    return probe;
}

gl::GlProbe noGl() {
    gl::GlProbe probe;
    probe.reason = "no display: none of DISPLAY, WAYLAND_DISPLAY, QT_QPA_PLATFORM is set";
    return probe;
}

TEST(Backend, SoftwareRenderersAreRecognisedFromTheirStrings) {
    EXPECT_TRUE(gl::isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(gl::isSoftwareRenderer("softpipe"));
    EXPECT_TRUE(gl::isSoftwareRenderer("Mesa X11 Software Rasterizer"));
    EXPECT_TRUE(gl::isSoftwareRenderer("swrast"));
    EXPECT_TRUE(gl::isSoftwareRenderer("Google SwiftShader"));
    EXPECT_TRUE(gl::isSoftwareRenderer(
        "ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero)), SwiftShader driver)"));
    EXPECT_TRUE(gl::isSoftwareRenderer("Microsoft Basic Render Driver"));
    EXPECT_TRUE(gl::isSoftwareRenderer("LLVMPIPE (LLVM 17.0.6, 128 bits)"));
    EXPECT_FALSE(gl::isSoftwareRenderer("NVIDIA GeForce RTX 4090/PCIe/SSE2"));
    EXPECT_FALSE(gl::isSoftwareRenderer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
    EXPECT_FALSE(gl::isSoftwareRenderer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7, DRM 3.54)"));
    EXPECT_FALSE(gl::isSoftwareRenderer("Apple M2"));
    EXPECT_FALSE(gl::isSoftwareRenderer(""));
}

TEST(Backend, PreferencesParseAndName) {
    for (BackendPreference p : {BackendPreference::Auto, BackendPreference::Gpu, BackendPreference::Cpu})
        EXPECT_EQ(gl::parseBackendPreference(gl::backendPreferenceName(p)), p);
    EXPECT_EQ(gl::parseBackendPreference(" CPU "), BackendPreference::Cpu);
    EXPECT_EQ(gl::parseBackendPreference("Gpu"), BackendPreference::Gpu);
    EXPECT_FALSE(gl::parseBackendPreference("opengl"));
    EXPECT_FALSE(gl::parseBackendPreference(""));
}

TEST(Backend, EnvironmentOverridesOnlyWithAValidValue) {
    const char* saved = std::getenv(gl::BackendEnvironmentVariable);
    const std::string keep = saved ? saved : "";
    ::setenv(gl::BackendEnvironmentVariable, "cpu", 1);
    EXPECT_EQ(gl::environmentBackendPreference(), BackendPreference::Cpu);
    ::setenv(gl::BackendEnvironmentVariable, "vulkan", 1);
    std::string problem;
    EXPECT_FALSE(gl::environmentBackendPreference(&problem));
    EXPECT_NE(problem.find("vulkan"), std::string::npos) << problem;
    ::unsetenv(gl::BackendEnvironmentVariable);
    EXPECT_FALSE(gl::environmentBackendPreference());
    if (saved) ::setenv(gl::BackendEnvironmentVariable, keep.c_str(), 1);
}

TEST(Backend, AutomaticPicksTheGpuOnlyForHardwareGl) {
    const gl::BackendChoice software =
        gl::chooseBackend(probeOf("llvmpipe (LLVM 15.0.6, 256 bits)"), BackendPreference::Auto);
    EXPECT_FALSE(software.useGl);
    EXPECT_EQ(software.why, "OpenGL is llvmpipe, a software rasteriser: the CPU renderer is faster");

    const gl::BackendChoice hardware =
        gl::chooseBackend(probeOf("NVIDIA GeForce RTX 4090/PCIe/SSE2"), BackendPreference::Auto);
    EXPECT_TRUE(hardware.useGl);
    EXPECT_NE(hardware.why.find("NVIDIA GeForce RTX 4090"), std::string::npos) << hardware.why;

    EXPECT_TRUE(
        gl::chooseBackend(probeOf("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"), BackendPreference::Auto)
            .useGl);

    const gl::BackendChoice none = gl::chooseBackend(noGl(), BackendPreference::Auto);
    EXPECT_FALSE(none.useGl);
    EXPECT_NE(none.why.find("no OpenGL"), std::string::npos) << none.why;
    EXPECT_NE(none.why.find(noGl().reason), std::string::npos)
        << "the probe's reason is passed on: " << none.why;
}

TEST(Backend, OverridesWin) {
    const gl::GlProbe software = probeOf("llvmpipe (LLVM 15.0.6, 256 bits)");
    const gl::GlProbe hardware = probeOf("NVIDIA GeForce RTX 4090/PCIe/SSE2");
    const gl::BackendChoice gpuOnSoftware = gl::chooseBackend(software, BackendPreference::Gpu);
    EXPECT_TRUE(gpuOnSoftware.useGl);
    EXPECT_NE(gpuOnSoftware.why.find("asked for"), std::string::npos) << gpuOnSoftware.why;
    EXPECT_TRUE(gl::chooseBackend(hardware, BackendPreference::Gpu).useGl);

    const gl::BackendChoice cpuOnHardware = gl::chooseBackend(hardware, BackendPreference::Cpu);
    EXPECT_FALSE(cpuOnHardware.useGl);
    EXPECT_NE(cpuOnHardware.why.find("CPU renderer was asked for"), std::string::npos) << cpuOnHardware.why;
    EXPECT_FALSE(gl::chooseBackend(software, BackendPreference::Cpu).useGl);
    EXPECT_FALSE(gl::chooseBackend(noGl(), BackendPreference::Cpu).useGl);

    // Asked for the GPU where there is no GL: the CPU, saying so and why.
    const gl::BackendChoice gpuWithoutGl = gl::chooseBackend(noGl(), BackendPreference::Gpu);
    EXPECT_FALSE(gpuWithoutGl.useGl);
    EXPECT_NE(gpuWithoutGl.why.find("GPU renderer was asked for"), std::string::npos) << gpuWithoutGl.why;
    EXPECT_NE(gpuWithoutGl.why.find(noGl().reason), std::string::npos) << gpuWithoutGl.why;
}

TEST(Backend, ProbeReadsTheDriversStrings) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    const gl::GlProbe probe = gl::probeGl();
    ASSERT_TRUE(probe.available) << probe.reason;
    EXPECT_TRUE(probe.reason.empty()) << probe.reason;
    EXPECT_FALSE(probe.renderer.empty());
    EXPECT_FALSE(probe.vendor.empty());
    EXPECT_FALSE(probe.version.empty());
    EXPECT_EQ(probe.software, gl::isSoftwareRenderer(probe.renderer));
    EXPECT_EQ(probe.renderer, test::glRenderer()->rendererName());
}

/// Mean channel difference and the share of channels off by more than 24.
void expectClose(const Image& actual, const Image& expected, const std::string& name) {
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);
    double sum = 0.0;
    std::size_t far = 0;
    for (std::size_t k = 0; k < actual.rgb.size(); ++k) {
        const int diff = std::abs(int(actual.rgb[k]) - int(expected.rgb[k]));
        sum += diff;
        if (diff > 24) ++far;
    }
    const double mean = sum / double(actual.rgb.size());
    // The GPU evaluates the colour rule in float, the kernel in double: the two differ only
    // where a sample sits within float rounding of an ink edge.
    const bool ok = mean < 0.6 && far * 200 < actual.rgb.size();
    if (!ok) {
        const auto dir = test::outputDir("gl-hybrid");
        test::savePng(actual, dir / (name + "-hybrid.png"));
        test::savePng(expected, dir / (name + "-gl.png"));
    }
    EXPECT_TRUE(ok) << name << ": mean difference " << mean << ", " << far << " of " << actual.rgb.size()
                    << " channels off by more than 24";
}

TEST(HybridMesh, AgreesWithTheGlMeshRender) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    gl::GlRenderer& renderer = *test::glRenderer();
    const Genome genome = randomGenome(5, 3);
    struct Case {
        std::string name;
        gl::MeshSettings settings;
    };
    std::vector<Case> cases;
    gl::MeshSettings vase;
    vase.width = 160;
    vase.height = 128;
    cases.push_back({"vase", vase});
    gl::MeshSettings flat = vase;
    flat.mesh = "torus";
    flat.lighting = false;
    flat.supersample = 1;
    flat.yaw = -40.0;
    cases.push_back({"torus-unlit", flat});
    gl::MeshSettings cut = vase;
    cut.mesh = "sphere";
    cut.cut = gl::CutPlane{{0.3, 0.2, 1.0}, 520.0};
    cut.supersample = 5;
    cut.width = cut.height = 96;
    cases.push_back({"sphere-cut", cut});
    for (const Case& c : cases) {
        const Image viaGl = renderer.renderMesh(genome, c.settings);
        const Image hybrid = gl::renderMeshHybrid(renderer, genome, c.settings);
        expectClose(hybrid, viaGl, c.name);
    }
}

TEST(HybridMesh, KeepsTheChecksOfTheMeshRender) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    gl::GlRenderer& renderer = *test::glRenderer();
    gl::MeshSettings settings;
    settings.width = settings.height = 32;
    // A flat design needs the object's own texture coordinates, which this file has none of.
    const std::filesystem::path bare = test::outputDir("hybrid-mesh-checks") / "bare.obj";
    test::writeFile(bare, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    settings.mesh = bare.string();
    EXPECT_THROW(gl::renderMeshHybrid(renderer, randomGenome(1, 2), settings), InputError);
    settings.mesh = DefaultMesh;
    settings.supersample = 2;
    EXPECT_THROW(gl::renderMeshHybrid(renderer, randomGenome(1, 3), settings), InputError);
    // A cancelled render stops with Cancelled, not a partial image.
    settings.supersample = 3;
    std::atomic<bool> cancel{true};
    RenderControl control;
    control.cancel = &cancel;
    EXPECT_THROW(gl::renderMeshHybrid(renderer, randomGenome(1, 3), settings, &control), Cancelled);
}

TEST(RenderView, EachViewTakesItsBackEndsPath) {
    // One request for every view: a flat raster on the CPU needs no GL and is the CPU renderer's
    // image byte for byte, an object on the CPU without GL is the CPU's own object render; a GL
    // view without a GL renderer is refused, not quietly rendered some other way.
    const Genome flat = randomGenome(7, 2);
    gl::ViewRequest request;
    request.raster.width = 48;
    request.raster.height = 40;
    request.raster.aa = "rgss";
    const Image cpu = gl::renderView(flat, request, nullptr);
    const Image expected = CpuRenderer(flat).render(request.raster);
    EXPECT_EQ(cpu.width, 48);
    EXPECT_EQ(cpu.height, 40);
    EXPECT_EQ(cpu.rgb, expected.rgb);
    const CpuRenderer prepared(flat);
    EXPECT_EQ(gl::renderView(flat, request, nullptr, nullptr, &prepared).rgb, expected.rgb);
    request.useGl = true;
    EXPECT_THROW(gl::renderView(flat, request, nullptr), RuntimeFailure);
    gl::ViewRequest object;
    object.object = gl::MeshSettings{};
    object.object->width = 64;
    object.object->height = 48;
    const Genome solid = randomGenome(7, 3);
    EXPECT_EQ(gl::renderView(solid, object, nullptr).rgb,
              renderObjectOnCpu(solid, builtinMesh(DefaultMesh), *object.object).rgb);
    object.useGl = true;
    EXPECT_THROW(gl::renderView(solid, object, nullptr), RuntimeFailure);
    object.useGl = false;

    MARBLER_REQUIRE_GL_OR_SKIP();
    gl::GlRenderer& renderer = *test::glRenderer();
    EXPECT_EQ(gl::renderView(flat, request, &renderer).rgb, renderer.render(flat, request.raster).rgb);
    object.useGl = true;
    EXPECT_EQ(gl::renderView(solid, object, &renderer).rgb, renderer.renderMesh(solid, *object.object).rgb);
    object.useGl = false;
    EXPECT_EQ(gl::renderView(solid, object, &renderer).rgb,
              gl::renderMeshHybrid(renderer, solid, *object.object).rgb);
}

} // namespace
} // namespace marbler
