#include "marbler/Paper.h"

#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h" // latticeName

#include <algorithm>
#include <cmath>
#include <string>

namespace marbler {
namespace {

// Separate streams for the parts of a paper, so that --pastel recolours the same shapes and
// --passes combs the same drops.
constexpr std::uint64_t PaperPaletteStream = 0x7061706572706131ULL;
constexpr std::uint64_t PaperDropStream = 0x7061706572647231ULL;
constexpr std::uint64_t PaperPassStream = 0x7061706572707331ULL;

constexpr double A4Area = 210.0 * 297.0;
constexpr double A4Spacing = 28.0;       // mm between drop centres of one colour at A4
constexpr double LayerShrink = 0.8;      // each later colour's radii, relative to the one before
constexpr double PassShrink = 0.6;       // each later pass's shift, relative to the one before
constexpr double LargestSide = 100000.0; // 100 m

/// Rounds to a hundredth of a millimetre, so files stay readable; exact everywhere.
double hundredth(double x) {
    return std::round(x * 100.0) / 100.0;
}

/// base^n by multiplication: std::pow is not required to be correctly rounded.
double power(double base, int n) {
    double result = 1.0;
    for (int i = 0; i < n; ++i)
        result *= base;
    return result;
}

/// Tooth positions from at most one gap below `from` until one at or past `to`, with gaps in
/// [g, 1.8 g]: a one-dimensional Poisson-disk sample (a maximal one has gaps below 2 g).
std::vector<double> teethBetween(Pcg32& rng, double from, double to, double g) {
    std::vector<double> teeth{hundredth(from - rng.uniform(0.0, g))};
    while (teeth.back() < to)
        teeth.push_back(hundredth(teeth.back() + g + hundredth(rng.uniform(0.0, 0.8 * g))));
    return teeth;
}

// The post's recipe (docs/paper.md).
constexpr double PostA4Spacing = 20.0; // the post's 2 cm between drop centres at A4

/// Tooth positions for a pass of the post's recipe across `extent`: the first at 0, gaps in
/// [g, 1.8 g], the last at `extent` exactly (teeth that end at the borders, so that the pass's
/// teeth span the wrapping bath), a last gap under g / 2 merged into the one before.
std::vector<double> teethAcross(Pcg32& rng, double extent, double g) {
    std::vector<double> teeth{0.0};
    while (teeth.back() < extent)
        teeth.push_back(hundredth(teeth.back() + g + hundredth(rng.uniform(0.0, 0.8 * g))));
    if (teeth.size() > 2 && extent - teeth[teeth.size() - 2] < 0.5 * g) teeth.pop_back();
    teeth.back() = extent;
    return teeth;
}

} // namespace

double paperPostSpacing(double width, double height, int colors) {
    double area = width * height;
    double spacing = PostA4Spacing * std::sqrt(std::sqrt(area / A4Area));
    // As paperSpacing: a layer holds about 0.7 points per d^2 (no margin here: the bath wraps).
    double perColour = static_cast<double>(MaxEntries - MaxPaperPasses) / std::max(colors - 1, 1);
    return std::max(spacing, std::sqrt(area / (0.5 * perColour)));
}

glm::dvec2 paperPostRadii(double spacing, int color) {
    double scale = spacing / power(GoldenRatio, std::max(color - 1, 0));
    return {0.75 * scale, 1.0 * scale};
}

glm::dvec2 paperPostFirstShift(double spacing) {
    return {2.0 * spacing, 7.0 * spacing};
}

glm::dvec2 paperPostToothGap(double spacing, int pass) {
    double scale = spacing * power(GoldenRatio, pass);
    return {0.5 * scale, 1.0 * scale};
}

double paperSpacing(double width, double height, int colors) {
    // The fourth root of the area: a sheet twice as wide (four times the area) gets drops
    // sqrt(2) times further apart, so twice as many of them, not four times (a fixed
    // distance) nor the same number (a distance proportional to the sheet).
    double area = width * height;
    double spacing = A4Spacing * std::sqrt(std::sqrt(area / A4Area));
    // A Poisson-disk sample holds about 0.7 points per d^2; at 0.4 per d^2 of the sheet a
    // colour's layer, margin included, stays well within its share of the format's entries.
    double perColour = static_cast<double>(MaxEntries - MaxPaperPasses) / std::max(colors, 1);
    return std::max(spacing, std::sqrt(area / (0.4 * perColour)));
}

glm::dvec2 paperRadii(double spacing, int layer) {
    double scale = power(LayerShrink, layer) * spacing;
    return {0.4 * scale, 0.6 * scale};
}

std::vector<glm::dvec2> poissonDisk(Pcg32& rng, double x0, double y0, double x1, double y1,
                                    double minDistance, std::size_t maxCount) {
    std::vector<glm::dvec2> points;
    if (!(x1 > x0) || !(y1 > y0) || !(minDistance > 0.0) || maxCount == 0) return points;
    // A cell of side d / sqrt(2) holds at most one point, so a point's rivals lie within two
    // cells of its own.
    const double cell = minDistance / std::sqrt(2.0);
    const int cols = static_cast<int>(std::ceil((x1 - x0) / cell)) + 1;
    const int rows = static_cast<int>(std::ceil((y1 - y0) / cell)) + 1;
    std::vector<int> grid(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows), -1);
    const double d2 = minDistance * minDistance;

