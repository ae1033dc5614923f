#include "cli/Cli.h"

#include "marbler/Error.h"
#include "marbler/GenomeImage.h"

#include <charconv>
#include <cmath>
#include <iostream>

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
        if (contains(flags, name)) {
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
        throw InputError("--" + name + ": must be between " + std::to_string(lo) + " and " + std::to_string(hi) +
                         " (got " + *text + ")");
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

std::uint64_t parseSeedOption(const Args& args, const std::string& name) {
    std::optional<std::string> text = args.get(name);
    if (!text) throw InputError("--" + name + " is required");
    std::uint64_t value = 0;
    auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
    if (ec != std::errc() || end != text->data() + text->size())
        throw InputError("--" + name + ": not a non-negative integer: '" + *text + "'");
    return value;
}

Genome loadGenomeArgument(const char* verb, const std::string& file) {
    std::vector<std::string> warnings;
    Genome genome = loadDesign(file, &warnings);
    for (const std::string& warning : warnings) std::cerr << "marbler " << verb << ": warning: " << warning << '\n';
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

} // namespace marbler::cli
