// A bath that wraps (docs/genome-format.md, "Wrapping bath"): the design is a straight-repeat
// tile, exactly, on the CPU renderer in every kernel variant as in the scalar reference.

#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/Image.h"
#include "marbler/Paper.h"
#include "marbler/Tools.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <utility>

namespace marbler {
namespace {

/// Sprays across every edge and corner and three stretches along both axes (one with its
/// teeth measured from the far edge), soft-edged or not.
Genome wrappedDesign(double bleed, bool wrap = true) {
    Genome g = parseGenome(R"({
      "format": "marbler-genome", "version": 3, "dimension": 2, "size": [120, 90],
      "background": "#203040", "palette": ["#203040", "#e0b040", "#b03020", "#f0f0e0"],
      "wrap": true,
      "initial": [
        {"tool": "spray", "center": [5, 5], "radius": 20, "color": 1},
        {"tool": "spray", "center": [118, 45], "radius": 15, "color": 2},
        {"tool": "spray", "center": [60, 88], "radius": 18, "color": 3},
        {"tool": "spray", "center": [60, 45], "radius": 12, "color": 1},
        {"tool": "spray", "center": [-3, 70], "radius": 9, "color": 3},
        {"tool": "spray", "center": [100, 10], "radius": 7, "color": 2}
      ],
      "operations": [
        {"tool": "stretch", "origin": [0, 0], "angle": 0, "teeth": [0, 20, 45, 70, 90], "shift": 35, "power": 1},
        {"tool": "stretch", "origin": [120, 0], "angle": 90, "teeth": [0, 30, 55, 90, 120], "shift": -25, "power": 2},
        {"tool": "stretch", "origin": [0, 0], "angle": 180, "teeth": [-90, -50, 0], "shift": 10, "power": 0.5}
      ]
    })",
                           "wrapped");
    g.bleed = bleed;
    g.wrap = wrap;
    return g;
}

RenderSettings over(double x0, double y0, int width, int height) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.region = Region{x0, y0, x0 + width, y0 + height};
    return settings;
}

/// The largest channel difference between `shifted`, a render of the design moved by (dx, dy)
/// pixels, and `tile` rolled by as much.
int rolledDifference(const Image& tile, const Image& shifted, int dx, int dy) {
    int worst = 0;
    for (int j = 0; j < shifted.height; ++j)
        for (int i = 0; i < shifted.width; ++i)
            for (int c = 0; c < 3; ++c) {
                int a = shifted.row(j)[i * 3 + c];
                int b = tile.row((j + dy) % tile.height)[((i + dx) % tile.width) * 3 + c];
                worst = std::max(worst, std::abs(a - b));
            }
    return worst;
}

TEST(WrappingBath, ATileAndItsShiftedCopyMeetWithoutASeam) {
    for (double bleed : {0.0, 1.5}) {
        SCOPED_TRACE("bleed " + std::to_string(bleed));
        const Genome g = wrappedDesign(bleed);
        // One design unit a pixel: the shifted copy's pixel (i, j) samples the point of the
        // tile's pixel (i + 60, j + 45), one period further where that leaves the tile. Its
        // middle column and row hold the tile's edges, side by side.
        const Image tile = CpuRenderer(g).render(over(0, 0, 120, 90));
        const Image shifted = CpuRenderer(g).render(over(60, 45, 120, 90));
        EXPECT_LE(rolledDifference(tile, shifted, 60, 45), 1);
        // Two periods away, and before the design's origin, the same.
        EXPECT_LE(rolledDifference(tile, CpuRenderer(g).render(over(-240, 180, 120, 90)), 0, 0), 1);
        // The same design without the wrap has seams: its discs stop at the edges.
        const Genome flat = wrappedDesign(bleed, false);
        EXPECT_GT(rolledDifference(CpuRenderer(flat).render(over(0, 0, 120, 90)),
                                   CpuRenderer(flat).render(over(60, 45, 120, 90)), 60, 45),
                  50);
    }
}

