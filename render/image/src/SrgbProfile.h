#pragma once
/// Internal to render/image: the ICC profile Marbler embeds in the PNG, TIFF and JPEG files it
/// writes, so that print and layout software (which may not read PNG's sRGB chunk or assume
/// anything of an untagged TIFF) keeps the colours. It is built here from the numbers of IEC
/// 61966-2-1 (sRGB): an ICC version 2.1 display profile with the sRGB primaries adapted to the
/// profile connection space's D50 white by the Bradford transform, that transform in a `chad`
/// tag, and the sRGB transfer curve as a 1024-entry table.

#include <vector>

namespace marbler::detail {

/// The profile's bytes (the same every call).
const std::vector<unsigned char>& srgbIccProfile();

/// The profile's description, as PNG's iCCP chunk names it.
inline constexpr const char* SrgbIccProfileName = "sRGB IEC61966-2.1";

} // namespace marbler::detail
