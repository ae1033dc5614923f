#include "marbler/Colourways.h"

#include "marbler/ChangeSummary.h"
#include "marbler/Error.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Operators.h"

#include <algorithm>
#include <set>
#include <string>

namespace marbler {
namespace {

/// Colourway i's own random stream (Random.h childRng), apart from breeding's.
Pcg32 colourwayRng(std::uint64_t seed, int index) {
    return childRng(seed, index, 0x636f6c6f75ULL, 0x636f6c7761790000ULL);
}

/// `count` inks from a pool, each apart from the background (inks too close to it are left
/// out) and from the one before it, after a seeded shuffle; fewer when the pool runs out.
std::vector<Color> orderInks(std::vector<Color> pool, int count, Color background, Pcg32& rng) {
    std::erase_if(pool, [&](Color c) { return colorDistance2(c, background) < MinInkContrast2; });
    for (std::size_t i = pool.size(); i > 1; --i)
        std::swap(pool[i - 1], pool[rng.below(static_cast<std::uint32_t>(i))]);
    std::vector<Color> inks;
    while (!pool.empty() && static_cast<int>(inks.size()) < count) {
        auto next = pool.begin();
        if (!inks.empty()) {
            next = std::find_if(pool.begin(), pool.end(),
                                [&](Color c) { return colorDistance2(c, inks.back()) >= MinInkContrast2; });
            if (next == pool.end()) break;
        }
        inks.push_back(*next);
        pool.erase(next);
    }
    return inks;
}

/// More inks from a pool that is too small: its inks with their hues turned a step each time.
void widenPool(std::vector<Color>& pool, std::size_t wanted, Pcg32& rng) {
    if (pool.empty()) pool.push_back(colorFromHsl(rng.uniform(0.0, 360.0), 0.5, 0.4));
    const std::size_t base = pool.size();
    for (int turn = 1; pool.size() < wanted + 2; ++turn)
        for (std::size_t i = 0; i < base; ++i) {
            Hsl c = hslOf(pool[i]);
            pool.push_back(colorFromHsl(wrapHue(c.h + 47.0 * turn), c.s,
                                        std::clamp(c.l + (turn % 2 ? 0.15 : -0.15), 0.15, 0.8)));
        }
}

/// A palette of its own: of the tradition (one time in two) or a harmony (Generator.h).
std::vector<Color> freshPalette(int count, Color& background, Pcg32& rng) {
    std::vector<Color> pool;
    if (rng.chance(0.5)) {
        const auto traditions = traditionalPalettes();
        const TraditionalPalette& t = traditions[rng.below(static_cast<std::uint32_t>(traditions.size()))];
        background = t.paper;
        pool.assign(t.inks.begin(), t.inks.end());
    } else {
        pool = randomPalette(rng, &background);
    }
    widenPool(pool, static_cast<std::size_t>(count), rng);
    return orderInks(std::move(pool), count, background, rng);
}

/// A variation of a palette: every hue turned by one angle, values shifted, inks reordered.
std::vector<Color> variedPalette(const std::vector<Color>& palette, Color& background, double strength,
                                 Pcg32& rng) {
    const double turn = rng.uniform(-180.0, 180.0) * strength;
    const auto vary = [&](Color c, double value) {
        Hsl h = hslOf(c);
        return colorFromHsl(wrapHue(h.h + turn),
                            std::clamp(h.s + rng.uniform(-0.2, 0.2) * strength, 0.0, 1.0),
                            std::clamp(h.l + value, 0.05, 0.95));
    };
    background = vary(background, rng.uniform(-0.05, 0.05) * strength);
    std::vector<Color> inks;
    for (Color c : palette)
        inks.push_back(vary(c, rng.uniform(-0.2, 0.2) * strength));
    if (rng.chance(strength)) {
        for (std::size_t i = inks.size(); i > 1; --i)
            std::swap(inks[i - 1], inks[rng.below(static_cast<std::uint32_t>(i))]);
    }
    return inks;
}

/// The palette of last resort, which always has contrast: greys of two values alternating on
/// a light ground (the values are 89 levels apart on every channel, the ground 95 above).
std::vector<Color> plainPalette(int count, Color& background) {
    background = {0xeb, 0xeb, 0xeb};
    std::vector<Color> inks;
    for (int i = 0; i < count; ++i)
        inks.push_back(i % 2 ? Color{0x8c, 0x8c, 0x8c} : Color{0x33, 0x33, 0x33});
    return inks;
}

/// Draws palettes until one has `count` inks with contrast (32 tries), else the plain palette.
template <typename Draw> void givePalette(Genome& g, int count, Draw draw) {
    for (int attempt = 0; attempt < 32; ++attempt) {
        Color background = g.background;
        std::vector<Color> inks = draw(background);
        if (static_cast<int>(inks.size()) == count && paletteHasContrast(inks, background)) {
            g.palette = std::move(inks);
            g.background = background;
            return;
        }
    }
    g.palette = plainPalette(count, g.background);
}

} // namespace

bool paletteHasContrast(const std::vector<Color>& palette, Color background) {
    for (std::size_t i = 0; i < palette.size(); ++i) {
        if (colorDistance2(palette[i], background) < MinInkContrast2) return false;
        if (i > 0 && colorDistance2(palette[i], palette[i - 1]) < MinInkContrast2) return false;
    }
    return true;
}

bool sameStructure(const Genome& a, const Genome& b) {
    return a.dimension == b.dimension && a.size == b.size && a.initial == b.initial &&
           a.operations == b.operations && a.source == b.source && a.bleed == b.bleed &&
           a.palette.size() == b.palette.size();
}

Genome colourwayOf(const Genome& design, double strength, Pcg32& rng) {
    Genome g = design;
    const int count = static_cast<int>(design.palette.size());
    givePalette(g, count, [&](Color& background) {
        // Now and then (more often the stronger) a palette of its own, else a variation.
        if (rng.chance(strength * strength)) return freshPalette(count, background, rng);
        return variedPalette(design.palette, background, std::max(strength, 0.05), rng);
    });
    return g;
}

Genome mixedColourway(const std::vector<Genome>& parents, std::size_t home, Pcg32& rng) {
    Genome g = parents[home];
    const int count = static_cast<int>(g.palette.size());
    std::vector<Color> pool;
    for (const Genome& p : parents)
        for (Color c : p.palette)
            if (std::find(pool.begin(), pool.end(), c) == pool.end()) pool.push_back(c);
    givePalette(g, count, [&](Color& background) {
        background = parents[rng.below(static_cast<std::uint32_t>(parents.size()))].background;
        std::vector<Color> wider = pool;
        std::erase_if(wider, [&](Color c) { return colorDistance2(c, background) < MinInkContrast2; });
        if (wider.size() < static_cast<std::size_t>(count) + 2)
            widenPool(wider, static_cast<std::size_t>(count), rng);
        return orderInks(std::move(wider), count, background, rng);
    });
    return g;
}

std::vector<Genome> colourways(const ColourwayRequest& request) {
    if (request.parents.empty()) throw InputError("colourways need a design");
    if (request.count < 1 || request.count > MaxChildren)
        throw InputError("count must be between 1 and " + std::to_string(MaxChildren) + " (got " +
                         std::to_string(request.count) + ")");
    if (!(request.strength >= 0.0 && request.strength <= 1.0))
        throw InputError("strength must be between 0 and 1 (got " + std::to_string(request.strength) + ")");
    if (!request.childNumbers.empty() && static_cast<int>(request.childNumbers.size()) != request.count)
        throw InputError("childNumbers must hold one number per child");
    std::vector<std::string> parentIds;
    std::set<std::string> taken;
    int generation = 0;
    for (std::size_t p = 0; p < request.parents.size(); ++p) {
        const Genome& parent = request.parents[p];
        validateGenome(parent, "parent " + std::to_string(p + 1));
        if (locksOf(parent).palette)
            throw InputError("parent " + std::to_string(p + 1) +
                             ": its palette is locked; unlock it to make colourways");
        parentIds.push_back(genomeId(parent));
        taken.insert(genomeId(parent));
        generation = std::max(generation, lineageGeneration(parent));
    }
    generation = request.generation.value_or(generation + 1);

    std::vector<Genome> children;
    for (int i = 0; i < request.count; ++i) {
        Pcg32 rng = colourwayRng(request.seed, i);
        const std::size_t home = request.mix ? static_cast<std::size_t>(i) % request.parents.size() : 0;
        const auto draw = [&] {
            return request.mix ? mixedColourway(request.parents, home, rng)
                               : colourwayOf(request.parents[0], request.strength, rng);
        };
        Genome child = draw();
        for (int attempt = 0; taken.count(genomeId(child)) && attempt < 16; ++attempt)
            child = draw();
        // A mix that keeps repeating (parents with few inks): a variation of it instead.
        for (int attempt = 0; taken.count(genomeId(child)) && attempt < 16; ++attempt)
            child = colourwayOf(request.parents[home], 0.5, rng);
        taken.insert(genomeId(child));

        const Genome& homeParent = request.parents[home];
        const int number =
            request.childNumbers.empty() ? i + 1 : request.childNumbers[static_cast<std::size_t>(i)];
        MetaLineage lineage;
        lineage.parents = parentIds;
        lineage.op = ColourwayOperator;
        lineage.seed = request.seed;
        lineage.child = i + 1;
        if (!request.mix) lineage.strength = request.strength;
        lineage.generation = generation;
        child.meta = childMeta(homeParent, generation, number, std::move(lineage));
        // Named from its own inks, not the parent's ("Russet Current" in purple is "Purple Current").
        if (child.meta.name) {
            const std::string& bred = *child.meta.name;
            const std::size_t suffix = bred.rfind(" (g");
            child.meta.name = recolouredName(bred.substr(0, suffix), homeParent, child) + bred.substr(suffix);
        }
        // What changed, in words, as every bred child says (ChangeSummary.h): inks and ground only.
        child.meta.lineage->change = describeChange(homeParent, child);
        child.meta.id = genomeId(child);
        try {
            validateGenome(child, "colourway " + std::to_string(i + 1));
        } catch (const GenomeError& e) {
            throw RuntimeFailure(std::string("made an invalid colourway: ") + e.what());
        }
        children.push_back(std::move(child));
    }
    return children;
}

} // namespace marbler
