#pragma once
/// What a raster render samples (genome-format.md, Rendering a raster): the region, the 3D
/// slice, the antialiasing patterns and the linear-light average. Shared by the CPU renderer
/// and the GL back end so both sample the same points.

#include "marbler/Genome.h"
#include "marbler/Image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace marbler {

/// One antialiasing pattern: offsets in pixels from the pixel centre, and their weights
/// (summing to 1).
struct AaPattern {
    std::string name;
    std::vector<glm::dvec2> offsets;
    std::vector<double> weights;
};

/// The pattern of a name of the spec (`none`, `rgss`, `quincunx`, `grid2`..`grid8`,
/// `checker4`, `rooks8`). Throws InputError for any other name.
AaPattern aaPattern(std::string_view name);
/// Every pattern name, for --help and tests.
std::vector<std::string> aaPatternNames();

/// A rectangle of the design space (x0 < x1, y0 < y1 in the slice's own axes).
struct Region {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// A cross-section of a solid genome: axis 0 (x = value), 1 (y = value) or 2 (z = value), or,
/// with a `normal`, the plane turned to any orientation: the points p with p·normal = value
/// (`normal` a unit vector; `axis` then names the plane it is tilted from, whose orientation its
/// coordinates keep).
struct Slice {
    int axis = 2;
    double value = 0.0;
    std::optional<glm::dvec3> normal = std::nullopt; ///< a turned section's unit normal; none: across `axis`
};

/// "x", "y" or "z" for axis 0, 1 or 2 (any other axis: "z").
const char* axisName(int axis);

/// The axis a name gives (x, y or z, either case), or nothing for any other text.
std::optional<int> parseAxis(std::string_view name);

/// The text of `--slice`: AXIS=VALUE with AXIS x, y or z and VALUE a finite number (e.g. z=500).
/// Every verb that takes a slice parses it here. Throws InputError naming `--slice`.
Slice parseSlice(std::string_view text);

/// The plane a flat design or a slice of a solid shows, in the plane's own 2D coordinates:
/// u along its columns, v down its rows (x-y for z = c and for a flat design, x-z for y = c,
/// y-z for x = c). The one mapping between those coordinates and the design's 3D points, for
/// the renderers, the editor's canvas and gestures, the render service and the export dialog.
///
/// A turned plane (`turned`) has unit axes `uTurned`, `vTurned` orthogonal to its normal, taken
/// from the axis-aligned plane it is tilted from (so a plane turned a little looks as that one
/// does), and
/// plane coordinate (0, 0) at `origin`, placed so the extent covers the whole design box.
struct SlicePlane {
    int uAxis = 0;                     ///< the design axis along the plane's first coordinate
    int vAxis = 1;                     ///< the design axis along the plane's second coordinate
    int normalAxis = 2;                ///< the axis the plane lies across (a turned plane: tilted from)
    double value = 0.0;                ///< where it crosses that axis (a turned plane: p·normal)
    bool turned = false;               ///< the plane is not across an axis
    glm::dvec3 uTurned{1.0, 0.0, 0.0}; ///< a turned plane's first axis
    glm::dvec3 vTurned{0.0, 1.0, 0.0}; ///< a turned plane's second axis
    glm::dvec3 nTurned{0.0, 0.0, 1.0}; ///< a turned plane's unit normal
    glm::dvec3 origin{0.0};            ///< a turned plane's point at coordinates (0, 0)
    glm::dvec2 span{0.0};              ///< a turned plane's extent over the design box

