#pragma once
/// What the editor's canvas (EditorCanvas.h) shows: the last render that came back and the
/// part of the design it covers, apart from the render asked for since, which may cover
/// another part (the view moved) until it comes.

#include "marbler/Sampling.h"

#include <QImage>

#include <optional>

namespace marbler::ui {

struct CanvasImage {
    QImage image;                    ///< the last render that came back
    Region region;                   ///< the part of the design (or of its slice) it shows
    std::optional<Region> requested; ///< the region of the render asked for last
    bool final = false;              ///< the sharp, antialiased pass (not a coarse one)
};

} // namespace marbler::ui
