#pragma once
/// Internal to render/: the decoded source image of a genome, which only ImageIO.cpp (the one
/// file that sees OpenImageIO) can load.

#include "marbler/Genome.h"

#include <string>
#include <vector>

namespace marbler::detail {

/// An RGB raster in linear light, rows top to bottom.
struct LinearRaster {
    int width = 0, height = 0;
    std::vector<float> rgb;
};

/// Loads a genome's `source` image: a path relative to `baseDirectory`, or a
/// `data:image/...;base64,` URL. Throws InputError naming the file when it cannot be loaded.
LinearRaster loadSourceImage(const SourceImage& source, const std::string& baseDirectory);

/// Decodes base64 (RFC 4648, padding optional, whitespace skipped). Throws InputError when the
/// text holds anything else.
std::vector<unsigned char> decodeBase64(std::string_view text);

} // namespace marbler::detail