    /// Unit vectors of the plane's coordinates and of its normal, in design space.
    glm::dvec3 u() const { return turned ? uTurned : unit(uAxis); }
    glm::dvec3 v() const { return turned ? vTurned : unit(vAxis); }
    glm::dvec3 normal() const { return turned ? nTurned : unit(normalAxis); }
    /// The plane's extent within a design box of `size`.
    glm::dvec2 extent(const glm::dvec3& size) const {
        return turned ? span : glm::dvec2{size[uAxis], size[vAxis]};
    }
    /// A design point's plane coordinates (its distance from the plane is dropped).
    glm::dvec2 toPlane(const glm::dvec3& p) const {
        if (turned) {
            const glm::dvec3 d = p - origin;
            return {d.x * uTurned.x + d.y * uTurned.y + d.z * uTurned.z,
                    d.x * vTurned.x + d.y * vTurned.y + d.z * vTurned.z};
        }
        return {p[uAxis], p[vAxis]};
    }
    /// The design point at plane coordinates q.
    glm::dvec3 fromPlane(const glm::dvec2& q) const {
        if (turned) return origin + q.x * uTurned + q.y * vTurned;
        glm::dvec3 p(0.0);
        p[uAxis] = q.x;
        p[vAxis] = q.y;
        p[normalAxis] = value;
        return p;
    }

private:
    static glm::dvec3 unit(int axis) {
        glm::dvec3 e(0.0);
        e[axis] = 1.0;
        return e;
    }
};

/// The plane across `axis` (clamped to 0..2) at `value` of a genome of `dimension`; a flat
/// design's plane is always x-y at 0.
SlicePlane slicePlane(int dimension, int axis, double value = 0.0);
/// The plane of `slice` (across its axis, or turned to its normal) in a design box of `size`, of
/// a genome of `dimension` (a flat design's: x-y at 0). A normal along an axis (either sense)
/// gives exactly the plane across that axis.
SlicePlane slicePlane(int dimension, const Slice& slice, const glm::dvec3& size);
/// The plane a render shows: its slice for a solid genome, else x-y at 0.
SlicePlane slicePlane(const Genome& genome, const std::optional<Slice>& slice);
/// The values p·normal takes over a design box of `size` (0 to size along an axis): the range
/// of a section's offset along `normal` (unit).
glm::dvec2 sliceOffsetRange(const glm::dvec3& normal, const glm::dvec3& size);
/// A direction typed by a user (a section's normal, a tool's axis): three finite numbers split by
/// commas, semicolons or spaces ("1, 0, 1"), not all 0. Returns the unit vector, or nothing with
/// `error` (when given) saying why and naming `what` and the text ("Normal \"0 0 0\": ...").
std::optional<glm::dvec3> parseDirection(std::string_view text, std::string_view what,
                                         std::string* error = nullptr);
/// The unit normal of `slice`: its own, else its axis.
glm::dvec3 sliceNormal(const Slice& slice);

/// Everything a raster render needs besides the genome.
struct RenderSettings {
    int width = 0, height = 0;
    std::string aa = "none";
    std::optional<Region> region; ///< default: the whole design space (of the slice plane)
    std::optional<Slice> slice;   ///< required for a 3D genome, ignored in 2D
    int threads = 0;              ///< 0: every core
};

/// The design-space rectangle the render covers: the region, or the whole design (in the
/// slice's plane: x-y for z=c, x-z for y=c, y-z for x=c).
Region effectiveRegion(const Genome& genome, const RenderSettings& settings);

/// Maps the two raster axes (u along columns, v along rows) to a point of the design space.
struct SampleFrame {
    glm::dvec3 origin{0.0}; ///< the point of raster coordinate (0, 0)
    glm::dvec3 du{0.0};     ///< design-space step of one pixel along a row
    glm::dvec3 dv{0.0};     ///< design-space step of one pixel down a column
    /// The design point of pixel (i, j) at sample offset (ox, oy).
    glm::dvec3 at(double i, double j, double ox, double oy) const {
        return origin + (i + 0.5 + ox) * du + (j + 0.5 + oy) * dv;
    }
};
SampleFrame sampleFrame(const Genome& genome, const RenderSettings& settings);

/// Largest raster Marbler renders: a side of at most MaxImageSide and at most MaxImagePixels.
inline constexpr int MaxImageSide = 65536;
inline constexpr std::int64_t MaxImagePixels = std::int64_t(1) << 31;
/// Throws InputError when the settings ask for an empty or absurd raster, a bad region or a
/// missing/bad slice.
void checkRenderSettings(const Genome& genome, const RenderSettings& settings);

} // namespace marbler
