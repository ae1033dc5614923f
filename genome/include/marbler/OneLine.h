#pragma once
/// A library's message made fit for one line of Marbler's own (cli.md: every message is one
/// line). Libraries report each error of a format library on a line of its own ("PNG read
/// error: IDAT: incorrect header check\nPNG library error"); those lines are joined with "; ",
/// other control characters become spaces, and trailing space goes.

#include <string>

namespace marbler {

inline std::string oneLine(const std::string& message) {
    std::string out;
    out.reserve(message.size());
    for (char c : message) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\n') {
            while (!out.empty() && out.back() == ' ')
                out.pop_back();
            if (!out.empty() && !out.ends_with("; ")) out += "; ";
        } else if (c == '\r') {
            continue;
        } else {
            out += byte < 0x20 || byte == 0x7f ? ' ' : c;
        }
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';'))
        out.pop_back();
    return out;
}

} // namespace marbler