TEST(WrappingBath, TheDefaultPaperIsAStraightRepeatTile) {
    // `marbler paper`'s default recipe at a millimetre a pixel: its shifted copy is the tile
    // rolled, so the sheet repeats without a seam.
    for (std::uint64_t seed : {1, 2}) {
        PaperOptions options;
        options.width = 80.0;
        options.height = 60.0;
        const Genome g = paperGenome(seed, options);
        ASSERT_TRUE(g.wrap);
        const Image tile = CpuRenderer(g).render(over(0, 0, 80, 60));
        EXPECT_LE(rolledDifference(tile, CpuRenderer(g).render(over(40, 30, 80, 60)), 40, 30), 1) << seed;
    }
}

/// The reference's render: traceCovers per pixel centre, composited newest ink first.
Image referenceRender(const Genome& genome, const RenderSettings& settings) {
    const std::vector<PreparedOp> ops = prepare(genome);
    const SampleFrame frame = sampleFrame(genome, settings);
    Image image;
    image.width = settings.width;
    image.height = settings.height;
    image.rgb.resize(std::size_t(image.width) * image.height * 3);
    std::vector<InkCover> covers;
    for (int j = 0; j < settings.height; ++j)
        for (int i = 0; i < settings.width; ++i) {
            const bool stopped = traceCovers(ops, genome.bleed, frame.at(i, j, 0.0, 0.0), covers);
            glm::dvec3 colour = stopped ? glm::dvec3(0.0) : linearOf(genome.background);
            for (auto it = covers.rbegin(); it != covers.rend(); ++it)
                colour = it->coverage * linearOf(genome.palette[std::size_t(it->color)]) +
                         (1.0 - it->coverage) * colour;
            std::uint8_t* out = image.row(j) + i * 3;
            for (int c = 0; c < 3; ++c)
                out[c] = encodeSrgb8(colour[c]);
        }
    return image;
}

TEST(WrappingBath, ManySpraysRenderAsTheReferenceInEveryVariant) {
    // A paper's hundreds of circles go through the renderer's spray grid (SprayGrid.h): the
    // same pixels as the reference, hard and soft, over the tile and beyond it.
    PaperOptions options;
    options.width = 90.0;
    options.height = 70.0;
    options.colors = 6;
    for (double bleed : {0.0, 0.8}) {
        Genome g = paperGenome(6, options);
        ASSERT_GT(g.initial.size(), 40u);
        g.bleed = bleed;
        const RenderSettings settings = over(-30, -20, 150, 110);
        const Image want = referenceRender(g, settings);
        for (const std::string& variant : cpuKernelsSupported()) {
            setCpuKernelForTesting(variant);
            const Image got = CpuRenderer(g).render(settings);
            int worst = 0;
            for (std::size_t k = 0; k < got.rgb.size(); ++k)
                worst = std::max(worst, std::abs(int(got.rgb[k]) - int(want.rgb[k])));
            EXPECT_LE(worst, 1) << variant << ", bleed " << bleed;
        }
        setCpuKernelForTesting("");
    }
}

