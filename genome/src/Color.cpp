#include "marbler/Color.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace marbler {

std::string toHex(Color c) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
    return text;
}

std::optional<Color> parseHexColor(const std::string& text) {
    if (text.size() != 7 || text[0] != '#') return std::nullopt;
    auto nibble = [](char ch) -> int {
        if (ch >= '0' && ch <= '9') return ch - '0';
        if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
        if (ch >= 'A' && ch <= 'F') return ch - 'A' + 10;
        return -1;
    };
    std::uint8_t channels[3];
    for (int i = 0; i < 3; ++i) {
        int hi = nibble(text[1 + 2 * i]), lo = nibble(text[2 + 2 * i]);
        if (hi < 0 || lo < 0) return std::nullopt;
        channels[i] = static_cast<std::uint8_t>(hi * 16 + lo);
    }
    return Color{channels[0], channels[1], channels[2]};
}

double rgbDistance2(Color a, Color b) {
    double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
    return dr * dr + dg * dg + db * db;
}

double lumaOf(Color c) {
    return (0.299 * c.r + 0.587 * c.g + 0.114 * c.b) / 255.0;
}

double colorDistance2(Color a, Color b) {
    double rm = (a.r + b.r) / 2.0;
    double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
    return (2.0 + rm / 256.0) * dr * dr + 4.0 * dg * dg + (2.0 + (255.0 - rm) / 256.0) * db * db;
}

Hsl hslOf(Color c) {
    const double r = c.r / 255.0, g = c.g / 255.0, b = c.b / 255.0;
    const double hi = std::max({r, g, b}), lo = std::min({r, g, b});
    Hsl out;
    out.l = (hi + lo) / 2.0;
    const double d = hi - lo;
    if (d <= 0.0) return out;
    out.s = out.l > 0.5 ? d / (2.0 - hi - lo) : d / (hi + lo);
    if (hi == r)
        out.h = 60.0 * ((g - b) / d + (g < b ? 6.0 : 0.0));
    else if (hi == g)
        out.h = 60.0 * ((b - r) / d + 2.0);
    else
        out.h = 60.0 * ((r - g) / d + 4.0);
    return out;
}

double wrapHue(double h) {
    h = std::fmod(h, 360.0);
    return h < 0.0 ? h + 360.0 : h;
}

Color colorFromHsl(const Hsl& c) {
    const double h = wrapHue(c.h) / 60.0;
    const double s = std::clamp(c.s, 0.0, 1.0), l = std::clamp(c.l, 0.0, 1.0);
    const double chroma = (1.0 - std::abs(2.0 * l - 1.0)) * s;
    const double hm = h - 2.0 * std::floor(h / 2.0);
    const double x = chroma * (1.0 - std::abs(hm - 1.0));
    double r = 0, g = 0, b = 0;
    switch (static_cast<int>(h)) {
    case 0:
        r = chroma, g = x;
        break;
    case 1:
        r = x, g = chroma;
        break;
    case 2:
        g = chroma, b = x;
        break;
    case 3:
        g = x, b = chroma;
        break;
    case 4:
        r = x, b = chroma;
        break;
    default:
        r = chroma, b = x;
        break;
    }
    const double m = l - chroma / 2.0;
    auto channel = [](double v) {
        return static_cast<std::uint8_t>(std::clamp(std::round(v * 255.0), 0.0, 255.0));
    };
    return {channel(r + m), channel(g + m), channel(b + m)};
}

Color colorFromHsl(double hue, double saturation, double lightness) {
    return colorFromHsl({hue, saturation, lightness});
}

} // namespace marbler
