#include "marbler/Genome.h"

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

double colorDistance2(Color a, Color b) {
    double rm = (a.r + b.r) / 2.0;
    double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
    return (2.0 + rm / 256.0) * dr * dr + 4.0 * dg * dg + (2.0 + (255.0 - rm) / 256.0) * db * db;
}

} // namespace marbler
