#include "marbler/SourcePath.h"

#include "marbler/Error.h"

#include <algorithm>
#include <system_error>

namespace marbler {
namespace fs = std::filesystem;

namespace {

/// The genome's folder, absolute, with its symbolic links resolved: the folder may itself be
/// reached through a link, and the file is compared in the same resolved form.
fs::path resolvedFolder(const Genome& genome) {
    std::error_code ec;
    fs::path folder =
        fs::absolute(genome.baseDirectory.empty() ? fs::path(".") : fs::path(genome.baseDirectory), ec);
    fs::path resolved = fs::weakly_canonical(folder, ec);
    return ec ? folder.lexically_normal() : resolved;
}

/// Whether `file` lies in `folder` or below it, comparing whole path components.
bool within(const fs::path& folder, const fs::path& file) {
    auto f = folder.begin(), p = file.begin();
    for (; f != folder.end(); ++f, ++p) {
        if (f->empty()) continue; // a trailing separator
        if (p == file.end() || *f != *p) return false;
    }
    return true;
}

} // namespace

bool isDataUri(const std::string& image) {
    return image.rfind("data:", 0) == 0;
}

std::string genomeName(const Genome& genome) {
    return genome.fileName.empty() ? std::string("the design") : genome.fileName;
}

SourceLocation locateSource(const Genome& genome) {
    SourceLocation location;
    if (!genome.source) return location;
    if (isDataUri(genome.source->image)) {
        location.kind = SourceLocation::Kind::DataUri;
        return location;
    }
    const fs::path folder = resolvedFolder(genome);
    const fs::path named(genome.source->image);
    // A design that came from no file (pasted or dropped as text) has no folder of its own: it
    // must not read the files round wherever Marbler runs, so every file it names is outside.
    const bool noFolder = genome.baseDirectory.empty();
    // weakly_canonical resolves every link of the part that exists (a link inside the folder
    // that points out of it is seen for where it points) and `..` in the rest, so a missing
    // file is still placed correctly.
    std::error_code ec;
    const fs::path joined = named.is_absolute() ? named : folder / named;
    fs::path file = fs::weakly_canonical(joined, ec);
    if (ec) file = joined.lexically_normal();
    location.file = file;
    location.kind = !noFolder && !named.is_absolute() && within(folder, file) ? SourceLocation::Kind::Inside
                                                                              : SourceLocation::Kind::Outside;
    return location;
}

fs::path sourceFileToRead(const Genome& genome) {
    const SourceLocation location = locateSource(genome);
    const std::string name = genomeName(genome);
    const std::string image = genome.source ? genome.source->image : std::string();
    if (location.kind == SourceLocation::Kind::Outside && !genome.allowExternalSource)
        throw GenomeError(
            name, "source.image",
            "'" + image + "' (" + location.file.string() +
                ") lies outside the genome's folder; a design may read images only from its own "
                "folder or below it, or from a data: URI (--allow-external-source reads it anyway)");
    std::error_code ec;
    if (location.kind == SourceLocation::Kind::Inside || location.kind == SourceLocation::Kind::Outside) {
        if (!fs::is_regular_file(location.file, ec))
            throw GenomeError(name, "source.image",
                              "'" + image + "': no such image file (" + location.file.string() + ")");
    }
    return location.file;
}

} // namespace marbler
