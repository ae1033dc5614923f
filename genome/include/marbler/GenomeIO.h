#pragma once
/// Reading and writing genome files (genome-format.md, File). Every rule of the format is
/// checked on load; what breaks a rule throws GenomeError naming the file and JSON location.

#include "marbler/AtomicFile.h" // writeFileAtomically, which saveGenome uses
#include "marbler/Genome.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace marbler {

/// Parses genome text. `name` is how errors and warnings name the source (a file name).
/// Warnings (unknown keys, skipped) are appended to `warnings` when given.
/// Throws GenomeError.
Genome parseGenome(std::string_view text, const std::string& name,
                   std::vector<std::string>* warnings = nullptr);

/// Loads a genome file (at most MaxFileBytes). Sets Genome::baseDirectory to its folder.
/// Throws GenomeError (also for a file that cannot be read).
Genome loadGenome(const std::filesystem::path& file, std::vector<std::string>* warnings = nullptr);

/// The genome as JSON text: stable key order, two-space indent, trailing newline.
std::string serializeGenome(const Genome& genome);

/// The genome as an ordered JSON value (what serializeGenome prints).
nlohmann::ordered_json toJson(const Genome& genome);

/// Checks every rule of the format on an in-memory genome (what the loader checks after
/// parsing). Throws GenomeError with `name` as the file.
void validateGenome(const Genome& genome, const std::string& name);

/// Whether a bath of the genome's size could wrap (docs/genome-format.md, "Wrapping bath"):
/// 2D, no source image, and every step one that commutes with the wrap. Whatever `wrap` says;
/// breeding clears `wrap` of a child whose new steps cannot wrap.
bool canWrap(const Genome& genome);

/// Why the genome's bath could not wrap, as the loader says it without the file's name
/// ("operations[2].tool: a drop pushes ..."), or "" where it can.
std::string wrapProblem(const Genome& genome);

/// Whether a step of `tool` can ever lie in a bath that wraps (spray always, stretch along an
/// axis); the editor offers only these tools for such a design.
bool toolMayWrap(Tool tool);

/// A wrap lattice's name in files and on the command line: "straight", "half-drop", "brick".
std::string_view latticeName(Lattice lattice);
/// The lattice of a name latticeName gives; nullopt for any other text.
std::optional<Lattice> latticeFromName(std::string_view name);

/// Saves a genome atomically. Throws RuntimeFailure.
void saveGenome(const Genome& genome, const std::filesystem::path& file);

} // namespace marbler
