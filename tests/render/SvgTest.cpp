// Vector output (`marbler svg`, marbler/Vector.h): the SVG rasterised by librsvg against the
// antialiased CPU render of the same genome, the tolerance read back from the path data, every
// vertex mapped back onto the circle its ink was laid on, and the command's failures.

#include "RenderTestUtil.h"
#include "TestUtil.h"

#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/ImageFile.h"
#include "marbler/Params.h"
#include "marbler/Separations.h"
#include "marbler/Tools.h"
#include "marbler/Vector.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>

namespace marbler {
namespace {

using test::runMarbler;

/// The flat genomes the vector output is held to: the examples, the conformance genomes and the
/// 2D render test designs. Together they use every 2D tool (checked below).
struct NamedGenome {
    std::string name;
    Genome genome;
    std::filesystem::path file; ///< a genome file the command line can read
};

/// Whether flatGenomes includes a stylus that drags ink (c = 15 alpha / (16 reach) >= 1: ebru
/// hearts). Its forward map gathers the ink along the track into the point that rides ahead of
/// the stylus, so it compresses without bound there and its inverse, exact in exact arithmetic,
/// amplifies rounding: outlines pushed through it need more refinement than the depth cap gives
/// and do not map back onto their circles. Its SVG is still checked against its render.
enum class Dragging { Without, With };

std::vector<NamedGenome> flatGenomes(const std::filesystem::path& dir,
                                     Dragging dragging = Dragging::Without) {
    std::vector<NamedGenome> genomes;
    std::vector<const char*> examples = {"five-stones", "flame-comb-vortex"};
    if (dragging == Dragging::With) examples.push_back("ebru-hearts");
    for (const char* name : examples) {
        auto file = test::dataDir() / "examples" / (std::string(name) + ".marble.json");
        genomes.push_back({name, loadGenome(file), file});
    }
    for (const char* name :
         {"drops-combs-2d", "waves-swirls-2d", "stretch-flow-2d", "bleed-2d", "stylus-gentle-2d"}) {
        auto file = test::dataDir() / "render" / (std::string(name) + ".marble.json");
        genomes.push_back({name, loadGenome(file), file});
    }
    for (const char* name : {"probes-0", "probes-1", "probes-2", "antialias"}) {
        Genome genome = test::genomeOf(test::loadConformance(std::string(name) + ".json"), name);
        auto file = dir / (std::string(name) + ".marble.json");
        saveGenome(genome, file);
        genomes.push_back({name, genome, file});
    }
    return genomes;
}

/// The polygons of an SVG written by toSvg: every number pair of each path's data (a regular
/// expression would recurse once a character on libstdc++'s, too deep for megabytes of data).
std::vector<std::vector<glm::dvec2>> parsePaths(const std::string& svg) {
    std::vector<std::vector<glm::dvec2>> paths;
    for (std::size_t at = svg.find("<path "); at != std::string::npos; at = svg.find("<path ", at + 1)) {
        std::size_t begin = svg.find(" d=\"M", at), end = svg.find("Z\"", begin);
        if (begin == std::string::npos || end == std::string::npos) {
            ADD_FAILURE() << "a path without data M...Z";
            break;
        }
        std::string data = svg.substr(begin + 5, end - begin - 5);
        for (char& c : data)
            if (c == 'L') c = ' ';
        std::vector<double> numbers;
        const char* p = data.c_str();
        char* next = nullptr;
        for (double v = std::strtod(p, &next); next != p; v = std::strtod(p, &next)) {
            numbers.push_back(v);
            p = next;
        }
        EXPECT_EQ(*p, '\0') << "unparsed path data";
        EXPECT_EQ(numbers.size() % 2, 0u);
        std::vector<glm::dvec2> points;
        for (std::size_t k = 0; k + 1 < numbers.size(); k += 2)
            points.emplace_back(numbers[k], numbers[k + 1]);
        paths.push_back(std::move(points));
    }
    return paths;
}

/// Runs librsvg's rsvg-convert; the test fails (never skips) when CMake did not find it, so a CI
/// machine without librsvg2-bin reports the missing program.
bool rasteriseSvg(const std::filesystem::path& svg, const std::filesystem::path& png, int width, int height) {
    const std::string program = MARBLER_RSVG_CONVERT;
    if (program.empty() || program.ends_with("NOTFOUND")) {
        ADD_FAILURE() << "rsvg-convert was not found when the build was configured (install librsvg2-bin)";
        return false;
    }
    std::string command = "'" + program + "' -w " + std::to_string(width) + " -h " + std::to_string(height) +
                          " -o '" + png.string() + "' '" + svg.string() + "'";
    int status = std::system(command.c_str());
    EXPECT_EQ(status, 0) << command;
    return status == 0 && std::filesystem::exists(png);
}

TEST(Svg, RasterisedSvgMatchesTheAntialiasedRender) {
    const auto dir = test::outputDir("svg-raster");
    std::set<std::string> seen;
    for (const NamedGenome& g : flatGenomes(dir, Dragging::With)) {
        SCOPED_TRACE(g.name);
        test::addToolsUsed(g.genome, seen);
        const auto svg = dir / (g.name + ".svg");
        // The outlines painted over each other: the layers of the default SVG abut, and a
        // rasteriser's coverage of two abutting edges lets the empty canvas show through (the
        // layers themselves are held to the render in SvgLayers below).
        auto r = runMarbler({"svg", g.file.string(), "-o", svg.string(), "--tolerance", "1", "--stacked"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const int size = 256;
        const auto png = dir / (g.name + "-svg.png");
        ASSERT_TRUE(rasteriseSvg(svg, png, size, size));
        Image vector = test::readImage8(png);

        RenderSettings settings;
        settings.width = settings.height = size;
        settings.aa = "grid4";
        Image raster = CpuRenderer(g.genome).render(settings);
        ASSERT_EQ(vector.width, raster.width);
        ASSERT_EQ(vector.height, raster.height);

        // Inside the regions the colours are the same; along the edges librsvg's coverage
        // (blended in sRGB) and the 4x4 samples (averaged in linear light) differ, by up to some
        // 60 levels between dark and light inks, so the designs with many filaments a fraction
        // of a pixel wide (flame-comb-vortex: 3.6 on average, 3.8 % of pixels beyond 40) differ
        // most. A region drawn in the wrong colour shows as pixels off by more than 128: none
        // of these designs has one.
        double sum = 0.0;
        std::size_t disagree = 0, wrong = 0, pixels = std::size_t(size) * size;
        for (std::size_t p = 0; p < pixels; ++p) {
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                int d = std::abs(int(vector.rgb[p * 3 + c]) - int(raster.rgb[p * 3 + c]));
                sum += d;
                worst = std::max(worst, d);
            }
            disagree += worst > 40;
            wrong += worst > 128;
        }
        double mean = sum / double(pixels * 3), share = double(disagree) / double(pixels);
        double wrongShare = double(wrong) / double(pixels);
        EXPECT_LT(mean, 5.0) << "mean absolute difference";
        EXPECT_LT(share, 0.05) << "share of pixels off by more than 40 levels";
        EXPECT_LT(wrongShare, 0.0005) << "share of pixels off by more than 128 levels";
        if (mean >= 5.0 || share >= 0.05 || wrongShare >= 0.0005)
            writeImage(raster, dir / (g.name + "-raster.png"));
    }
    // Every ink-laying and every moving 2D tool took part.
    for (const ToolSpec& spec : allTools())
        if (spec.in2D) {
            EXPECT_TRUE(seen.count("2D " + std::string(spec.name))) << spec.name;
        }
}

TEST(Svg, BleedIsDrawnAsTheHardEdges) {
    // A soft edge's coverage is 1/2 on the hard boundary: the outlines are the hard design's.
    Genome soft = loadGenome(test::dataDir() / "render" / "bleed-2d.marble.json");
    ASSERT_GT(soft.bleed, 0.0);
    Genome hard = soft;
    hard.bleed = 0.0;
    VectorOptions options;
    options.tolerance = 2.0;
    const VectorDesign a = traceDesign(soft, options), b = traceDesign(hard, options);
    EXPECT_EQ(a.bleed, soft.bleed);
    EXPECT_EQ(b.bleed, 0.0);
    EXPECT_EQ(toSvg(a, 2), toSvg(b, 2));
}

TEST(Svg, NeighbouringVerticesAreWithinTheTolerance) {
    const auto dir = test::outputDir("svg-tolerance");
    for (const NamedGenome& g : flatGenomes(dir)) {
        for (double tolerance : {4.0, 1.0, 0.25}) {
            // The finest tolerance on two small designs only (flame-comb-vortex makes 14 MB).
            if (tolerance < 1.0 && g.name != "five-stones" && g.name != "drops-combs-2d") continue;
            SCOPED_TRACE(g.name + " at " + std::to_string(tolerance));
            const auto svg = dir / (g.name + ".svg");
            auto r = runMarbler({"svg", g.file.string(), "-o", svg.string(), "--tolerance",
                                 std::to_string(tolerance), "--stacked"});
            ASSERT_EQ(r.exitCode, 0) << r.err;
            auto paths = parsePaths(test::readFile(svg));
            VectorOptions options;
            options.tolerance = tolerance;
            VectorDesign design = traceDesign(g.genome, options);
            ASSERT_EQ(paths.size(), design.outlines.size());
            // Written coordinates are rounded to half a unit of the last digit each.
            const double rounding = std::sqrt(2.0) * std::pow(10.0, -decimalsFor(tolerance));
            std::size_t vertices = 0;
            double longest = 0.0;
            for (const auto& path : paths) {
                vertices += path.size();
                for (std::size_t k = 0; k < path.size(); ++k)
                    longest = std::max(longest, glm::distance(path[k], path[(k + 1) % path.size()]));
            }
            EXPECT_EQ(vertices, design.vertexCount);
            // Gaps at the depth cap straddle a tear the forward maps open at a later drop's centre;
            // none of these designs has one.
            EXPECT_EQ(design.gapsAtDepthCap, 0u);
            EXPECT_LE(longest, tolerance + rounding);
            // And the refinement is not wasteful: chords are not all far below the tolerance.
            EXPECT_GT(longest, 0.5 * tolerance);
        }
    }
}

TEST(Svg, VerticesLieOnTheTrueBoundary) {
    const auto dir = test::outputDir("svg-boundary");
    for (const NamedGenome& g : flatGenomes(dir)) {
        SCOPED_TRACE(g.name);
        VectorOptions options;
        options.tolerance = 2.0;
        VectorDesign design = traceDesign(g.genome, options);
        const std::vector<PreparedOp> ops = prepare(g.genome);
        double worst = 0.0;
        for (const InkOutline& outline : design.outlines) {
            const PreparedOp& ink = ops[outline.step];
            EXPECT_EQ(outline.color, ink.color);
            for (std::size_t k = 0; k < outline.points.size(); k += 7) {
                glm::dvec3 p(outline.points[k], 0.0);
                for (std::size_t j = ops.size(); j-- > outline.step + 1;)
                    p = inverseMap(ops[j], p);
                worst = std::max(worst, std::abs(glm::distance(p, ink.c) - ink.r));
            }
        }
        EXPECT_LT(worst, 1e-6);
    }
}

TEST(Svg, LaterInksCoverEarlierOnesInStackingOrder) {
    // A drop inside a drop makes a ring; a spray covers without moving; a comb drags them all.
    const auto dir = test::outputDir("svg-stacking");
    Genome genome =
        parseGenome(R"({"format": "marbler-genome", "version": 1, "dimension": 2, "size": [400, 200],
        "background": "#ffffff", "palette": ["#ff0000", "#0000ff", "#00ff00"],
        "initial": [{"tool": "drop", "center": [200, 100], "radius": 60, "color": 0},
                    {"tool": "drop", "center": [200, 100], "radius": 30, "color": 1},
                    {"tool": "spray", "center": [260, 100], "radius": 25, "color": 2}],
        "operations": [{"tool": "line", "origin": [0, 100], "angle": 0, "alpha": 40, "lambda": 20}]})",
                    "stack");
    VectorDesign design = traceDesign(genome);
    ASSERT_EQ(design.outlines.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_EQ(design.outlines[k].step, k);
    // The first drop's outline was pushed out to the area law's radius sqrt(60^2 + 30^2) before
    // the line; the line moves points along x only, so its top and bottom keep their height.
    double top = 1e9;
    for (const glm::dvec2& p : design.outlines[0].points)
        top = std::min(top, p.y);
    EXPECT_NEAR(top, 100.0 - std::sqrt(60.0 * 60.0 + 30.0 * 30.0), 0.05);
    // The spray moved nothing: the blue drop's outline is a circle shifted by the line only.
    auto file = dir / "stack.marble.json";
    saveGenome(genome, file);
    auto r = runMarbler(
        {"svg", file.string(), "-o", (dir / "stack.svg").string(), "--tolerance", "0.5", "--stacked"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string svg = test::readFile(dir / "stack.svg");
    EXPECT_NE(svg.find(R"(viewBox="0 0 400 200")"), std::string::npos);
    EXPECT_NE(svg.find(R"(<rect x="0" y="0" width="400" height="200" fill="#ffffff"/>)"), std::string::npos);
    std::size_t red = svg.find("#ff0000\" d="), blue = svg.find("#0000ff\" d="),
                green = svg.find("#00ff00\" d=");
    ASSERT_NE(green, std::string::npos);
    EXPECT_LT(red, blue);
    EXPECT_LT(blue, green);
    ASSERT_TRUE(rasteriseSvg(dir / "stack.svg", dir / "stack.png", 400, 200));
    Image image = test::readImage8(dir / "stack.png");
    auto at = [&](int x, int y) {
        const std::uint8_t* px = image.row(y) + x * 3;
        return std::array<int, 3>{px[0], px[1], px[2]};
    };
    // Along the line y = 100 everything moved by alpha: the ring's red, the blue core, the green
    // spray over the ring's right side, the white bath.
    CpuRenderer renderer(genome);
    for (int x : {150, 200, 240, 290, 330, 380}) {
        int k = renderer.colorIndexAt({x + 0.5, 100.5, 0.0});
        std::array<int, 3> expected =
            k < 0 ? std::array<int, 3>{255, 255, 255}
                  : std::array<int, 3>{genome.palette[k].r, genome.palette[k].g, genome.palette[k].b};
        EXPECT_EQ(at(x, 100), expected) << "x = " << x << ", ink " << k;
    }
}

TEST(Svg, NearlyStraightRunsLoseTheirInnerVertices) {
    // A drop of radius 2 at tolerance 10: its 64 initial samples are 0.2 apart, and a run of
    // them bends less than a tenth of a unit (T/100) from its chord for about 0.9 units.
    Genome genome =
        parseGenome(R"({"format": "marbler-genome", "version": 1, "dimension": 2, "size": [100, 100],
        "background": "#ffffff", "palette": ["#000000"], "initial": [{"tool": "drop", "center": [50, 50], "radius": 2, "color": 0}],
        "operations": []})",
                    "small");
    VectorOptions options;
    options.tolerance = 10.0;
    VectorDesign simplified = traceDesign(genome, options);
    options.straightness = 0.0;
    VectorDesign plain = traceDesign(genome, options);
    EXPECT_EQ(plain.droppedAsStraight, 0u);
    EXPECT_EQ(plain.vertexCount, 64u);
    EXPECT_GT(simplified.droppedAsStraight, 0u);
    EXPECT_EQ(simplified.vertexCount + simplified.droppedAsStraight, 64u);
    // What is kept still lies on the circle, and no kept chord bends off it by more than T/100.
    const auto& kept = simplified.outlines.at(0).points;
    for (std::size_t k = 0; k < kept.size(); ++k) {
        EXPECT_NEAR(glm::distance(kept[k], glm::dvec2(50, 50)), 2.0, 1e-12);
        double chord = glm::distance(kept[k], kept[(k + 1) % kept.size()]);
        EXPECT_LE(2.0 - std::sqrt(4.0 - chord * chord / 4.0), 0.1 + 1e-12);
    }
}

TEST(Svg, SimplifyReplacesOnlyStraightRuns) {
    // --simplify: chords up to 16 T where every replaced vertex is within T/100 of them. The
    // kept vertices are a subsequence of the strict outline's, so each dropped one is checked
    // against the chord that replaced it.
    const auto dir = test::outputDir("svg-simplify");
    for (const NamedGenome& g : flatGenomes(dir)) {
        SCOPED_TRACE(g.name);
        VectorOptions options;
        options.tolerance = 1.0;
        options.straightChord = 0.0; // nothing dropped
        VectorDesign strict = traceDesign(g.genome, options);
        EXPECT_EQ(strict.droppedAsStraight, 0u);
        options.straightChord = 16.0;
        VectorDesign loose = traceDesign(g.genome, options);
        ASSERT_EQ(strict.outlines.size(), loose.outlines.size());
        EXPECT_LT(loose.vertexCount * 4, strict.vertexCount * 3) << "at least a quarter fewer";
        double worst = 0.0, longest = 0.0;
        for (std::size_t o = 0; o < strict.outlines.size(); ++o) {
            const auto& all = strict.outlines[o].points;
            const auto& kept = loose.outlines[o].points;
            std::size_t i = 0;
            for (std::size_t k = 0; k < kept.size(); ++k) {
                const glm::dvec2 a = kept[k], b = kept[(k + 1) % kept.size()];
                ASSERT_LT(i, all.size());
                ASSERT_EQ(all[i], a) << "kept vertices are the strict outline's";
                longest = std::max(longest, glm::distance(a, b));
                for (++i; i < all.size() && all[i] != b; ++i) {
                    glm::dvec2 ab = b - a;
                    double t = std::clamp(glm::dot(all[i] - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
                    worst = std::max(worst, glm::distance(all[i], a + t * ab));
                }
            }
        }
        EXPECT_LE(worst, 0.01 + 1e-9);
        EXPECT_LE(longest, 16.0 + 1e-9);
        EXPECT_GT(longest, 1.0); // it did join runs beyond T
    }
    // The command line's --simplify is this.
    const auto svg = dir / "five-stones.svg";
    auto r = runMarbler({"svg", (test::dataDir() / "examples" / "five-stones.marble.json").string(), "-o",
                         svg.string(), "--simplify", "--stacked"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    VectorOptions options;
    options.straightChord = 16.0;
    std::size_t vertices = 0;
    for (const auto& path : parsePaths(test::readFile(svg)))
        vertices += path.size();
    EXPECT_EQ(vertices,
              traceDesign(loadGenome(test::dataDir() / "examples" / "five-stones.marble.json"), options)
                  .vertexCount);
}

/// One layer of a layered SVG (toLayeredSvg): its group's text and what it says.
struct SvgLayer {
    std::string label, id, fill, group;
    std::vector<std::vector<glm::dvec2>> rings; ///< the path's subpaths
};

/// The value of attribute `name` in `tag`, or "".
std::string attribute(const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    std::size_t at = tag.find(key);
    if (at == std::string::npos) return "";
    at += key.size();
    return tag.substr(at, tag.find('"', at) - at);
}

std::vector<SvgLayer> parseLayers(const std::string& svg) {
    std::vector<SvgLayer> layers;
    for (std::size_t at = svg.find("<g "); at != std::string::npos; at = svg.find("<g ", at + 1)) {
        const std::size_t end = svg.find("</g>", at);
        if (end == std::string::npos) {
            ADD_FAILURE() << "a group without its end";
            break;
        }
        SvgLayer layer;
        layer.group = svg.substr(at, end + 4 - at);
        const std::string tag = layer.group.substr(0, layer.group.find('>'));
        EXPECT_EQ(attribute(tag, "inkscape:groupmode"), "layer");
        layer.label = attribute(tag, "inkscape:label");
        layer.id = attribute(tag, "id");
        const std::size_t path = layer.group.find("<path ");
        if (path != std::string::npos) {
            const std::string pathTag = layer.group.substr(path, layer.group.find("/>", path) - path);
            layer.fill = attribute(pathTag, "fill");
            EXPECT_EQ(attribute(pathTag, "fill-rule"), "evenodd");
            std::string data = attribute(pathTag, "d");
            const char* p = data.c_str();
            while (*p) {
                if (*p == 'M') {
                    layer.rings.emplace_back();
                    ++p;
                } else if (*p == 'L' || *p == 'Z' || *p == ' ') {
                    ++p;
                } else {
                    char* next = nullptr;
                    const double x = std::strtod(p, &next);
                    EXPECT_NE(next, p) << "unparsed path data at " << p;
                    if (next == p || layer.rings.empty()) break;
                    const double y = std::strtod(next, &next);
                    layer.rings.back().emplace_back(x, y);
                    p = next;
                }
            }
        }
        layers.push_back(std::move(layer));
    }
    return layers;
}

/// The signed area of a ring (shoelace).
double signedArea(const std::vector<glm::dvec2>& ring) {
    double sum = 0.0;
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const glm::dvec2 a = ring[k], b = ring[(k + 1) % ring.size()];
        sum += a.x * b.y - b.x * a.y;
    }
    return 0.5 * sum;
}

/// A raster size of the design's aspect, about 256 pixels wide, whose pixels are square.
std::pair<int, int> rasterSizeOf(const Genome& genome) {
    for (int width : {256, 250, 240, 200, 300, 320, 160, 128, 100}) {
        const double height = width * genome.size.y / genome.size.x;
        if (std::abs(height - std::round(height)) < 1e-9) return {width, int(std::round(height))};
    }
    ADD_FAILURE() << "no raster size of the aspect " << genome.size.x << " x " << genome.size.y;
    return {256, 256};
}

/// The issue's promise to a screen printer: each layer of `marbler svg`'s file of `g`, printed
/// alone, is where its ink shows in the raster render (the hard colour rule at each pixel's
/// centre), within 0.5 % of the page, and together the layers cover every pixel once.
/// At the tolerance `tolerance` (design units).
void expectLayersAreTheRendersInks(const NamedGenome& g, const std::filesystem::path& dir,
                                   const std::string& tolerance = "1") {
    {
        SCOPED_TRACE(g.name);
        const auto svgFile = dir / (g.name + ".svg");
        auto r = runMarbler({"svg", g.file.string(), "-o", svgFile.string(), "--tolerance", tolerance});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const std::string svg = test::readFile(svgFile);
        const std::vector<SvgLayer> layers = parseLayers(svg);
        ASSERT_EQ(layers.size(), g.genome.palette.size() + 1);
        const std::string header = svg.substr(0, svg.find("<g "));

        const auto [width, height] = rasterSizeOf(g.genome);
        CpuRenderer renderer(g.genome);
        std::vector<int> inkAt(std::size_t(width) * height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                inkAt[std::size_t(y) * width + x] = renderer.colorIndexAt(
                    {(x + 0.5) * g.genome.size.x / width, (y + 0.5) * g.genome.size.y / height, 0.0});

        // Each pixel's coverage summed over the layers: 255 where they tile it.
        std::vector<int> coverageAt(inkAt.size(), 0);
        for (std::size_t k = 0; k < layers.size(); ++k) {
            const int ink = int(k) - 1; // the background first, then the palette in order
            SCOPED_TRACE(layers[k].label);
            // The layer alone, white on black: its coverage is the red channel.
            std::string group = layers[k].group;
            if (!layers[k].fill.empty()) {
                const std::string fill = "fill=\"" + layers[k].fill + "\"";
                group.replace(group.find(fill), fill.size(), "fill=\"#ffffff\"");
            }
            const auto alone = dir / (g.name + "-" + layers[k].id + ".svg");
            {
                std::ofstream out(alone);
                out << header << group << "\n</svg>\n";
            }
            const auto png = dir / (g.name + "-" + layers[k].id + ".png");
            const std::string command = std::string("'") + MARBLER_RSVG_CONVERT + "' -b black -w " +
                                        std::to_string(width) + " -h " + std::to_string(height) + " -o '" +
                                        png.string() + "' '" + alone.string() + "'";
            ASSERT_EQ(std::system(command.c_str()), 0) << command;
            const Image image = test::readImage8(png);
            ASSERT_EQ(image.width, width);
            ASSERT_EQ(image.height, height);
            // The layer's area in pixels against the ink's pixels in the render (the issue's
            // measure), and pixels the layer clearly covers (3/4) where the ink is not, or clearly
            // leaves (1/4) where it is. Filaments thinner than a pixel are partly covered, seen by
            // the render's one sample or not, so only the clear pixels are counted one by one.
            double area = 0.0;
            std::size_t clearlyWrong = 0, inkPixels = 0;
            for (std::size_t p = 0; p < inkAt.size(); ++p) {
                const int coverage = image.rgb[p * 3];
                coverageAt[p] += coverage;
                area += coverage / 255.0;
                const bool isInk = inkAt[p] == ink;
                inkPixels += isInk;
                clearlyWrong += isInk ? coverage < 64 : coverage > 191;
            }

            const double page = double(inkAt.size());
            EXPECT_LE(std::abs(area - double(inkPixels)), 0.005 * page)
                << "the layer covers " << area << " pixels, the ink " << inkPixels;
            EXPECT_LE(double(clearlyWrong), 0.005 * page) << clearlyWrong << " pixels clearly wrong";
            std::cout << "[ measure  ] " << g.name << " " << layers[k].label << ": layer "
                      << 100.0 * area / page << " % of the page, ink " << 100.0 * inkPixels / page
                      << " %, clearly wrong " << 100.0 * clearlyWrong / page << " %\n";
        }
        // Together the layers cover every pixel once: no overlaps, no gaps (the antialiased
        // coverage of abutting edges adds up to the pixel).
        std::size_t notOnce = 0;
        for (int sum : coverageAt)
            notOnce += std::abs(sum - 255) > 64;
        EXPECT_LE(double(notOnce), 0.005 * double(coverageAt.size())) << "pixels not covered once";
    }
}

TEST(SvgLayers, EachLayerAloneCoversThePixelsOfItsInk) {
    const auto dir = test::outputDir("svg-layers");
    for (const NamedGenome& g : flatGenomes(dir, Dragging::With))
        expectLayersAreTheRendersInks(g, dir);
}

TEST(SvgLayers, AWrappingBathsInkCarriedOverAnEdgeComesBackOverTheOther) {
    // Issue 23: where the bath wraps, a painted circle laid across an edge of the tile, and ink a
    // pass carries out over one edge, show on the other side in the render, and so in each layer
    // of the SVG (the lattice's images of each outline, cut at the tile's edges). Sprays across
    // every edge and corner on each lattice, and stretches along both axes on the straight one.
    const auto dir = test::outputDir("svg-layers-wrap");
    for (const Lattice lattice : {Lattice::Straight, Lattice::HalfDrop, Lattice::Brick}) {
        const std::string name = lattice == Lattice::Straight   ? "wrap-straight"
                                 : lattice == Lattice::HalfDrop ? "wrap-half-drop"
                                                                : "wrap-brick";
        SCOPED_TRACE(name);
        Genome genome = parseGenome(R"({
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
            {"tool": "stretch", "origin": [120, 0], "angle": 90, "teeth": [0, 30, 55, 90, 120], "shift": -25, "power": 2}
          ]
        })",
                                    name);
        genome.lattice = lattice;
        if (lattice != Lattice::Straight) genome.operations.clear();
        const auto file = dir / (name + ".marble.json");
        saveGenome(genome, file);
        // A tenth of a design unit is a fifth of a pixel of the 256-pixel raster.
        expectLayersAreTheRendersInks({name, genome, file}, dir, "0.1");
    }
}

TEST(SvgLayers, LayersAreNamedTileThePageAndHaveAPrintedSize) {
    const auto dir = test::outputDir("svg-layers-page");
    for (const NamedGenome& g : flatGenomes(dir)) {
        SCOPED_TRACE(g.name);
        const auto svgFile = dir / (g.name + ".svg");
        auto r = runMarbler({"svg", g.file.string(), "-o", svgFile.string(), "--tolerance", "2"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const std::string svg = test::readFile(svgFile);
        // The printed size in millimetres, a design unit being a CSS pixel (96 dpi) by default;
        // the viewBox stays in design units.
        const std::string root =
            svg.substr(svg.find("<svg "), svg.find('>', svg.find("<svg ")) - svg.find("<svg "));
        EXPECT_EQ(attribute(root, "width"), svgLength(g.genome.size.x / 96.0 * 25.4));
        EXPECT_EQ(attribute(root, "height"), svgLength(g.genome.size.y / 96.0 * 25.4));
        EXPECT_TRUE(attribute(root, "width").ends_with("mm"));
        EXPECT_EQ(attribute(root, "xmlns:inkscape"), "http://www.inkscape.org/namespaces/inkscape");

        const std::vector<SvgLayer> layers = parseLayers(svg);
        ASSERT_EQ(layers.size(), g.genome.palette.size() + 1);
        EXPECT_EQ(layers[0].label, "Background " + toHex(g.genome.background));
        EXPECT_EQ(layers[0].id, "background");
        std::set<std::string> ids;
        double area = 0.0;
        for (std::size_t k = 0; k < layers.size(); ++k) {
            const SvgLayer& layer = layers[k];
            ids.insert(layer.id);
            if (k > 0) {
                const std::string hex = toHex(g.genome.palette[k - 1]);
                EXPECT_EQ(layer.label, "Ink " + std::to_string(k) + " " + hex);
                EXPECT_EQ(layer.id, "ink-" + std::to_string(k));
                if (!layer.rings.empty()) {
                    EXPECT_EQ(layer.fill, hex);
                }
            }
            // Nothing outside the page.
            for (const auto& ring : layer.rings) {
                area += signedArea(ring);
                for (const glm::dvec2& p : ring) {
                    EXPECT_GE(p.x, 0.0);
                    EXPECT_GE(p.y, 0.0);
                    EXPECT_LE(p.x, g.genome.size.x);
                    EXPECT_LE(p.y, g.genome.size.y);
                }
            }
        }
        EXPECT_EQ(ids.size(), layers.size()) << "ids are unique";
        // The layers do not overlap and leave nothing out: their areas add up to the page's
        // (holes count negative; every ring of the clipper has the same orientation as its kind).
        EXPECT_NEAR(std::abs(area), g.genome.size.x * g.genome.size.y,
                    1e-6 * g.genome.size.x * g.genome.size.y);
    }
}

TEST(SvgLayers, DpiAndPrintSizeSetTheMillimetres) {
    const auto dir = test::outputDir("svg-layers-size");
    const auto genomeFile = test::dataDir() / "examples" / "ebru-hearts.marble.json";
    const Genome genome = loadGenome(genomeFile);
    auto rootOf = [&](const std::vector<std::string>& extra) {
        const auto svg = dir / "out.svg";
        std::vector<std::string> args = {"svg", genomeFile.string(), "-o", svg.string(), "--tolerance", "4"};
        args.insert(args.end(), extra.begin(), extra.end());
        auto r = runMarbler(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        const std::string text = test::readFile(svg);
        return text.substr(text.find("<svg "), text.find('>', text.find("<svg ")) - text.find("<svg "));
    };
    std::string root = rootOf({"--dpi", "300"});
    EXPECT_EQ(attribute(root, "width"), svgLength(genome.size.x / 300.0 * 25.4));
    EXPECT_EQ(attribute(root, "height"), svgLength(genome.size.y / 300.0 * 25.4));
    EXPECT_EQ(attribute(root, "viewBox"),
              "0 0 " + std::to_string(int(genome.size.x)) + " " + std::to_string(int(genome.size.y)));
    // A print size of the design's aspect (1000 x 600): 50 x 30 cm.
    root = rootOf({"--size", "50x30cm"});
    EXPECT_EQ(attribute(root, "width"), "500mm");
    EXPECT_EQ(attribute(root, "height"), "300mm");
    // The stacked paths keep today's unitless size, unless a size is asked for.
    root = rootOf({"--stacked"});
    EXPECT_EQ(attribute(root, "width"), std::to_string(int(genome.size.x)));
    root = rootOf({"--stacked", "--size", "10x6in"});
    EXPECT_EQ(attribute(root, "width"), "254mm");
}

TEST(SvgLayers, StackedIsThePaintedOutlines) {
    const auto dir = test::outputDir("svg-stacked");
    const auto genomeFile = test::dataDir() / "examples" / "five-stones.marble.json";
    const auto svg = dir / "five-stones.svg";
    auto r = runMarbler({"svg", genomeFile.string(), "-o", svg.string(), "--stacked"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readFile(svg), toSvg(traceDesign(loadGenome(genomeFile)), decimalsFor(1.0)));
}

/// A failure: the exit status, one stderr line that mentions `mention`, and no output file.
void expectFailure(const std::vector<std::string>& args, int exitCode, const std::string& mention,
                   const std::filesystem::path& out) {
    auto r = runMarbler(args);
    EXPECT_EQ(r.exitCode, exitCode) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << out;
    for (const auto& entry : std::filesystem::directory_iterator(out.parent_path()))
        ADD_FAILURE() << "left behind: " << entry.path();
}

TEST(SvgCli, BadInputExitsTwoWithOneLineAndNoOutput) {
    const auto dir = test::outputDir("svg-bad");
    const std::string out = (dir / "out.svg").string();
    const std::string good = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    expectFailure({"svg", (test::dataDir() / "examples" / "slate-block.marble.json").string(), "-o", out}, 2,
                  "slate-block.marble.json: vector output needs a flat (2D) genome", out);
    expectFailure({"svg", (test::dataDir() / "render" / "source-2d.marble.json").string(), "-o", out}, 2,
                  "source-2d.marble.json: vector output cannot draw a source image", out);
    expectFailure({"svg", good, "-o", out, "--tolerance", "0"}, 2, "--tolerance", out);
    expectFailure({"svg", good, "-o", out, "--tolerance", "-1"}, 2, "--tolerance", out);
    expectFailure({"svg", good, "-o", out, "--tolerance", "fine"}, 2, "--tolerance", out);
    expectFailure({"svg", good, "-o", out, "--tolerance", "1e-9"}, 2, "larger tolerance", out);
    expectFailure({"svg", good, "-o", out, "--frobnicate"}, 2, "--frobnicate", out);
    expectFailure({"svg", good, "-o", (dir / "out.png").string()}, 2, "out.png", dir / "out.png");
    expectFailure({"svg", good}, 2, "-o", out);
    expectFailure({"svg", good, "-o", out, "--dpi", "0"}, 2, "--dpi", out);
    expectFailure({"svg", good, "-o", out, "--dpi", "300", "--size", "10x10cm"}, 2, "exclude", out);
    expectFailure({"svg", good, "-o", out, "--size", "10x20cm"}, 2, "--size 10x20cm", out);
    expectFailure({"svg", good, "-o", out, "--size", "wide"}, 2, "wide", out);
    expectFailure({"svg", (dir.parent_path() / "absent.marble.json").string(), "-o", out}, 2,
                  "absent.marble.json", out);
}

TEST(SvgCli, UnwritableFolderExitsOne) {
    const auto dir = test::outputDir("svg-unwritable");
    const auto out = dir / "no" / "such" / "folder" / "out.svg";
    auto r = runMarbler(
        {"svg", (test::dataDir() / "examples" / "five-stones.marble.json").string(), "-o", out.string()});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("out.svg"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(SvgCli, HelpDescribesEveryOption) {
    auto r = runMarbler({"svg", "--help"});
    EXPECT_EQ(r.exitCode, 0);
    for (const char* option : {"-o", "--tolerance", "--simplify", "--stats", "source", "(3D)", "viewBox",
                               "--stacked", "--dpi", "--size", "layer", "millimetres"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option;
    r = runMarbler({"--help"});
    EXPECT_NE(r.out.find("svg GENOME"), std::string::npos);
}

} // namespace
} // namespace marbler
