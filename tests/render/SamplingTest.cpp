// What a render samples: patterns, the pixel-to-point formula, slices, settings checks, sRGB;
// and the renderer's geometry, source images, threads, progress and cancel.

#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <set>

namespace marbler {
namespace {

TEST(AaPattern, EveryPatternOfTheSpec) {
    for (const std::string& name : aaPatternNames()) {
        AaPattern p = aaPattern(name);
        ASSERT_EQ(p.offsets.size(), p.weights.size()) << name;
        double sum = 0;
        for (double w : p.weights)
            sum += w;
        EXPECT_NEAR(sum, 1.0, 1e-15) << name;
        for (const glm::dvec2& o : p.offsets) {
            EXPECT_LE(std::abs(o.x), 0.5) << name;
            EXPECT_LE(std::abs(o.y), 0.5) << name;
        }
    }
    EXPECT_EQ(aaPattern("none").offsets, std::vector<glm::dvec2>{glm::dvec2(0.0)});
    EXPECT_EQ(aaPattern("rgss").offsets[1], glm::dvec2(0.375, -0.125));
    AaPattern q = aaPattern("quincunx");
    ASSERT_EQ(q.offsets.size(), 5u);
    EXPECT_EQ(q.offsets[0], glm::dvec2(0.0));
    EXPECT_EQ(q.weights[0], 0.5);
    for (int k = 1; k < 5; ++k) {
        EXPECT_EQ(std::abs(q.offsets[k].x), 0.5);
        EXPECT_EQ(q.weights[k], 0.125);
    }
    for (int n = 2; n <= 8; ++n) {
        AaPattern g = aaPattern("grid" + std::to_string(n));
        ASSERT_EQ(g.offsets.size(), std::size_t(n * n));
        EXPECT_DOUBLE_EQ(g.offsets[0].x, 0.5 / n - 0.5);
    }
    AaPattern c = aaPattern("checker4");
    ASSERT_EQ(c.offsets.size(), 8u);
    for (const glm::dvec2& o : c.offsets) {
        int i = static_cast<int>(std::lround((o.x + 0.5) * 4 - 0.5)),
            j = static_cast<int>(std::lround((o.y + 0.5) * 4 - 0.5));
        EXPECT_EQ((i + j) % 2, 0);
    }
    AaPattern r = aaPattern("rooks8");
    std::set<double> xs, ys;
    for (const glm::dvec2& o : r.offsets) {
        xs.insert(o.x);
        ys.insert(o.y);
    }
    EXPECT_EQ(xs.size(), 8u); // one sample in every column and every row
    EXPECT_EQ(ys.size(), 8u);
    EXPECT_EQ(r.offsets[1], glm::dvec2((3 + 0.5) / 8 - 0.5, (1 + 0.5) / 8 - 0.5));
    EXPECT_THROW(aaPattern("grid9"), InputError);
    EXPECT_THROW(aaPattern("msaa"), InputError);
}

Genome solid(glm::dvec3 size) {
    Genome g;
    g.dimension = 3;
    g.size = size;
    g.palette = {{255, 0, 0}};
    return g;
}

TEST(SampleFrame, PixelToPointFollowsTheSpec) {
    Genome g;
    g.size = {1000, 500, 0};
    RenderSettings s;
    s.width = 40;
    s.height = 20;
    s.region = Region{100, 50, 300, 250};
    SampleFrame f = sampleFrame(g, s);
    glm::dvec3 p = f.at(3, 7, 0.25, -0.5);
    EXPECT_DOUBLE_EQ(p.x, 100 + (3 + 0.5 + 0.25) * 200.0 / 40);
    EXPECT_DOUBLE_EQ(p.y, 50 + (7 + 0.5 - 0.5) * 200.0 / 20);
    EXPECT_EQ(p.z, 0.0);
    s.region.reset();
    Region r = effectiveRegion(g, s);
    EXPECT_EQ(r.x1, 1000);
    EXPECT_EQ(r.y1, 500);
}

TEST(SampleFrame, SlicesOnEveryAxis) {
    Genome g = solid({100, 200, 300});
    RenderSettings s;
    s.width = 10;
    s.height = 10;
    s.slice = Slice{2, 7.0};
    Region r = effectiveRegion(g, s);
    EXPECT_EQ((glm::dvec4(r.x0, r.y0, r.x1, r.y1)), glm::dvec4(0, 0, 100, 200));
    EXPECT_EQ(sampleFrame(g, s).at(1, 2, 0, 0), glm::dvec3(15, 50, 7)); // (x, y, c)

    s.slice = Slice{1, 7.0};
    r = effectiveRegion(g, s);
    EXPECT_EQ((glm::dvec4(r.x0, r.y0, r.x1, r.y1)), glm::dvec4(0, 0, 100, 300));
    EXPECT_EQ(sampleFrame(g, s).at(1, 2, 0, 0), glm::dvec3(15, 7, 75)); // (x, c, z), rows along z

    s.slice = Slice{0, 7.0};
    r = effectiveRegion(g, s);
    EXPECT_EQ((glm::dvec4(r.x0, r.y0, r.x1, r.y1)), glm::dvec4(0, 0, 200, 300));
    EXPECT_EQ(sampleFrame(g, s).at(1, 2, 0, 0), glm::dvec3(7, 30, 75)); // (c, y, z)
}

TEST(SlicePlane, MapsThePlaneBothWaysOnEveryAxis) {
    const glm::dvec3 size{100, 200, 300};
    struct Case {
        int axis;
        glm::dvec2 extent;
        glm::dvec3 point; ///< the design point of plane coordinates (1, 2) at value 7
    };
    for (const Case& c :
         {Case{0, {200, 300}, {7, 1, 2}}, Case{1, {100, 300}, {1, 7, 2}}, Case{2, {100, 200}, {1, 2, 7}}}) {
        const SlicePlane plane = slicePlane(3, c.axis, 7.0);
        EXPECT_EQ(plane.normalAxis, c.axis);
        EXPECT_EQ(plane.extent(size), c.extent) << c.axis;
        EXPECT_EQ(plane.fromPlane({1, 2}), c.point) << c.axis;
        EXPECT_EQ(plane.toPlane(c.point), glm::dvec2(1, 2)) << c.axis;
        EXPECT_EQ(plane.fromPlane({1, 0}) - plane.fromPlane({0, 0}), plane.u()) << c.axis;
        EXPECT_EQ(plane.fromPlane({0, 1}) - plane.fromPlane({0, 0}), plane.v()) << c.axis;
        EXPECT_EQ(glm::dot(plane.normal(), plane.u()) + glm::dot(plane.normal(), plane.v()), 0.0) << c.axis;
    }
    // A flat design is always the x-y plane at 0, whatever slice a caller holds.
    const SlicePlane flat = slicePlane(2, 0, 7.0);
    EXPECT_EQ(flat.fromPlane({1, 2}), glm::dvec3(1, 2, 0));
    EXPECT_EQ(flat.extent(size), glm::dvec2(100, 200));
    EXPECT_EQ(slicePlane(solid({1, 2, 3}), std::nullopt).normalAxis, 2);
    EXPECT_EQ(slicePlane(solid({1, 2, 3}), Slice{1, 0.5}).fromPlane({0, 0}), glm::dvec3(0, 0.5, 0));
}

TEST(SlicePlane, AxisNamesAndTheSliceOption) {
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(parseAxis(axisName(axis)), axis);
        std::string upper = axisName(axis);
        upper[0] = char(upper[0] - 'a' + 'A');
        EXPECT_EQ(parseAxis(upper), axis);
    }
    EXPECT_EQ(parseAxis("w"), std::nullopt);
    EXPECT_EQ(parseAxis(""), std::nullopt);
    EXPECT_EQ(parseAxis("xy"), std::nullopt);