    auto cellOf = [&](const glm::dvec2& p) {
        int cx = std::clamp(static_cast<int>((p.x - x0) / cell), 0, cols - 1);
        int cy = std::clamp(static_cast<int>((p.y - y0) / cell), 0, rows - 1);
        return glm::ivec2(cx, cy);
    };
    auto fits = [&](const glm::dvec2& p) {
        if (p.x < x0 || p.x > x1 || p.y < y0 || p.y > y1) return false;
        glm::ivec2 c = cellOf(p);
        for (int y = std::max(c.y - 2, 0); y <= std::min(c.y + 2, rows - 1); ++y)
            for (int x = std::max(c.x - 2, 0); x <= std::min(c.x + 2, cols - 1); ++x) {
                int index = grid[static_cast<std::size_t>(y) * cols + x];
                if (index < 0) continue;
                glm::dvec2 delta = points[static_cast<std::size_t>(index)] - p;
                if (delta.x * delta.x + delta.y * delta.y < d2) return false;
            }
        return true;
    };
    std::vector<int> active;
    auto add = [&](const glm::dvec2& p) {
        glm::ivec2 c = cellOf(p);
        grid[static_cast<std::size_t>(c.y) * cols + c.x] = static_cast<int>(points.size());
        active.push_back(static_cast<int>(points.size()));
        points.push_back(p);
    };

    add({hundredth(rng.uniform(x0, x1)), hundredth(rng.uniform(y0, y1))});
    while (!active.empty() && points.size() < maxCount) {
        std::size_t pick = rng.below(static_cast<std::uint32_t>(active.size()));
        const glm::dvec2 from = points[static_cast<std::size_t>(active[pick])];
        bool placed = false;
        for (int attempt = 0; attempt < 30 && !placed; ++attempt) {
            // Uniform in the annulus [d, 2d] by rejection from its square: no trigonometry.
            glm::dvec2 step;
            double len2 = 0.0;
            do {
                step = {rng.uniform(-2.0, 2.0) * minDistance, rng.uniform(-2.0, 2.0) * minDistance};
                len2 = step.x * step.x + step.y * step.y;
            } while (len2 < d2 || len2 >= 4.0 * d2);
            glm::dvec2 candidate{hundredth(from.x + step.x), hundredth(from.y + step.y)};
            if (fits(candidate)) {
                add(candidate);
                placed = true;
            }
        }
        if (!placed) {
            active[pick] = active.back();
            active.pop_back();
        }
    }
    return points;
}

std::vector<Color> paperPalette(Pcg32& rng, int count, bool pastel, Color* background) {
    Color bath = pastel
                     ? colorFromHsl(rng.uniform(20.0, 60.0), rng.uniform(0.2, 0.5), rng.uniform(0.95, 0.975))
                     : colorFromHsl(rng.uniform(35.0, 50.0), rng.uniform(0.3, 0.5), rng.uniform(0.88, 0.93));
    // Pale inks sit closer to the bath and to each other, so they are kept less far apart.
    const double minLumaGap = pastel ? 0.06 : 0.18;
    const double minInkDistance = pastel ? 40.0 : 70.0;
    std::vector<Color> inks;
    for (int i = 0; i < count; ++i) {
        Color ink;
        for (int attempt = 0; attempt < 12; ++attempt) {
            double hue = rng.uniform(0.0, 360.0);
            double saturation = pastel ? rng.uniform(0.35, 0.75) : rng.uniform(0.35, 0.9);
            double lightness = pastel ? rng.uniform(0.7, 0.84) : rng.uniform(0.22, 0.62);
            ink = colorFromHsl(hue, saturation, lightness);
            // Darker until it shows on the bath (a light yellow barely does).
            while (std::abs(lumaOf(ink) - lumaOf(bath)) < minLumaGap && lightness > 0.1) {
                lightness -= 0.04;
                ink = colorFromHsl(hue, saturation, lightness);
            }
            bool apart = true;
            for (Color other : inks)
                apart = apart && rgbDistance2(ink, other) >= minInkDistance * minInkDistance;
            if (apart) break;
        }
        inks.push_back(ink);
    }
    if (background) *background = bath;
    return inks;
}