TEST(WrappingBath, TheKernelMatchesTheReferenceInEveryVariant) {
    for (double bleed : {0.0, 1.5}) {
        const Genome g = wrappedDesign(bleed);
        const std::vector<PreparedOp> ops = prepare(g);
        const RenderSettings settings = over(-130, -95, 380, 280); // the tile and its neighbours
        const SampleFrame frame = sampleFrame(g, settings);
        for (const std::string& variant : cpuKernelsSupported()) {
            setCpuKernelForTesting(variant);
            CpuRenderer renderer(g);
            std::vector<double> x, y, z;
            for (int j = 0; j < settings.height; j += 2)
                for (int i = 0; i < settings.width; i += 2) {
                    glm::dvec3 p = frame.at(i, j, 0.25, -0.25);
                    x.push_back(p.x);
                    y.push_back(p.y);
                    z.push_back(0.0);
                }
            std::vector<int> colors(x.size());
            renderer.colorIndicesAt(x.data(), y.data(), z.data(), x.size(), colors.data());
            std::vector<double> rgb(3 * x.size());
            renderer.linearColorsAt(x.data(), y.data(), z.data(), x.size(), rgb.data());
            int differ = 0;
            std::vector<InkCover> covers;
            for (std::size_t k = 0; k < x.size(); ++k) {
                glm::dvec3 p(x[k], y[k], 0.0);
                differ += colors[k] != traceColor(ops, p);
                bool stopped = traceCovers(ops, g.bleed, p, covers);
                glm::dvec3 colour = stopped ? glm::dvec3(0.0) : linearOf(g.background);
                for (auto it = covers.rbegin(); it != covers.rend(); ++it)
                    colour = it->coverage * linearOf(g.palette[std::size_t(it->color)]) +
                             (1.0 - it->coverage) * colour;
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(rgb[3 * k + c], colour[c], 1e-9) << variant << " at " << x[k] << ", " << y[k];
            }
            EXPECT_EQ(differ, 0) << variant;
        }
        setCpuKernelForTesting("");
    }
}

// ---- Half-drop and brick repeats (docs/genome-format.md, "Wrapping bath", lattices) ----

/// wrappedDesign on a lattice: its stretches' teeth span the period the lattice gives across
/// each pass (half the height for an x-shift in half-drop, half the width for a y-shift in brick).
Genome latticeDesign(Lattice lattice, double bleed) {
    const bool halfDrop = lattice == Lattice::HalfDrop, brick = lattice == Lattice::Brick;
    const std::string x = halfDrop ? "[0, 10, 25, 45]" : "[0, 20, 45, 70, 90]"; // across an x-shift
    const std::string y = brick ? "[0, 30, 45, 60]" : "[0, 30, 55, 90, 120]";   // across a y-shift
    const std::string x2 = halfDrop ? "[-45, -20, 0]" : "[-90, -50, 0]";
    Genome g = parseGenome(R"({
      "format": "marbler-genome", "version": 3, "dimension": 2, "size": [120, 90],
      "background": "#203040", "palette": ["#203040", "#e0b040", "#b03020", "#f0f0e0"],
      "wrap": ")" + std::string(latticeName(lattice)) +
                               R"(",
      "initial": [
        {"tool": "spray", "center": [5, 5], "radius": 20, "color": 1},
        {"tool": "spray", "center": [118, 45], "radius": 15, "color": 2},
        {"tool": "spray", "center": [60, 88], "radius": 18, "color": 3},
        {"tool": "spray", "center": [60, 45], "radius": 12, "color": 1},
        {"tool": "spray", "center": [-3, 70], "radius": 9, "color": 3},
        {"tool": "spray", "center": [100, 10], "radius": 7, "color": 2}
      ],
      "operations": [
        {"tool": "stretch", "origin": [0, 0], "angle": 0, "teeth": )" +
                               x + R"(, "shift": 35, "power": 1},
        {"tool": "stretch", "origin": [120, 0], "angle": 90, "teeth": )" +
                               y + R"(, "shift": -25, "power": 2},
        {"tool": "stretch", "origin": [0, 0], "angle": 180, "teeth": )" +
                               x2 + R"(, "shift": 10, "power": 0.5}
      ]
    })",
                           "lattice");
    g.bleed = bleed;
    return g;
}

/// The largest channel difference between two renders of one size.
int largestDifference(const Image& a, const Image& b) {
    int worst = 0;
    for (std::size_t k = 0; k < a.rgb.size() && k < b.rgb.size(); ++k)
        worst = std::max(worst, std::abs(int(a.rgb[k]) - int(b.rgb[k])));
    return worst;
}

struct LatticeCase {
    Lattice lattice;
    int ax, ay, bx, by; ///< its vectors, in pixels (a design unit a pixel)
};