    const Slice slice = parseSlice("Y=12.5");
    EXPECT_EQ(slice.axis, 1);
    EXPECT_EQ(slice.value, 12.5);
    EXPECT_EQ(parseSlice("z=-3e2").value, -300.0);
    for (const char* bad : {"", "z", "=5", "w=5", "z=", "z=abc", "z=1,2", "z=5x", "z=inf", "z=nan", "z= 5"}) {
        try {
            parseSlice(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("--slice: '" + std::string(bad) + "' is not AXIS=VALUE", 0),
                      0u)
                << e.what();
        }
    }
}

TEST(CheckRenderSettings, RefusesWhatCannotBeRendered) {
    Genome flat;
    Genome block = solid({100, 100, 100});
    RenderSettings s;
    s.width = s.height = 16;
    EXPECT_NO_THROW(checkRenderSettings(flat, s));
    EXPECT_THROW(checkRenderSettings(block, s), InputError); // 3D without a slice
    s.slice = Slice{2, 50};
    EXPECT_NO_THROW(checkRenderSettings(block, s));
    EXPECT_THROW(checkRenderSettings(flat, s), InputError); // slice of a flat genome
    s.slice.reset();

    RenderSettings huge = s;
    huge.width = huge.height = 1000000;
    try {
        checkRenderSettings(flat, huge);
        FAIL() << "10^6 x 10^6 accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("too large"), std::string::npos) << e.what();
    }
    RenderSettings wide = s;
    wide.width = 60000;
    wide.height = 60000; // each side allowed, the total is not
    EXPECT_THROW(checkRenderSettings(flat, wide), InputError);
    RenderSettings empty = s;
    empty.width = 0;
    EXPECT_THROW(checkRenderSettings(flat, empty), InputError);
    RenderSettings region = s;
    region.region = Region{10, 10, 10, 20};
    EXPECT_THROW(checkRenderSettings(flat, region), InputError);
    region.region = Region{0, 0, NAN, 5};
    EXPECT_THROW(checkRenderSettings(flat, region), InputError);
    RenderSettings aa = s;
    aa.aa = "fxaa";
    EXPECT_THROW(checkRenderSettings(flat, aa), InputError);
}

TEST(Srgb, EightBitValuesRoundTripAndEncodingRounds) {
    for (int k = 0; k < 256; ++k) {
        EXPECT_EQ(encodeSrgb8(srgbToLinear(k / 255.0)), k);
        EXPECT_FLOAT_EQ(srgbToLinearTable()[k], static_cast<float>(srgbToLinear(k / 255.0)));
    }
    EXPECT_NEAR(linearToSrgb(srgbToLinear(0.3)), 0.3, 1e-15);
    EXPECT_EQ(encodeSrgb8(-1.0), 0);
    EXPECT_EQ(encodeSrgb8(NAN), 0);
    EXPECT_EQ(encodeSrgb8(2.0), 255);
    // The table encoder gives exactly what the formula gives.
    for (int i = 0; i <= 200000; ++i) {
        double l = i / 200000.0;
        auto direct = static_cast<int>(std::floor(linearToSrgb(l) * 255.0 + 0.5));
        ASSERT_EQ(encodeSrgb8(l), std::clamp(direct, 0, 255)) << l;
    }
}

/// A flat genome with one spray dot, to see where a render looks.
Genome dotGenome(glm::dvec2 center, double radius) {
    Genome g;
    g.size = {1000, 1000, 0};
    g.background = {0, 0, 0};
    g.palette = {{255, 255, 255}};
    Operation dot;
    dot.tool = Tool::Spray;
    dot.center = {center, 0};
    dot.radius = radius;
    g.initial = {dot};
    return g;
}

bool white(const Image& image, int x, int y) {
    return image.row(y)[x * 3] == 255;
}

TEST(Render, RegionPlacesThePixels) {
    Genome g = dotGenome({250, 250}, 100);
    RenderSettings s;
    s.width = s.height = 20;
    s.region = Region{150, 150, 350, 350}; // 10 units a pixel
    Image image = CpuRenderer(g).render(s);
    EXPECT_TRUE(white(image, 10, 10));
    EXPECT_TRUE(white(image, 0, 10));   // (155, 255): 95 from the centre
    EXPECT_FALSE(white(image, 0, 0));   // (155, 155): 134 from the centre
    EXPECT_FALSE(white(image, 19, 19)); // (345, 345)
    s.region = Region{400, 400, 600, 600};
    image = CpuRenderer(g).render(s);
    EXPECT_FALSE(white(image, 10, 10));
}

TEST(Render, SlicesSeeTheRightPlane) {
    Genome g = solid({1000, 1000, 1000});
    g.background = {0, 0, 0};
    g.palette = {{255, 255, 255}};
    Operation dot;
    dot.tool = Tool::Spray;
    dot.center = {200, 300, 400};
    dot.radius = 30;
    g.initial = {dot};
    CpuRenderer renderer(g);
    RenderSettings s;
    s.width = s.height = 100; // 10 units a pixel, pixel k centred on 10k + 5
    s.slice = Slice{2, 400};
    Image z = renderer.render(s);
    EXPECT_TRUE(white(z, 19, 29));  // (195, 295)
    EXPECT_FALSE(white(z, 29, 19)); // transposed
    s.slice = Slice{1, 300};
    Image y = renderer.render(s);
    EXPECT_TRUE(white(y, 19, 39)); // (195, c, 395): columns x, rows z
    EXPECT_FALSE(white(y, 39, 19));
    s.slice = Slice{0, 200};
    Image x = renderer.render(s);
    EXPECT_TRUE(white(x, 29, 39)); // (c, 295, 395): columns y, rows z
    EXPECT_FALSE(white(x, 39, 29));
    s.slice = Slice{2, 500}; // beyond the dot
    EXPECT_FALSE(white(renderer.render(s), 19, 29));
}

TEST(Render, ThreadCountDoesNotChangeTheImage) {
    Genome g = loadGenome(test::dataDir() / "examples" / "flame-comb-vortex.marble.json");
    CpuRenderer renderer(g);
    RenderSettings s;
    s.width = 97;
    s.height = 61;
    s.aa = "rgss";
    s.threads = 1;
    Image one = renderer.render(s);
    s.threads = 3;
    Image three = renderer.render(s);
    EXPECT_EQ(one.rgb, three.rgb);
    // Rows rendered separately are the same rows.
    std::vector<std::uint8_t> rows(std::size_t(s.width) * 10 * 3);
    renderer.renderRows(s, 20, 30, rows.data());
    EXPECT_TRUE(std::equal(rows.begin(), rows.end(), one.row(20)));
    std::vector<float> linear(rows.size());
    renderer.renderRowsLinear(s, 20, 30, linear.data());
    for (std::size_t k = 0; k < rows.size(); ++k)
        ASSERT_EQ(encodeSrgb8(linear[k]), rows[k]);
}

TEST(Render, ProgressReachesOneAndCancelStops) {
    Genome g = loadGenome(test::dataDir() / "examples" / "flame-comb-vortex.marble.json");
    CpuRenderer renderer(g);
    RenderSettings s;
    s.width = s.height = 64;
    std::atomic<double> last{0.0};
    RenderControl control;
    control.progress = [&](double f) {
        EXPECT_GE(f, 0.0);
        EXPECT_LE(f, 1.0);
        last = f;
    };
    renderer.render(s, &control);
    EXPECT_EQ(last.load(), 1.0);

    std::atomic<bool> cancel{false};
    RenderControl stop;
    stop.cancel = &cancel;
    stop.progress = [&](double f) {
        if (f > 0.2) cancel = true;
    };
    EXPECT_THROW(renderer.render(s, &stop), Cancelled);
}

TEST(Render, SourceImageIsStretchedOverTheDesign) {
    const std::filesystem::path dir = test::dataDir() / "render";
    // source-4x2.png: 4x2 pixels over an 800x400 design, so pixel (i, j) centres on
    // (100 + 200 i, 100 + 200 j), away from the genome's drops.
    const std::uint8_t expected[2][4][3] = {{{200, 30, 30}, {30, 160, 60}, {40, 60, 200}, {240, 220, 60}},
                                            {{20, 20, 20}, {250, 250, 250}, {120, 40, 160}, {60, 200, 210}}};
    for (const char* name : {"source-2d.marble.json", "source-dataurl-2d.marble.json"}) {
        Genome g = loadGenome(dir / name);
        g.initial.clear();
        g.operations.clear();
        CpuRenderer renderer(g);
        RenderSettings s;
        s.width = 8;
        s.height = 4; // 100 units a pixel: pixel 2i + k centres on 50 + 100 (2i + k)
        s.region = Region{50, 50, 850, 450};
        Image image = renderer.render(s);
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 4; ++i)
                for (int c = 0; c < 3; ++c)
                    EXPECT_EQ(image.row(2 * j)[2 * i * 3 + c], expected[j][i][c])
                        << name << " pixel " << i << "," << j;
        // Between two centres: the average in linear light.
        double mid = (srgbToLinear(200 / 255.0) + srgbToLinear(30 / 255.0)) / 2;
        EXPECT_EQ(image.row(0)[1 * 3], encodeSrgb8(mid)) << name;
        // Clamped to the edge pixels inside the design, background outside.
        s.width = s.height = 1;
        s.region = Region{1, 1, 3, 3};
        EXPECT_EQ(renderer.render(s).rgb[0], 200) << name;
        s.region = Region{-30, 10, -10, 30};
        EXPECT_EQ(renderer.render(s).rgb[0], 255) << name; // background #ffffff
    }
}

