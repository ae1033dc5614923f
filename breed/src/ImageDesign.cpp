#include "marbler/ImageDesign.h"

#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/Params.h"
#include "marbler/Random.h"

#include <algorithm>
#include <cmath>

namespace marbler {
namespace {

// Streams of their own, apart from randomGenome's, so a picture's design of seed N is not a
// random design of seed N with its inks taken away.
constexpr std::uint64_t PictureFlowStream = 0x696d616765666c31ULL;
constexpr std::uint64_t PictureStrokeStream = 0x696d616765737431ULL;
constexpr std::uint64_t PicturePaletteStream = 0x696d616765706131ULL;

/// The flow that carries the picture: cells over the whole bath, or one cavity filling most of
/// it. Moves ink by about a tenth to a third of the bath, whatever the design's size.
Operation pictureFlow(Pcg32& rng, const glm::dvec3& size) {
    Operation op = defaultOperation(Tool::Flow, 2, 0.5 * size);
    const double side = std::min(size.x, size.y);
    double reach; // about how far the flow carries ink: |U| T
    if (rng.chance(0.5)) {
        op.field = FlowField::Cells;
        // Two to four cells across the shorter side, a little uneven.
        double cell = side / rng.between(2, 4);
        op.extent = {tenth(cell * rng.uniform(0.85, 1.15)), tenth(cell * rng.uniform(0.85, 1.15))};
        op.center = {tenth(rng.uniform(0.0, op.extent.x)), tenth(rng.uniform(0.0, op.extent.y)), 0.0};
        op.angle = tenth(rng.uniform(-20.0, 20.0));
        reach = cell * rng.uniform(0.3, 0.8);
    } else {
        op.field = FlowField::Cavity;
        // A box over 70-95 % of the bath, its lid (the y = 0 side, strongest) on any edge.
        const double fill = rng.uniform(0.7, 0.95);
        const int edge = rng.between(0, 3);
        const bool across = edge % 2 == 1; // the box turned a quarter: its x runs down the bath
        const double w = across ? size.y : size.x, h = across ? size.x : size.y;
        op.extent = {tenth(w * fill), tenth(h * fill)};
        // Angle 0: M = +x, N = +y, the box's origin its top-left corner; 90: M = +y, N = -x;
        // 180 and 270 the other two, each with the origin at the corner that keeps the box
        // inside the bath.
        const double mx = (size.x - (across ? op.extent.y : op.extent.x)) * 0.5;
        const double my = (size.y - (across ? op.extent.x : op.extent.y)) * 0.5;
        switch (edge) {
        case 0:
            op.angle = 0.0, op.center = {mx, my, 0.0};
            break;
        case 1:
            op.angle = 90.0, op.center = {size.x - mx, my, 0.0};
            break;
        case 2:
            op.angle = 180.0, op.center = {size.x - mx, size.y - my, 0.0};
            break;
        default:
            op.angle = 270.0, op.center = {mx, size.y - my, 0.0};
            break;
        }
        op.center = {tenth(op.center.x), tenth(op.center.y), 0.0};
        reach = side * rng.uniform(0.4, 1.0);
    }
    op.time = tenth(rng.uniform(1.0, 3.0));
    op.speed = tenth((rng.chance(0.5) ? 1.0 : -1.0) * reach / op.time);
    op.steps = minimumFlowSteps(op);
    return op;
}

} // namespace

Genome imageDesign(std::uint64_t seed, const std::string& image, double aspect, const std::string& name) {
    if (!(aspect > 0.0) || !std::isfinite(aspect)) throw InputError("the picture's aspect must be > 0");
    if (image.empty()) throw InputError("no picture to marble");
    Genome g;
    g.dimension = 2;
    // 1000 units across, at least 50 down (a panorama of 20:1 stays a valid design).
    g.size = {1000.0, std::max(50.0, tenth(1000.0 / aspect)), 1000.0};
    // Inks for later: reinitialising a picture's design drops these on it.
    Pcg32 paletteRng(seed, PicturePaletteStream);
    g.palette = randomPalette(paletteRng, &g.background);
    g.source = SourceImage{image};
    Pcg32 flowRng(seed, PictureFlowStream);
    Pcg32 strokeRng(seed, PictureStrokeStream);
    // Most designs first let the picture flow, then stroke it; some stroke first.
    std::vector<Operation> strokes = randomStrokes(strokeRng, 2, g.size);
    Operation flow = pictureFlow(flowRng, g.size);
    if (flowRng.chance(0.75)) {
        g.operations.push_back(flow);
        g.operations.insert(g.operations.end(), strokes.begin(), strokes.end());
    } else {
        g.operations = strokes;
        g.operations.push_back(flow);
    }
    g.meta = Meta{};
    g.meta.name = name;
    g.meta.seed = seed;
    return g;
}

} // namespace marbler
