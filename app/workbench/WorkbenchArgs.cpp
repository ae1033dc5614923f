#include "workbench/WorkbenchArgs.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <string_view>

namespace marbler::ui {
namespace {

/// Qt's own options that take a value (QGuiApplication / QApplication), with one or two dashes.
constexpr std::array QtValueOptions{
    "platform",     "platformpluginpath", "platformtheme", "plugin",     "qwindowgeometry",
    "qwindowtitle", "qwindowicon",        "style",         "stylesheet", "session",
    "display",      "geometry",           "title"};
/// Qt's own options without a value.
constexpr std::array QtFlagOptions{"reverse", "widgetcount", "nograb", "dograb", "sync"};

template <std::size_t N> bool contains(const std::array<const char*, N>& names, std::string_view name) {
    return std::any_of(names.begin(), names.end(), [&](const char* n) { return name == n; });
}

} // namespace

WorkbenchArgs parseWorkbenchArgs(std::span<const std::string> words) {
    WorkbenchArgs args;
    bool optionsEnded = false;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& word = words[i];
        if (optionsEnded || word.size() < 2 || word[0] != '-') {
            args.files.push_back(word);
            continue;
        }
        if (word == "--") {
            optionsEnded = true;
            continue;
        }
        const bool doubleDash = word.starts_with("--");
        std::string name = word.substr(doubleDash ? 2 : 1);
        std::optional<std::string> inlineValue;
        if (const auto eq = name.find('='); eq != std::string::npos) {
            inlineValue = name.substr(eq + 1);
            name.resize(eq);
        }
        const auto value = [&]() -> std::optional<std::string> {
            if (inlineValue) return inlineValue;
            if (i + 1 < words.size()) return words[++i];
            args.error = "marbler: " + word + " needs a value";
            return std::nullopt;
        };
        if (word == "--help" || word == "-h") {
            args.help = true;
        } else if (doubleDash && name == "screenshot") {
            const auto file = value();
            if (!file) return args;
            if (file->empty()) {
                args.error = "marbler: --screenshot needs a file name";
                return args;
            }
            args.screenshot = *file;
        } else if (doubleDash && name == "seed") {
            const auto text = value();
            if (!text) return args;
            unsigned long long seed = 0;
            const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), seed);
            if (ec != std::errc() || end != text->data() + text->size() || text->empty()) {
                args.error = "marbler: --seed needs a whole number, not '" + *text + "'";
                return args;
            }
            args.seed = seed;
        } else if (doubleDash && (name == "solid" || name == "flat") && !inlineValue) {
            args.dimension = name == "solid" ? 3 : 2;
        } else if (contains(QtValueOptions, name)) {
            if (!inlineValue && !value()) return args; // Qt reads the value itself
        } else if (contains(QtFlagOptions, name) && !inlineValue) {
        } else {
            args.error = "marbler: unknown option " + word + " (see marbler --help)";
            return args;
        }
    }
    return args;
}

} // namespace marbler::ui
