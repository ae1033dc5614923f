#pragma once
/// The genome as shader data: PreparedOp records packed as 7 vec4 (a buffer texture of RGBA32F)
/// per tool, in the layout tools.glsl documents, the teeth of every stretch in a second buffer
/// (R32F) and the path segments of every stylus in a third (RGBA32F), which the records index.

#include "marbler/Tools.h"

#include <glm/vec3.hpp>

#include <vector>

namespace marbler::gl {

/// Floats per packed record.
inline constexpr int PackedOpFloats = 28;

/// A flow's fixed-point iteration stops when an iterate moves less than this share of Lx + Ly
/// (or than a few float steps of the point, if more), where the CPU's double iteration stops at
/// 1e-12 (Lx + Ly) (genome-format.md, flow). 1e-6 is about ten float steps of a point within
/// one field size of the origin: tighter, float rounding alone would keep the iteration going.
/// The shader caps the iteration at FlowIterations (tools.glsl): with the format's step bound
/// each iteration shrinks the error twenty-fold or more, so the cap is met only where rounding,
/// not the iteration, sets the error. A stylus's iteration shares both, its tolerance a share
/// of L + reach where the CPU's is 1e-12 (L + reach): its step rule contracts alike.
inline constexpr double FlowToleranceShare = 1e-6;

/// Texels (vec4) per stylus path segment in PackedOps::paths.
inline constexpr int StylusSegmentTexels = 2;

/// A packed genome.
struct PackedOps {
    std::vector<float> records; ///< PackedOpFloats per operation
    std::vector<float> teeth;   ///< the teeth of every stretch, one after another
    /// Every stylus's path segments, one after another, StylusSegmentTexels vec4 each (relative
    /// to the reference, as the records).
    std::vector<float> paths;
};

/// Packs `ops` (time order) with every position taken relative to `reference` (in double, before
/// the cast to float), so the shader keeps float precision near the reference.
PackedOps packOps(const std::vector<PreparedOp>& ops, const glm::dvec3& reference);

/// Whether `ops` need the shaders' version-2 forms (MARBLER_VERSION2): a stretch, a flow, a
/// stylus or a swirl with a finite core. Designs without them run the version-1 body, which pays
/// for none.
bool needsVersion2Forms(const std::vector<PreparedOp>& ops);

/// The shaders' stylus that `ops` need (MARBLER_STYLUS, within the version-2 forms): 0 none,
/// 1 styluses of one tine only (no loop over tines), 2 a rake among them.
int stylusForm(const std::vector<PreparedOp>& ops);

/// What one sample of the colour rule costs through `ops`, in version-1 operations: one each,
/// a stylus its steps times its tines (the tile size of a draw keeps a driver's watchdog away).
double shaderWork(const std::vector<PreparedOp>& ops);

} // namespace marbler::gl
