#pragma once
/// Colours: the 8-bit sRGB colour of a palette and a bath, as files write it (`#rrggbb`), and
/// the measures and conversions that generation, breeding and colourways share. Only basic
/// operations, so every machine makes the same colours.

#include <cstdint>
#include <optional>
#include <string>

namespace marbler {

/// An sRGB colour, 8 bits a channel, as written `#rrggbb`.
struct Color {
    std::uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Color&, const Color&) = default;
};

/// `#rrggbb`, lower case.
std::string toHex(Color c);
/// Parses `#rrggbb` (either case); nullopt when malformed.
std::optional<Color> parseHexColor(const std::string& text);
/// How far apart two colours look, squared: the "redmean" distance (RGB weighted by how red the
/// pair is, after Riemersma). Only basic operations, so the same on every machine.
double colorDistance2(Color a, Color b);
/// The plain squared distance of two colours in RGB (0 to 3 * 255²).
double rgbDistance2(Color a, Color b);
/// The luma of an sRGB colour, 0 to 1 (Rec. 601 weights on the encoded values).
double lumaOf(Color c);

/// Hue (degrees, [0, 360)), saturation and lightness (0 to 1) of an sRGB colour.
struct Hsl {
    double h = 0.0, s = 0.0, l = 0.0;
};
/// A colour's HSL, with basic operations only (colorFromHsl's inverse).
Hsl hslOf(Color c);
/// An sRGB colour from HSL (hue wrapped, saturation and lightness clamped). HSL is piecewise
/// linear, so the 8-bit result is the same on every machine.
Color colorFromHsl(const Hsl& c);
Color colorFromHsl(double hue, double saturation, double lightness);
/// An angle in degrees wrapped into [0, 360).
double wrapHue(double h);

} // namespace marbler