namespace {

/// The post's recipe (docs/paper.md): the bath the palette's first colour; a layer of painted
/// circles (sprays, newest on top) for each other colour, radii shrinking by the golden ratio;
/// stretch passes along x or y whose teeth end at the borders, shifts shrinking and gaps
/// growing by the golden ratio; a bleed for the post's blur; a bath that wraps.
Genome postPaper(std::uint64_t seed, const PaperOptions& options) {
    const double w = options.width, h = options.height;
    const double spacing = paperPostSpacing(w, h, options.colors);

    Genome g;
    g.dimension = 2;
    g.size = {w, h, 1000.0};
    g.wrap = true;
    g.lattice = options.lattice;
    Pcg32 paletteRng(seed, PaperPaletteStream);
    Color unused;
    g.palette = paperPalette(paletteRng, options.colors, options.pastel, &unused);
    g.background = g.palette.front();

    Pcg32 dropRng(seed, PaperDropStream);
    const std::size_t perColour =
        (MaxEntries - MaxPaperPasses) / static_cast<std::size_t>(std::max(options.colors - 1, 1));
    for (int color = 1; color < options.colors; ++color) {
        glm::dvec2 radii = paperPostRadii(spacing, color);
        for (const glm::dvec2& p : poissonDisk(dropRng, 0.0, 0.0, w, h, spacing, perColour)) {
            Operation spray;
            spray.tool = Tool::Spray;
            spray.center = {p.x, p.y, 0.0};
            // A hundredth at least: the smallest colours of a tiny card round to nothing.
            spray.radius = std::max(0.01, hundredth(dropRng.uniform(radii.x, radii.y)));
            spray.color = color;
            g.initial.push_back(spray);
        }
    }

    // As in the classic recipe, along x the pass is at angle 0 from the top left corner (teeth
    // along y), along y at angle 90 from the top right corner (teeth along x from the right).
    Pcg32 passRng(seed, PaperPassStream);
    const glm::dvec2 shifts = paperPostFirstShift(spacing);
    const double firstShift = passRng.uniform(shifts.x, shifts.y);
    static constexpr double Powers[] = {0.5, 1.0, 2.0};
    for (int pass = 0; pass < options.passes; ++pass) {
        const bool alongX = passRng.chance(0.5);
        // Half-drop: an x-shift repeats every h / 2; brick: a y-shift every w / 2 (the lattice).
        const bool halved = alongX ? options.lattice == Lattice::HalfDrop : options.lattice == Lattice::Brick;
        const double extent = (alongX ? h : w) * (halved ? 0.5 : 1.0);
        Operation stretch;
        stretch.tool = Tool::Stretch;
        stretch.angle = alongX ? 0.0 : 90.0;
        stretch.center = alongX ? glm::dvec3(0.0) : glm::dvec3(w, 0.0, 0.0);
        const double direction = passRng.chance(0.5) ? 1.0 : -1.0;
        stretch.shift = hundredth(direction * firstShift / power(GoldenRatio, pass));
        stretch.power = Powers[passRng.below(3)];
        const glm::dvec2 gaps = paperPostToothGap(spacing, pass);
        // At most some 600 teeth, and at least one interval, whatever the sheet.
        const double gap = std::max(
            0.01, hundredth(std::clamp(passRng.uniform(gaps.x, gaps.y), extent / 600.0, 0.5 * extent)));
        stretch.teeth = teethAcross(passRng, extent, gap);
        g.operations.push_back(stretch);
    }
    g.bleed = hundredth(spacing / 25.0);

    g.meta.name = randomName(seed, g);
    g.meta.seed = seed;
    g.meta.generator = PaperPostGeneratorVersion;
    nlohmann::ordered_json paper = nlohmann::ordered_json::object();
    paper["recipe"] = "post";
    paper["size"] = {w, h};
    paper["unit"] = "mm";
    paper["colors"] = options.colors;
    paper["passes"] = options.passes;
    paper["pastel"] = options.pastel;
    if (options.lattice != Lattice::Straight) paper["repeat"] = std::string(latticeName(options.lattice));
    paper["spacing"] = spacing;
    g.meta.paper = paper;
    return g;
}

} // namespace