const LatticeCase Lattices[] = {{Lattice::Straight, 120, 0, 0, 90},
                                {Lattice::HalfDrop, 120, 45, 0, 90},
                                {Lattice::Brick, 120, 0, 60, 90}};

TEST(WrapLattice, ARegionLargerThanATileEqualsItselfShiftedByEachLatticeVector) {
    for (const LatticeCase& lc : Lattices)
        for (double bleed : {0.0, 1.5}) {
            SCOPED_TRACE(std::string(latticeName(lc.lattice)) + ", bleed " + std::to_string(bleed));
            const Genome g = latticeDesign(lc.lattice, bleed);
            // A region of about 2.5 x 2.8 tiles, off the design's origin: every seam of the
            // tile lies inside it, and the same region moved by a lattice vector is the same.
            const Image region = CpuRenderer(g).render(over(-50, -40, 300, 250));
            for (auto [dx, dy] : {std::pair{lc.ax, lc.ay}, std::pair{lc.bx, lc.by}, std::pair{-lc.ax, -lc.ay},
                                  std::pair{lc.ax + lc.bx, lc.ay + lc.by}}) {
                const Image moved = CpuRenderer(g).render(over(-50 + dx, -40 + dy, 300, 250));
                EXPECT_LE(largestDifference(region, moved), 1) << "moved by " << dx << ", " << dy;
            }
            // Not a straight repeat where the lattice is another: moved by (w, 0) or (0, h) the
            // region differs.
            if (lc.lattice != Lattice::Straight) {
                const int dx = lc.lattice == Lattice::HalfDrop ? 120 : 0;
                const int dy = lc.lattice == Lattice::HalfDrop ? 0 : 90;
                EXPECT_GT(
                    largestDifference(region, CpuRenderer(g).render(over(-50 + dx, -40 + dy, 300, 250))), 50);
            }
            // The renderer and the scalar reference agree everywhere in the region.
            EXPECT_LE(largestDifference(region, referenceRender(g, over(-50, -40, 300, 250))), 1);
        }
}

TEST(WrapLattice, TheTileIsTheSameWhereverTheWrapChoosesTheStraightLattice) {
    // "wrap": "straight" is "wrap": true, and a straight design renders as before (the same
    // bytes as its wrap: true twin; the file says true).
    Genome g = latticeDesign(Lattice::Straight, 0.0);
    EXPECT_TRUE(g.wrap);
    EXPECT_EQ(g.lattice, Lattice::Straight);
    EXPECT_EQ(toJson(g)["wrap"], true);
    const Image a = CpuRenderer(g).render(over(-20, -10, 160, 120));
    const Image b = CpuRenderer(wrappedDesign(0.0)).render(over(-20, -10, 160, 120));
    EXPECT_EQ(a.rgb, b.rgb);
}

TEST(WrapLattice, ManySpraysOnEachLatticeRenderAsTheReferenceInEveryVariant) {
    // A half-drop or brick paper's hundreds of circles go through the spray grid: the same
    // pixels as the reference, hard and soft, over the tile and beyond it.
    for (Lattice lattice : {Lattice::HalfDrop, Lattice::Brick}) {
        PaperOptions options;
        options.width = 90.0;
        options.height = 70.0;
        options.colors = 6;
        options.lattice = lattice;
        for (double bleed : {0.0, 0.8}) {
            Genome g = paperGenome(6, options);
            ASSERT_GT(g.initial.size(), 40u);
            ASSERT_EQ(g.lattice, lattice);
            g.bleed = bleed;
            const RenderSettings settings = over(-30, -20, 150, 110);
            const Image want = referenceRender(g, settings);
            for (const std::string& variant : cpuKernelsSupported()) {
                setCpuKernelForTesting(variant);
                EXPECT_LE(largestDifference(CpuRenderer(g).render(settings), want), 1)
                    << latticeName(lattice) << ", " << variant << ", bleed " << bleed;
            }
            setCpuKernelForTesting("");
        }
    }
}

// ---- end half-drop and brick repeats ----

} // namespace
} // namespace marbler
