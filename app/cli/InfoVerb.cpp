// `marbler info GENOME`: checks a genome file and prints a summary of it (spec/cli.md).

#include "cli/Cli.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "marbler/SourcePath.h"

#include <array>
#include <iostream>
#include <sstream>

namespace marbler::cli {
namespace {

constexpr const char* InfoHelp = R"(usage: marbler info GENOME

Checks a genome file (or the genome inside a PNG or TIFF image Marbler wrote) against every
rule of the format and prints a summary: the format version the design needs (1, or 2 when it
uses a version-2 tool, core or bleed; what Marbler writes it as), dimension, size, palette,
background, the bleed when set, how many entries of each tool lie in `initial` and
`operations`, the source image and the design's name, if any. Unknown keys, and a source image that lies
outside the genome's folder (which `render` reads only with --allow-external-source), are
reported as warnings on stderr; the image itself is not read.

exit status: 0 when the genome is valid, 2 when it is not (one line on stderr naming the
file and the JSON location of the first problem).
)";

/// "5 (drop 3, spray 2)": the total, then the count of each tool in table order.
std::string countsByTool(const std::vector<Operation>& ops) {
    std::array<std::size_t, ToolCount> counts{};
    for (const Operation& op : ops)
        ++counts[static_cast<std::size_t>(op.tool)];
    std::ostringstream text;
    text << ops.size();
    const char* separator = " (";
    for (const ToolSpec& spec : allTools()) {
        std::size_t count = counts[static_cast<std::size_t>(spec.tool)];
        if (count == 0) continue;
        text << separator << spec.name << ' ' << count;
        separator = ", ";
    }
    if (!ops.empty()) text << ')';
    return text.str();
}

std::string number(double value) {
    std::ostringstream text;
    text.precision(15);
    text << value;
    return text.str();
}

} // namespace

int runInfo(std::span<const std::string> words) {
    return guarded("info", [&] {
        Args args = parseArgs(words, {}, {"help", "h"});
        if (args.has("help") || args.has("h")) {
            std::cout << InfoHelp;
            return ExitOk;
        }
        if (args.positional.size() != 1)
            throw InputError("expected one genome file (see marbler info --help)");
        const std::string& file = args.positional[0];

        Genome genome = loadGenomeArgument("info", file);
        if (const SourceLocation where = locateSource(genome); where.kind == SourceLocation::Kind::Outside)
            std::cerr
                << "marbler info: warning: " << file << ": source.image: '" << genome.source->image << "' ("
                << where.file.string()
                << ") lies outside the genome's folder; render reads it only with --allow-external-source\n";

        std::ostringstream out;
        out << "file:       " << file << '\n';
        // The version the design needs, which need not be the one its file says (a version-2
        // file that uses nothing new is saved back as version 1).
        out << "version:    " << requiredVersion(genome) << '\n';
        out << "dimension:  " << genome.dimension << '\n';
        out << "size:       " << number(genome.size.x) << " x " << number(genome.size.y);
        if (genome.dimension == 3) out << " x " << number(genome.size.z);
        out << '\n';
        out << "palette:    " << genome.palette.size()
            << (genome.palette.size() == 1 ? " colour:" : " colours:");
        for (const Color& color : genome.palette)
            out << ' ' << toHex(color);
        out << '\n';
        out << "background: " << toHex(genome.background) << '\n';
        if (genome.bleed > 0.0) out << "bleed:      " << number(genome.bleed) << " design units\n";
        if (genome.wrap && genome.lattice == Lattice::Straight)
            out << "wrap:       the bath wraps: a straight-repeat tile\n";
        else if (genome.wrap) // a half-drop or brick lattice (docs/genome-format.md)
            out << "wrap:       the bath wraps: a " << latticeName(genome.lattice) << " repeat tile\n";
        out << "initial:    " << countsByTool(genome.initial) << '\n';
        out << "operations: " << countsByTool(genome.operations) << '\n';
        if (genome.source) {
            const std::string& image = genome.source->image;
            // A data URL would flood the terminal; its length says enough.
            if (image.starts_with("data:"))
                out << "source:     embedded image (" << image.size() << " characters)\n";
            else
                out << "source:     " << image << '\n';
        }
        if (genome.meta.name) out << "name:       " << *genome.meta.name << '\n';
        std::cout << out.str();
        return ExitOk;
    });
}

} // namespace marbler::cli
