#pragma once
/// Designs that marble a picture: a raster image is the bath (the genome's `source`) and
/// strokes carry its colours along, the way particles of a scanned image were once advected
/// through flow fields, but exact. Each design has a `flow` (a lattice of cells or one cavity)
/// and a few strokes of the craft (combs, waves, swirls); no ink is laid, so the picture is
/// all there is to see until breeding changes the initial state.

#include "marbler/Genome.h"

#include <cstdint>
#include <string>

namespace marbler {

/// A design that marbles `image` (a path relative to the design's folder, or a data: URI) of
/// `aspect` = width / height (> 0): 1000 design units across, the height to match, so the
/// picture is not distorted. The same seed gives the same design. meta.name is `name`.
Genome imageDesign(std::uint64_t seed, const std::string& image, double aspect, const std::string& name);

} // namespace marbler
