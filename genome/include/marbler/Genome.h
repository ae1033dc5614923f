#pragma once
/// The genome: the whole recipe of one marbling design (genome-format.md, versions 1 to 3).
///
/// A genome is plain data. Its tools are kept with the parameters exactly as the file gives them
/// (angles in degrees, vectors as written but normalised by the loader); `Tools.h` turns them into
/// the forward and inverse maps.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "marbler/Color.h"
#include "marbler/Meta.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace marbler {

/// Every tool of the format, in the order of the registry (Params.h), which a static_assert holds.
enum class Tool : std::uint8_t {
    Drop,
    Spray,
    Cylinder,
    Line,
    Comb,
    Wave,
    Circle,
    Sphere,
    Vortex,
    Stretch,
    Flow,
    Stylus
};
inline constexpr int ToolCount = 12;

/// The two shapes of a 3D wave.
enum class WaveShape : std::uint8_t { Eggcrate, Ripple };

/// The two velocity fields of `flow` (version 2).
enum class FlowField : std::uint8_t { Cells, Cavity };

/// One entry of `initial` or `operations`. Which fields matter depends on the tool and the
/// dimension (see the parameter tables); the others keep their defaults and are not saved.
struct Operation {
    Tool tool = Tool::Drop;
    glm::dvec3 center{0.0};              ///< `center` or `origin`
    glm::dvec3 axis{0.0, 0.0, 1.0};      ///< 3D `axis` of cylinder, circle, sphere, vortex (unit)
    glm::dvec3 direction{1.0, 0.0, 0.0}; ///< 3D `direction` of line, comb, wave (unit)
    glm::dvec3 normal{0.0, 1.0, 0.0};    ///< 3D `normal`, unit and orthogonal to `direction`
    double angle = 0.0;                  ///< 2D direction, degrees, clockwise on screen
    double radius = 1.0;
    double alpha = 0.0;        ///< largest shift
    double lambda = 1.0;       ///< sharpness
    double spacing = 1.0;      ///< distance between the tines of a comb
    glm::dvec2 amplitude{0.0}; ///< wave; 2D and ripple use [0]
    glm::dvec2 wavelength{1.0};
    glm::dvec2 phase{0.0}; ///< degrees
    WaveShape shape = WaveShape::Eggcrate;
    int color = 0; ///< palette index of an ink-laying tool
    // Version 2.
    double core = 0.0;                  ///< circle, sphere, vortex: finite centre c >= 0
    std::vector<double> teeth;          ///< stretch: tooth positions along N, increasing
    double shift = 0.0;                 ///< stretch: largest shift (its sign the direction)
    double power = 1.0;                 ///< stretch: tooth profile |sin|^p
    FlowField field = FlowField::Cells; ///< flow: which velocity field
    glm::dvec2 extent{1.0, 1.0};        ///< flow: `size` [Lx, Ly] of a cell or the cavity
    double speed = 0.0;                 ///< flow: U
    double time = 1.0;                  ///< flow: T > 0
    int steps = 1;                      ///< flow, stylus: implicit midpoint steps n
    // Version 3.
    std::vector<glm::dvec2> path; ///< stylus: the polyline the stylus is drawn along
    std::vector<double> pressure; ///< stylus: one value in [0, 1] per path point; empty: all 1
    double reach = 1.0;           ///< stylus: how far ahead of and behind the stylus the bath moves
    int tines = 1;                ///< stylus: 1 a stylus, more a rake (with `spacing`)

    friend bool operator==(const Operation&, const Operation&) = default;
};

/// A raster start of a 2D design: a file path (relative to the genome file) or a data URL.
struct SourceImage {
    std::string image;
    friend bool operator==(const SourceImage&, const SourceImage&) = default;
};

/// The lattice a wrapping bath repeats on (docs/genome-format.md, "Wrapping bath"), for a design
/// of size w x h: straight (w, 0), (0, h); half-drop (w, h / 2), (0, h), each column dropped half
/// a tile below the one to its left; brick (w, 0), (w / 2, h), each row moved half a tile right.
enum class Lattice { Straight, HalfDrop, Brick };

/// A whole design.
struct Genome {
    int dimension = 2;
    glm::dvec3 size{1000.0, 1000.0, 1000.0}; ///< design space; z unused in 2D
    Color background{0xf3, 0xec, 0xdc};
    std::vector<Color> palette;
    std::vector<Operation> initial;    ///< drops, sprays and (3D) cylinders, applied first
    std::vector<Operation> operations; ///< strokes applied after `initial`
    std::optional<SourceImage> source;
    double bleed = 0.0; ///< version 2: soft ink edges, width in design units
    /// Version 3 (Marbler's addition, docs/genome-format.md "Wrapping bath"): the bath is a
    /// torus of the design's size, so the design repeats without a seam.
    bool wrap = false;
    /// The lattice of the wrap (`"wrap": "half-drop"` or `"brick"`); Straight where `wrap` is
    /// false.
    Lattice lattice = Lattice::Straight;
    Meta meta; ///< name, lineage and notes (Meta.h); not part of the design

    /// The folder relative paths of `source` are resolved against (the genome file's folder);
    /// not part of the design and not saved.
    std::string baseDirectory;
    /// The file the genome was read from, as given (for messages); empty when made in memory.
    /// Not part of the design and not saved.
    std::string fileName;
    /// Whether `source` may name an image outside baseDirectory (SourcePath.h): set only by
    /// whoever asked the user (`--allow-external-source`, the window's question). Not part of
    /// the design and not saved.
    bool allowExternalSource = false;

    friend bool operator==(const Genome& a, const Genome& b) {
        return a.dimension == b.dimension && a.size == b.size && a.background == b.background &&
               a.palette == b.palette && a.initial == b.initial && a.operations == b.operations &&
               a.source == b.source && a.bleed == b.bleed && a.wrap == b.wrap && a.lattice == b.lattice &&
               a.meta == b.meta;
    }
};

/// Format limits (genome-format.md, Validation).
inline constexpr std::size_t MaxEntries = 10000;
inline constexpr std::size_t MaxFileBytes = 16u * 1024u * 1024u;
inline constexpr std::size_t MaxPaletteSize = 16;
/// The newest format version this Marbler reads and writes.
inline constexpr int FormatVersion = 3;
/// The largest number of teeth of a `stretch` and of steps of a `flow` (genome-format.md, version 2).
inline constexpr std::size_t MaxTeeth = 1000;
inline constexpr int MaxFlowSteps = 10000;
/// A stylus's limits (genome-format.md, version 3): path points, tines and integration steps.
inline constexpr std::size_t MaxPathPoints = 1000;
inline constexpr int MaxTines = 64;
inline constexpr int MaxStylusSteps = 100000;

} // namespace marbler
