#pragma once
/// Internal to render/image: what the decoding of source images needs (decodeSourceImage, in
/// SourceDecoder.cpp, is the public entry).

#include "marbler/Genome.h"
#include "marbler/SourceDecoder.h"

#include <string>
#include <string_view>
#include <vector>

namespace marbler::detail {

/// The public raster (SourceDecoder.h), by the name the image module's interface uses.
using LinearRaster = marbler::LinearRaster;

/// Decodes base64 (RFC 4648, padding optional, whitespace skipped). Throws InputError when the
/// text holds anything else.
std::vector<unsigned char> decodeBase64(std::string_view text);

} // namespace marbler::detail
