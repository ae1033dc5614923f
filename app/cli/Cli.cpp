#include "cli/Cli.h"

#include "marbler/Error.h"
#ifdef MARBLER_HAVE_GUI
#include "WindowModule.h"
#endif
#include "marbler/GenomeImage.h"
#include "marbler/Sampling.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>

#include <unistd.h>

namespace marbler::cli {

std::optional<std::string> Args::get(const std::string& name) const {
    auto it = options.find(name);
    if (it == options.end()) return std::nullopt;
    return it->second;
}

Args parseArgs(std::span<const std::string> words, const std::vector<std::string>& valued,
               const std::vector<std::string>& flags) {
    auto contains = [](const std::vector<std::string>& list, const std::string& name) {
        for (const std::string& item : list)
            if (item == name) return true;
        return false;
    };
    Args args;
    bool onlyPositional = false;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& word = words[i];
        if (onlyPositional || word.size() < 2 || word[0] != '-') {
            args.positional.push_back(word);
            continue;
        }
        if (word == "--") {
            onlyPositional = true;
            continue;
        }
        std::string name = word.substr(word[1] == '-' ? 2 : 1);
        std::optional<std::string> value;
        if (auto eq = name.find('='); eq != std::string::npos) {
            value = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        if (contains(flags, name) || contains(CommonFlags, name)) {
            if (value) throw InputError("option --" + name + " takes no value");
            args.options[name] = "";
        } else if (contains(valued, name)) {
            if (!value) {
                if (i + 1 >= words.size()) throw InputError("option " + word + " needs a value");
                value = words[++i];
            }
            args.options[name] = *value;
        } else {
            throw InputError("unknown option " + word);
        }
    }
    return args;
}

int parseIntOption(const Args& args, const std::string& name, int fallback, int lo, int hi) {
    std::optional<std::string> text = args.get(name);
    if (!text) return fallback;
    long long value = 0;
    auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
    if (ec != std::errc() || end != text->data() + text->size())
        throw InputError("--" + name + ": not an integer: '" + *text + "'");
    if (value < lo || value > hi)
        throw InputError("--" + name + ": must be between " + std::to_string(lo) + " and " +
                         std::to_string(hi) + " (got " + *text + ")");
    return static_cast<int>(value);
}

double parseDoubleOption(const Args& args, const std::string& name, double fallback) {
    std::optional<std::string> text = args.get(name);
    if (!text) return fallback;
    double value = 0;
    auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
    if (ec != std::errc() || end != text->data() + text->size() || !std::isfinite(value))
        throw InputError("--" + name + ": not a number: '" + *text + "'");
    return value;
}

const std::string& oneGenomeArgument(const Args& args, const std::string& verb) {
    if (args.positional.size() != 1)
        throw InputError(args.positional.empty()
                             ? "a genome file is required (see marbler " + verb + " --help)"
                             : "exactly one genome file is expected (got " +
                                   std::to_string(args.positional.size()) + ")");
    return args.positional.front();
}

std::string requiredOutput(const Args& args, const std::string& verb, const std::string& what) {
    const std::optional<std::string> output = args.has("o") ? args.get("o") : args.get("output");
    if (!output || output->empty())
        throw InputError("-o " + what + " is required (see marbler " + verb + " --help)");
    return *output;
}

std::uint64_t parseSeedOption(const Args& args, const std::string& name) {
    std::optional<std::string> text = args.get(name);
    if (!text) throw InputError("--" + name + " is required");
    std::uint64_t value = 0;
    auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
    if (ec != std::errc() || end != text->data() + text->size())
        throw InputError("--" + name + ": not a non-negative integer: '" + *text + "'");
    return value;
}

double parseDpiOption(const Args& args, double fallback) {
    if (!args.has("dpi")) return fallback;
    double dpi = parseDoubleOption(args, "dpi", 0.0);
    if (!(dpi > 0.0) || dpi > 1e6)
        throw InputError("--dpi: must be a positive number (got " + *args.get("dpi") + ")");
    return dpi;
}

std::vector<double> parseNumberList(const std::string& option, const std::string& text, std::size_t count) {
    std::vector<double> values;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t comma = text.find(',', start);
        std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        double value = 0;
        auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (part.empty() || ec != std::errc() || end != part.data() + part.size() || !std::isfinite(value))
            throw InputError("--" + option + ": '" + text + "' is not " + std::to_string(count) +
                             " numbers separated by commas");
        values.push_back(value);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (values.size() != count)
        throw InputError("--" + option + ": '" + text + "' is not " + std::to_string(count) +
                         " numbers separated by commas");
    return values;
}

std::pair<double, double> parsePrintSize(const std::string& text) {
    auto bad = [&] {
        return InputError("--size: '" + text +
                          "' is not WIDTHxHEIGHT with a unit cm, mm or in (e.g. 42x59.4cm)");
    };
    if (text.size() < 3) throw bad();
    std::string unit = text.substr(text.size() - 2);
    double perInch = unit == "cm" ? 2.54 : unit == "mm" ? 25.4 : unit == "in" ? 1.0 : 0.0;
    if (perInch == 0.0) throw bad();
    std::string numbers = text.substr(0, text.size() - 2);
    std::size_t x = numbers.find_first_of("xX");
    if (x == std::string::npos) throw bad();
    std::vector<double> w = parseNumberList("size", numbers.substr(0, x), 1);
    std::vector<double> h = parseNumberList("size", numbers.substr(x + 1), 1);
    if (!(w[0] > 0.0) || !(h[0] > 0.0))
        throw InputError("--size: width and height must be > 0 (got '" + text + "')");
    return {w[0] / perInch, h[0] / perInch};
}

int pixelsOf(double value, const std::string& what) {
    double rounded = std::round(value);
    if (!(rounded >= 1.0)) throw InputError(what + " comes to less than one pixel");
    if (rounded > MaxImageSide)
        throw InputError(what + " comes to " +
                         std::to_string(static_cast<long long>(std::min(rounded, 1e18))) +
                         " pixels, more than the largest side of " + std::to_string(MaxImageSide));
    return static_cast<int>(rounded);
}

Genome loadGenomeArgument(const char* verb, const std::string& file) {
    std::vector<std::string> warnings;
    Genome genome = loadDesign(file, &warnings);
    for (const std::string& warning : warnings)
        std::cerr << "marbler " << verb << ": warning: " << warning << '\n';
    return genome;
}

int guarded(const char* verb, const std::function<int()>& body) {
    try {
        return body();
    } catch (const InputError& e) {
        std::cerr << "marbler " << verb << ": " << e.what() << '\n';
        return ExitBadInput;
    } catch (const std::bad_alloc&) {
        std::cerr << "marbler " << verb << ": out of memory\n";
        return ExitFailure;
    } catch (const std::exception& e) {
        std::cerr << "marbler " << verb << ": " << e.what() << '\n';
        return ExitFailure;
    }
}

ProgressLine::ProgressLine(const Args& args)
    : mEnabled(!args.has("quiet") && (args.has("progress") || ::isatty(2))) {}

void ProgressLine::show(const std::string& text) {
    if (!mEnabled) return;
    std::lock_guard lock(mMutex);
    if (text == mText) return;
    // Spaces over what the longer old text leaves, so nothing of it stays on the line.
    const std::size_t blank = mText.size() > text.size() ? mText.size() - text.size() : 0;
    std::cerr << '\r' << text << std::string(blank, ' ') << std::flush;
    mText = text;
}

void ProgressLine::finish() {
    std::lock_guard lock(mMutex);
    if (mText.empty()) return;
    std::cerr << '\r' << std::string(mText.size(), ' ') << '\r' << std::flush;
    mText.clear();
}

MeshData meshOf(const std::string& nameOrFile) {
    if (isBuiltinMesh(nameOrFile)) return builtinMesh(nameOrFile);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(nameOrFile, ec))
        throw InputError("--mesh: '" + nameOrFile + "' is neither a built-in object (" + builtinMeshList() +
                         ") nor a mesh file");
#ifdef MARBLER_HAVE_GUI
    return app::windowModule().loadMesh(nameOrFile);
#else
    throw RuntimeFailure(
        "--mesh FILE needs assimp, which comes with the window module, and this build has none "
        "(built without MARBLER_BUILD_GUI); the built-in objects work");
#endif
}

} // namespace marbler::cli
