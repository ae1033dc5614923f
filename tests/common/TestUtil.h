#pragma once
/// Helpers shared by the test executables.

#include "marbler/Genome.h"

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace marbler::test {

/// Whether this build runs under AddressSanitizer (dev.sh's second pass), where the CPU renderer
/// is some ten times slower than in the release build.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool Sanitized = true;
#else
inline constexpr bool Sanitized = false;
#endif

/// `full` in the release build, `reduced` under the sanitiser: for a test that repeats the same
/// work many times, so that every case of it still runs under the sanitiser, on less of it. The
/// release build runs it in full.
template <class T> constexpr T fullOrSanitized(T full, T reduced) {
    return Sanitized ? reduced : full;
}

/// The committed test data folder (tests/data).
std::filesystem::path dataDir();

/// A fresh, empty folder under the build tree for one test's outputs (and failure images).
std::filesystem::path outputDir(const std::string& name);

/// An example design's file (tests/data/examples/NAME), as a command line names it.
std::string examplePath(const std::string& name);
/// An example design, loaded.
Genome loadExample(const std::string& name);
/// How many lines a text has (its newlines).
std::size_t lineCount(const std::string& text);

/// Reads a whole file; fails the test (throws) when it cannot.
std::string readFile(const std::filesystem::path& file);
void writeFile(const std::filesystem::path& file, const std::string& text);

/// The result of running the marbler executable.
struct RunResult {
    int exitCode = -1;
    std::string out; ///< stdout
    std::string err; ///< stderr
};

/// Runs the built `marbler` executable with the given arguments (no shell interpretation),
/// capturing stdout and stderr.
RunResult runMarbler(const std::vector<std::string>& args);

/// A change to the child's environment: set NAME to a value, or unset it (nullopt).
using EnvChange = std::pair<std::string, std::optional<std::string>>;

/// As runMarbler, with these changes to the environment the child inherits.
RunResult runMarbler(const std::vector<std::string>& args, const std::vector<EnvChange>& env);

/// Adds the tools `genome` uses to `seen`, named "2D wave", and for each choice parameter also
/// "3D wave shape=ripple".
void addToolsUsed(const Genome& genome, std::set<std::string>& seen);

/// Fails the test for every tool of the registry, in every dimension it exists in and with every
/// choice of its choice parameters, that `seen` (as addToolsUsed names them) lacks; `what`
/// completes the message ("no baseline renders").
void expectEveryRegistryTool(const std::set<std::string>& seen, const std::string& what);

} // namespace marbler::test
