// The CPU's object path against the GL one: the CPU's rasterised G-buffer covers the samples
// GL covers with the same design points, and the CPU render of an object equals the hybrid
// render (GL G-buffer, CPU colouring) but for a few edge samples.

#include "GlTestUtil.h"
#include "TestUtil.h"
#include "marbler/GenomeIO.h"
#include "marbler/ObjectView.h"
#include "marbler/gl/HybridMesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace marbler {
namespace {

Genome slateBlock() {
    return loadGenome(test::dataDir() / "examples" / "slate-block.marble.json");
}

struct Case {
    const char* mesh;
    double yaw, pitch;
    bool cut;
};

const Case Cases[] = {
    {"vase", 30, 20, false}, {"teapot", 60, 30, true}, {"torus", -20, 50, false}, {"cube", 45, 35, true}};

MeshSettings settingsOf(const Case& c, const Genome& genome) {
    MeshSettings settings;
    settings.width = 120;
    settings.height = 90;
    settings.supersample = 3;
    settings.mesh = c.mesh;
    settings.yaw = c.yaw;
    settings.pitch = c.pitch;
    if (c.cut) settings.cut = CutPlane{{0.3, 0.2, 1.0}, 0.55 * genome.size.z};
    return settings;
}

TEST(ObjectRaster, TheCpuGBufferIsTheGlOne) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    const Genome genome = slateBlock();
    for (const Case& c : Cases) {
        SCOPED_TRACE(c.mesh);
        const MeshSettings settings = settingsOf(c, genome);
        const MeshGBuffer gl = test::glRenderer()->renderMeshGBuffer(genome, settings);
        const MeshGBuffer cpu = rasterizeObject(genome, builtinMesh(c.mesh), settings);
        ASSERT_EQ(gl.positions.size(), cpu.positions.size());
        EXPECT_LT(glm::length(gl.eye - cpu.eye), 1e-9 * glm::length(gl.eye));
        EXPECT_LT(glm::length(gl.light - cpu.light), 1e-12);
        std::size_t samples = gl.positions.size() / 4, disagree = 0, far = 0, covered = 0;
        for (std::size_t s = 0; s < samples; ++s) {
            const bool a = gl.positions[s * 4 + 3] > 0.0f, b = cpu.positions[s * 4 + 3] > 0.0f;
            covered += a;
            if (a != b) {
                ++disagree;
                continue;
            }
            if (!a) continue;
            // The same point of the surface: GL interpolates in float, the CPU in double.
            double d = 0.0;
            for (int k = 0; k < 3; ++k)
                d = std::max(d, double(std::abs(gl.positions[s * 4 + k] - cpu.positions[s * 4 + k])));
            far += d > 1e-3 * genome.size.x;
        }
        ASSERT_GT(covered, samples / 10);
        // Samples right on a triangle's edge may fall either way.
        EXPECT_LT(double(disagree) / double(covered), 0.002);
        EXPECT_LT(double(far) / double(covered), 0.002);
    }
}

TEST(ObjectRaster, TheCpuRenderIsTheHybridOne) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    const Genome genome = slateBlock();
    for (const Case& c : Cases) {
        SCOPED_TRACE(c.mesh);
        const MeshSettings settings = settingsOf(c, genome);
        const Image hybrid = gl::renderMeshHybrid(*test::glRenderer(), genome, settings);
        const Image cpu = renderObjectOnCpu(genome, builtinMesh(c.mesh), settings);
        ASSERT_EQ(hybrid.rgb.size(), cpu.rgb.size());
        std::size_t off = 0, pixels = hybrid.rgb.size() / 3;
        for (std::size_t p = 0; p < pixels; ++p) {
            int worst = 0;
            for (int k = 0; k < 3; ++k)
                worst = std::max(worst, std::abs(int(hybrid.rgb[p * 3 + k]) - int(cpu.rgb[p * 3 + k])));
            off += worst > 8;
        }
        EXPECT_LT(double(off) / double(pixels), 0.005);
    }
}

} // namespace
} // namespace marbler
