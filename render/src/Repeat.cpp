#include "marbler/Repeat.h"

#include <algorithm>

namespace marbler {

Image mirrorRepeat(const Image& image) {
    const int w = image.width, h = image.height;
    Image tile;
    tile.width = 2 * w;
    tile.height = 2 * h;
    tile.rgb.resize(std::size_t(tile.width) * std::size_t(tile.height) * 3);
    for (int y = 0; y < tile.height; ++y) {
        const std::uint8_t* source = image.row(y < h ? y : 2 * h - 1 - y);
        std::uint8_t* out = tile.row(y);
        std::copy(source, source + std::size_t(w) * 3, out);
        for (int x = 0; x < w; ++x)
            std::copy(source + x * 3, source + x * 3 + 3, out + std::size_t(2 * w - 1 - x) * 3);
    }
    return tile;
}

Image straightRepeat(const Image& image) {
    const int w = image.width, h = image.height;
    Image tile;
    tile.width = 2 * w;
    tile.height = 2 * h;
    tile.rgb.resize(std::size_t(tile.width) * std::size_t(tile.height) * 3);
    for (int y = 0; y < tile.height; ++y) {
        const std::uint8_t* source = image.row(y % h);
        std::uint8_t* out = tile.row(y);
        std::copy(source, source + std::size_t(w) * 3, out);
        std::copy(source, source + std::size_t(w) * 3, out + std::size_t(w) * 3);
    }
    return tile;
}

} // namespace marbler
