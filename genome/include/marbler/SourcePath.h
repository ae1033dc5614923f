#pragma once
/// Where a genome's `source` image may be read from (genome-format.md, cli.md): a `data:` URI,
/// or a file in the genome's own folder or below it. A path that is absolute or leads out of
/// that folder (by `..` or through a symbolic link) is refused unless the user allowed it
/// (`--allow-external-source`, the window's question), so a shared genome cannot read the
/// receiver's other files. The one place this rule lives: the CPU renderer, the GL back end
/// and the window all resolve sources here.

#include "marbler/Genome.h"

#include <filesystem>
#include <string>

namespace marbler {

/// Where a genome's source image lies.
struct SourceLocation {
    enum class Kind {
        None,    ///< the genome has no source image
        DataUri, ///< embedded in the genome
        Inside,  ///< a file in the genome's folder or below it
        Outside, ///< absolute, or leading out of the folder (`..`, a symbolic link)
    };
    Kind kind = Kind::None;
    /// For a file: its path with every symbolic link resolved (what would be read), made
    /// absolute. A missing file keeps the part that does not exist as written.
    std::filesystem::path file;
};

/// Finds where the genome's source image lies, relative to Genome::baseDirectory. A genome with
/// no folder (empty baseDirectory: pasted or dropped as text, made in memory) has every file
/// outside, resolved against the current folder. Reads no image and never throws for a missing
/// file.
SourceLocation locateSource(const Genome& genome);

/// The file a genome's source image is to be read from (its canonical path), after the rule
/// above: a file outside the folder only with Genome::allowExternalSource. Throws GenomeError
/// naming the genome (Genome::fileName) and `source.image`: for a file outside the folder
/// that is not allowed, and for a file that does not exist. Not for `data:` URIs.
std::filesystem::path sourceFileToRead(const Genome& genome);

/// How messages name the genome: Genome::fileName, or "the design" for one made in memory.
std::string genomeName(const Genome& genome);

/// Whether `image` (a `source.image` value) is a `data:` URI.
bool isDataUri(const std::string& image);

} // namespace marbler