TEST(Render, MissingSourceImageIsAnInputErrorNamingTheFile) {
    Genome g = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
    g.source = SourceImage{"no-such-image.png"};
    try {
        CpuRenderer renderer(g);
        FAIL() << "loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("no-such-image.png"), std::string::npos) << e.what();
    }
    g.source = SourceImage{"data:image/png;base64,AAAA"};
    EXPECT_THROW(CpuRenderer{g}, InputError);
    g.source = SourceImage{"data:image/png;base64,!!"};
    EXPECT_THROW(CpuRenderer{g}, InputError);
}

/// A PNG whose header claims `width` x `height` RGB pixels and that holds almost no data.
std::string pngHeaderOnly(std::uint32_t width, std::uint32_t height) {
    auto crc32 = [](const std::string& bytes) {
        std::uint32_t crc = 0xffffffffu;
        for (unsigned char b : bytes) {
            crc ^= b;
            for (int k = 0; k < 8; ++k)
                crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
        }
        return ~crc;
    };
    auto be32 = [](std::uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    };
    auto chunk = [&](const std::string& type, const std::string& data) {
        return be32(std::uint32_t(data.size())) + type + data + be32(crc32(type + data));
    };
    std::string ihdr = be32(width) + be32(height) + std::string{8, 2, 0, 0, 0};
    const std::string emptyZlibStream("\x78\x9c\x03\x00\x00\x00\x00\x01", 8);
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", emptyZlibStream) +
           chunk("IEND", "");
}

TEST(Render, HugeSourceImageIsRefusedBeforeDecoding) {
    // A hostile file may claim a giant raster in a few bytes; the loader must refuse it with a
    // clear message instead of trying to allocate it.
    std::filesystem::path dir = test::outputDir("huge-source");
    test::writeFile(dir / "huge.png", pngHeaderOnly(100000, 100000));
    Genome g = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
    g.baseDirectory = dir.string();
    g.source = SourceImage{"huge.png"};
    try {
        CpuRenderer renderer(g);
        FAIL() << "a 100000 x 100000 source was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("100000 x 100000 pixels is too large"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("source.image"), std::string::npos) << e.what();
    }
    // One side past the cap, though its pixels would fit.
    test::writeFile(dir / "long.png", pngHeaderOnly(40000, 2));
    g.source = SourceImage{"long.png"};
    try {
        CpuRenderer renderer(g);
        FAIL() << "a 40000 x 2 source was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("40000 x 2 pixels is too large"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace marbler
