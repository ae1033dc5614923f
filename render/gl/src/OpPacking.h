#pragma once
/// The genome as shader data: PreparedOp records packed as 7 vec4 (a buffer texture of RGBA32F)
/// per tool, in the layout tools.glsl documents.

#include "marbler/Tools.h"

#include <glm/vec3.hpp>

#include <vector>

namespace marbler::gl {

/// Floats per packed record.
inline constexpr int PackedOpFloats = 28;

/// Packs `ops` (time order) with every position taken relative to `reference` (in double, before
/// the cast to float), so the shader keeps float precision near the reference.
std::vector<float> packOps(const std::vector<PreparedOp>& ops, const glm::dvec3& reference);

} // namespace marbler::gl
