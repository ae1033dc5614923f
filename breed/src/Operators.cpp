#include "marbler/Operators.h"

#include "marbler/ChangeSummary.h"
#include "marbler/Error.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "marbler/Tools.h"
#include "marbler/Workers.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace marbler {
namespace {

constexpr std::array<std::string_view, 4> OperatorNames{"alter", "recombine", "swap", "reinit"};

/// Child i's own random stream (Random.h childRng), apart from the colourways'.
Pcg32 bredChildRng(std::uint64_t seed, int index) {
    return childRng(seed, index, 0, 0x6272656564000000ULL);
}

double largestSide(const Genome& g) {
    return std::max({g.size.x, g.size.y, g.dimension == 3 ? g.size.z : 0.0});
}

/// Reflects a value back into [lo, hi] (a mutation near an edge bounces instead of piling up).
double reflectInto(double v, double lo, double hi) {
    if (!(hi > lo)) return v;
    double span = hi - lo;
    double t = std::fmod(v - lo, 2.0 * span);
    if (t < 0.0) t += 2.0 * span;
    return lo + (t <= span ? t : 2.0 * span - t);
}

/// Brings a mutated value back into the table's range: a bound reflects it (as at the design's
/// edges), and an open bound keeps it `margin` clear of the bound. Values the range accepts are
/// returned unchanged.
double keepInRange(const ParamRange& range, double v, double margin) {
    const bool hasMin = std::isfinite(range.min), hasMax = std::isfinite(range.max);
    if (hasMin && hasMax) {
        v = reflectInto(v, range.min, range.max);
    } else if (hasMin) {
        v = range.min + std::abs(v - range.min);
    } else if (hasMax) {
        v = range.max - std::abs(range.max - v);
    }
    if (range.minOpen) {
        double floor = range.min + margin;
        if (hasMax && !(floor < range.max)) floor = 0.5 * (range.min + range.max);
        v = std::max(v, floor);
    }
    return v;
}

/// Moves a stylus's path as a hand would draw it again: the whole stroke shifted by about
/// `scale` design units, each point a quarter of that on its own, and now and then (more at a
/// higher strength) smoothed, each inner point drawn towards its neighbours. Consecutive points
/// stay different (a point that lands on the one before it is dropped, with its pressure).
void alterPath(Operation& op, double scale, double strength, Pcg32& rng) {
    const glm::dvec2 shift(rng.normal() * scale, rng.normal() * scale);
    for (glm::dvec2& p : op.path)
        p += shift + glm::dvec2(rng.normal(), rng.normal()) * (0.25 * scale);
    if (op.path.size() > 2 && rng.chance(0.5 * strength)) {
        std::vector<glm::dvec2> smoothed = op.path;
        for (std::size_t i = 1; i + 1 < op.path.size(); ++i)
            smoothed[i] = 0.25 * op.path[i - 1] + 0.5 * op.path[i] + 0.25 * op.path[i + 1];
        op.path = std::move(smoothed);
    }
    for (std::size_t i = 1; i < op.path.size();) {
        if (op.path[i] != op.path[i - 1]) {
            ++i;
            continue;
        }
        op.path.erase(op.path.begin() + static_cast<std::ptrdiff_t>(i));
        if (i < op.pressure.size()) op.pressure.erase(op.pressure.begin() + static_cast<std::ptrdiff_t>(i));
    }
}

/// Perturbs every numeric parameter of one entry by its table's mutation scale. The tool,
/// the 3D wave's shape, a flow's field and ink colours stay: they are the "sequence of tools",
/// not its parameters. An optional version-2 parameter at its default (a swirl's core of 0)
/// stays there too: alteration varies a design and adds no feature to it, so a version-1
/// design's children stay version 1 (and draw exactly what they drew before version 2).
///
/// `relative` (a family's design altered gently): lengths, shifts and sizes move by a factor
/// of their own value, teeth by a share of their mean gap, so a fine comb stays fine.
void perturb(Operation& op, const Genome& g, double strength, Pcg32& rng, bool relative = false) {
    const double side = largestSide(g);
    const auto factor = [&] {
        return 1.0 + std::clamp(rng.normal() * FamilyRelativeScale * strength, -0.5, 1.0);
    };
    const double floorLength = 1e-3 * side; // lengths stay clearly > 0
    constexpr double AngleMargin = 1e-3;    // degrees, for an angle whose range is open
    const glm::dvec3 before = op.direction, beforeNormal = op.normal;
    const Operation original = op;
    bool hasFrame = false;
    for (const ParamSpec& spec : toolSpec(op.tool).params(g.dimension)) {
        if (spec.optional && !usesVersion2(spec, op)) continue;
        const int n = componentCount(spec, op, g.dimension);
        switch (spec.kind) {
        case ParamKind::Position:
            for (int i = 0; i < n; ++i) {
                double v = getComponent(spec, op, i);
                double moved = v + rng.normal() * spec.mutationScale * strength * side;
                // Centres inside the design stay inside; ones a user put outside roam freely.
                if (v >= 0.0 && v <= g.size[i]) moved = reflectInto(moved, 0.0, g.size[i]);
                setComponent(spec, op, i, keepInRange(spec.range, moved, floorLength));
            }
            break;
        case ParamKind::Direction: {
            glm::dvec3 v(0.0);
            for (int i = 0; i < n; ++i)
                v[i] = getComponent(spec, op, i);
            glm::dvec3 moved = v;
            for (int i = 0; i < n; ++i)
                moved[i] += rng.normal() * spec.mutationScale * strength;
            double len = glm::length(moved);
            if (len > 1e-6 && std::isfinite(len))
                moved /= len;
            else
                moved = v; // a degenerate draw keeps the old direction
            for (int i = 0; i < n; ++i)
                setComponent(spec, op, i, moved[i]);
            if (spec.field == ParamField::Direction || spec.field == ParamField::Normal) hasFrame = true;
            break;
        }
        case ParamKind::Angle:
        case ParamKind::Phase:
            for (int i = 0; i < n; ++i) {
                double v = getComponent(spec, op, i) + rng.normal() * spec.mutationScale * strength;
                // Keep angles in a readable range; only whole turns are removed, so nothing moves.
                if (std::abs(v) > 360.0) v = std::fmod(v, 360.0);
                setComponent(spec, op, i, keepInRange(spec.range, v, AngleMargin));
            }
            break;
        case ParamKind::Length:
        case ParamKind::Shift:
        case ParamKind::Extent:
            for (int i = 0; i < n; ++i) {
                double v = relative ? getComponent(spec, op, i) * factor()
                                    : getComponent(spec, op, i) +
                                          rng.normal() * spec.mutationScale * strength * side;
                // Lengths that must be > 0 stay clearly so.
                setComponent(spec, op, i, keepInRange(spec.range, v, floorLength));
            }
            break;
        case ParamKind::Number:
            for (int i = 0; i < n; ++i) {
                double v = getComponent(spec, op, i) + rng.normal() * spec.mutationScale * strength;
                setComponent(spec, op, i, keepInRange(spec.range, v, 0.05 * spec.mutationScale));
            }
            break;
        case ParamKind::Teeth: {
            // Each tooth moves; then they are put back in order, at least a hair apart (and at
            // least one representable step where a hair is lost in rounding, far out).
            double scale = spec.mutationScale * strength * side;
            if (relative && op.teeth.size() > 1)
                scale = FamilyRelativeScale * strength * (op.teeth.back() - op.teeth.front()) /
                        static_cast<double>(op.teeth.size() - 1);
            for (int i = 0; i < n; ++i)
                setComponent(spec, op, i, getComponent(spec, op, i) + rng.normal() * scale);
            std::sort(op.teeth.begin(), op.teeth.end());
            for (std::size_t i = 1; i < op.teeth.size(); ++i) {
                const double before = op.teeth[i - 1];
                op.teeth[i] = std::max({op.teeth[i], before + floorLength,
                                        std::nextafter(before, std::numeric_limits<double>::infinity())});
            }
            break;
        }
        case ParamKind::Path:
            alterPath(op, spec.mutationScale * strength * side * (relative ? 0.5 : 1.0), strength, rng);
            break;
        case ParamKind::Pressure:
            // A pen's pressure (only where the stroke has one: one at the default stays so).
            for (double& p : op.pressure)
                p = reflectInto(p + rng.normal() * 0.1 * strength, 0.0, 1.0);
            break;
        case ParamKind::Count: // a flow's and a stylus's steps follow their other values, below
        case ParamKind::Color:
        case ParamKind::Choice:
            break;
        }
    }
    if (op.tool == Tool::Flow) {
        // Enough steps for the new speed, time and size; a draw that would need more than the
        // format allows keeps the old ones.
        if (minimumFlowSteps(op) > MaxFlowSteps) {
            op.speed = original.speed;
            op.time = original.time;
            op.extent = original.extent;
        }
        op.steps = std::max(op.steps, minimumFlowSteps(op));
    }
    if (op.tool == Tool::Stylus) {
        // Enough steps for the new pull, sharpness, reach and path; a draw that would need more
        // than the format allows keeps the old ones.
        if (op.path.size() < 2 || minimumStylusSteps(op) > MaxStylusSteps) {
            op.alpha = original.alpha;
            op.lambda = original.lambda;
            op.reach = original.reach;
            op.spacing = original.spacing;
            op.path = original.path;
            op.pressure = original.pressure;
        }
        // Re-timed now and then: more steps than the fewest (a finer integration of the same
        // stroke), drawn near the fewest so a render stays quick; else as many as before.
        const int least = minimumStylusSteps(op);
        if (rng.chance(0.5 * strength))
            op.steps = least + static_cast<int>(std::abs(rng.normal()) * 0.25 * strength * least);
        op.steps = std::clamp(op.steps, least, MaxStylusSteps);
    }
    if (hasFrame) {
        // Keep direction and normal a valid frame: the normal loses its part along the
        // direction; should they have become (nearly) parallel, the old frame stays.
        glm::dvec3 d = op.direction;
        glm::dvec3 nrm = op.normal - glm::dot(op.normal, d) * d;
        double len = glm::length(nrm);
        if (len > 1e-3 && std::isfinite(len)) {
            op.normal = nrm / len;
        } else {
            op.direction = before;
            op.normal = beforeNormal;
        }
    }
}

std::uint8_t nudgeChannel(std::uint8_t c, double sigma, Pcg32& rng) {
    return static_cast<std::uint8_t>(std::clamp(std::round(c + rng.normal() * sigma), 0.0, 255.0));
}

Color nudgeColor(Color c, double sigma, Pcg32& rng) {
    return {nudgeChannel(c.r, sigma, rng), nudgeChannel(c.g, sigma, rng), nudgeChannel(c.b, sigma, rng)};
}

/// Colour indices folded into a palette of `size` inks (clamped to its last ink).
void clampColors(std::vector<Operation>& ops, std::size_t size) {
    int last = static_cast<int>(size) - 1;
    for (Operation& op : ops)
        if (toolSpec(op.tool).laysInk) op.color = std::clamp(op.color, 0, std::max(0, last));
}

/// Keeps a child within the format's entry limit (only crossovers could exceed it).
void capEntries(Genome& g) {
    std::size_t room = MaxEntries > g.initial.size() ? MaxEntries - g.initial.size() : 0;
    if (g.operations.size() > room) g.operations.resize(room);
}

int generationOf(const Genome& g) {
    if (!g.meta.lineage || !g.meta.lineage->generation) return 0;
    return std::max(0, *g.meta.lineage->generation);
}

/// The home parent's name without an earlier child suffix " (gN #K)".
std::string rootName(const Genome& g) {
    std::string name = g.meta.name && !g.meta.name->empty() ? *g.meta.name : "Untitled";
    if (auto pos = name.rfind(" (g"); pos != std::string::npos && name.back() == ')') name.erase(pos);
    return name;
}

/// The n-th root of x >= 0 by bisection: basic operations only, so the same on every machine.
double rootOf(double x, int n) {
    double lo = 0.0, hi = std::max(1.0, x);
    for (int k = 0; k < 64; ++k) {
        const double mid = 0.5 * (lo + hi);
        double p = 1.0;
        for (int j = 0; j < n; ++j)
            p *= mid;
        (p < x ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

/// sRGB to CIE L*a*b* under D65.
std::array<double, 3> labOf(Color c) {
    const auto linear = [](std::uint8_t v) {
        const double x = v / 255.0;
        if (x <= 0.04045) return x / 12.92;
        const double t = (x + 0.055) / 1.055, t2 = t * t, t4 = t2 * t2, t12 = t4 * t4 * t4;
        return rootOf(t12, 5); // t^2.4
    };
    const double r = linear(c.r), g = linear(c.g), b = linear(c.b);
    const double x = (0.4124564 * r + 0.3575761 * g + 0.1804375 * b) / 0.95047;
    const double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
    const double z = (0.0193339 * r + 0.1191920 * g + 0.9503041 * b) / 1.08883;
    constexpr double Delta = 6.0 / 29.0;
    const auto f = [](double t) {
        return t > Delta * Delta * Delta ? rootOf(t, 3) : t / (3.0 * Delta * Delta) + 4.0 / 29.0;
    };
    const double fx = f(x), fy = f(y), fz = f(z);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

/// How a candidate child fares in the filter: acceptable, or how good a second best.
struct Verdict {
    bool dull = false;
    double nearest = std::numeric_limits<double>::infinity(); ///< smallest mean ΔE to the others
    bool passes() const { return !dull && nearest >= NearDuplicateDeltaE; }
    bool betterThan(const Verdict& o) const { return dull != o.dull ? !dull : nearest > o.nearest; }
};

} // namespace

Glimpse glimpseOf(const Genome& genome) {
    return glimpseOf(genome, GlimpseSide);
}

Glimpse glimpseOf(const Genome& genome, int side) {
    const int GlimpseSide = std::max(side, 1); // the glimpse's side for this call
    std::vector<std::array<double, 3>> inks;
    inks.reserve(genome.palette.size() + 1);
    inks.push_back(labOf(genome.background)); // index 0: no ink (the ground, or the source)
    for (Color c : genome.palette)
        inks.push_back(labOf(c));
    const std::vector<PreparedOp> ops = prepare(genome);
    const int Cells = GlimpseSide * GlimpseSide;
    std::vector<int> counts(inks.size(), 0);
    Glimpse glimpse;
    glimpse.lab.reserve(3 * Cells);
    const double z = genome.dimension == 3 ? 0.5 * genome.size.z : 0.0;
    for (int j = 0; j < GlimpseSide; ++j)
        for (int i = 0; i < GlimpseSide; ++i) {
            const glm::dvec3 p{(i + 0.5) / GlimpseSide * genome.size.x,
                               (j + 0.5) / GlimpseSide * genome.size.y, z};
            const int color = traceColor(ops, p);
            const auto index = static_cast<std::size_t>(
                color >= 0 && color < static_cast<int>(genome.palette.size()) ? color + 1 : 0);
            ++counts[index];
            glimpse.lab.insert(glimpse.lab.end(), inks[index].begin(), inks[index].end());
        }
    glimpse.dominantShare = static_cast<double>(*std::max_element(counts.begin(), counts.end())) / Cells;
    return glimpse;
}

double meanDeltaE(const Glimpse& a, const Glimpse& b) {
    const std::size_t n = std::min(a.lab.size(), b.lab.size()) / 3;
    if (n == 0) return 0.0;
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double dl = a.lab[3 * k] - b.lab[3 * k], da = a.lab[3 * k + 1] - b.lab[3 * k + 1],
                     db = a.lab[3 * k + 2] - b.lab[3 * k + 2];
        sum += std::sqrt(dl * dl + da * da + db * db);
    }
    return sum / static_cast<double>(n);
}

std::string_view operatorName(GeneticOperator op) {
    return OperatorNames[static_cast<std::size_t>(op)];
}

std::optional<GeneticOperator> parseOperator(std::string_view name) {
    for (std::size_t i = 0; i < OperatorNames.size(); ++i)
        if (OperatorNames[i] == name) return static_cast<GeneticOperator>(i);
    return std::nullopt;
}

int minParents(GeneticOperator op) {
    return op == GeneticOperator::Recombine || op == GeneticOperator::Swap ? 2 : 1;
}

int maxParents(GeneticOperator op) {
    switch (op) {
    case GeneticOperator::Recombine:
        return 0;
    case GeneticOperator::Swap:
        return 2;
    default:
        return 1;
    }
}

Locks locksOf(const Genome& genome) {
    Locks locks;
    if (!genome.meta.locks) return locks;
    const MetaLocks& kept = *genome.meta.locks;
    locks.palette = kept.palette.value_or(false);
    locks.initial = kept.initial.value_or(false);
    locks.operations = kept.operations.value_or(false);
    return locks;
}

void setLocks(Genome& genome, const Locks& locks) {
    if (locks == Locks{}) {
        genome.meta.erase(MetaKey::Locks);
        return;
    }
    genome.meta.locks = MetaLocks{locks.palette, locks.initial, locks.operations, {}};
}

int lineageGeneration(const Genome& genome) {
    return generationOf(genome);
}

Meta childMeta(const Genome& home, int generation, int number, MetaLineage lineage) {
    Meta meta = home.meta.keptByChild();
    meta.name = rootName(home) + " (g" + std::to_string(generation) + " #" + std::to_string(number) + ")";
    meta.lineage = std::move(lineage);
    return meta;
}

std::string genomeId(const Genome& genome) {
    nlohmann::ordered_json json = toJson(genome);
    json.erase("meta");
    std::string text = json.dump();
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (unsigned char ch : text) {
        hash ^= ch;
        hash *= 0x100000001b3ULL;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

Genome alterGenome(const Genome& parent, double strength, Pcg32& rng) {
    Genome child = parent;
    if (strength == 0.0) return child; // exactly the parent, not a renormalised copy
    Locks locks = locksOf(parent);
    const bool relative = strength < FamilyKeepStrength && child.meta.has(MetaKey::Family);
    if (!locks.operations && !child.operations.empty()) {
        for (Operation& op : child.operations)
            perturb(op, child, strength, rng, relative);
        return child;
    }
    // The strokes are locked, or there are none (a bath of drops): vary what is free instead,
    // more gently, so the operator still offers a choice.
    if (!locks.initial)
        for (Operation& op : child.initial)
            perturb(op, child, 0.5 * strength, rng, relative);
    if (!locks.palette) {
        for (Color& c : child.palette)
            c = nudgeColor(c, 24.0 * strength, rng);
        child.background = nudgeColor(child.background, 8.0 * strength, rng);
    }
    return child;
}

Genome alterPart(const Genome& parent, DesignPart part, double strength, Pcg32& rng) {
    Genome child = parent;
    const Locks locks = locksOf(parent);
    const bool relative = strength < FamilyKeepStrength && child.meta.has(MetaKey::Family);
    // Indices of a random subset of `count` entries, each in with probability `p`, never empty.
    const auto subset = [&](std::size_t count, double p) {
        std::vector<std::size_t> chosen;
        for (std::size_t i = 0; i < count; ++i)
            if (rng.chance(p)) chosen.push_back(i);
        if (chosen.empty() && count > 0) chosen.push_back(rng.below(static_cast<std::uint32_t>(count)));
        return chosen;
    };
    switch (part) {
    case DesignPart::Palette:
        if (locks.palette || child.palette.empty()) break;
        {
            const std::size_t one = rng.below(static_cast<std::uint32_t>(child.palette.size()));
            for (std::size_t i = 0; i < child.palette.size(); ++i)
                if (i == one || rng.chance(0.25))
                    child.palette[i] = nudgeColor(child.palette[i], 90.0 * strength, rng);
            if (rng.chance(0.25)) child.background = nudgeColor(child.background, 45.0 * strength, rng);
        }
        break;
    case DesignPart::Initial:
        if (locks.initial) break;
        for (std::size_t i : subset(child.initial.size(), 0.3))
            perturb(child.initial[i], child, strength, rng, relative);
        break;
    case DesignPart::Strokes:
        if (locks.operations) break;
        {
            const double n = static_cast<double>(child.operations.size());
            for (std::size_t i : subset(child.operations.size(), n > 0.0 ? 1.0 / std::sqrt(n) : 0.0))
                perturb(child.operations[i], child, strength, rng, relative);
        }
        break;
    }
    return child;
}

/// One crossover of the parents' stroke lists, the home parent's first.
static std::vector<Operation> crossover(const std::vector<Genome>& parents, std::size_t home, Pcg32& rng);

Genome recombineGenomes(const std::vector<Genome>& parents, std::size_t home, Pcg32& rng) {
    if (parents.size() < 2 || home >= parents.size()) throw InputError("recombine needs two or more parents");
    Genome child = parents[home];
    if (locksOf(parents[home]).operations) return child;
    const std::vector<Operation>& mine = parents[home].operations;
    bool othersDiffer = false;
    for (const Genome& parent : parents)
        othersDiffer = othersDiffer || parent.operations != mine;
    // A child whose strokes all come from its home parent is a copy of it, which wastes a cell
    // of the population; draw again a few times while another parent has different strokes.
    std::vector<Operation> ops = crossover(parents, home, rng);
    for (int attempt = 0; othersDiffer && ops == mine && attempt < 16; ++attempt)
        ops = crossover(parents, home, rng);
    clampColors(ops, child.palette.size());
    child.operations = std::move(ops);
    capEntries(child);
    return child;
}

static std::vector<Operation> crossover(const std::vector<Genome>& parents, std::size_t home, Pcg32& rng) {
    std::vector<Operation> ops;
    const std::vector<Operation>& mine = parents[home].operations;
    if (parents.size() == 2 && rng.chance(0.5)) {
        // One-point crossover: a head of the home parent's strokes, the tail of the other's.
        const std::vector<Operation>& theirs = parents[1 - home].operations;
        std::size_t a = mine.empty() ? 0 : 1 + rng.below(static_cast<std::uint32_t>(mine.size()));
        std::size_t b = theirs.empty() ? 0 : rng.below(static_cast<std::uint32_t>(theirs.size()));
        ops.assign(mine.begin(), mine.begin() + static_cast<std::ptrdiff_t>(a));
        ops.insert(ops.end(), theirs.begin() + static_cast<std::ptrdiff_t>(b), theirs.end());
    } else {
        // Uniform crossover: stroke k comes from any parent that has a k-th stroke; the child
        // is as long as one of the parents, chosen at random.
        std::size_t length = parents[rng.below(static_cast<std::uint32_t>(parents.size()))].operations.size();
        std::vector<std::size_t> holders;
        for (std::size_t k = 0; k < length; ++k) {
            holders.clear();
            for (std::size_t p = 0; p < parents.size(); ++p)
                if (parents[p].operations.size() > k) holders.push_back(p);
            ops.push_back(
                parents[holders[rng.below(static_cast<std::uint32_t>(holders.size()))]].operations[k]);
        }
    }
    return ops;
}

Genome swapGenomes(const Genome& home, const Genome& other) {
    Genome child = home;
    if (locksOf(home).operations) return child;
    child.operations = other.operations;
    clampColors(child.operations, child.palette.size());
    capEntries(child);
    return child;
}

Genome reinitGenome(const Genome& parent, Pcg32& rng) {
    Genome child = parent;
    Locks locks = locksOf(parent);
    if (!locks.initial) {
        child.initial =
            randomInitial(rng, child.dimension, child.size, static_cast<int>(child.palette.size()));
        capEntries(child);
    } else if (!locks.palette) {
        // The drops are locked: recolour them instead, with as many inks as before so every
        // colour index stays valid.
        std::vector<Color> fresh = randomPalette(rng, &child.background);
        for (std::size_t i = 0; i < child.palette.size(); ++i)
            child.palette[i] = fresh[i % fresh.size()];
    }
    return child;
}

/// A varied child's change: against the design it varies (a parent, or a sibling made before
/// it, named as the window and the verb number it: "#2"), not against its home parent, from
/// which it may differ in everything the repeated design already did.
static std::string describeVariation(const BreedRequest& request, const std::vector<Genome>& siblings,
                                     const Genome& repeated, const Genome& child) {
    const std::string id = genomeId(repeated);
    std::string of = "an earlier design";
    for (std::size_t p = 0; p < request.parents.size(); ++p)
        if (genomeId(request.parents[p]) == id) of = "parent " + std::to_string(p + 1);
    for (std::size_t k = 0; k < siblings.size(); ++k)
        if (genomeId(siblings[k]) == id)
            of = "#" + std::to_string(request.childNumbers.empty() ? static_cast<int>(k) + 1
                                                                   : request.childNumbers[k]);
    return "a variation of " + of + ": " + describeChange(repeated, child);
}

Genome wildcardChild(const BreedRequest& request, const Genome& replaced) {
    if (request.parents.empty()) throw InputError("a wildcard needs the parents it stands beside");
    const Family* family = parentsFamily(request.parents);
    const int dimension = request.parents.front().dimension;
    std::set<std::string> taken;
    for (const Genome& parent : request.parents)
        taken.insert(genomeId(parent));
    Genome g;
    std::uint64_t seed = 0;
    for (std::uint64_t draw = 0; draw < 16; ++draw) {
        seed = mixSeed(request.seed, 0x77696c64ULL + draw) & 0xffffffffULL;
        g = family ? familyGenome(*family, seed) : randomGenome(seed, dimension);
        if (!taken.count(genomeId(g))) break;
    }
    // The wildcard takes the replaced child's place in the lineage: its generation and number,
    // and an operator of its own so the tree and tooltips can say what it is.
    MetaLineage lineage;
    lineage.op = "wildcard";
    lineage.seed = seed;
    if (replaced.meta.lineage) {
        lineage.child = replaced.meta.lineage->child;
        lineage.generation = replaced.meta.lineage->generation;
    }
    g.meta.lineage = lineage;
    if (lineage.generation && lineage.child && g.meta.name)
        g.meta.name =
            *g.meta.name + " (g" + std::to_string(*lineage.generation) + " #" +
            std::to_string(request.childNumbers.empty() ? *lineage.child : request.childNumbers.back()) + ")";
    g.meta.id = genomeId(g);
    return g;
}

void keepWrapValid(Genome& child) {
    if (child.wrap && !canWrap(child)) {
        child.wrap = false;
        child.lattice = Lattice::Straight;
    }
}

void checkBreedRequest(const BreedRequest& request) {
    const GeneticOperator op = request.op;
    const auto parentCount = static_cast<int>(request.parents.size());
    const std::string name(operatorName(op));
    if (parentCount < minParents(op) || (maxParents(op) > 0 && parentCount > maxParents(op))) {
        std::string want =
            maxParents(op) == 0 ? std::to_string(minParents(op)) + " or more parents"
            : minParents(op) == maxParents(op)
                ? (minParents(op) == 1 ? std::string("one parent")
                                       : std::to_string(minParents(op)) + " parents")
                : std::to_string(minParents(op)) + " to " + std::to_string(maxParents(op)) + " parents";
        throw InputError(name + " takes " + want + " (got " + std::to_string(parentCount) + ")");
    }
    if (request.count < 1 || request.count > MaxChildren)
        throw InputError("count must be between 1 and " + std::to_string(MaxChildren) + " (got " +
                         std::to_string(request.count) + ")");
    if (!(request.strength >= 0.0 && request.strength <= 1.0))
        throw InputError("strength must be between 0 and 1 (got " + std::to_string(request.strength) + ")");
    for (int p = 0; p < parentCount; ++p) {
        validateGenome(request.parents[static_cast<std::size_t>(p)], "parent " + std::to_string(p + 1));
        if (request.parents[static_cast<std::size_t>(p)].dimension != request.parents[0].dimension)
            throw InputError("parent " + std::to_string(p + 1) + ": dimension " +
                             std::to_string(request.parents[static_cast<std::size_t>(p)].dimension) +
                             " differs from parent 1's " + std::to_string(request.parents[0].dimension));
    }

    if (request.generation && *request.generation < 1)
        throw InputError("generation must be 1 or more (got " + std::to_string(*request.generation) + ")");
    if (!request.childNumbers.empty() && static_cast<int>(request.childNumbers.size()) != request.count)
        throw InputError("childNumbers must hold one number per child");
}

/// Child i's draw by the request's operator from its stream (home: the parent it is told
/// against).
static Genome drawChild(const BreedRequest& request, int i, Pcg32& rng, std::size_t& home) {
    switch (request.op) {
    case GeneticOperator::Alter:
        return alterGenome(request.parents[0], request.strength, rng);
    case GeneticOperator::Recombine:
        home = static_cast<std::size_t>(i) % request.parents.size();
        return recombineGenomes(request.parents, home, rng);
    case GeneticOperator::Swap:
        home = static_cast<std::size_t>(i % 2);
        return swapGenomes(request.parents[home], request.parents[1 - home]);
    case GeneticOperator::Reinit:
        return reinitGenome(request.parents[0], rng);
    }
    return request.parents[0];
}

/// A child's first draw, made ahead on some core (breed()): the design with its wrap kept
/// valid, its id as drawn, its glimpse, and the stream and home parent as the draw left them.
/// (Named, not anonymous: the unity build puts this file beside the other breed sources.)
namespace breeddetail {
struct FirstDraw {
    Genome child;
    std::string id;
    Pcg32 rng{0};
    std::size_t home = 0;
    Glimpse look;
    bool ready = false;
};
} // namespace breeddetail

std::vector<Genome> breed(const BreedRequest& request) {
    checkBreedRequest(request);
    const GeneticOperator op = request.op;
    const std::string name(operatorName(op));

    std::vector<std::string> parentIds;
    // The designs already in the generation: no child may repeat one (the window keeps the
    // parents beside their children).
    std::set<std::string> taken;
    int generation = 0;
    for (const Genome& parent : request.parents) {
        parentIds.push_back(genomeId(parent));
        taken.insert(genomeId(parent));
        generation = std::max(generation, generationOf(parent));
    }
    generation = request.generation.value_or(generation + 1);

    // Swap has exactly two results and alter at strength 0 one: drawing again cannot help, so
    // they are neither drawn again nor filtered.
    const bool random = op == GeneticOperator::Recombine || op == GeneticOperator::Reinit ||
                        (op == GeneticOperator::Alter && request.strength > 0.0);
    const auto parentCount = request.parents.size();
    const auto count = static_cast<std::size_t>(request.count);
    // The glimpses the filter compares a child with: the parents', then each child's in turn.
    // They are most of a generation's work, and each child's first draw depends only on its own
    // stream: the parents' glimpses and every child's first draw with its glimpse are made on
    // every core up front. A first draw is used below only where it is what the child's turn
    // would draw (it repeats no design taken before it), so the children are the same as made
    // one at a time.
    std::vector<Glimpse> looks(random ? parentCount : 0);
    std::vector<breeddetail::FirstDraw> firstDraws(random ? count : 0);
    forEachOnCores(looks.size() + firstDraws.size(), [&](std::size_t k) {
        if (k < looks.size()) {
            looks[k] = glimpseOf(request.parents[k]);
            return;
        }
        breeddetail::FirstDraw& first = firstDraws[k - looks.size()];
        try {
            const int i = static_cast<int>(k - looks.size());
            first.rng = bredChildRng(request.seed, i);
            first.child = drawChild(request, i, first.rng, first.home);
            first.id = genomeId(first.child);
            keepWrapValid(first.child);
            first.look = glimpseOf(first.child);
            first.ready = true;
        } catch (...) {
            first.ready = false; // drawn again in the child's turn, which reports the failure
        }
    });
    double parentShare = 0.0;
    for (const Glimpse& look : looks)
        parentShare = std::max(parentShare, look.dominantShare);

    std::vector<Genome> children;
    children.reserve(count);
    for (int i = 0; i < request.count; ++i) {
        Pcg32 rng = bredChildRng(request.seed, i);
        std::size_t home = 0;
        const auto draw = [&] { return drawChild(request, i, rng, home); };
        // One draw, and what the operator does when it repeats a design already in the generation.
        // `variedFrom` keeps the repeated design, which a varied child's change is told against.
        const auto candidate = [&](std::optional<MetaVariation>& variation,
                                   std::optional<Genome>& variedFrom) {
            Genome child = draw();
            for (int attempt = 0; random && taken.count(genomeId(child)) && attempt < 16; ++attempt)
                child = draw();
            if (taken.count(genomeId(child))) {
                // A repeat wastes a cell: vary it gently instead (more on a further repeat). alterGenome
                // honours the home parent's locks, which the child carries in its meta.
                const Genome repeated = child;
                double strength = VariationStrength;
                for (int attempt = 0; attempt < 8; ++attempt) {
                    if (attempt > 0) strength = std::min(1.0, strength * 1.5);
                    child = alterGenome(repeated, strength, rng);
                    if (!taken.count(genomeId(child))) break;
                }
                if (genomeId(child) != genomeId(repeated)) {
                    variation = MetaVariation{genomeId(repeated), strength, {}};
                    variedFrom = repeated;
                }
            }
            keepWrapValid(child);
            return child;
        };
        std::optional<MetaVariation> variation;
        std::optional<Genome> variedFrom;
        std::optional<Glimpse> firstLook;
        Genome child;
        if (random && firstDraws[std::size_t(i)].ready && !taken.count(firstDraws[std::size_t(i)].id)) {
            breeddetail::FirstDraw& first = firstDraws[std::size_t(i)];
            rng = first.rng;
            home = first.home;
            child = std::move(first.child);
            firstLook = std::move(first.look);
        } else {
            child = candidate(variation, variedFrom);
        }
        int redraws = 0;
        if (random) {
            // The filter: a dull child or a near-duplicate of a parent or an earlier sibling is
            // drawn again (a fixed number of times; the best draw stays).
            const auto judge = [&](const Glimpse& look) {
                Verdict verdict;
                verdict.dull = look.dominantShare > DullShare && look.dominantShare > parentShare;
                for (const Glimpse& other : looks)
                    verdict.nearest = std::min(verdict.nearest, meanDeltaE(look, other));
                return verdict;
            };
            Glimpse look = firstLook ? std::move(*firstLook) : glimpseOf(child);
            Verdict verdict = judge(look);
            for (int attempt = 1; attempt <= ChildRedraws && !verdict.passes(); ++attempt) {
                std::optional<MetaVariation> againVariation;
                std::optional<Genome> againVariedFrom;
                Genome again = candidate(againVariation, againVariedFrom);
                Glimpse againLook = glimpseOf(again);
                Verdict againVerdict = judge(againLook);
                redraws = attempt;
                if (againVerdict.betterThan(verdict)) {
                    child = std::move(again);
                    variation = std::move(againVariation);
                    variedFrom = std::move(againVariedFrom);
                    look = std::move(againLook);
                    verdict = againVerdict;
                }
            }
            looks.push_back(std::move(look));
        }
        taken.insert(genomeId(child));

        const Genome& homeParent = request.parents[home];
        const int number =
            request.childNumbers.empty() ? i + 1 : request.childNumbers[static_cast<std::size_t>(i)];
        MetaLineage lineage;
        lineage.parents = parentIds;
        lineage.op = name;
        lineage.seed = request.seed;
        lineage.child = i + 1;
        if (op == GeneticOperator::Alter) lineage.strength = request.strength;
        lineage.variation = variation;
        if (redraws > 0) lineage.redraws = redraws;
        lineage.generation = generation;
        child.meta = childMeta(homeParent, generation, number, std::move(lineage));
        child.meta.id = genomeId(child);
        child.meta.lineage->change = variedFrom ? describeVariation(request, children, *variedFrom, child)
                                                : describeChange(request.parents, home, child);

        try {
            validateGenome(child, "child " + std::to_string(i + 1));
        } catch (const GenomeError& e) {
            // Valid parents must give valid children; anything else is a bug, not bad input.
            throw RuntimeFailure(std::string("bred an invalid genome: ") + e.what());
        }
        children.push_back(std::move(child));
    }
    return children;
}

} // namespace marbler