Genome paperGenome(std::uint64_t seed, const PaperOptions& options) {
    auto sizeOk = [](double v) { return std::isfinite(v) && v > 0.0 && v <= LargestSide; };
    if (!sizeOk(options.width) || !sizeOk(options.height))
        throw InputError("a paper's width and height must be between 0 and 100 m (got " +
                         std::to_string(options.width) + " x " + std::to_string(options.height) + " mm)");
    if (options.colors < 1 || options.colors > MaxPaperColors)
        throw InputError("a paper has 1 to " + std::to_string(MaxPaperColors) + " colours (got " +
                         std::to_string(options.colors) + ")");
    if (options.passes < 0 || options.passes > MaxPaperPasses)
        throw InputError("a paper has 0 to " + std::to_string(MaxPaperPasses) + " passes (got " +
                         std::to_string(options.passes) + ")");
    if (options.recipe == PaperRecipe::Post) {
        // A spray's nearest image is sought among three columns or rows (genome-format.md).
        if (options.lattice == Lattice::HalfDrop && options.height > 4.0 * options.width)
            throw InputError("a half-drop paper can be at most 4 times as tall as it is wide");
        if (options.lattice == Lattice::Brick && options.width > 4.0 * options.height)
            throw InputError("a brick paper can be at most 4 times as wide as it is tall");
        return postPaper(seed, options);
    }
    if (options.lattice != Lattice::Straight)
        throw InputError("only the post's recipe wraps, so only it makes a half-drop or brick repeat");
    const double w = options.width, h = options.height;
    const double spacing = paperSpacing(w, h, options.colors);

    Genome g;
    g.dimension = 2;
    g.size = {w, h, 1000.0};
    Pcg32 paletteRng(seed, PaperPaletteStream);
    g.palette = paperPalette(paletteRng, options.colors, options.pastel, &g.background);

    // Drops: one Poisson-disk layer a colour over the sheet and half a spacing round it, so
    // ink reaches the edges; each layer pushes the ones before it aside.
    Pcg32 dropRng(seed, PaperDropStream);
    const double margin = 0.5 * spacing;
    const std::size_t perColour = (MaxEntries - MaxPaperPasses) / static_cast<std::size_t>(options.colors);
    for (int layer = 0; layer < options.colors; ++layer) {
        glm::dvec2 radii = paperRadii(spacing, layer);
        for (const glm::dvec2& p :
             poissonDisk(dropRng, -margin, -margin, w + margin, h + margin, spacing, perColour)) {
            Operation drop;
            drop.tool = Tool::Drop;
            drop.center = {p.x, p.y, 0.0};
            drop.radius = hundredth(dropRng.uniform(radii.x, radii.y));
            drop.color = layer;
            g.initial.push_back(drop);
        }
    }

    // Stretch passes, each along x or y, in either direction, weaker than the one before.
    // Along x the pass is at angle 0 from the top left corner (N points down, teeth along y);
    // along y at angle 90 from the top right corner (N points left, teeth along x from the
    // right edge). The teeth reach past the sheet by every shift together, so points that an
    // earlier pass sees carried off the sheet by a later one are combed too.
    Pcg32 passRng(seed, PaperPassStream);
    const double firstShift = spacing * passRng.uniform(0.6, 1.2);
    double reach = margin;
    for (int pass = 0; pass < options.passes; ++pass)
        reach += firstShift * power(PassShrink, pass);
    for (int pass = 0; pass < options.passes; ++pass) {
        const bool alongX = passRng.chance(0.5);
        const double extent = alongX ? h : w;
        Operation stretch;
        stretch.tool = Tool::Stretch;
        stretch.angle = alongX ? 0.0 : 90.0;
        stretch.center = alongX ? glm::dvec3(0.0) : glm::dvec3(w, 0.0, 0.0);
        const double direction = passRng.chance(0.5) ? 1.0 : -1.0;
        stretch.shift = hundredth(direction * firstShift * power(PassShrink, pass));
        stretch.power = hundredth(passRng.uniform(0.25, 0.75));
        // At most some 600 teeth, whatever the sheet's proportions (the format allows 1,000).
        double gap =
            hundredth(std::max(spacing * passRng.uniform(0.35, 0.7), (extent + 2.0 * reach) / 600.0));
        stretch.teeth = teethBetween(passRng, -reach, extent + reach, gap);
        g.operations.push_back(stretch);
    }
    g.bleed = hundredth(spacing / 80.0);

    g.meta.name = randomName(seed, g);
    g.meta.seed = seed;
    g.meta.generator = PaperGeneratorVersion;
    nlohmann::ordered_json paper = nlohmann::ordered_json::object();
    paper["size"] = {w, h};
    paper["unit"] = "mm";
    paper["colors"] = options.colors;
    paper["passes"] = options.passes;
    paper["pastel"] = options.pastel;
    paper["spacing"] = spacing;
    g.meta.paper = paper;
    return g;
}

} // namespace marbler
