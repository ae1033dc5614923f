#pragma once
/// A coordinate or length as the SVG writers put it (Vector.cpp's toSvg, Separations.cpp's
/// layered SVG): fixed with `decimals` places, trailing zeros and a bare point dropped, "-0"
/// as "0", so equal numbers are always the same text.

#include "marbler/Error.h"

#include <charconv>
#include <string>
#include <string_view>
#include <system_error>

namespace marbler::detail {

inline void appendSvgNumber(std::string& out, double value, int decimals) {
    char text[64];
    auto [end, ec] = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, decimals);
    if (ec != std::errc()) throw RuntimeFailure("a coordinate cannot be written");
    std::string_view s(text, end - text);
    if (s.find('.') != std::string_view::npos) {
        while (s.back() == '0')
            s.remove_suffix(1);
        if (s.back() == '.') s.remove_suffix(1);
    }
    if (s == "-0") s = "0";
    out.append(s);
}

} // namespace marbler::detail
