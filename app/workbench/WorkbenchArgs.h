#pragma once
/// The window's command line, parsed without Qt so that main() can report a bad option (exit 2)
/// before the window module, Qt or a display is involved.

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace marbler::ui {

/// What the command line asks of the window. Besides genome files it takes a few hidden options
/// (`--screenshot FILE`, `--seed N`, `--solid`, `--flat`) and Qt's own (`-platform NAME`,
/// `-style NAME`, ...), each also as `--name=value`; `--` ends the options.
struct WorkbenchArgs {
    std::vector<std::string> files;
    std::string screenshot;                 ///< save a picture of the window and quit
    std::optional<unsigned long long> seed; ///< the session seed
    std::optional<int> dimension;           ///< --solid (3) or --flat (2): skip the start choice
    bool help = false;                      ///< --help / -h among the words
    std::string error;                      ///< one line naming a bad option; empty when all is well
};

/// Parses the words after the program name (no Qt application needed, so main() can report a
/// bad option with exit status 2 before any window or display is involved).
WorkbenchArgs parseWorkbenchArgs(std::span<const std::string> words);

} // namespace marbler::ui
