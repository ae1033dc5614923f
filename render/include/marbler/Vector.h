#pragma once
/// Vector output of a flat design (spec/cli.md, `marbler svg`): every ink region as a filled
/// polygon whose vertices lie on the true boundary.
///
/// Rendering a raster goes backward (ARCHITECTURE.md); a vector outline has to go forward. The
/// boundary of an ink is the circle its drop or spray laid (genome-format.md: the ink of a drop
/// is the open disc |P - C| < r right after the drop), and every later step is a homeomorphism,
/// so the ink's region in the finished design is the image of that disc under the later steps'
/// forward maps, bounded by the image of the circle. Points of the circle are mapped forward
/// exactly, and a point is inserted on the circle wherever two mapped neighbours are more than
/// the tolerance apart. Painting the regions in time order, later inks over earlier ones, gives
/// the colour rule: a pixel shows the newest ink whose mapped disc holds it. A drop laid inside
/// an older ink pushes that ink into a ring; its hole is exactly the newer drop's region, which
/// is painted over it, so filling the older outline whole is right.
///
/// Version 2's stretch and flow are homeomorphisms too and are traced forward like the others
/// (a flow costs its steps' fixed-point iterations per vertex: a few seconds for a design of
/// two flows at the default tolerance). A genome's `bleed` is drawn as hard edges: a soft edge
/// has no exact outline, and its coverage is 1/2 exactly on the hard boundary (e = 0), so the
/// hard outline is the middle of the soft edge and the limit of the design as the bleed goes
/// to 0. Filled paths with blurred edges would be an approximation of a different kind
/// (SVG filters blur in screen space, not along the deformed design), so they are not drawn;
/// VectorDesign::bleed says a design had one, so a caller can tell the user.

#include "marbler/Genome.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace marbler {

/// How finely boundaries are traced.
struct VectorOptions {
    /// Neighbouring vertices of an outline are at most this far apart (design units).
    double tolerance = 1.0;
    /// Simplification: a run of vertices is replaced by its chord where every one lies within
    /// `straightness` x tolerance of it and the chord is at most `straightChord` x tolerance
    /// long. With straightChord 1 (the default) the spacing guarantee holds after
    /// simplification too, and little is dropped (refinement leaves gaps of T/2 to T); larger
    /// values (`marbler svg --simplify`: 16) waive it where the outline is straight.
    double straightness = 0.01;
    double straightChord = 1.0;
    /// The most vertices traced for all outlines together (before simplification and before
    /// outlines outside the design are left out); more throws InputError (a larger tolerance is
    /// needed). 4 million vertices make an SVG of some 60 MB.
    std::size_t maxVertices = 4'000'000;
    /// How often a stretch of circle is halved at most. A gap that is still wider than the
    /// tolerance after this many halvings straddles a point where the forward maps tear the
    /// outline open (a boundary through the exact centre of a later drop, which the drop covers);
    /// such gaps are counted (VectorDesign::gapsAtDepthCap), not refined further.
    int maxDepth = 40;
};

/// The outline of one ink in the finished design.
struct InkOutline {
    std::size_t step = 0;           ///< the ink's step: an index into initial, then operations
    int color = 0;                  ///< palette index
    std::vector<glm::dvec2> points; ///< a closed polygon (the last point joins the first)
};

/// A flat design as outlines in stacking order.
struct VectorDesign {
    double width = 0.0, height = 0.0; ///< the design space
    Color background;
    std::vector<Color> palette;
    std::vector<InkOutline> outlines;  ///< oldest first: later outlines cover earlier ones
    std::size_t vertexCount = 0;       ///< of every outline together
    std::size_t droppedAsStraight = 0; ///< vertices removed by simplification
    std::size_t outlinesOutside = 0;   ///< inks pushed wholly out of the design space, left out
    std::size_t gapsAtDepthCap = 0;    ///< gaps wider than the tolerance at VectorOptions::maxDepth
    double bleed = 0.0;                ///< the genome's soft edges, drawn as their hard middles (see above)
};

/// Traces every ink of a flat genome, on every core. Throws InputError for a solid (3D) genome, for a genome
/// with a source image (its marbled pixels have no outlines; render it as a raster), for a
/// tolerance that is not a positive number and when more than VectorOptions::maxVertices
/// vertices would be needed.
VectorDesign traceDesign(const Genome& genome, const VectorOptions& options = {});

/// The printed size of an SVG: its width and height attributes in millimetres.
struct SvgPage {
    double widthMm = 0.0, heightMm = 0.0;
};

/// The page of a design whose design units are pixels at `dpi` (96, the CSS pixel, keeps the
/// size an SVG without units has).
SvgPage pageAtDpi(double width, double height, double dpi);

/// A length of the page as an SVG attribute: millimetres to the micrometre, "264.583mm".
std::string svgLength(double mm);

/// The design as an SVG document: the viewBox is the design space in design units, the
/// background a full rectangle, each outline a filled path (stacked: later outlines cover
/// earlier ones). Coordinates are written with `decimals` digits after the point. The width and
/// height are the page's in millimetres, or without units (design units) when there is none.
std::string toSvg(const VectorDesign& design, int decimals,
                  const std::optional<SvgPage>& page = std::nullopt);

/// Digits after the point that keep rounding below a hundredth of the tolerance (1 to 9).
int decimalsFor(double tolerance);

/// Writes what `marbler svg` writes by default, atomically: the layers a printer can use
/// (marbler/Separations.h: knockOut, toLayeredSvg) on the page of `dpi` (96: a design unit is a
/// CSS pixel). Throws RuntimeFailure for I/O failures.
void writeSvg(const VectorDesign& design, const std::filesystem::path& file, int decimals, double dpi = 96.0);

} // namespace marbler
