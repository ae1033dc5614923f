#pragma once
/// Helpers shared by the test executables.

#include <filesystem>
#include <string>
#include <vector>

namespace marbler::test {

/// The committed test data folder (tests/data).
std::filesystem::path dataDir();

/// A fresh, empty folder under the build tree for one test's outputs (and failure images).
std::filesystem::path outputDir(const std::string& name);

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

} // namespace marbler::test
