#pragma once
/// Repeat tiles for print and textiles (spec/cli.md, `marbler render --repeat mirror`).
///
/// A marbled design does not wrap unless its bath does (Marbler's `wrap`, docs/genome-format.md):
/// its drops are discs, and no other stroke of the format joins the left edge to the right. An
/// exact straight repeat is therefore impossible for most designs, but the design and its mirror
/// images, 2 x 2, wrap without a seam: each edge of the tile meets its own mirror
/// image, pixel for pixel.

#include "marbler/Sampling.h"

namespace marbler {

/// The mirror repeat of `image`, twice its width and height: the image at the top left, its
/// horizontal mirror at the top right, and the vertical mirrors of both below.
Image mirrorRepeat(const Image& image);

/// The straight repeat of `image`, twice its width and height: the image 2 x 2. A seamless tile
/// where the image is the render of a design whose bath wraps (genome-format.md, "Wrapping
/// bath"), whose edges meet each other exactly.
Image straightRepeat(const Image& image);

} // namespace marbler
