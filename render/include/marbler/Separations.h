#pragma once
/// Separations a printer can use (issue 29): each ink's *visible* region of a flat design, as
/// vectors (one Inkscape layer per ink in the default `marbler svg`) and as raster masks
/// (`marbler render --separations DIR`).
///
/// The vector outlines of marbler/Vector.h are painted oldest first, later inks over earlier
/// ones; a screen printer needs each ink knocked out instead: the part of its outline that no
/// later outline covers, inside the design's rectangle. The polygon boolean operations are
/// Debian's Clipper (libpolyclipping), on integer coordinates at the precision the SVG writes
/// (10^-decimals design units), so a layer is exact to the tolerance and the layers tile the
/// page without overlapping.

#include "marbler/CpuRenderer.h"
#include "marbler/Genome.h"
#include "marbler/Vector.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace marbler {

/// The visible region of one ink (or of the bare bath).
struct InkLayer {
    int color = -1; ///< palette index; -1 for the background (the bath no ink covers)
    /// Closed rings that do not cross each other; holes run the other way round from the rings
    /// around them, so the region is the same under the even-odd and the nonzero rule.
    std::vector<std::vector<glm::dvec2>> rings;
};

/// A flat design as disjoint layers: the background first, then one layer per palette ink in
/// palette order (an ink that shows nowhere has a layer without rings).
struct SeparatedDesign {
    double width = 0.0, height = 0.0; ///< the design space
    Color background;
    std::vector<Color> palette;
    std::vector<InkLayer> layers;
};

/// Knocks each ink out of the inks laid after it and clips every layer to the design's
/// rectangle [0, width] x [0, height]. Coordinates are rounded to 10^-decimals design units
/// (decimals 1 to 9, decimalsFor(tolerance)). Throws RuntimeFailure where the coordinates are
/// out of the clipper's range (beyond some 10^9 units at 9 decimals).
SeparatedDesign knockOut(const VectorDesign& design, int decimals);

/// The layer's name as Inkscape shows it: "Background #rrggbb" or "Ink N #rrggbb" (N from 1).
std::string layerLabel(const SeparatedDesign& design, const InkLayer& layer);

/// The separated design as an SVG document: the page in millimetres, the viewBox the design
/// space in design units, and one Inkscape layer (a group with inkscape:groupmode="layer", an
/// inkscape:label from layerLabel and an id "background" or "ink-N") per layer, each holding
/// one even-odd path filled with its colour.
std::string toLayeredSvg(const SeparatedDesign& design, const SvgPage& page, int decimals);

/// Raster separations: what each pixel of a render is made of, ink by ink, with the render's
/// own samples (its antialiasing pattern), so recombining them gives the render back.
struct RasterSeparations {
    int width = 0, height = 0;
    Color background;
    std::vector<Color> palette;
    /// One mask per layer (the background first, then each palette ink), width x height bytes
    /// row by row: round(255 x the weight of the pixel's samples that show it).
    std::vector<std::vector<std::uint8_t>> coverage;
    /// Per pixel, the palette index of the ink that covers the most of it (the background:
    /// index palette.size()); with no antialiasing, the one ink it shows.
    std::vector<std::uint8_t> indices;
};

/// Renders the separations of a flat design, or of a solid's slice, on the CPU (settings as
/// for CpuRenderer::render). A genome's `bleed` is drawn as its hard edges (as in the SVG).
/// Throws InputError for a genome with a source image (its pixels are no inks), for more than
/// 255 inks (an indexed PNG holds 256 colours) and for bad settings; Cancelled when cancelled.
RasterSeparations renderSeparations(const Genome& genome, const RenderSettings& settings,
                                    const RenderControl* control = nullptr);

/// How separations are written.
struct SeparationFileOptions {
    int maskBits = 8;          ///< 8: coverage; 1: on where at least half the pixel is the ink
    std::optional<double> dpi; ///< written into every file's resolution when set
};

/// The file names of separations: "background.png", "ink-N.png" (N from 1, palette order) and
/// "indexed.png", in that order.
std::vector<std::string> separationFileNames(std::size_t inks);

/// Writes the separations into `folder` (made if missing): a greyscale PNG mask per layer
/// (white where the ink is) and an indexed PNG whose palette is the inks in palette order, the
/// background last. All files appear together or none. Returns the files written. Throws
/// InputError for a mask depth other than 1 or 8 and where `folder` is a file, RuntimeFailure
/// for I/O failures.
std::vector<std::filesystem::path> writeSeparations(const RasterSeparations& separations,
                                                    const std::filesystem::path& folder,
                                                    const SeparationFileOptions& options = {});

} // namespace marbler
