// A solid's tools drawn on a cross-section (issue 27, item 7): every 3D tool the editor offers,
// drawn on a section across each axis, changes that section visibly, and not by sliding it
// rigidly (a line or comb whose normal was the section's axis only moved the section).

#include "editor/Gestures.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Params.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <limits>

using namespace marbler;
using namespace marbler::ui;

namespace section_tools_test {

constexpr EditorTool SectionTools[] = {Tool::Drop,
                                       Tool::Spray,
                                       EditorTool::DropLine,
                                       EditorTool::DropRings,
                                       EditorTool::DropScatter,
                                       Tool::Line,
                                       Tool::Comb,
                                       Tool::Wave,
                                       Tool::Circle,
                                       Tool::Sphere,
                                       Tool::Vortex,
                                       Tool::Stretch,
                                       Tool::Flow};

/// A solid of concentric shells in two inks about its centre: any section through the middle
/// shows rings, which any real deformation bends and a translation only moves.
Genome shells() {
    Genome g;
    g.dimension = 3;
    g.size = {600, 600, 600};
    g.palette = {{200, 30, 30}, {30, 30, 200}, {240, 200, 40}};
    for (int i = 0; i < 10; ++i) {
        Operation drop = defaultOperation(Tool::Drop, 3, {300, 300, 300});
        drop.radius = 120;
        drop.color = i % 2;
        g.initial.push_back(drop);
    }
    return g;
}

/// 96 px over 600 units: 6.25 units a pixel, so a 200-unit slide is exactly 32 pixels.
constexpr int Side = 96;

Image section(const Genome& g, int axis) {
    RenderSettings settings;
    settings.width = settings.height = Side;
    settings.slice = Slice{axis, 300.0};
    return CpuRenderer(g).render(settings);
}

bool differs(const Image& a, int ax, int ay, const Image& b, int bx, int by) {
    const std::uint8_t* p = a.row(ay) + 3 * ax;
    const std::uint8_t* q = b.row(by) + 3 * bx;
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(p[c]) - int(q[c])) > 8) return true;
    return false;
}

/// The fraction of pixels that differ between `a` and `b` shifted by (dx, dy), over the pixels
/// both cover (none when they overlap in less than a quarter of the image).
double mismatch(const Image& a, const Image& b, int dx, int dy) {
    int count = 0, diff = 0;
    for (int y = std::max(0, dy); y < std::min(Side, Side + dy); ++y)
        for (int x = std::max(0, dx); x < std::min(Side, Side + dx); ++x) {
            ++count;
            diff += differs(b, x, y, a, x - dx, y - dy);
        }
    return count * 4 < Side * Side ? 1.0 : double(diff) / count;
}

/// The press and release of a drag on the section across `axis` at 300: 200 units along the
/// plane's first axis, off the shells' centre.
void drag(int axis, glm::dvec3& press, glm::dvec3& release) {
    press = release = glm::dvec3(300.0);
    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    press[u] = 175;
    press[v] = 250;
    release = press;
    release[u] += 200;
}

TEST(SectionToolsTest, EveryToolChangesTheSectionItIsDrawnOn) {
    const Genome g = shells();
    ToolSettings settings;
    settings.color = 2;
    // Droplets wide enough to cover whole pixels of this small render (4 units is under one).
    settings.sprayRadius = 12;
    for (int axis = 0; axis < 3; ++axis) {
        const Image before = section(g, axis);
        glm::dvec3 press, release;
        drag(axis, press, release);
        for (EditorTool tool : SectionTools) {
            const std::vector<Operation> ops = gestureSteps(tool, settings, press, release, g, axis);
            if (!toolAvailable(tool, 3)) {
                EXPECT_TRUE(ops.empty()) << toolId(tool);
                continue;
            }
            ASSERT_FALSE(ops.empty()) << toolId(tool) << " on axis " << axis;
            const Image after = section(withSteps(g, ops), axis);
            const double changed = mismatch(before, after, 0, 0);
            EXPECT_GE(changed, 0.01) << toolId(tool) << " on the section across axis " << axis
                                     << " changed too little of it";
            double rigid = std::numeric_limits<double>::infinity();
            // Slides along the drag (the raster's rows run along it), and a little across.
            for (int dy = -4; dy <= 4; ++dy)
                for (int dx = -Side + 1; dx < Side; ++dx)
                    rigid = std::min(rigid, mismatch(before, after, dx, dy));
            EXPECT_GE(rigid, 0.005) << toolId(tool) << " on the section across axis " << axis
                                    << " only slid the section";
        }
    }
}

/// The stroke tools act in the section plane: their shift lies in it, and the line's and comb's
/// distance to the tine is measured across the drag in that plane; the wave is the flat wave,
/// its second (egg-crate) term off.
TEST(SectionToolsTest, StrokesLieInTheSectionPlaneAcrossTheDrag) {
    const Genome g = shells();
    ToolSettings settings;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 press, release;
        drag(axis, press, release);
        const glm::dvec3 along = glm::normalize(release - press);
        glm::dvec3 n(0.0);
        n[axis] = 1.0;
        for (EditorTool tool : {Tool::Line, Tool::Comb}) {
            const auto ops = gestureSteps(tool, settings, press, release, g, axis);
            ASSERT_EQ(ops.size(), 1u);
            EXPECT_NEAR(glm::length(ops[0].direction - along), 0.0, 1e-12) << toolId(tool);
            EXPECT_NEAR(glm::dot(ops[0].normal, n), 0.0, 1e-12) << toolId(tool) << ": normal in the plane";
            EXPECT_NEAR(glm::dot(ops[0].normal, along), 0.0, 1e-12) << toolId(tool) << ": across the drag";
        }
        const auto wave = gestureSteps(Tool::Wave, settings, press, release, g, axis);
        ASSERT_EQ(wave.size(), 1u);
        EXPECT_NEAR(glm::length(wave[0].normal - along), 0.0, 1e-12) << "the wave shifts along the drag";
        EXPECT_NEAR(glm::dot(wave[0].direction, n), 0.0, 1e-12) << "and varies across it, in the plane";
        EXPECT_EQ(wave[0].shape, WaveShape::Eggcrate);
        EXPECT_DOUBLE_EQ(wave[0].amplitude[0], 200.0);
        EXPECT_DOUBLE_EQ(wave[0].amplitude[1], 0.0) << "no egg-crate";
    }
}

} // namespace section_tools_test
