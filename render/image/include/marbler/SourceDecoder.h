#pragma once
/// The one decoder of a genome's `source` image, shared by the CPU renderer and the GL back end
/// so both see the same pixels, in the same light, and refuse the same inputs: a file found by
/// the rule of SourcePath.h, or a base64 `data:` URI, decoded by OpenImageIO (in the module
/// marbler-imageio.so) into linear-light RGB (8- and 16-bit images are sRGB-decoded, linear
/// formats such as EXR kept as they are).

#include "marbler/Genome.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace marbler {

/// An RGB raster in linear light, rows top to bottom.
struct LinearRaster {
    int width = 0, height = 0;
    std::vector<float> rgb; ///< width * height * 3 values
};

/// Decodes the genome's source image (which it must have). Throws GenomeError naming the
/// genome and `source.image` when the image is refused (SourcePath.h), missing, malformed
/// (bad base64 included), too large or cannot be decoded; RuntimeFailure when the image
/// module cannot be loaded.
LinearRaster decodeSourceImage(const Genome& genome);

/// An 8-bit sRGB RGB raster (rows top first, `stride` bytes apart) in linear light, exactly as
/// decodeSourceImage decodes a PNG of the same pixels: for a source that is not a file, such as
/// a video frame (CpuRenderer's second constructor).
LinearRaster linearRasterOfSrgb8(const std::uint8_t* rgb, int width, int height, std::size_t stride);

} // namespace marbler
