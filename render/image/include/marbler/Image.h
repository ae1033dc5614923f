#pragma once
/// Pixels: an 8-bit sRGB raster and the sRGB transfer functions every renderer, writer and
/// reader shares, so an image is encoded one way wherever it is made.

#include "marbler/Color.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace marbler {

/// sRGB transfer functions on [0, 1].
double srgbToLinear(double c);
double linearToSrgb(double c);
/// A table of the 256 linear values of 8-bit sRGB.
const float* srgbToLinearTable();
/// A palette colour in linear light, each channel srgbToLinear of its 8-bit value.
glm::dvec3 linearOf(Color c);
/// Linear [0, 1] to 8-bit sRGB, rounded to nearest.
std::uint8_t encodeSrgb8(double linear);

/// An 8-bit sRGB raster, rows top to bottom, 3 channels interleaved.
struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;
    std::uint8_t* row(int y) { return rgb.data() + std::size_t(y) * std::size_t(width) * 3; }
    const std::uint8_t* row(int y) const { return rgb.data() + std::size_t(y) * std::size_t(width) * 3; }
};

} // namespace marbler
