#include "marbler/Growth.h"

#include "marbler/Error.h"
#include "marbler/Params.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace marbler {
namespace {

/// How a step grows: the parameter scaled with progress, and whether it is an ink's radius
/// (scaled so the ink's area or volume grows evenly) or scaled in proportion.
struct GrowthRule {
    ParamField field;
    bool inkRadius;
    /// A stylus grows by travelling: at progress s it runs its first floor(s n) steps.
    bool travels = false;
};

/// A stylus that has run only its first `steps` integration steps: its path cut at arc length
/// steps h (h = L / n kept, so each step's time and the stylus's place are those of the whole
/// stroke), with its pressure interpolated at the cut.
Operation travelled(const Operation& op, int steps) {
    const double cut = pathLength(op) * steps / op.steps;
    Operation part = op;
    part.steps = steps;
    part.path.assign(1, op.path.front());
    if (!op.pressure.empty()) part.pressure.assign(1, op.pressure.front());
    double at = 0.0;
    for (std::size_t i = 1; i < op.path.size(); ++i) {
        const double len = glm::length(op.path[i] - op.path[i - 1]);
        if (at + len < cut) {
            part.path.push_back(op.path[i]);
            if (!op.pressure.empty()) part.pressure.push_back(op.pressure[i]);
            at += len;
            continue;
        }
        // The cut on a point keeps the point itself.
        const double f = std::clamp((cut - at) / len, 0.0, 1.0);
        part.path.push_back(f >= 1.0 ? op.path[i] : op.path[i - 1] + f * (op.path[i] - op.path[i - 1]));
        if (!op.pressure.empty())
            part.pressure.push_back(op.pressure[i - 1] + f * (op.pressure[i] - op.pressure[i - 1]));
        break;
    }
    return part;
}

/// Every tool says how it grows (no default: a new tool fails the build until it does).
GrowthRule growthRule(Tool tool) {
    switch (tool) {
    case Tool::Drop:
    case Tool::Spray:
    case Tool::Cylinder:
        return {ParamField::Radius, true};
    case Tool::Line:
    case Tool::Comb:
    case Tool::Circle:
    case Tool::Sphere:
    case Tool::Vortex:
        return {ParamField::Alpha, false};
    case Tool::Wave:
        return {ParamField::Amplitude, false};
    case Tool::Stretch:
        return {ParamField::Shift, false};
    case Tool::Flow:
        return {ParamField::Time, false};
    case Tool::Stylus:
        return {ParamField::Steps, false, true};
    }
    throw std::logic_error("growthRule: unknown tool");
}

} // namespace

std::size_t stepCount(const Genome& genome) {
    return genome.initial.size() + genome.operations.size();
}

Genome designAfterSteps(const Genome& genome, std::size_t steps) {
    const std::size_t count = stepCount(genome);
    if (steps > count)
        throw InputError("the design has " + std::to_string(count) + " steps, so it has no design after " +
                         std::to_string(steps));
    Genome design = genome;
    if (steps <= genome.initial.size()) {
        design.initial.resize(steps);
        design.operations.clear();
    } else {
        design.operations.resize(steps - genome.initial.size());
    }
    return design;
}

std::optional<Operation> grownOperation(const Operation& op, int dimension, double s) {
    if (!(s > 0.0)) return std::nullopt;
    if (s >= 1.0) return op;
    const GrowthRule rule = growthRule(op.tool);
    if (rule.travels) {
        const int steps = static_cast<int>(std::floor(s * op.steps));
        if (steps <= 0) return std::nullopt;
        return travelled(op, steps);
    }
    const double factor = !rule.inkRadius ? s : dimension == 3 ? std::cbrt(s) : std::sqrt(s);
    Operation grown = op;
    // The registry's row of the parameter knows its components (both amplitudes of an egg-crate).
    for (const ParamSpec& spec : toolSpec(op.tool).params(dimension)) {
        if (spec.field != rule.field) continue;
        for (int i = 0; i < componentCount(spec, grown, dimension); ++i)
            setComponent(spec, grown, i, getComponent(spec, grown, i) * factor);
    }
    return grown;
}

Genome designAtGrowth(const Genome& genome, double g) {
    const std::size_t count = stepCount(genome);
    if (!(g >= 0.0 && g <= static_cast<double>(count)))
        throw InputError("growth " + std::to_string(g) + " is outside 0 to the design's " +
                         std::to_string(count) + " steps");
    const double whole = std::floor(g);
    const auto steps = static_cast<std::size_t>(whole);
    Genome design = designAfterSteps(genome, steps);
    if (steps == count) return design;
    const bool inInitial = steps < genome.initial.size();
    const Operation& step =
        inInitial ? genome.initial[steps] : genome.operations[steps - genome.initial.size()];
    if (std::optional<Operation> grown = grownOperation(step, genome.dimension, g - whole))
        (inInitial ? design.initial : design.operations).push_back(*grown);
    return design;
}

double frameGrowth(std::size_t steps, int frame, int frames) {
    if (frames <= 1) return static_cast<double>(steps);
    return static_cast<double>(steps) * frame / (frames - 1);
}

} // namespace marbler
