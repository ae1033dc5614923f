#pragma once
/// The making of a design (genome-format.md, "The making of a design"): the design after its
/// first K steps, and the design part way through a step, for `marbler render --steps` and the
/// frames of `marbler animate`. Every result is a genome that renders and saves like any other.

#include "marbler/Genome.h"

#include <cstddef>
#include <optional>

namespace marbler {

/// A design's steps: the entries of `initial`, then those of `operations`.
std::size_t stepCount(const Genome& genome);

/// The design after its first `steps` steps (0: the bare bath or source). Throws InputError when
/// `steps` exceeds stepCount.
Genome designAfterSteps(const Genome& genome, std::size_t steps);

/// Step `op` of a design of `dimension` at progress `s` in [0, 1]: an ink's radius r sqrt(s) in 2D
/// and r cbrt(s) in 3D (its area or volume grows evenly), a stroke's alpha, a wave's amplitudes, a
/// stretch's shift and a flow's time s times theirs. nullopt at s = 0, where the step does
/// nothing (and an ink of radius 0 would be no valid genome).
std::optional<Operation> grownOperation(const Operation& op, int dimension, double s);

/// The design at growth `g` in [0, stepCount]: the first floor(g) steps whole and step floor(g)
/// at progress g - floor(g). Throws InputError when g is outside that range or not finite.
Genome designAtGrowth(const Genome& genome, double g);

/// The growth frame `frame` of an animation of `frames` frames shows over a design of `steps`
/// steps: steps * frame / (frames - 1) (a single frame shows the whole design).
double frameGrowth(std::size_t steps, int frame, int frames);

} // namespace marbler
